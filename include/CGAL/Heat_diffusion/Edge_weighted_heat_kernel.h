// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Edge-weighted heat kernels (EHK): paper, section 4 and eq. 20.

#ifndef CGAL_HEAT_DIFFUSION_EDGE_WEIGHTED_HEAT_KERNEL_H
#define CGAL_HEAT_DIFFUSION_EDGE_WEIGHTED_HEAT_KERNEL_H

#include <CGAL/Heat_diffusion/internal/coarse_level.h>
#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/generalized_eigensolver.h>
#include <CGAL/Heat_diffusion/internal/heat_operators.h>
#include <CGAL/Heat_diffusion/internal/progress.h>
#include <CGAL/Heat_diffusion/internal/vertex_normals_from_parameters.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/parameters.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionKernel
/// Wall-clock seconds of the stages of the construction of an `Edge_weighted_heat_kernel`,
/// for tools and benchmarks that report where time goes.
struct Heat_kernel_timings
{
  double normal_controlled_coordinates = 0; ///< NCC of the mesh (indexing, normals, weights)
  double simplification = 0;                ///< coarse level: edge collapse and prolongation (0 without)
  double operators = 0;                     ///< assembly of L and B (on the coarse level too, if any)
  double eigen_solve = 0;                   ///< factorisation and Lanczos (or the dense solver)
  double rayleigh_ritz = 0;                 ///< coarse level: prolongation of the vectors and Rayleigh-Ritz
};

/// \cond SKIP_IN_MANUAL
template <typename TriangleMesh, typename GeomTraits>
class Anisotropic_heat_diffusion;

namespace internal {

// The default coarse level of Edge_weighted_heat_kernel, outside the class template so
// that code without a mesh type (the command-line tool) applies the same rule.
constexpr std::size_t automatic_coarse_threshold = 100000;
constexpr std::size_t automatic_coarse_vertex_count = 20000;

// The vertex count the coarse level aims at for a mesh of n vertices (before the
// simplification rounds it; 0 for none): `requested` if it is not negative (none unless
// it is smaller than n), else the automatic choice.
inline std::size_t coarse_vertex_count_for(double requested, std::size_t n)
{
  if(requested < 0)
    return n > automatic_coarse_threshold ? automatic_coarse_vertex_count : 0;
  return std::size_t(requested) < n ? std::size_t(requested) : 0;
}

} // namespace internal
/// \endcond

/// \ingroup PkgHeatDiffusionKernel
/// The edge-weighted heat kernel of a triangle mesh (paper, eq. 10-14 and 20),
/// computed once from the m smallest generalized eigenpairs and evaluated many times.
///
/// The stiffness matrix is the positive semi-definite \f$ L = D - W \f$ with edge
/// weights \f$ w_{ij} = \exp(-\|\delta'_i - \delta'_j\|^2/\sigma^2) \f$ from the NCC, the
/// mass matrix is the FEM mass matrix \f$ B \f$ of eq. 11, both on a copy of the surface
/// rescaled to total area = number of vertices (so that \f$ t = 1 \f$ is about one ring,
/// whatever the size and sampling of the mesh; the mesh itself is not modified). The
/// eigenpairs \f$ L\phi_k = \lambda_k B\phi_k \f$, \f$ 0 = \lambda_1 \le \lambda_2 \le \dots \f$,
/// are \f$ B \f$-orthonormal and come from Spectra's shift-invert Lanczos solver with
/// a negative shift (a dense solver for meshes of at most 400 vertices). The kernel is
/// \f[ h_t(i,j) = \sum_{k=1}^m e^{-\lambda_k t}\phi_k(i)\phi_k(j) , \f]
/// or, with `scale_invariant_kernel(true)`, eq. 14:
/// \f$ \beta \sum_k e^{-\lambda'_k t}\phi_k(i)\phi_k(j) \f$ with
/// \f$ \beta = (B_{ii}+B_{jj})/2 \f$ and \f$ \lambda'_k = \lambda_k / \lambda_\ast \f$, where
/// \f$ \lambda_\ast \f$ is the first eigenvalue above \f$ 10^{-8}\lambda_m \f$: \f$ \lambda_2 \f$ on a
/// connected mesh, \f$ \lambda_{c+1} \f$ on a mesh with \f$ c \f$ connected components (each has its
/// zero eigenvalue), so the normalisation never divides by zero. A small `sigma` can cut
/// a mesh into numerically separate pieces (with `sigma` = 0.1 the weights across the
/// sharp creases of fandisk fall to \f$ 10^{-11} \f$ and below), which count as components here.
///
/// <b>Coarse level (paper, eq. 21).</b> On large meshes the eigen solve dominates (and
/// grows superlinearly). With `coarse_vertex_count(N)`, the mesh is simplified to about
/// N vertices (Garland-Heckbert edge collapse, after a faster first pass down to 4N
/// vertices on larger meshes), the NCC, \f$ L \f$, \f$ B \f$ and the eigenpairs
/// are computed there (rescaled to the fine mesh's vertex count, so t keeps its meaning),
/// and each eigenvector is prolongated to the fine vertices with the barycentric
/// coordinates of their closest points on the coarse mesh. A Rayleigh-Ritz step with
/// the fine \f$ L \f$ and \f$ B \f$ on the span of the prolongated vectors then gives the
/// eigenvalues and \f$ B \f$-orthonormal eigenvectors (n x m) the package uses; it removes
/// the bias of the coarse eigenvalues (about 20 % on fandisk with 5000 coarse vertices).
/// `stiffness_matrix()` and `mass_matrix()` are those of the fine mesh. By default the coarse level is used
/// for meshes of more than `automatic_coarse_threshold` vertices, with
/// `automatic_coarse_vertex_count` coarse vertices; `coarse_vertex_count(0)` turns it off.
///
/// <b>Validity.</b> The truncated kernel is accurate only for
/// \f$ t \gtrsim 4\ln 10/\lambda_m \f$ (about 18 on fandisk with m = 150, 74 on armadillo):
/// at smaller t it is too flat and too wide (see the user manual). It is the paper's
/// method, and the right one for large t and for the heat kernel signature.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// @tparam GeomTraits a model of `Kernel`
template <typename TriangleMesh,
          typename GeomTraits = typename CGAL::Kernel_traits<typename boost::property_traits<
              typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel>
