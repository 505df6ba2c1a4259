// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Conservative multi-scale diffusion by local heat kernel convolution: paper, section 5.

#ifndef CGAL_HEAT_DIFFUSION_ANISOTROPIC_HEAT_DIFFUSION_H
#define CGAL_HEAT_DIFFUSION_ANISOTROPIC_HEAT_DIFFUSION_H

#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/heat_kernel_method.h>
#include <CGAL/Heat_diffusion/internal/diffusion_construction.h>
#include <CGAL/Heat_diffusion/internal/diffusion_operator.h>
#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/heat_operators.h>
#include <CGAL/Heat_diffusion/internal/kernel_columns.h>
#include <CGAL/Heat_diffusion/internal/progress.h>
#include <CGAL/Heat_diffusion/internal/vertex_fields.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/operator_normalization.h>
#include <CGAL/Heat_diffusion/parameters.h>

#include <Eigen/Sparse>

#include <cmath>
#include <functional>
#include <memory>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionDiffusion
/// Statistics of the heat regions \f$ \Omega_j \f$ of an `Anisotropic_heat_diffusion`.
struct Heat_region_statistics
{
  std::size_t min_size = 0;          ///< the smallest region, in vertices
  double mean_size = 0;              ///< the mean region size
  std::size_t max_size = 0;          ///< the largest region
  std::size_t collapsed_regions = 0; ///< regions reduced to their source vertex: it keeps its heat
  std::size_t capped_regions = 0;    ///< regions that reached `Anisotropic_heat_diffusion::maximum_region_size`
};

/// \ingroup PkgHeatDiffusionDiffusion
/// The diffusion operator \f$ A_t \f$ of the paper (eq. 15-19) built once, and
/// \f$ F^k = A_t^k F^0 \f$ computed many times by sparse matrix-vector products.
///
/// <b>Kernel.</b> \f$ h_t = \exp(-t B^{-1} L) B^{-1} \f$ of the edge-weighted operator of
/// `Edge_weighted_heat_kernel`, evaluated as the named parameter `kernel_method` says:
/// `Heat_kernel_method::spectral` (the paper's m eigenpairs) or
/// `Heat_kernel_method::local` (each column on a patch around its source, with no
/// eigen solve and no truncation: the NCC, \f$ L \f$ and \f$ B \f$ are all it computes; see
/// the user manual for the accuracy and the cost of each). By default
/// (`Heat_kernel_method::automatic`) the kernel is local unless the eigenpairs are asked
/// for.
///
/// <b>Heat regions (eq. 15).</b> The region \f$ \Omega_j \f$ of a vertex \f$ v_j \f$ is grown
/// breadth first from \f$ v_j \f$ over mesh edges, taking the vertices with
/// \f$ h_t(j, i) > \tau(t) = 0.01/(1+t) \f$ and never expanding through a vertex at or
/// below the threshold; \f$ v_j \f$ always belongs. For the scale-invariant kernel (eq. 14),
/// whose values live on another scale, the threshold is relative to the column's peak,
/// \f$ h_t(j, i) > \tau(t)\, h_t(j, j) \f$: with the absolute threshold every region
/// would collapse to its source vertex. Growing from the source keeps the regions local
/// even where the truncated kernel oscillates far away.
///
/// <b>Normalisation (the named parameter `operator_normalization`).</b> By default
/// (`Operator_normalization::balanced`) \f$ A_t = D K D + \mathrm{diag}(c) \f$: \f$ K \f$ is
/// the symmetric kernel matrix on the symmetrised regions (\f$ K_{ij} \f$ is the mean of
/// \f$ h_t(j, i) \f$ where \f$ i \in \Omega_j \f$ and \f$ h_t(i, j) \f$ where \f$ j \in \Omega_i \f$,
/// each 0 where its region does not hold it), \f$ D \f$ the positive diagonal that balances
/// it (symmetric Sinkhorn-Knopp iteration, to \f$ |(DKD\mathbf{1})_i - 1| \le 10^{-4} \f$)
/// and \f$ c \f$ the remainder \f$ 1 - (DKD\mathbf{1})_i \f$ on the diagonal (the iteration goes on
/// until the corrected diagonal is nonnegative), so that every row
/// and every column sums to 1 to rounding. \f$ A_t \f$ is nonnegative, symmetric and doubly
/// stochastic: the total heat \f$ \sum_i F^k(i) \f$ is conserved (paper, Fig. 5), a constant
/// field stays constant, \f$ \min F^0 \le F^k \le \max F^0 \f$, adding a constant commutes
/// with diffusion, and no vertex is a sink (a vertex whose region collapsed keeps its
/// value, or exchanges heat with the regions that hold it). The paper's normalisation
/// (`Operator_normalization::columns`, eq. 16-18 with the sum over \f$ \Omega_j \f$ that
/// conservation requires: the paper's \f$ \Omega_i \f$ conserves nothing unless the regions
/// happen to be symmetric) is \f$ A_t(i, j) = h_t(j, i) / \sum_{k \in \Omega_j} h_t(j, k) \f$
/// for \f$ i \in \Omega_j \f$: its columns sum to 1, so heat is conserved, but its rows do
/// not, and a constant field does not stay constant.
///
/// <b>Capped regions.</b> A kernel that is nearly flat (the scale-invariant kernel at
/// t = 1, whose time unit is \f$ 1/\lambda_\ast \f$, is nearly constant over fandisk) would
/// give regions as large as the mesh and a dense \f$ A_t \f$. Regions stop growing at
/// `maximum_region_size` vertices (breadth first, so the nearest are kept);
/// the normalisation, and so the conservation, is unchanged. `region_statistics()`
/// counts capped regions.
///
/// <b>Collapsed regions.</b> When the kernel of a vertex is below the threshold at all
/// its neighbours (the truncated kernel can be that flat at small t; with either kernel,
/// the weights of a small `sigma` can isolate a vertex, such as a corner where sharp
/// creases meet), its region is the vertex alone and it never diffuses. `region_statistics()` counts such regions.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// @tparam GeomTraits a model of `Kernel`
template <typename TriangleMesh,
          typename GeomTraits = typename CGAL::Kernel_traits<typename boost::property_traits<
              typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel>
