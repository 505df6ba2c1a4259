// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Conservative multi-scale diffusion by local heat kernel convolution (paper, section 5)
// on a point set, over the surface of its local fans.

#ifndef CGAL_HEAT_DIFFUSION_POINT_SET_ANISOTROPIC_HEAT_DIFFUSION_H
#define CGAL_HEAT_DIFFUSION_POINT_SET_ANISOTROPIC_HEAT_DIFFUSION_H

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/heat_kernel_method.h>
#include <CGAL/Heat_diffusion/internal/diffusion_construction.h>
#include <CGAL/Heat_diffusion/internal/diffusion_operator.h>
#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/generalized_eigensolver.h>
#include <CGAL/Heat_diffusion/internal/kernel_columns.h>
#include <CGAL/Heat_diffusion/internal/local_heat_kernel.h>
#include <CGAL/Heat_diffusion/internal/point_set_heat_operators.h>
#include <CGAL/Heat_diffusion/internal/progress.h>
#include <CGAL/Heat_diffusion/internal/vertex_fields.h>
#include <CGAL/Heat_diffusion/operator_normalization.h>
#include <CGAL/Heat_diffusion/parameter_defaults.h>
#include <CGAL/Heat_diffusion/parameters.h>
#include <CGAL/Heat_diffusion/point_set_normal_controlled_coordinates.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionDiffusion
/// The diffusion operator \f$ A_t \f$ of a point set, built once, and
/// \f$ F^k = A_t^k F^0 \f$ computed many times: `Anisotropic_heat_diffusion` on the
/// surface of the points' fans (see `Point_set_normal_controlled_coordinates`).
///
/// The stiffness \f$ L = D - W \f$ has the weights of eq. 10 from the points' NCC on the
/// edges of the union of the fans' triangles; the mass \f$ B \f$ (eq. 11) sums those
/// triangles, each weighted by the number of fans that hold it divided by 3 (Sharp and
/// Crane's point-cloud Laplacian: a triangle all three of its corners see counts once).
/// Both are symmetric, \f$ L \f$'s rows sum to 0 and \f$ B \f$ is positive definite; the
/// kernels, the heat regions (grown over the edges of that union), the normalisations
/// and their guarantees are those of `Anisotropic_heat_diffusion` (the spectral kernel
/// without a coarse level).
///
/// Fields are given and returned per point, in the order of the range.
///
/// @tparam PointRange a model of `ConstRange` whose iterator type is `InputIterator`
/// @tparam GeomTraits a model of `Kernel`
template <typename PointRange,
          typename GeomTraits = typename CGAL::Point_set_processing_3_np_helper<
              PointRange, parameters::Default_named_parameters>::Geom_traits>
class Point_set_anisotropic_heat_diffusion
{
public:
  /// The NCC the operators are built from.
  typedef Point_set_normal_controlled_coordinates<PointRange, GeomTraits> NCC;
  /// The sparse matrix type of \f$ A_t \f$.
  typedef Eigen::SparseMatrix<double> Sparse_matrix;