class Edge_weighted_heat_kernel
{
public:
  /// The vertex type of `TriangleMesh`.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// The Normal-Controlled Coordinates the kernel is built from.
  typedef Normal_controlled_coordinates<TriangleMesh, GeomTraits> NCC;

  /// Meshes larger than this use a coarse level by default.
  static constexpr std::size_t automatic_coarse_threshold = internal::automatic_coarse_threshold;
  /// The coarse vertex count chosen by default for such meshes.
  static constexpr std::size_t automatic_coarse_vertex_count = internal::automatic_coarse_vertex_count;

  /// Computes the NCC, \f$ L \f$, \f$ B \f$ and the eigenpairs.
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{sigma}
  ///     \cgalParamDescription{the width of the edge weights: small preserves features (the paper uses 0.1), large smooths (1); `std::numeric_limits<double>::infinity()` gives the plain, isotropic Laplacian}
  ///     \cgalParamType{`double`, positive}
  ///     \cgalParamDefault{`0.1`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_eigenpairs}
  ///     \cgalParamDescription{the number m of eigenpairs; clamped to the number of vertices}
  ///     \cgalParamType{`std::size_t`, positive}
  ///     \cgalParamDefault{`150`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{scale_invariant_kernel}
  ///     \cgalParamDescription{evaluate eq. 14 instead of eq. 13}
  ///     \cgalParamType{`bool`}
  ///     \cgalParamDefault{`false`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{coarse_vertex_count}
  ///     \cgalParamDescription{the vertex count of the coarse level on which the eigenpairs are computed; 0 for none}
  ///     \cgalParamType{`std::size_t`}
  ///     \cgalParamDefault{`automatic_coarse_vertex_count` for meshes of more than `automatic_coarse_threshold` vertices, else 0}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{progress_callback}
  ///     \cgalParamDescription{called on the calling thread with the fraction done of the construction (the eigen solve, and the
  ///       coarse level's simplification if any); returning `false` cancels the construction with a `std::runtime_error`}
  ///     \cgalParamType{a callable `bool(double)`}
  ///     \cgalParamDefault{none}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_point_map, vertex_index_map, vertex_normal_map, vertex_normal_rule, geom_traits}
  ///     \cgalParamDescription{as for `Normal_controlled_coordinates`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws std::invalid_argument on a mesh the package cannot process (see
  ///   `Normal_controlled_coordinates`) or an invalid parameter.
  /// \throws std::runtime_error if the eigen solve fails or is cancelled.
  ///
  /// Complexity: one sparse Cholesky factorisation and a Lanczos iteration of
  /// \f$ O(n m^2) \f$ dense work.
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Edge_weighted_heat_kernel(const TriangleMesh& tm,
                                     const NamedParameters& np = parameters::default_values())
    : ncc_(tm, np)
  {
    timings_.normal_controlled_coordinates = lap();
    using parameters::choose_parameter;
    using parameters::get_parameter;
    sigma_ = internal::parameter_value(np, internal_np::sigma, defaults::sigma);
    const double requested_m =
        double(internal::parameter_value(np, internal_np::number_of_eigenpairs, defaults::number_of_eigenpairs));
    scale_invariant_ = internal::parameter_value(np, internal_np::scale_invariant_kernel, false);
    const internal::Progress progress = internal::progress_of(np);
    internal::checked_sigma(sigma_, "Edge_weighted_heat_kernel");
    if(!(requested_m >= 1))
      internal::throw_invalid_input("Edge_weighted_heat_kernel: number_of_eigenpairs must be positive");

    const internal::Indexed_mesh& mesh = ncc_.indexed_mesh();
    if(mesh.number_of_vertices() == 0)
      internal::throw_invalid_input("Edge_weighted_heat_kernel: the mesh is empty");
    const std::size_t n = mesh.number_of_vertices();
    // -1: not given (the automatic choice below)
    const double requested_coarse = internal::is_given(np, internal_np::coarse_vertex_count)
                                        ? double(internal::parameter_value(np, internal_np::coarse_vertex_count, 0))
                                        : -1.;
    if(!std::isfinite(requested_coarse))
      internal::throw_invalid_input("Edge_weighted_heat_kernel: coarse_vertex_count must be finite");
    coarse_vertices_ = internal::coarse_vertex_count_for(requested_coarse, n);
    if(coarse_vertices_ > 0 && coarse_vertices_ < 4)
      internal::throw_invalid_input("Edge_weighted_heat_kernel: coarse_vertex_count must be at least 4 (or 0 for none)");

    operators_ = internal::assemble_heat_operators(mesh, ncc_.data(), sigma_);
    mass_diagonal_ = operators_.mass.diagonal();
    timings_.operators = lap();
    if(coarse_vertices_ == 0)
    {
      internal::Generalized_eigenpairs pairs = internal::compute_smallest_generalized_eigenpairs(
          operators_.stiffness, operators_.mass, Eigen::Index((std::min)(requested_m, double(n))),
          progress.as_callback());
      timings_.eigen_solve = lap();
      eigenvalues_ = std::move(pairs.eigenvalues);
      eigenvectors_ = std::move(pairs.eigenvectors);
      used_dense_solver_ = pairs.dense_solver;
    }
    else
    {
      // Shares of the progress bar, after the stages' shares of the time on large meshes:
      // the simplification and the eigen solve take most of it, Rayleigh-Ritz the rest.
      const internal::Coarse_level level =
          internal::make_coarse_level(mesh, coarse_vertices_, progress.part(0., 0.5));
      coarse_vertices_ = level.mesh.number_of_vertices();
      timings_.simplification = lap();
      const internal::Ncc_data coarse_ncc =
          internal::compute_ncc_data(level.mesh, internal::area_weighted_vertex_normals(level.mesh));
      const internal::Heat_operators coarse_operators =
          internal::assemble_heat_operators(level.mesh, coarse_ncc, sigma_, double(n));
      timings_.operators += lap();
      internal::Generalized_eigenpairs pairs = internal::compute_smallest_generalized_eigenpairs(
          coarse_operators.stiffness, coarse_operators.mass,
          Eigen::Index((std::min)(requested_m, double(coarse_vertices_))),
          progress.part(0.5, 0.88).as_callback());
      used_dense_solver_ = pairs.dense_solver;
      timings_.eigen_solve = lap();
      rayleigh_ritz_on_fine_mesh(level.prolongation, pairs.eigenvectors);
      timings_.rayleigh_ritz = lap();
      progress.report(1., "the coarse level");
    }
    number_of_components_ = count_components(mesh);
    eigenvalues_ = internal::clamped_eigenvalues(eigenvalues_);
    first_nonzero_eigenvalue_ = internal::first_nonzero_eigenvalue(eigenvalues_);
  }