class Anisotropic_heat_diffusion
{
public:
  /// The vertex type of `TriangleMesh`.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// The spectral heat kernel, when the diffusion uses one (see `heat_kernel()`).
  typedef Edge_weighted_heat_kernel<TriangleMesh, GeomTraits> Heat_kernel;
  /// The NCC the operators are built from.
  typedef Normal_controlled_coordinates<TriangleMesh, GeomTraits> NCC;
  /// The sparse matrix type of \f$ A_t \f$.
  typedef Eigen::SparseMatrix<double> Sparse_matrix;

  /// Builds the heat kernel of `tm` and \f$ A_t \f$.
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{time}
  ///     \cgalParamDescription{the time t of one step (on the surface rescaled to area = number of vertices)}
  ///     \cgalParamType{`double`, positive}
  ///     \cgalParamDefault{`1`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{kernel_method}
  ///     \cgalParamDescription{how the heat kernel is evaluated}
  ///     \cgalParamType{`Heat_kernel_method`}
  ///     \cgalParamDefault{`Heat_kernel_method::automatic`: spectral if `number_of_eigenpairs` or
  ///       `coarse_vertex_count` is given or `scale_invariant_kernel` is `true`, else local}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{operator_normalization}
  ///     \cgalParamDescription{how \f$ A_t \f$ is made from the kernel (see above)}
  ///     \cgalParamType{`Operator_normalization`}
  ///     \cgalParamDefault{`Operator_normalization::balanced`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{local_kernel_tolerance}
  ///     \cgalParamDescription{the local kernel's accuracy: the heat a column may lose through the
  ///       border of its patch, relative to its heat; it also chooses the rational approximation
  ///       of the exponential (two poles from about 5e-4 on, four times their error, else three).
  ///       The spectral method ignores it.}
  ///     \cgalParamType{`double`, in (0, 1)}
  ///     \cgalParamDefault{`defaults::local_kernel_tolerance`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{sigma, vertex_point_map, vertex_index_map, vertex_normal_map, vertex_normal_rule, geom_traits}
  ///     \cgalParamDescription{as for `Edge_weighted_heat_kernel`, with either method}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_eigenpairs, scale_invariant_kernel, coarse_vertex_count}
  ///     \cgalParamDescription{as for `Edge_weighted_heat_kernel`, for the spectral method; the
  ///       local method ignores them, except `scale_invariant_kernel(true)`, which it rejects
  ///       (eq. 14 needs the eigenvalues)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{progress_callback}
  ///     \cgalParamDescription{called on the calling thread with the fraction done of the whole
  ///       construction (spectral: the eigenpairs, the coarse level's simplification included,
  ///       then the heat regions; local: the heat regions, block by block of sources);
  ///       returning `false` cancels the construction with a `std::runtime_error`}
  ///     \cgalParamType{a callable `bool(double)`}
  ///     \cgalParamDefault{none}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws std::invalid_argument on a mesh the package cannot process (see
  ///   `Normal_controlled_coordinates`) or an invalid parameter.
  /// \throws std::runtime_error if the eigen solve fails (spectral method) or if the
  ///   construction is cancelled.
  ///
  /// Complexity: that of `Edge_weighted_heat_kernel` plus the construction from a kernel
  /// below (spectral); linear in the number of vertices for a fixed t (local: per
  /// cluster of 96 sources, one complex sparse factorisation per pole of the rational
  /// exponential (two at the default tolerance, three below about 5e-4) on a patch whose size
  /// grows like t, and block solves on the part of it that the heat regions read;
  /// parallel with TBB); the balancing adds a few tens of products with \f$ A_t \f$
  /// (linear, parallel).
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Anisotropic_heat_diffusion(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
    : method_(internal::resolve_kernel_method(
          np, internal::parameter_value(np, internal_np::scale_invariant_kernel, false))),
      diffusion_operator_(checked_normalization(
          internal::parameter_value(np, internal_np::operator_normalization, Operator_normalization::balanced)))
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    const double t = checked_time(internal::parameter_value(np, internal_np::time, defaults::time));
    // (checked whichever kernel runs: the spectral one ignores it, but a bad value is a mistake)
    const double tolerance = internal::checked_kernel_tolerance(
        internal::parameter_value(np, internal_np::local_kernel_tolerance, defaults::local_kernel_tolerance),
        "Anisotropic_heat_diffusion");
    const internal::Progress progress = internal::progress_of(np);
    if constexpr(internal::can_select_spectral_kernel<NamedParameters>)
      if(method_ == Heat_kernel_method::spectral)
      {
        // One progress bar: the kernel (eigen solve) takes most of it, the regions the rest.
        use_kernel(std::make_shared<Heat_kernel>(tm, internal::with_progress(np, progress.part(0., 0.8))));
        build_spectral(t, progress.part(0.8, 1.));
        return;
      }
    if(method_ != Heat_kernel_method::local)
      internal::throw_invalid_input("Anisotropic_heat_diffusion: unknown kernel_method");
    if(internal::parameter_value(np, internal_np::scale_invariant_kernel, false))
      internal::throw_invalid_input("Anisotropic_heat_diffusion: the scale-invariant kernel (eq. 14) needs the "
                                    "eigenvalues; use Heat_kernel_method::spectral");
    sigma_ = internal::checked_sigma(internal::parameter_value(np, internal_np::sigma, defaults::sigma),
                                     "Anisotropic_heat_diffusion");
    ncc_ = std::make_shared<NCC>(tm, np);
    const internal::Indexed_mesh& mesh = ncc_->indexed_mesh();
    if(mesh.number_of_vertices() == 0)
      internal::throw_invalid_input("Anisotropic_heat_diffusion: the mesh is empty");
    time_ = t;
    internal::build_local_diffusion_operator(mesh, internal::assemble_heat_operators(mesh, ncc_->data(), sigma_), t,
                                             construction_options(tolerance), progress, diffusion_operator_,
                                             statistics_);
  }

