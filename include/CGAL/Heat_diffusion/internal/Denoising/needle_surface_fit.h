// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The surface the denoising returns or starts from on meshes of needle triangles: the
// measure of how needle-like the faces are and the copy of such a mesh smoothed by the
// cotangent flow (normal_fit.h fits the vertices to the copy's normals).

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NEEDLE_SURFACE_FIT_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NEEDLE_SURFACE_FIT_H

#include <CGAL/Heat_diffusion/internal/Denoising/cotangent_flow.h>
#include <CGAL/Heat_diffusion/internal/Denoising/face_adjacency.h>
#include <CGAL/Heat_diffusion/internal/Denoising/noise_level.h>
#include <CGAL/Heat_diffusion/internal/Denoising/volume_preservation.h>
#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The median over the faces of 2 area / (longest edge)^2: the smallest altitude over
// the longest edge, 0.87 for an equilateral triangle, under 0.17 for a face whose
// smallest angle is under 10 degrees (a needle).
inline double median_face_aspect(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& points)
{
  std::vector<double> aspects;
  aspects.reserve(mesh.triangles.size());
  for(const auto& t : mesh.triangles)
  {
    const Eigen::Vector3d a = points[t[1]] - points[t[0]], b = points[t[2]] - points[t[1]],
                          c = points[t[0]] - points[t[2]];
    const double longest = (std::max)({a.squaredNorm(), b.squaredNorm(), c.squaredNorm()});
    const double aspect = longest > 0 ? a.cross(c).norm() / longest : 0.;
    if(std::isfinite(aspect))
      aspects.push_back(aspect);
  }
  if(aspects.empty())
    return 0.;
  std::nth_element(aspects.begin(), aspects.begin() + std::ptrdiff_t(aspects.size() / 2), aspects.end());
  return aspects[aspects.size() / 2];
}

// Needle meshes (curved surfaces only). A face's normal moves by about the noise over
// its smallest altitude, that is over a times its longest edge, a = 2 area / longest
// edge^2 its aspect (0.87 for an equilateral triangle): where the median aspect a is
// below needle_reference_aspect, the normals are mostly noise, and filtering them
// cannot recover the surface. The needle factor
// nu = (needle_reference_aspect / a)^2 - 1 (0 on well-shaped meshes) grows with the
// square of that amplification of the noise of the normals. There the positions are
// smoothed with the cotangent operator, whose result does not depend on the triangles'
// shape, for the time needle_smoothing_time nu eps^2 (eps the noise level along the
// smoothed normals, see plane_fit_noise_level).
// From nu = 1 on, a smoothed surface, rescaled to the input's volume, is the result
// (this one, the flow stopped by its residual, or their blend: see
// smooth_needle_mesh()); below, the vertices are fitted to its normals in one
// least-squares solve anchored to the input (weight needle_fit_anchor_weight), and the
// normal filter goes on from there. The smoothed surface alone was measured against
// that fit followed by the filter with the benchmark's seeds, at 0.1, 0.3 and 0.5 mean
// edge length of noise along the normals: rotor_small 9.29, 17.4, 25.8 degrees against
// 18.5, 26.1, 32.9; blade 6.65 and 11.2 against 9.71 and 16.5 at 0.3 and 0.5 (at 0.1 it
// is piecewise flat). The aspect is measured on the pilot surface (the input smoothed
// for the time of one squared mean edge length), because noise along the normals alone
// makes well-shaped faces look thin. The constants were chosen on CGAL's needle meshes
// (blade, rotor_small, anchor) for the fit followed by the filter, and checked not to
// change the organic ones (elephant, bunny: nu = 0; armadillo: 0 to 0.03). The stop's
// noise level moves from that of plane_fit_noise_level along the input's normals
// (nu = 0, unchanged behaviour) to that along the smoothed normals (nu >= 1), which is
// the better estimate on needles.
constexpr double needle_reference_aspect = 0.5;
constexpr double needle_smoothing_time = 2.;
constexpr double needle_fit_anchor_weight = 0.01;

// How needle-like a mesh is (see needle_reference_aspect): the needle factor nu, the
// noise level eps along the normals of the pilot surface (plane_fit_noise_level), and
// the time needle_smoothing_time nu eps^2 of its smoothed copy. On a mesh that is not
// one of needles the factor is 0 and the rest 0; a failed estimate leaves `noise` and
// `copy_time` 0. `flow` is the Cotangent_flow of the input.
struct Needle_measure
{
  double factor = 0;
  double noise = 0;
  double copy_time = 0;
};

inline Needle_measure measure_needles(const Indexed_mesh& mesh, const Face_adjacency& adjacency, Cotangent_flow& flow)
{
  Needle_measure result;
  const double mean_edge = mean_edge_length(mesh);
  std::vector<Eigen::Vector3d> pilot;
  if(!(mean_edge > 0) || !std::isfinite(mean_edge) || !flow.smooth(mean_edge * mean_edge, 1, pilot))
    return result;
  const double aspect = median_face_aspect(mesh, pilot);
  if(!(aspect > 0))
    return result;
  const double ratio = needle_reference_aspect / aspect;
  result.factor = (std::max)(0., ratio * ratio - 1.);
  if(result.factor == 0)
    return result;
  const double noise = plane_fit_noise_level(mesh, adjacency, mesh.points, &pilot);
  if(!(noise > 0) || !std::isfinite(noise))
    return result;
  result.noise = noise;
  result.copy_time = needle_smoothing_time * result.factor * noise * noise;
  return result;
}