  /// The NCC the kernel was built from (also gives `vertex_index()`).
  const NCC& normal_controlled_coordinates() const { return ncc_; }
  /// The row of `v` in `eigenvectors()`.
  std::size_t vertex_index(vertex_descriptor v) const { return ncc_.vertex_index(v); }
  /// The number of vertices.
  std::size_t number_of_vertices() const { return std::size_t(eigenvectors_.rows()); }
  /// The number m of eigenpairs (the requested one, clamped to the number of vertices).
  std::size_t number_of_eigenpairs() const { return std::size_t(eigenvalues_.size()); }
  /// The eigenvalues, ascending (for the surface rescaled to area = number of vertices).
  const Eigen::VectorXd& eigenvalues() const { return eigenvalues_; }
  /// The eigenvectors, one column each, \f$ B \f$-orthonormal; rows follow `vertex_index()`.
  const Eigen::MatrixXd& eigenvectors() const { return eigenvectors_; }
  /// The stiffness matrix \f$ L \f$ (positive semi-definite).
  const Eigen::SparseMatrix<double>& stiffness_matrix() const { return operators_.stiffness; }
  /// The mass matrix \f$ B \f$ of the rescaled surface.
  const Eigen::SparseMatrix<double>& mass_matrix() const { return operators_.mass; }
  /// `sigma` of the edge weights.
  double sigma() const { return sigma_; }
  /// `true` if the kernel evaluates eq. 14.
  bool is_scale_invariant() const { return scale_invariant_; }
  /// The number of connected components of the mesh (each has a zero eigenvalue).
  std::size_t number_of_connected_components() const { return number_of_components_; }
  /// Where the construction spent its time.
  const Heat_kernel_timings& timings() const { return timings_; }
  /// The vertex count of the coarse level the eigenpairs were computed on, 0 if none.
  std::size_t coarse_vertex_count() const { return coarse_vertices_; }
  /// `true` if the eigenpairs came from the dense solver (small meshes).
  bool used_dense_solver() const { return used_dense_solver_; }