  /// Builds \f$ A_t \f$ from an existing (spectral) kernel, which must outlive this object.
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{operator_normalization}
  ///     \cgalParamDescription{how \f$ A_t \f$ is made from the kernel (see above)}
  ///     \cgalParamType{`Operator_normalization`}
  ///     \cgalParamDefault{`Operator_normalization::balanced`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{progress_callback}
  ///     \cgalParamDescription{called with the fraction done while the heat regions are
  ///       built and \f$ A_t \f$ balanced; returning `false` cancels the construction with a `std::runtime_error`}
  ///     \cgalParamType{a callable `bool(double)`}
  ///     \cgalParamDefault{none}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws std::invalid_argument if `t` is not positive and finite.
  ///
  /// Complexity: linear in the number of vertices for a fixed t (one breadth-first
  /// search per vertex, over its region and the region's one-ring, and the balancing's
  /// products with \f$ A_t \f$; parallel with TBB).
  template <typename NamedParameters = parameters::Default_named_parameters>
  Anisotropic_heat_diffusion(const Heat_kernel& kernel, double t,
                             const NamedParameters& np = parameters::default_values())
    : method_(Heat_kernel_method::spectral),
      diffusion_operator_(checked_normalization(
          internal::parameter_value(np, internal_np::operator_normalization, Operator_normalization::balanced)))
  {
    // (borrowed: an owner-less shared pointer, which never deletes the kernel)
    use_kernel(std::shared_ptr<const Heat_kernel>(std::shared_ptr<const Heat_kernel>(), &kernel));
    build_spectral(checked_time(t), internal::progress_of(np));
  }

