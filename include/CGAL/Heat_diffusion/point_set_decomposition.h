// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Detail bands of a field on a point set, the positions whose Normal Signature is given,
// and shape filtering through the Normal Signature (paper, eq. 23-26), on the surface of
// the points' fans.

#ifndef CGAL_HEAT_DIFFUSION_POINT_SET_DECOMPOSITION_H
#define CGAL_HEAT_DIFFUSION_POINT_SET_DECOMPOSITION_H

#include <CGAL/Heat_diffusion/internal/detail_bands.h>
#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/ncc_reconstruction.h>
#include <CGAL/Heat_diffusion/internal/vertex_fields.h>
#include <CGAL/Heat_diffusion/parameter_defaults.h>
#include <CGAL/Heat_diffusion/parameters.h>
#include <CGAL/Heat_diffusion/point_set_anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/point_set_normal_controlled_coordinates.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

namespace internal {

// The rows of `positions` (in the normalised frame of `surface`) in the units of the points.
inline Eigen::MatrixXd in_user_frame(const Point_set_surface& surface, Eigen::MatrixXd positions)
{
  for(Eigen::Index i = 0; i < positions.rows(); ++i)
    positions.row(i) = surface.mesh.to_user_frame(positions.row(i).transpose()).transpose();
  return positions;
}

// Moves the points to the rows of `positions`, in the order of the range.
template <typename PointRange, typename NamedParameters>
void write_point_positions(PointRange& points, const Eigen::MatrixXd& positions, const NamedParameters& np)
{
  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits::Point_3 Point_3;
  typename NP_helper::Point_map point_map = NP_helper::get_point_map(points, np);
  Eigen::Index i = 0;
  for(auto it = points.begin(); it != points.end(); ++it, ++i)
    put(point_map, *it, Point_3(positions(i, 0), positions(i, 1), positions(i, 2)));
}

} // namespace internal

/// \ingroup PkgHeatDiffusionApplications
/// Decomposes the field \f$ S \f$ of a point set (one value per point, in the order of the
/// range) into \f$ L \f$ = `number_of_levels` detail bands and a residual, by the diffusion
/// of `diffusion`: eq. 24 as `decompose_field()` computes it on a mesh, with the same
/// `steps_per_level` and `progress_callback`. The result holds \f$ D^1, \dots, D^L \f$
/// (finest first), then \f$ S^L \f$; they add up to \f$ S \f$, and every band sums to zero
/// (eq. 25), up to rounding.
///
/// \throws std::invalid_argument if `field` has the wrong size or a value that is not
///   finite, or if `steps_per_level` is not a positive integer.
/// \throws std::runtime_error if the `progress_callback` cancels.
///
/// Complexity: \f$ L s \f$ sparse products by \f$ A_t \f$.
template <typename PointRange, typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Eigen::VectorXd>
decompose_point_set_field(const Point_set_anisotropic_heat_diffusion<PointRange, GeomTraits>& diffusion,
                          const Eigen::VectorXd& field, std::size_t number_of_levels,
                          const NamedParameters& np = parameters::default_values())
{
  const char* const where = "decompose_point_set_field";
  const std::size_t steps_per_level = internal::checked_steps_per_level(
      double(internal::parameter_value(np, internal_np::steps_per_level, defaults::decomposition_steps_per_level)),
      where);
  internal::check_point_field(field, diffusion.number_of_points(), where, "field");
  return internal::decompose(diffusion, field, number_of_levels, steps_per_level, internal::progress_of(np));
}

/// \ingroup PkgHeatDiffusionApplications
/// Re-synthesises a field from the result of `decompose_point_set_field()` with band
/// weights (eq. 26): \f$ \tilde S = \sum_j w_j D^j + S^L \f$.
///
/// \throws std::invalid_argument if `weights` does not hold one finite weight per band.
template <typename WeightRange>
Eigen::VectorXd synthesize_point_set_field(const std::vector<Eigen::VectorXd>& bands, const WeightRange& weights)
{
  const std::vector<double> w = internal::checked_weights(weights, "synthesize_point_set_field");
  if(bands.empty() || w.size() + 1 != bands.size())
    internal::throw_invalid_input("synthesize_point_set_field: " + std::to_string(w.size()) + " weights for " +
                                  std::to_string(bands.empty() ? 0 : bands.size() - 1) + " detail bands");
  return internal::synthesize(bands, w);
}