  /// The exponent rate of mode k: \f$ \lambda_k \f$, or \f$ \lambda'_k \f$ for eq. 14.
  double decay_rate(std::size_t k) const
  {
    return scale_invariant_ ? eigenvalues_[Eigen::Index(k)] / first_nonzero_eigenvalue_ : eigenvalues_[Eigen::Index(k)];
  }

  /// \f$ h_t(i, j) \f$ between the vertices of indices `i` and `j`.
  double kernel(std::size_t i, std::size_t j, double t) const
  {
    double sum = 0;
    for(Eigen::Index k = 0; k < eigenvalues_.size(); ++k)
      sum += std::exp(-decay_rate(std::size_t(k)) * t) * eigenvectors_(Eigen::Index(i), k) *
             eigenvectors_(Eigen::Index(j), k);
    return scale_invariant_ ? beta(i, j) * sum : sum;
  }

  /// \f$ h_t(u, v) \f$. Symmetric in `u` and `v`.
  double operator()(vertex_descriptor u, vertex_descriptor v, double t) const
  {
    return kernel(vertex_index(u), vertex_index(v), t);
  }

  /// The heat kernel signature \f$ \mathrm{HKS}(v, t) = h_t(v, v) \f$
  /// (Sun, Ovsjanikov and Guibas 2009), with this kernel's weights and normalisation.
  double heat_kernel_signature(vertex_descriptor v, double t) const
  {
    const std::size_t i = vertex_index(v);
    return kernel(i, i, t);
  }

  /// The global heat-kernel smoothing of a field given by vertex index,
  /// \f$ F_t = \sum_k e^{-\lambda_k t}\phi_k\phi_k^T B F_0 \f$ (Patane and Falcidieno 2010,
  /// Seo et al. 2010), the baseline the paper compares against (Fig. 5 and 8); with
  /// `sigma` infinite it is the isotropic one. It conserves the area-weighted integral
  /// \f$ \mathbf{1}^T B F \f$ (the constant mode is among the m), not the plain vertex sum
  /// the paper's Fig. 5 measures: as t grows \f$ F_t \f$ tends to the area-weighted mean,
  /// and the vertex sum drifts by the difference between the two means (1.7 % on fandisk,
  /// 3.3 % on armadillo at t = 1000), with or without truncation.
  Eigen::VectorXd global_heat_smoothing(const Eigen::VectorXd& field, double t) const
  {
    Eigen::VectorXd coefficients = eigenvectors_.transpose() * (operators_.mass * field);
    for(Eigen::Index k = 0; k < coefficients.size(); ++k)
      coefficients[k] *= std::exp(-eigenvalues_[k] * t);
    return eigenvectors_ * coefficients;
  }

  /// \cond SKIP_IN_MANUAL
  // What Anisotropic_heat_diffusion evaluates the kernel from (internal/kernel_columns.h).
  // With a coarse level, eigenvectors() = coarse_prolongation() * coarse_eigenvectors()
  // (fine x coarse, three entries a row, times coarse x m). Empty without a coarse level.
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& coarse_prolongation() const { return coarse_prolongation_; }
  const Eigen::MatrixXd& coarse_eigenvectors() const { return coarse_eigenvectors_; }
  // The diagonal of B, of which eq. 14's beta is made.
  const Eigen::VectorXd& mass_diagonal() const { return mass_diagonal_; }
  /// \endcond

private:

  // The factor beta_ij of eq. 14 (evaluated for every entry of every heat region of the
  // scale-invariant kernel: from the stored diagonal, not searched in B's columns).
  double beta(std::size_t i, std::size_t j) const { return internal::scale_invariant_factor(mass_diagonal_, i, j); }

  // Seconds since the last lap.
  double lap()
  {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - clock_).count();
    clock_ = now;
    return seconds;
  }

  // The prolongated coarse eigenvectors span a good subspace, but their coarse
  // eigenvalues are biased (about 20 % high on fandisk with 5000 coarse vertices: the
  // graph Laplacian depends on the triangle shapes, which simplification changes).
  // Rayleigh-Ritz with the fine L and B on that subspace gives the best pairs it
  // contains for the fine operator: Ritz values, and vectors that are exactly
  // B-orthonormal on the fine mesh. With the basis P Phi_c (P the prolongation), the
  // projections Phi_c^T (P^T L P) Phi_c are computed through the sparse Galerkin
  // products P^T L P and P^T B P on the coarse level: O(n) sparse work instead of
  // O(n m^2) dense work, and the one n x m matrix formed is the result P (Phi_c Y).
  void rayleigh_ritz_on_fine_mesh(const Eigen::SparseMatrix<double>& prolongation, const Eigen::MatrixXd& coarse_vectors)
  {
    const Eigen::SparseMatrix<double> transposed = prolongation.transpose();
    Eigen::SparseMatrix<double> galerkin = transposed * (operators_.stiffness * prolongation);
    Eigen::MatrixXd projected_stiffness = coarse_vectors.transpose() * (galerkin * coarse_vectors);
    galerkin = transposed * (operators_.mass * prolongation);
    Eigen::MatrixXd projected_mass = coarse_vectors.transpose() * (galerkin * coarse_vectors);
    // symmetrise the rounding
    projected_stiffness = 0.5 * (projected_stiffness + projected_stiffness.transpose()).eval();
    projected_mass = 0.5 * (projected_mass + projected_mass.transpose()).eval();
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(projected_stiffness, projected_mass);
    if(ritz.info() != Eigen::Success)
      throw std::runtime_error("CGAL::Heat_diffusion: the Rayleigh-Ritz step of the coarse level failed "
                               "(the prolongated eigenvectors are linearly dependent)");
    eigenvalues_ = ritz.eigenvalues();
    coarse_eigenvectors_ = coarse_vectors * ritz.eigenvectors();
    // Row-major: the product below then runs column by column, streaming.
    coarse_prolongation_ = prolongation;
    eigenvectors_.resize(prolongation.rows(), coarse_eigenvectors_.cols());
    eigenvectors_.noalias() = coarse_prolongation_ * coarse_eigenvectors_;
  }

  static std::size_t count_components(const internal::Indexed_mesh& mesh)
  {
    const std::size_t n = mesh.number_of_vertices();
    std::vector<unsigned char> seen(n, 0);
    std::vector<std::size_t> stack;
    std::size_t components = 0;
    for(std::size_t s = 0; s < n; ++s)
    {
      if(seen[s])
        continue;
      ++components;
      seen[s] = 1;
      stack.push_back(s);
      while(!stack.empty())
      {
        const std::size_t i = stack.back();
        stack.pop_back();
        for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
          if(!seen[mesh.fan[k]])
          {
            seen[mesh.fan[k]] = 1;
            stack.push_back(mesh.fan[k]);
          }
      }
    }
    return components;
  }

  // First member: initialised before ncc_, whose construction it times.
  std::chrono::steady_clock::time_point clock_ = std::chrono::steady_clock::now();
  NCC ncc_;
  internal::Heat_operators operators_;
  Eigen::VectorXd mass_diagonal_;  // of operators_.mass, for beta()
  Eigen::VectorXd eigenvalues_;
  Eigen::MatrixXd eigenvectors_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> coarse_prolongation_;  // coarse level: P, n x c
  Eigen::MatrixXd coarse_eigenvectors_;  // coarse level: eigenvectors_ = P coarse_eigenvectors_
  double sigma_ = 0.1;
  double first_nonzero_eigenvalue_ = 1.;
  std::size_t number_of_components_ = 1;
  std::size_t coarse_vertices_ = 0;
  Heat_kernel_timings timings_;
  bool scale_invariant_ = false;
  bool used_dense_solver_ = false;
};

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_EDGE_WEIGHTED_HEAT_KERNEL_H