  /// Builds the surface of `points` (with `k` neighbours per point), its heat kernel and
  /// \f$ A_t \f$.
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{point_map, normal_map, neighbor_radius, geom_traits}
  ///     \cgalParamDescription{as for `Point_set_normal_controlled_coordinates`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{time}
  ///     \cgalParamDescription{the time t of one step (on the surface rescaled to area = number of points)}
  ///     \cgalParamType{`double`, positive}
  ///     \cgalParamDefault{`1`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{sigma}
  ///     \cgalParamDescription{the width of the edge weights of eq. 10 (`+infinity`: isotropic)}
  ///     \cgalParamType{`double`, positive}
  ///     \cgalParamDefault{`defaults::sigma`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{kernel_method}
  ///     \cgalParamDescription{how the heat kernel is evaluated, as for `Anisotropic_heat_diffusion`:
  ///       the local kernel, or the paper's truncated spectral kernel from the smallest eigenpairs
  ///       of the points' \f$ (L, B) \f$, computed on all the points (there is no coarse level
  ///       on point sets)}
  ///     \cgalParamType{`Heat_kernel_method`}
  ///     \cgalParamDefault{`Heat_kernel_method::automatic`: spectral if `number_of_eigenpairs` or
  ///       `scale_invariant_kernel` is given, else local}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{number_of_eigenpairs, scale_invariant_kernel}
  ///     \cgalParamDescription{the spectral kernel's, as for `Edge_weighted_heat_kernel`
  ///       (`number_of_eigenpairs` is clamped to the number of points)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{local_kernel_tolerance}
  ///     \cgalParamDescription{the local kernel's accuracy (see `Anisotropic_heat_diffusion`)}
  ///     \cgalParamType{`double`, in (0, 1)}
  ///     \cgalParamDefault{`defaults::local_kernel_tolerance`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{operator_normalization}
  ///     \cgalParamDescription{how \f$ A_t \f$ is made from the kernel (see `Anisotropic_heat_diffusion`)}
  ///     \cgalParamType{`Operator_normalization`}
  ///     \cgalParamDefault{`Operator_normalization::balanced`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{progress_callback}
  ///     \cgalParamDescription{called with the fraction done while the heat regions are built and
  ///       \f$ A_t \f$ balanced; returning `false` cancels the construction with a `std::runtime_error`}
  ///     \cgalParamType{a callable `bool(double)`}
  ///     \cgalParamDefault{none}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws std::invalid_argument on a point set the package cannot process (see
  ///   `Point_set_normal_controlled_coordinates`), an empty one, or an invalid parameter
  ///   (`coarse_vertex_count` included: it simplifies a mesh).
  /// \throws std::runtime_error if the construction is cancelled or the eigen solve fails.
  ///
  /// Complexity: that of `Point_set_normal_controlled_coordinates`, then, with the local
  /// kernel, linear in the number of points for fixed t and k (parallel with TBB); with
  /// the spectral kernel, that of the eigen solve (see `Edge_weighted_heat_kernel`) and
  /// of the heat regions.
  template <typename NamedParameters = parameters::Default_named_parameters>
  Point_set_anisotropic_heat_diffusion(const PointRange& points, unsigned int k,
                                       const NamedParameters& np = parameters::default_values())
    : diffusion_operator_(checked_normalization(
          internal::parameter_value(np, internal_np::operator_normalization, Operator_normalization::balanced)))
  {
    const char* const where = "Point_set_anisotropic_heat_diffusion";
    time_ = internal::checked_positive(internal::parameter_value(np, internal_np::time, defaults::time), where, "time");
    sigma_ = internal::checked_sigma(internal::parameter_value(np, internal_np::sigma, defaults::sigma), where);
    kernel_tolerance_ = internal::checked_kernel_tolerance(
        internal::parameter_value(np, internal_np::local_kernel_tolerance, defaults::local_kernel_tolerance), where);
    const bool scale_invariant = internal::parameter_value(np, internal_np::scale_invariant_kernel, false);
    if(internal::is_given(np, internal_np::coarse_vertex_count))
      internal::throw_invalid_input(std::string(where) +
                                    ": coarse_vertex_count simplifies a mesh; on point sets the eigenpairs are "
                                    "computed on all the points");
    method_ = internal::resolve_kernel_method(np, scale_invariant);
    if(method_ != Heat_kernel_method::local && method_ != Heat_kernel_method::spectral)
      internal::throw_invalid_input(std::string(where) + ": unknown kernel_method");
    if(method_ == Heat_kernel_method::local && scale_invariant)
      internal::throw_invalid_input(std::string(where) +
                                    ": the scale-invariant kernel (eq. 14) needs the eigenvalues; use "
                                    "Heat_kernel_method::spectral");
    const internal::Progress progress = internal::progress_of(np);
    ncc_ = std::make_shared<NCC>(points, k, np);
    const internal::Point_set_surface& surface = ncc_->surface();
    if(surface.number_of_points() == 0)
      internal::throw_invalid_input(std::string(where) + ": the point set is empty");
    internal::Heat_operators operators = internal::assemble_point_set_heat_operators(surface, sigma_);
    // (a program that never asks for the spectral kernel does not compile the eigen solver)
    if constexpr(internal::can_select_spectral_kernel<NamedParameters>)
      if(method_ == Heat_kernel_method::spectral)
      {
        build_spectral(operators, np, scale_invariant, progress);
        return;
      }
    internal::build_local_diffusion_operator(surface.mesh, std::move(operators), time_, construction_options(),
                                             progress, diffusion_operator_, statistics_);
  }

  /// The largest heat region, in points (that of `Anisotropic_heat_diffusion`).
  static constexpr std::size_t maximum_region_size = 4096;

  /// The diffusion time t of one step.
  double time() const { return time_; }
  /// The width `sigma` of the edge weights (eq. 10).
  double sigma() const { return sigma_; }
  /// The threshold \f$ \tau(t) = 0.01/(1+t) \f$ of the heat regions.
  double threshold() const { return 0.01 / (1. + time_); }
  /// How the heat kernel was evaluated: `spectral` or `local`, never `automatic`.
  Heat_kernel_method kernel_method() const { return method_; }
  /// The eigenvalues of the spectral kernel, ascending (clamped to be nonnegative: the
  /// zero eigenvalues come out of the solver as tiny values of either sign); empty with
  /// the local kernel.
  const Eigen::VectorXd& eigenvalues() const { return eigenvalues_; }
  /// The NCC of the points.
  const NCC& normal_controlled_coordinates() const { return *ncc_; }
  /// The number of points.
  std::size_t number_of_points() const { return ncc_->number_of_points(); }
  /// How \f$ A_t \f$ was made from the kernel.
  Operator_normalization operator_normalization() const { return diffusion_operator_.normalization(); }
  /// \f$ A_t \f$, rows and columns in the order of the points (see
  /// `Anisotropic_heat_diffusion::operator_matrix()`); made on the first call and kept.
  const Sparse_matrix& operator_matrix() const
  {
    std::call_once(column_major_->once, [this] { column_major_->matrix = diffusion_operator_.column_major(); });
    return column_major_->matrix;
  }
  /// The number of products with the kernel matrix that its balancing took.
  std::size_t balancing_iterations() const { return diffusion_operator_.balancing_iterations(); }
  /// Sizes of the heat regions.
  const Heat_region_statistics& region_statistics() const { return statistics_; }