  /// The largest heat region, in vertices.
  static constexpr std::size_t maximum_region_size = 4096;

  /// The diffusion time t of one step.
  double time() const { return time_; }
  /// The width `sigma` of the edge weights of the kernel (eq. 10).
  double sigma() const { return sigma_; }
  /// The threshold \f$ \tau(t) = 0.01/(1+t) \f$.
  double threshold() const { return 0.01 / (1. + time_); }
  /// How the heat kernel was evaluated: `spectral` or `local`, never `automatic`.
  Heat_kernel_method kernel_method() const { return method_; }
  /// The spectral heat kernel.
  /// \throws std::logic_error if `kernel_method()` is `Heat_kernel_method::local`, which has none.
  const Heat_kernel& heat_kernel() const
  {
    if(kernel_ == nullptr)
      throw std::logic_error("CGAL::Heat_diffusion::Anisotropic_heat_diffusion: the local kernel method has no "
                             "spectral heat kernel");
    return *kernel_;
  }
  /// The NCC of the mesh (both methods).
  const NCC& normal_controlled_coordinates() const { return *ncc_; }
  /// The row and column of `v` in `operator_matrix()`.
  std::size_t vertex_index(vertex_descriptor v) const { return ncc_->vertex_index(v); }
  /// The number of vertices.
  std::size_t number_of_vertices() const { return ncc_->indexed_mesh().number_of_vertices(); }
  /// How \f$ A_t \f$ was made from the kernel.
  Operator_normalization operator_normalization() const { return diffusion_operator_.normalization(); }
  /// \f$ A_t \f$: doubly stochastic and symmetric (`Operator_normalization::balanced`) or
  /// column-stochastic (`Operator_normalization::columns`); rows and columns follow
  /// `vertex_index()`. The diffusion keeps \f$ A_t \f$ in its own layout only; this
  /// compressed-column copy is made on the first call (thread-safe) and kept.
  const Sparse_matrix& operator_matrix() const
  {
    std::call_once(column_major_->once, [this] { column_major_->matrix = diffusion_operator_.column_major(); });
    return column_major_->matrix;
  }
  /// The number of products with the kernel matrix that its balancing took (0 with
  /// `Operator_normalization::columns`).
  std::size_t balancing_iterations() const { return diffusion_operator_.balancing_iterations(); }
  /// Sizes of the heat regions.
  const Heat_region_statistics& region_statistics() const { return statistics_; }