// The smoothed copy of a mesh of needles: the input smoothed by `flow` (its
// Cotangent_flow) for the copy's time. Returns false, leaving `copy` untouched, if
// there is no such time or the flow fails.
inline bool needle_copy(const Needle_measure& needles, Cotangent_flow& flow, std::vector<Eigen::Vector3d>& copy)
{
  return needles.copy_time > 0 && flow.smooth(needles.copy_time, flow_substeps, copy);
}

// The weight of the needle copy against W, the flow stopped by its residual, where the
// copy's time is the longer and the copy does not shrink the shape (see
// smooth_needle_mesh()). At W's stop the residual's neighbour correlation is
// whiteness_correlation; the fraction f of it that the residual's components along the
// normals of W keep (residual_neighbour_correlation() along them) says what correlates
// it: the sliding of the vertices along the needles (f near 0: the stop came early, and
// the copy's longer time removes more noise) or removed shape (f near 1: the copy would
// remove more shape). The weight is 1 for f <= needle_copy_sliding_fraction, 0 for
// f >= 1, linear between; 0 if the residual is not correlated at all. Measured with the
// benchmark's seeds (f, then the MAD of the copy and of the result): blade, f 0.45 at
// most on its 8 noisy rows, keeps the copy (mean 4.85 degrees; W alone 6.11), and its
// clean mesh (f 1.2 at the stop's shortest time) goes from 1.77 to 0.00;
// couplingdown at 0.1 along the normals and in random directions (f 1.02 and 1.16)
// from 18.91 and 20.66 to 15.76 and 14.89; rotor_small (f 0.58 to 1.09) from a mean of
// 14.51 over its 8 noisy rows to 13.93 (at 0.1 along the normals 10.27 to 8.02, at 0.5
// 20.50 to 20.83). With bounds of 1/5 or 1/2 instead of 1/3, and 0.9 or 1.1 instead of
// 1, no row moves by more than 0.2 degrees.
constexpr double needle_copy_sliding_fraction = 1. / 3;

inline double needle_copy_weight(const Indexed_mesh& mesh, const Face_adjacency& adjacency,
                                 const std::vector<Eigen::Vector3d>& stopped)
{
  const double correlation = residual_neighbour_correlation(mesh, mesh.points, stopped);
  if(!(correlation > 0))
    return 0.;
  std::vector<Eigen::Vector3d> normals;
  area_weighted_normals(mesh, adjacency, stopped, normals);
  const double fraction = residual_neighbour_correlation(mesh, mesh.points, stopped, &normals) / correlation;
  return std::clamp((1. - fraction) / (1. - needle_copy_sliding_fraction), 0., 1.);
}

// The result on a mesh of needles with nu >= 1: a smoothed copy of the input, rescaled
// to its volume (restore_component_volumes()). It is the flow W stopped when its
// residual turns correlated (smooth_until_residual_is_correlated(), `noise` the input's
// noise level eps), or, where the needle copy's time is the longer and the copy does not
// shrink the shape (`shrinks`, a predicate on the copy's points), a blend of the copy and
// W (needle_copy_weight()): the residual's stop is a lower bound, since on needles the
// flow also slides the vertices along the surface, which correlates the residual without
// removing shape (blade: the copy's time is 94 to 183 eps^2, the stop's 26 to 66). The
// copy of a mesh whose parts are a few faces thick, or whose needles span curved holes,
// shrinks them (anchor and cheese, where the noise estimate also counts the shape: eps'
// reads 0.36 to 0.61 mean edge length whatever the noise); W is then the relinearised
// flow (see relinearised_steps), or, if that fails, the flow with the input's operator.
// Measured with the benchmark's seeds, mean MAD over the six noisy rows (0.1, 0.3, 0.5,
// both directions), against the copy for nu >= 2, its blend with weight nu - 1 with the
// filter for 1 <= nu < 2, and the copy's time halved while it shrank the shape: anchor
// 30.3 degrees against 39.1, cheese 20.2 against 36.9, b9_mesh (nu 1.05 to 2.1) 23.0
// against 26.1, turbine in random directions at 0.3 and 0.5 (nu 1.3 and 1.9) 8.13 and
// 10.96 against 19.2 and 22.8. Returns false, leaving `result` untouched, if the flow
// with the input's operator fails.
template <typename Shrinks>
bool smooth_needle_mesh(const Indexed_mesh& mesh, const Face_adjacency& adjacency, double noise,
                        const Needle_measure& needles, Cotangent_flow& flow, const Shrinks& shrinks,
                        std::vector<Eigen::Vector3d>& result)
{
  std::vector<Eigen::Vector3d> smoothed, copy, relinearised;
  double time = 0;
  if(!smooth_until_residual_is_correlated(mesh, noise, flow, smoothed, time))
    return false;
  if(needles.copy_time > time && needle_copy(needles, flow, copy))
  {
    if(!shrinks(copy))
    {
      const double weight = needle_copy_weight(mesh, adjacency, smoothed);
      for(std::size_t i = 0; i < smoothed.size(); ++i)
        smoothed[i] = weight * copy[i] + (1. - weight) * smoothed[i];
    }
    else if(smooth_relinearised_until_residual_is_correlated(mesh, noise, flow, relinearised, time))
      smoothed.swap(relinearised);
  }
  restore_component_volumes(mesh, mesh.points, smoothed);
  result.swap(smoothed);
  return true;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NEEDLE_SURFACE_FIT_H
