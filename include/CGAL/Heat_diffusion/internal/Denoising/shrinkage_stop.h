// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The rules that keep denoise_mesh()'s normal filtering from shrinking the shape: the
// one-way displacement that ends its phases and rejects a needle copy, and the volume
// check that replaces a filter that eroded thin walls by the volume-preserving flow.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_SHRINKAGE_STOP_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_SHRINKAGE_STOP_H

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Shrinkage. Removing noise moves the vertices both ways along the normals, so that the
// mean of their displacement along the input's normals stays near 0 (fandisk,
// anchor_dense, blade: below 0.03 of the noise level, and below a thirtieth of the root
// mean square displacement); a filter that erodes the shape moves them one way. On
// meshes of needles across holes or with parts a few faces thick the filters of
// filter_normals() did that to the clean meshes as much as to noisy ones (CGAL's cheese
// and anchor: -77 % and -43 % of volume in the crease-preserving phase of the clean
// meshes, -84 % and -38 % at the end). A phase of the filter therefore ends at the
// iterate before the one whose mean displacement exceeds both shrinkage_bound times the
// noise level and systematic_fraction of the root mean square displacement: mostly
// one-way, and more than the noise explains. The second condition spares the phases
// whose displacement is mostly noise removed from a shrinking surface: the mean of
// elephant's crease-preserving phase reaches 0.14 times the noise level, but 0.15 of
// its root mean square displacement, turbine's (thin walls, whose rims the phase
// erodes) 0.19 of it before its iterations go on; the collapses of cheese and anchor
// reach 0.28 to 0.6. (On turbine the stop still comes later, in the continuation of
// piecewise flat meshes or the needle path: less noise is removed, and less volume lost;
// see the user manual.)
constexpr double shrinkage_bound = 0.1;
constexpr double systematic_fraction = 0.25;

// Thin walls. A normal filter whose result changes the volume of a closed component by
// more than volume_tolerance has eroded it: on CGAL's turbine (walls about 2.4 mean edge
// lengths thick, whose rims are strips one face wide between creases, see
// filter_normals()) the crease-preserving filter shrinks it by 1.3, 7.6 and 15 % at 0.1,
// 0.3 and 0.5 mean edge length of noise along the normals, while no other closed mesh of
// the benchmark moves by more than 0.54 % (armadillo at 0.5). The result is then the
// input smoothed by the cotangent flow until its residual turns correlated
// (smooth_until_residual_is_correlated()), rescaled to the input's volume. Measured on
// turbine with the benchmark's seeds at 0.1, 0.2, 0.3, 0.5: 5.92, 7.05, 8.17, 10.3
// degrees at -0.02 to -0.13 % of volume, against 10.5, 11.3, 15.2, 20.9 for the filter
// (and 5.66, 7.92, 8.95, 11.7 for the flow at the fixed time 32 eps^2, halved while it
// shrank the shape). (The flow would round the creases of the meshes that the filter
// does not erode: fandisk at 0.3 noise 13.4 degrees against 2.71.)
// A displacement limit above erosion_check_limit (the defaults are 1 for denoise_mesh()
// and 1.1 for the tool) asks the filter to move the vertices further than the noise:
// its result is then returned as it is, volume change included.
constexpr double volume_tolerance = 0.01;
constexpr double erosion_check_limit = 1.1;

// The mean displacement from `input` to `points` along the vertex normals of the input,
// weighted by the vertices' areas: `normals` are the area-weighted vertex normals of
// `input` (area_weighted_normals()), whose lengths are the weights.
inline double mean_normal_displacement(const std::vector<Eigen::Vector3d>& input,
                                       const std::vector<Eigen::Vector3d>& points,
                                       const std::vector<Eigen::Vector3d>& normals)
{
  double sum = 0, weights = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    sum += normals[i].dot(points[i] - input[i]);
    weights += normals[i].norm();
  }
  return weights > 0 ? sum / weights : 0.;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_SHRINKAGE_STOP_H