  /// \f$ F^k = A_t^k F^0 \f$ for a field given per point; named parameters and errors as
  /// `Anisotropic_heat_diffusion::diffuse()`.
  template <typename NamedParameters = parameters::Default_named_parameters>
  Eigen::VectorXd diffuse(const Eigen::VectorXd& field, std::size_t number_of_steps,
                          const NamedParameters& np = parameters::default_values()) const
  {
    return diffuse(field, std::vector<std::size_t>(1, number_of_steps), np).front();
  }

  /// The fields \f$ F^k \f$ for every k of `steps` (in any order), in one pass.
  template <typename NamedParameters = parameters::Default_named_parameters>
  std::vector<Eigen::VectorXd> diffuse(const Eigen::VectorXd& field, const std::vector<std::size_t>& steps,
                                       const NamedParameters& np = parameters::default_values()) const
  {
    internal::check_point_field(field, number_of_points(), "Point_set_anisotropic_heat_diffusion");
    return internal::diffuse_steps(diffusion_operator_, field, steps, internal::progress_of(np));
  }

private:
  static Operator_normalization checked_normalization(Operator_normalization normalization)
  {
    if(normalization != Operator_normalization::balanced && normalization != Operator_normalization::columns)
      internal::throw_invalid_input("Point_set_anisotropic_heat_diffusion: unknown operator_normalization");
    return normalization;
  }

  internal::Diffusion_construction_options construction_options() const
  {
    return {threshold(), maximum_region_size, kernel_tolerance_};
  }

  // A_t from the truncated spectral kernel of eq. 13 (eq. 14's if scale-invariant): the
  // smallest eigenpairs of the points' (L, B), as Edge_weighted_heat_kernel computes them
  // on a mesh without a coarse level, then the heat regions of the mesh's spectral path.
  template <typename NamedParameters>
  void build_spectral(const internal::Heat_operators& operators, const NamedParameters& np, bool scale_invariant,
                      const internal::Progress& progress)
  {
    const double requested_m =
        double(internal::parameter_value(np, internal_np::number_of_eigenpairs, defaults::number_of_eigenpairs));
    if(!(requested_m >= 1))
      internal::throw_invalid_input("Point_set_anisotropic_heat_diffusion: number_of_eigenpairs must be positive");
    const std::size_t n = number_of_points();
    // One progress bar: the eigen solve takes most of it, the regions the rest.
    internal::Generalized_eigenpairs pairs = internal::compute_smallest_generalized_eigenpairs(
        operators.stiffness, operators.mass, Eigen::Index((std::min)(requested_m, double(n))),
        progress.part(0., 0.8).as_callback());
    eigenvalues_ = internal::clamped_eigenvalues(pairs.eigenvalues);
    const double rate_unit = scale_invariant ? internal::first_nonzero_eigenvalue(eigenvalues_) : 1.;
    const Eigen::VectorXd mass_diagonal = operators.mass.diagonal();
    // psi = Phi exp(-rate t / 2), column by column
    internal::Spectral_columns columns{pairs.eigenvectors, scale_invariant ? &mass_diagonal : nullptr};
    for(Eigen::Index k = 0; k < columns.psi.cols(); ++k)
      columns.psi.col(k) *= std::exp(-0.5 * eigenvalues_[k] / rate_unit * time_);
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    Eigen::VectorXd column_sums, peaks;
    const internal::Diffusion_construction_options options = construction_options();
    const internal::Progress regions = progress.part(0.8, 1.);
    internal::compute_heat_regions(columns, ncc_->surface().mesh, order, std::vector<std::size_t>(), options, regions,
                                   diffusion_operator_, statistics_, column_sums, peaks);
    internal::complete_diffusion_operator(column_sums, peaks, options, regions, diffusion_operator_);
  }

  struct Column_major_copy
  {
    std::once_flag once;
    Sparse_matrix matrix;
  };

  std::shared_ptr<const NCC> ncc_;
  double sigma_ = defaults::sigma;
  double time_ = defaults::time;
  double kernel_tolerance_ = defaults::local_kernel_tolerance;
  Heat_kernel_method method_ = Heat_kernel_method::local;
  Eigen::VectorXd eigenvalues_;  // of the spectral kernel
  internal::Diffusion_operator diffusion_operator_;
  std::shared_ptr<Column_major_copy> column_major_ = std::make_shared<Column_major_copy>();
  Heat_region_statistics statistics_;
};

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_POINT_SET_ANISOTROPIC_HEAT_DIFFUSION_H