  /// \f$ F^k = A_t^k F^0 \f$ for a field given by vertex index.
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{progress_callback}
  ///     \cgalParamDescription{called on the calling thread after each step with the fraction
  ///       of the steps done; returning `false` cancels the diffusion with a `std::runtime_error`}
  ///     \cgalParamType{a callable `bool(double)`}
  ///     \cgalParamDefault{none}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws std::invalid_argument if the field has the wrong size or a value that is not finite.
  template <typename NamedParameters = parameters::Default_named_parameters>
  Eigen::VectorXd diffuse(const Eigen::VectorXd& field, std::size_t number_of_steps,
                          const NamedParameters& np = parameters::default_values()) const
  {
    return diffuse(field, std::vector<std::size_t>(1, number_of_steps), np).front();
  }

  /// The fields \f$ F^k \f$ for every k of `steps` (in any order), in one pass; named
  /// parameters as above.
  template <typename NamedParameters = parameters::Default_named_parameters>
  std::vector<Eigen::VectorXd> diffuse(const Eigen::VectorXd& field, const std::vector<std::size_t>& steps,
                                       const NamedParameters& np = parameters::default_values()) const
  {
    check_field(field);
    return internal::diffuse_steps(diffusion_operator_, field, steps, internal::progress_of(np));
  }

  /// Diffuses the field `field_in` by `number_of_steps` steps and writes it to `field_out`;
  /// named parameters as above.
  /// @tparam InputFieldMap a model of `ReadablePropertyMap`, `vertex_descriptor` to a floating-point type
  /// @tparam OutputFieldMap a model of `WritablePropertyMap`, `vertex_descriptor` to a floating-point type
  /// \throws std::invalid_argument if a value of `field_in` is not finite.
  template <typename InputFieldMap, typename OutputFieldMap,
            typename NamedParameters = parameters::Default_named_parameters>
  void diffuse(InputFieldMap field_in, OutputFieldMap field_out, std::size_t number_of_steps,
               const NamedParameters& np = parameters::default_values()) const
  {
    const TriangleMesh& tm = ncc_->mesh();
    const auto index_of = [this](vertex_descriptor v) { return vertex_index(v); };
    const Eigen::VectorXd field =
        internal::read_vertex_field(tm, number_of_vertices(), field_in, index_of, "Anisotropic_heat_diffusion");
    internal::write_vertex_field(tm, diffuse(field, number_of_steps, np), field_out, index_of);
  }

private:
  void check_field(const Eigen::VectorXd& field) const
  {
    if(field.size() != Eigen::Index(number_of_vertices()))
      internal::throw_invalid_input("Anisotropic_heat_diffusion: the field has the wrong size");
    internal::check_finite_field(field, ncc_->mesh(), [this](vertex_descriptor v) { return vertex_index(v); },
                                 "Anisotropic_heat_diffusion");
  }

  static Operator_normalization checked_normalization(Operator_normalization normalization)
  {
    if(normalization != Operator_normalization::balanced && normalization != Operator_normalization::columns)
      internal::throw_invalid_input("Anisotropic_heat_diffusion: unknown operator_normalization");
    return normalization;
  }

  static double checked_time(double t) { return internal::checked_positive(t, "Anisotropic_heat_diffusion", "time"); }

  // The spectral kernel, and its NCC (which keeps the kernel alive).
  void use_kernel(std::shared_ptr<const Heat_kernel> kernel)
  {
    kernel_ = std::move(kernel);
    ncc_ = std::shared_ptr<const NCC>(kernel_, &kernel_->normal_controlled_coordinates());
    sigma_ = kernel_->sigma();
  }

  void build_spectral(double t, const internal::Progress& progress)
  {
    time_ = t;
    std::vector<std::size_t> order(number_of_vertices());
    std::iota(order.begin(), order.end(), std::size_t(0));
    // psi = (eigenvectors, fine or coarse) exp(-rate t / 2), column by column
    auto build = [&](auto columns) {
      for(Eigen::Index k = 0; k < columns.psi.cols(); ++k)
        columns.psi.col(k) *= std::exp(-0.5 * kernel_->decay_rate(std::size_t(k)) * t);
      build_from_columns(columns, order, std::vector<std::size_t>(), progress);
    };
    const Eigen::VectorXd* mass_diagonal = kernel_->is_scale_invariant() ? &kernel_->mass_diagonal() : nullptr;
    if(kernel_->coarse_eigenvectors().size() > 0)
      build(internal::Coarse_spectral_columns{kernel_->coarse_eigenvectors(), &kernel_->coarse_prolongation(),
                                              mass_diagonal});
    else
      build(internal::Spectral_columns{kernel_->eigenvectors(), mass_diagonal});
  }