/// \ingroup PkgHeatDiffusionNCC
/// Moves the points so that their NCC match the Normal Signature `signature` (one value
/// per point, in the order of the range) along their current normals, in the
/// least-squares sense of `reconstruct_from_normal_signature()` (eq. 23): the NCC
/// operator \f$ \mathbf{N} \f$ is that of the current points' fans
/// (`Point_set_normal_controlled_coordinates` with `k` and `np`), whose weights and
/// tangential parts are kept, and the current positions are the anchors. With the
/// points' own Normal Signature the points stay where they are (up to rounding).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of the range; the new positions are written to it}
///     \cgalParamType{a model of `ReadWritePropertyMap` with value type `GeomTraits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<GeomTraits::Point_3>` (the point map of a `CGAL::Point_set_3`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_map, neighbor_radius, geom_traits}
///     \cgalParamDescription{as for `Point_set_normal_controlled_coordinates`; the normals are read, not updated}
///   \cgalParamNEnd
///   \cgalParamNBegin{anchor_weight}
///     \cgalParamDescription{as for `reconstruct_from_normal_signature()`}
///     \cgalParamType{`double`, positive and finite}
///     \cgalParamDefault{`defaults::reconstruction_anchor_weight`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument on a point set the NCC reject, a signature of the wrong
///   size or with a value that is not finite, or an `anchor_weight` that is not positive
///   and finite.
/// \throws std::runtime_error if the sparse factorisation fails.
///
/// Complexity: that of the NCC, then one sparse Cholesky factorisation.
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
void reconstruct_point_set_from_normal_signature(PointRange& points, unsigned int k, const Eigen::VectorXd& signature,
                                                 const NamedParameters& np = parameters::default_values())
{
  const char* const where = "reconstruct_point_set_from_normal_signature";
  const double anchor_weight = internal::checked_positive(
      internal::parameter_value(np, internal_np::anchor_weight, defaults::reconstruction_anchor_weight), where,
      "anchor_weight");
  const internal::Point_set_surface surface = internal::make_point_set_surface(points, k, np);
  internal::check_point_field(signature, surface.number_of_points(), where, "signature");
  if(surface.number_of_points() == 0)
    return;
  const Eigen::MatrixXd positions = internal::reconstruct_positions(surface.mesh, surface.ncc, signature,
                                                                    surface.ncc.normals, anchor_weight, where);
  internal::write_point_positions(points, internal::in_user_frame(surface, positions), np);
}

/// \ingroup PkgHeatDiffusionApplications
/// Filters the shape of a point set through its Normal Signature, as `filter_shape()` does
/// a mesh's (paper, Fig. 10): the NS is decomposed into L = `weights.size()` detail bands
/// and a residual by `decompose_point_set_field()`, re-synthesised with the band weights,
/// and the points are moved along their normals by
/// `reconstruct_point_set_from_normal_signature()` to match it. The paper's smoothing
/// filter is \f$ w = (0, 0, 1) \f$, its enhancement filter \f$ w = (1, 3, 3) \f$; weights
/// all 1 leave the points where they are (up to rounding).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{as for `reconstruct_point_set_from_normal_signature()`: it must be writable}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_map, neighbor_radius, geom_traits}
///     \cgalParamDescription{as for `Point_set_normal_controlled_coordinates`; the normals are read, not updated}
///   \cgalParamNEnd
///   \cgalParamNBegin{time, sigma, local_kernel_tolerance, operator_normalization, progress_callback}
///     \cgalParamDescription{the diffusion, as for `Point_set_anisotropic_heat_diffusion`}
///   \cgalParamNEnd
///   \cgalParamNBegin{steps_per_level, anchor_weight}
///     \cgalParamDescription{as for `filter_shape()`}
///     \cgalParamDefault{`defaults::shape_filter_steps_per_level` and `defaults::shape_filter_anchor_weight`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument on a point set or parameter the diffusion or the
///   reconstruction rejects, or a weight that is not finite.
/// \throws std::runtime_error if the construction is cancelled or the sparse
///   factorisation fails.
///
/// Complexity: that of building a `Point_set_anisotropic_heat_diffusion`, plus
/// \f$ L s \f$ sparse products and one sparse Cholesky factorisation.
template <typename PointRange, typename WeightRange, typename NamedParameters = parameters::Default_named_parameters>
void filter_point_set_shape(PointRange& points, unsigned int k, const WeightRange& weights,
                            const NamedParameters& np = parameters::default_values())
{
  typedef typename Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GeomTraits;
  const char* const where = "filter_point_set_shape";
  const std::vector<double> w = internal::checked_weights(weights, where);
  const std::size_t steps_per_level = internal::checked_steps_per_level(
      double(internal::parameter_value(np, internal_np::steps_per_level, defaults::shape_filter_steps_per_level)),
      where);
  const double anchor_weight = internal::checked_positive(
      internal::parameter_value(np, internal_np::anchor_weight, defaults::shape_filter_anchor_weight), where,
      "anchor_weight");
  Eigen::MatrixXd positions;
  {
    // (the diffusion and its surface are freed before the points move)
    const Point_set_anisotropic_heat_diffusion<PointRange, GeomTraits> diffusion(points, k, np);
    const internal::Point_set_surface& surface = diffusion.normal_controlled_coordinates().surface();
    const Eigen::VectorXd signature = Eigen::Map<const Eigen::VectorXd>(
        surface.ncc.signature.data(), Eigen::Index(surface.ncc.signature.size()));
    // The construction fills the progress bar; the products only check for cancellation.
    const Eigen::VectorXd edited = internal::synthesize(
        internal::decompose(diffusion, signature, w.size(), steps_per_level, internal::progress_of(np).part(1., 1.)),
        w);
    positions = internal::in_user_frame(surface, internal::reconstruct_positions(surface.mesh, surface.ncc, edited,
                                                                                  surface.ncc.normals, anchor_weight,
                                                                                  where));
  }
  internal::write_point_positions(points, positions, np);
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_POINT_SET_DECOMPOSITION_H
