// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Feature-preserving denoising of a point set: its normals filtered on the neighbour
// graph, each point moved along its own normal.

#ifndef CGAL_HEAT_DIFFUSION_POINT_SET_DENOISING_H
#define CGAL_HEAT_DIFFUSION_POINT_SET_DENOISING_H

#include <CGAL/Heat_diffusion/internal/Denoising/point_set_filtering.h>
#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/point_set_surface.h>
#include <CGAL/Heat_diffusion/parameter_defaults.h>
#include <CGAL/Heat_diffusion/parameters.h>
#include <CGAL/Heat_diffusion/point_set_normal_controlled_coordinates.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionApplications
/// What `denoise_point_set()` did.
struct Point_set_denoising_report
{
  /// The estimated noise level (the standard deviation of the noise along the normals),
  /// in the units of the points; 0 where nothing was done.
  double noise_level = 0;
  /// The width \f$ \sigma_n \f$ of the range weights: the user's `normal_sigma`, or the
  /// automatic one; 0 where nothing was done.
  double normal_sigma = 0;
  /// The iterations done.
  std::size_t iterations = 0;
  /// The mean distance the points moved, in the units of the points.
  double mean_displacement = 0;
};

/// \ingroup PkgHeatDiffusionApplications
/// Denoises the point set `points` in place, keeping its sharp features: the points move
/// along their normals only, never within the surface, and the normals are filtered.
///
/// Each point has its `k` nearest neighbours (or those within `neighbor_radius`) and a
/// unit normal: the `normal_map`'s, or else one estimated by `CGAL::jet_estimate_normals()`
/// and oriented by `CGAL::mst_orient_normals()`, as `Point_set_normal_controlled_coordinates`
/// does. Then
///  1. the noise level \f$ \hat\varepsilon \f$ is the median over the points of \f$ |\delta_i| \f$, the
///     offset along \f$ n_i \f$ that puts \f$ p_i \f$ in the planes through its neighbours
///     \f$ p_j \f$ orthogonal to the mean normals \f$ m_{ij} = (n_i + n_j)/|n_i + n_j| \f$ (least
///     squares, see 3), divided by \f$ 0.6745 \sqrt{1 + 1/k} \f$: about the standard deviation of
///     Gaussian noise along the normals (the mesh denoiser's estimate of `denoise_mesh()` on the
///     neighbourhoods, without the bias of the curvature: the chord of two points of a sphere is
///     orthogonal to their mean normal);
///  2. the width \f$ \sigma_n \f$ of the range weights \f$ w_{ij} = e^{-|n_i - n_j|^2/2\sigma_n^2} \f$ is
///     `normal_sigma`, or else grows with the tilt that the noise gives the normals, the ratio
///     r of \f$ \hat\varepsilon \f$ to the median distance of a point to its neighbours: 0.25 up to
///     r = 0.2, 0.5 from r = 0.33, linear between (narrow widths keep creases, wide ones keep
///     strong noise from being frozen into false creases);
///  3. an iteration sets each normal to that of the plane fitted (weighted least squares) to the
///     point and its neighbours moved so far, with the range weights of width \f$ 1.5\,\sigma_n \f$
///     on the previous normals, so that a fit near a crease keeps to its own side (from the
///     second iteration on; the first starts from the input normals); filters the normals
///     `number_of_steps` times, \f$ n_i \leftarrow \sum_{j} w_{ij}\, n_j \f$ (normalised) over i and
///     its neighbours, the range weights of `denoise_mesh()` on the neighbour graph; then
///     moves each point along its own normal \f$ n_i \f$ by half of the weighted least-squares
///     offset \f$ \delta_i \f$ that puts it in the planes of its pairs,
///     \f$ m_{ij} \cdot (q_j - q_i - \delta_i n_i) = 0 \f$, with the weights \f$ w_{ij} \f$ (a sphere is a
///     fixed point, where the neighbours' own tangent planes would inflate it);
///  4. the iterations run until the root mean square displacement of the points reaches
///     `displacement_limit` \f$ \times\, \hat\varepsilon \f$, the last one cut back to reach it
///     exactly, or until the points stop moving, at most `number_of_iterations`. When the
///     limit is reached, \f$ \hat\varepsilon \f$ is measured again as in 1, the input points against
///     the planes of the moved ones; if it is more than 5 % higher, it replaces the estimate
///     and the iterations go on: along normals that tilt with strong noise the first estimate
///     is low (`benchmark_point_set_denoising`: after the re-estimates, 0.72 to 0.90 of the true
///     level at noise of 1 % of the diagonal on 20000 points, 0.95 to 1.10 at 0.25 and 0.5 %).
/// The displacement of each point, from its input position, is along its output normal:
/// at every iteration the displacement so far is projected on the point's new normal.
///
/// @tparam PointRange a model of `Range` whose iterator type is `ForwardIterator`; its
///   value type is the key type of the point and normal maps
///
/// @param points the points, moved in place
/// @param k the number of neighbours of each point (with `neighbor_radius`: at most that
///   many of the neighbours within the radius, the nearest; 0 for no limit)
/// @param np the named parameters below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{point_map}
///     \cgalParamDescription{a property map associating points to the elements of the point range; the denoised positions are written to it}
///     \cgalParamType{a model of `ReadWritePropertyMap` with value type `GeomTraits::Point_3`}
///     \cgalParamDefault{`CGAL::Identity_property_map<GeomTraits::Point_3>` (the point map of a `CGAL::Point_set_3`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_map}
///     \cgalParamDescription{oriented normals of the points (they are normalised); the filtered unit normals are written to it}
///     \cgalParamType{a model of `ReadWritePropertyMap` with value type `GeomTraits::Vector_3`}
///     \cgalParamDefault{the normal map of a `CGAL::Point_set_3` that has one; else the normals are estimated (see above) and not returned}
///   \cgalParamNEnd
///   \cgalParamNBegin{neighbor_radius}
///     \cgalParamDescription{the radius of the neighbourhoods, in the units of the points}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`0`: the `k` nearest neighbours}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the most iterations (the displacement limit usually stops them first); 0 leaves the points as they are}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`defaults::point_set_denoising::iterations`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_steps}
///     \cgalParamDescription{the normal filtering steps per iteration}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`defaults::point_set_denoising::number_of_steps`}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_sigma}
///     \cgalParamDescription{the width \f$ \sigma_n \f$ of the range weights (unit normals differ by at most 2)}
///     \cgalParamType{`double`, positive and finite}
///     \cgalParamDefault{automatic, from the noise level (see 2)}
///   \cgalParamNEnd
///   \cgalParamNBegin{displacement_limit}
///     \cgalParamDescription{the root mean square displacement at which the iterations stop, in multiples of the estimated noise level}
///     \cgalParamType{`double`, positive and finite}
///     \cgalParamDefault{`defaults::point_set_denoising::displacement_limit`}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{called after each iteration with the fraction of `number_of_iterations` done; returning `false` cancels with a `std::runtime_error`, the points left unchanged}
///     \cgalParamType{a callable `bool(double)`, stored in a `std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the estimated noise level, the iterations done and the mean displacement
///   (`Point_set_denoising_report`).
///
/// \throws std::invalid_argument, naming the point or the parameter, before any point is
///   moved: a non-finite coordinate or normal, a null normal, fewer than `k + 1` points,
///   two points that coincide, a point whose neighbourhood lies on a line (it fits no
///   plane), normals whose median angle to the planes fitted to the neighbourhoods is over
///   60 degrees (normals that lie in the surface), a normal that cannot be estimated or
///   oriented (give the
///   normals then), `k < 2` without a radius, a radius that is negative or not finite, a
///   parameter out of its range.
/// \throws std::runtime_error if the `progress_callback` cancels.
///
/// Complexity: \f$ O(n \log n) \f$ for the neighbour search, then \f$ O(n k) \f$ per step and
/// iteration (parallel over points with TBB).
template <typename PointRange, typename NamedParameters = parameters::Default_named_parameters>
Point_set_denoising_report denoise_point_set(PointRange& points, unsigned int k,
                                             const NamedParameters& np = parameters::default_values())
{
  typedef CGAL::Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Geom_traits GeomTraits;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename GeomTraits::Vector_3 Vector_3;

  // Every parameter is checked before a point moves.
  const double iterations = double(internal::parameter_value(np, CGAL::internal_np::number_of_iterations,
                                                             defaults::point_set_denoising::iterations));
  const double steps = double(
      internal::parameter_value(np, internal_np::number_of_steps, defaults::point_set_denoising::number_of_steps));
  const double normal_sigma = internal::parameter_value(np, internal_np::normal_sigma, 0.);
  const bool automatic_normal_sigma = !internal::is_given(np, internal_np::normal_sigma);
  const double displacement_limit = internal::parameter_value(np, internal_np::displacement_limit,
                                                              defaults::point_set_denoising::displacement_limit);
  const std::function<bool(double)> progress =
      internal::parameter_value(np, internal_np::progress_callback, std::function<bool(double)>());
  if(!(iterations >= 0) || !std::isfinite(iterations))
    internal::throw_invalid_input("denoise_point_set: number_of_iterations must not be negative");
  if(!(steps >= 0) || !std::isfinite(steps))
    internal::throw_invalid_input("denoise_point_set: number_of_steps must not be negative");
  if(!automatic_normal_sigma)
    internal::checked_positive(normal_sigma, "denoise_point_set", "normal_sigma");
  internal::checked_positive(displacement_limit, "denoise_point_set", "displacement_limit");

  internal::Point_set_input input = internal::read_point_set_input(points, k, np);
  const bool given_normals = !input.normals.empty();
  internal::Indexed_mesh frame;
  const internal::Point_set_neighbourhoods prepared =
      internal::prepare_point_set(std::move(input.points), std::move(input.normals), input.options, frame);
  Point_set_denoising_report report;
  if(frame.points.empty() || iterations < 1)
    return report;
  const internal::Neighbourhood_planes planes =
      internal::neighbourhood_planes(frame.points, prepared.neighbours, prepared.normals);
  if(planes.first_collinear < frame.points.size())
    internal::throw_point_error(planes.first_collinear,
                                "has a degenerate neighbourhood: it and its " +
                                    std::to_string(prepared.neighbours[planes.first_collinear].size()) +
                                    " neighbours lie on a line, to which no plane fits");
  // Normals that lie in the surface would move the points within it: most normals must
  // be near those of the planes of the neighbourhoods (creases tilt a few of them only).
  if(given_normals && planes.median_tilt > 60.)
  {
    std::ostringstream os;
    os << "denoise_point_set: the normals are not those of the points' surface: the median angle between a "
          "normal and the plane fitted to its point's neighbourhood is "
       << planes.median_tilt << " degrees (more than 60)";
    internal::throw_invalid_input(os.str());
  }

  internal::Point_set_filtering_options options;
  options.iterations = std::size_t(iterations);
  options.steps = std::size_t(steps);
  options.normal_sigma = automatic_normal_sigma ? 0. : normal_sigma;
  options.displacement_limit = displacement_limit;
  const internal::Point_set_filtering_result result = internal::filter_point_set(
      frame.points, prepared.neighbours, prepared.normals, options, internal::Progress(progress));

  report.noise_level = result.noise_level / frame.scale;
  report.normal_sigma = result.normal_sigma;
  report.iterations = result.iterations;
  double sum = 0;
  for(std::size_t i = 0; i < frame.points.size(); ++i)
    sum += (result.points[i] - frame.points[i]).norm();
  report.mean_displacement = sum / double(frame.points.size()) / frame.scale;

  const auto point_map = NP_helper::get_point_map(points, np);
  std::size_t i = 0;
  for(auto& item : points)
  {
    // (the normalised frame is a power of two and a translation: a point that did not
    // move comes back as it was, up to the rounding of the translation)
    const Eigen::Vector3d x = frame.to_user_frame(result.points[i]);
    put(point_map, item, Point_3(x.x(), x.y(), x.z()));
    ++i;
  }
  if(given_normals)
  {
    const auto normal_map = NP_helper::get_normal_map(points, np);
    i = 0;
    for(auto& item : points)
    {
      const Eigen::Vector3d& v = result.normals[i++];
      put(normal_map, item, Vector_3(v.x(), v.y(), v.z()));
    }
  }
  return report;
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_POINT_SET_DENOISING_H