  template <typename Columns>
  void build_from_columns(const Columns& columns, const std::vector<std::size_t>& order,
                          const std::vector<std::size_t>& group_begin, const internal::Progress& progress)
  {
    // (the spectral kernels ignore the local kernel's tolerance)
    const internal::Diffusion_construction_options options = construction_options(defaults::local_kernel_tolerance);
    Eigen::VectorXd column_sums, peaks;
    internal::compute_heat_regions(columns, ncc_->indexed_mesh(), order, group_begin, options, progress,
                                   diffusion_operator_, statistics_, column_sums, peaks);
    internal::complete_diffusion_operator(column_sums, peaks, options, progress, diffusion_operator_);
  }

  internal::Diffusion_construction_options construction_options(double local_kernel_tolerance) const
  {
    return {threshold(), maximum_region_size, local_kernel_tolerance};
  }

  // operator_matrix(), made on the first call (thread-safe), shared by copies.
  struct Column_major_copy
  {
    std::once_flag once;
    Sparse_matrix matrix;
  };

  // The spectral kernel (owned when built from the mesh, borrowed when given), none
  // with the local method; the NCC, the kernel's or the local method's own.
  std::shared_ptr<const Heat_kernel> kernel_;
  std::shared_ptr<const NCC> ncc_;
  Heat_kernel_method method_ = Heat_kernel_method::spectral;
  double sigma_ = defaults::sigma;
  double time_ = defaults::time;
  internal::Diffusion_operator diffusion_operator_;  // A_t
  std::shared_ptr<Column_major_copy> column_major_ = std::make_shared<Column_major_copy>();
  Heat_region_statistics statistics_;
};

/// \ingroup PkgHeatDiffusionDiffusion
/// Diffuses the scalar field `field_in` anisotropically over `tm` and writes
/// \f$ F^k = A_t^k F^0 \f$ to `field_out`: a thin wrapper over
/// `Anisotropic_heat_diffusion` for a single use (build the class to diffuse several
/// fields or to several k without recomputing the kernel).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_steps}
///     \cgalParamDescription{the number k of diffusion steps}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{time}
///     \cgalParamDescription{the time t of one step (on the surface rescaled to area = number of vertices)}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{kernel_method}
///     \cgalParamDescription{how the heat kernel is evaluated (see `Anisotropic_heat_diffusion`)}
///     \cgalParamType{`Heat_kernel_method`}
///     \cgalParamDefault{`Heat_kernel_method::automatic`}
///   \cgalParamNEnd
///   \cgalParamNBegin{operator_normalization}
///     \cgalParamDescription{how \f$ A_t \f$ is made from the kernel (see `Anisotropic_heat_diffusion`)}
///     \cgalParamType{`Operator_normalization`}
///     \cgalParamDefault{`Operator_normalization::balanced`: doubly stochastic}
///   \cgalParamNEnd
///   \cgalParamNBegin{sigma, number_of_eigenpairs, scale_invariant_kernel, progress_callback, vertex_point_map, ...}
///     \cgalParamDescription{as for `Edge_weighted_heat_kernel`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument on invalid input or parameters (a negative k included).
template <typename TriangleMesh, typename InputFieldMap, typename OutputFieldMap,
          typename NamedParameters = parameters::Default_named_parameters>
void anisotropic_heat_diffusion(const TriangleMesh& tm, InputFieldMap field_in, OutputFieldMap field_out,
                                const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GeomTraits;
  const auto steps = internal::parameter_value(np, internal_np::number_of_steps, defaults::number_of_steps);
  if(!(double(steps) >= 0))
    internal::throw_invalid_input("anisotropic_heat_diffusion: number_of_steps must not be negative");
  const Anisotropic_heat_diffusion<TriangleMesh, GeomTraits> diffusion(tm, np);
  diffusion.diffuse(field_in, field_out, std::size_t(steps));
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_ANISOTROPIC_HEAT_DIFFUSION_H
