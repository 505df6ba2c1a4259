// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The widths of the range weights with which denoise_mesh()'s crease-preserving phase
// diffuses the face normals, one per face: narrow where the noise tilts the normals
// little and the shape is flat, wide where the noise or the shape's own bending would
// otherwise be frozen into false creases.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NORMAL_WIDTHS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NORMAL_WIDTHS_H

#include <CGAL/Heat_diffusion/internal/Denoising/face_adjacency.h>
#include <CGAL/Heat_diffusion/internal/Denoising/cotangent_flow.h>
#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The widest width: two faces of a crease of 40 degrees or more (|n_f - n_g| >= 0.68)
// weigh each other less than a third. It was the width of every face before the widths
// adapted to the noise and the shape (see crease_preserving_widths()).
constexpr double crease_preserving_sigma = 0.45;
// The narrowest width: faces whose normals differ by 0.2 (11 degrees) still weigh
// each other 0.6.
constexpr double narrowest_crease_preserving_sigma = 0.2;
// sigma_f >= noise_tilt_factor * (the tilt the noise gives the normal of f)
constexpr double noise_tilt_factor = 0.75;
// sigma_f >= shape_bend_factor * (how much the smoothed surface's normals turn around f)
constexpr double shape_bend_factor = 1.5;
// The time of the implicit smoothing that takes the noise away before the bend is
// measured, in squared mean edge lengths.
constexpr double shape_smoothing_time = 9.;

// The width sigma_f of each face f for the range weight
// exp(-|n_f - n_g|^2 / (sigma_f^2 + sigma_g^2)) between f and its neighbour g (the
// weight exp(-|n_f - n_g|^2 / 2 sigma^2) of eq. 10 when the widths are equal). A width
// must exceed the differences that the noise makes between neighbouring normals, or the
// noise is frozen, and it must exceed those of the shape's own bending, or the curved
// parts are faceted; beyond that, the narrower the width, the less the flat parts leak
// across creases (a single width of 0.45 left fandisk at 2.16 degrees with noise of 0.1
// mean edge length, against 1.51 for Bilateral Normal Filtering). So
//   sigma_f = clamp(max(noise_tilt_factor tilt_f, shape_bend_factor bend_f),
//                   narrowest_crease_preserving_sigma, crease_preserving_sigma):
//  - tilt_f = noise sqrt(|e_1|^2 + |e_2|^2 + |e_3|^2) / (2 area_f), the standard deviation
//    of the gradient of the linear interpolant of independent heights of standard
//    deviation `noise` at the corners of f: the tilt of its normal. It is large on small
//    or thin faces (needles: the widest width) and small on large ones, whatever the
//    mesh's mean edge length;
//  - bend_f, the area-weighted mean of |n_f - n_g| over the faces g sharing a vertex with
//    f, on the input smoothed by the implicit cotangent flow for shape_smoothing_time
//    squared mean edge lengths: the turn of the surface itself around f, about 0 on the
//    flat parts and up to the widest width on fillets, cylinders and on the creases
//    (which the smoothing rounds, so that the faces along them keep the widest width).
// Measured by benchmark_denoising (seeds 5 and 6), against a single width of 0.45: fandisk
// at 0.1, 0.2 and 0.3 noise, along the normals then in random directions, from 2.16,
// 2.40, 2.77 and 2.08, 2.29, 3.31 to 1.46, 2.06, 2.71 and 1.48, 1.83, 3.02 degrees;
// anchor_dense from 3.59, 4.42, 5.19 and 3.48, 4.51, 5.88 to 3.03, 4.37, 5.33 and 2.69, 4.19,
// 5.75. The factors were chosen on these two meshes (noise factors 0.6 to 0.9, bend factors
// 1 to 2 and smoothing times 4 and 9 measured).
// `noise` is the noise level of the input (plane_fit_noise_level), `flow` the
// Cotangent_flow of the input. If the smoothing fails, the bend is not known and every
// face gets the widest width.
inline std::vector<double> crease_preserving_widths(const Indexed_mesh& mesh, const Face_adjacency& adjacency,
                                                    double noise, Cotangent_flow& flow)
{
  const std::size_t m = mesh.triangles.size();
  std::vector<Eigen::Vector3d> normals, centroids, smoothed;
  std::vector<double> areas;
  const double edge = mean_edge_length(mesh);
  if(!(edge > 0) || !std::isfinite(edge) ||
     !flow.smooth(shape_smoothing_time * edge * edge, 1, smoothed))
    return std::vector<double>(m, crease_preserving_sigma);
  std::vector<double> widths(m);
  face_geometry(mesh, mesh.points, normals, areas, centroids);
  for(std::size_t f = 0; f < m; ++f)
  {
    const auto& t = mesh.triangles[f];
    const double squares = (mesh.points[t[1]] - mesh.points[t[0]]).squaredNorm() +
                           (mesh.points[t[2]] - mesh.points[t[1]]).squaredNorm() +
                           (mesh.points[t[0]] - mesh.points[t[2]]).squaredNorm();
    const double tilt = areas[f] > 0 ? noise * std::sqrt(squares) / (2. * areas[f])
                                     : std::numeric_limits<double>::infinity();
    widths[f] = noise_tilt_factor * tilt;
  }
  face_geometry(mesh, smoothed, normals, areas, centroids);
  for(std::size_t f = 0; f < m; ++f)
  {
    double turn = 0, area = 0;
    for(std::size_t k = adjacency.face_faces_begin[f]; k < adjacency.face_faces_begin[f + 1]; ++k)
    {
      const std::size_t g = adjacency.face_faces[k];
      turn += areas[g] * (normals[f] - normals[g]).norm();
      area += areas[g];
    }
    const double bend = area > 0 ? turn / area : 0.;
    const double width = (std::max)(widths[f], shape_bend_factor * bend);
    // (NaN, from a non-finite input, takes the widest width)
    widths[f] = std::isnan(width) ? crease_preserving_sigma
                                  : std::clamp(width, narrowest_crease_preserving_sigma, crease_preserving_sigma);
  }
  return widths;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NORMAL_WIDTHS_H
