// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Multi-scale feature detection (paper, section 7) on a point set.

#ifndef CGAL_HEAT_DIFFUSION_POINT_SET_MULTISCALE_FEATURES_H
#define CGAL_HEAT_DIFFUSION_POINT_SET_MULTISCALE_FEATURES_H

#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/feature_detection.h>
#include <CGAL/Heat_diffusion/internal/vertex_fields.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>
#include <CGAL/Heat_diffusion/parameter_defaults.h>
#include <CGAL/Heat_diffusion/parameters.h>
#include <CGAL/Heat_diffusion/point_set_anisotropic_heat_diffusion.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionApplications
/// Detects the convex and concave features of the field `field` as it is (one value per
/// point, in the order of the range; no diffusion), by the criterion of
/// `detect_multiscale_features()` with the 2-ring taken in the graph of the union of the
/// points' fans (the graph that the diffusion's heat regions grow on): the point-set
/// counterpart of `detect_multiscale_features(tm, field, convex, concave, np)`, for a
/// field diffused already, or any other one. The features are point indices, in
/// increasing order; the result's `number_of_steps` is 0.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{feature_threshold}
///     \cgalParamDescription{the paper's c}
///     \cgalParamType{`double`, in [0, 1]}
///     \cgalParamDefault{`defaults::feature_threshold`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if `field` has the wrong size or a non-finite value, or
///   if the threshold is not in [0, 1].
///
/// Complexity: linear in the number of points.
template <typename PointRange, typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
Features_at_scale<std::size_t>
detect_point_set_features(const Point_set_normal_controlled_coordinates<PointRange, GeomTraits>& ncc,
                          const Eigen::VectorXd& field, const NamedParameters& np = parameters::default_values())
{
  const char* const where = "detect_point_set_features";
  const double c = internal::checked_feature_threshold(
      internal::parameter_value(np, internal_np::feature_threshold, defaults::feature_threshold), where);
  internal::check_point_field(field, ncc.number_of_points(), where);
  Features_at_scale<std::size_t> result;
  internal::detect_features(internal::make_vertex_adjacency(ncc.surface().mesh), field, c, result.convex,
                            result.concave);
  return result;
}

/// \ingroup PkgHeatDiffusionApplications
/// Detects the convex and concave features of the field `field` (one value per point,
/// in the order of the range) at the scales k of `steps`, as
/// `detect_multiscale_features()` does on a mesh: `detect_point_set_features()` of each
/// \f$ F^k = A_t^k F^0 \f$, computed in one pass.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{feature_threshold}
///     \cgalParamDescription{the paper's c}
///     \cgalParamType{`double`, in [0, 1]}
///     \cgalParamDefault{`defaults::feature_threshold`}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{as for `Point_set_anisotropic_heat_diffusion::diffuse()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if `field` has the wrong size or a non-finite value, or
///   if the threshold is not in [0, 1].
///
/// Complexity: the diffusion's steps up to the largest k, and linear in the number of
/// points per scale.
template <typename PointRange, typename GeomTraits, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Features_at_scale<std::size_t> >
detect_point_set_multiscale_features(const Point_set_anisotropic_heat_diffusion<PointRange, GeomTraits>& diffusion,
                                     const Eigen::VectorXd& field, const std::vector<std::size_t>& steps,
                                     const NamedParameters& np = parameters::default_values())
{
  // (the threshold is checked before the diffusion's steps)
  internal::checked_feature_threshold(
      internal::parameter_value(np, internal_np::feature_threshold, defaults::feature_threshold),
      "detect_point_set_multiscale_features");
  const std::vector<Eigen::VectorXd> fields = diffusion.diffuse(field, steps, np);
  std::vector<Features_at_scale<std::size_t> > result(steps.size());
  for(std::size_t s = 0; s < steps.size(); ++s)
  {
    result[s] = detect_point_set_features(diffusion.normal_controlled_coordinates(), fields[s], np);
    result[s].number_of_steps = steps[s];
  }
  return result;
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_POINT_SET_MULTISCALE_FEATURES_H
