// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The outlier test that denoise_mesh() runs before its filters: vertices displaced far
// from the surface that their neighbours span (impulsive noise) are put back onto it,
// along the normal of that surface only.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_IMPULSE_REMOVAL_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_IMPULSE_REMOVAL_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/parallel_for.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The ring of an interior vertex v_i (its neighbours u_k, in fan order) defines a plane
// without v_i: through their mean c_i, with the normal n_i of the ring polygon
// (sum_k (u_k - c_i) x (u_k+1 - c_i), normalised), neither of which depends on v_i.
// The height of v_i is h_i = n_i . (v_i - c_i), the flatness of its ring
// rho_i = (mean_k (n_i . (u_k - c_i))^2)^(1/2), and its residual r_i = h_i - p_i, where
// the prediction p_i is the mean of the neighbours' own heights (along n_i): a smooth
// surface changes its height above the rings slowly, so that its curvature, which puts
// every vertex at about the same height above its ring, cancels in r_i. An impulse d
// on v_i gives h_i and r_i of about d, with the same sign, and leaves rho_i as it is
// (the neighbours are where they were); a crease or a corner folds the ring itself, so
// that rho_i grows with h_i, and a vertex beside a crease has a small h_i (its
// residual, from the heights of the crease vertices around it, is not an impulse: on
// r_i alone, 1702 of the clean fandisk's 6475 vertices were outliers). A vertex is an
// outlier if
//   |h_i| > impulse_flatness_ratio rho_i,   |h_i| > impulse_floor e_i,
//   |r_i| > impulse_scale_ratio s,           r_i h_i > 0,
// e_i the mean length of its edges and s the median of |r_j| / 0.6745 over the interior
// vertices: the scale of the clean majority, which impulses on a tenth or a fifth of
// the vertices do not move much (a robust reference for the outliers, not an estimate
// of their size). An outlier is moved along n_i to the height its neighbours predict
// (r_i = 0): it does not slide within the surface. The test runs again on the result,
// up to impulse_rounds times, and every outlier found so far is moved again: in the
// first round the neighbours' heights still hold a part of the impulses, and a cluster
// of impulses folds the rings of its own members, whose largest is found first.
// Fewer outliers than impulse_minimum_fraction of the tested vertices in the first
// round are the shape's own spikes (the tips and corners of a clean mesh: 5 of
// fandisk's 6475 vertices, 2 of head's 1487, 6 of elephant's 2775), which no local
// test tells from an impulse: the mesh is left to the filters.
constexpr double impulse_flatness_ratio = 3.;
constexpr double impulse_floor = 0.05;
constexpr double impulse_scale_ratio = 4.;
constexpr double impulse_minimum_fraction = 0.01;
constexpr std::size_t impulse_rounds = 8;

struct Ring_height
{
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double height = 0, flatness = 0, edge = 0;
  bool valid = false;
};

inline Ring_height ring_height(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& points, std::size_t i)
{
  Ring_height r;
  const std::size_t begin = mesh.fan_begin[i], end = mesh.fan_begin[i + 1], degree = end - begin;
  if(degree < 3 || !mesh.fan_is_closed[i])
    return r;
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for(std::size_t k = begin; k < end; ++k)
    c += points[mesh.fan[k]];
  c /= double(degree);
  Eigen::Vector3d area = Eigen::Vector3d::Zero();
  double edges = 0;
  for(std::size_t k = begin; k < end; ++k)
  {
    const Eigen::Vector3d& a = points[mesh.fan[k]];
    const Eigen::Vector3d& b = points[mesh.fan[k + 1 < end ? k + 1 : begin]];
    area += (a - c).cross(b - c);
    edges += (a - points[i]).norm();
  }
  const double length = area.norm();
  if(!(length > 0) || !std::isfinite(length))
    return r;
  r.normal = area / length;
  double squares = 0;
  for(std::size_t k = begin; k < end; ++k)
    squares += std::pow(r.normal.dot(points[mesh.fan[k]] - c), 2);
  r.height = r.normal.dot(points[i] - c);
  r.flatness = std::sqrt(squares / double(degree));
  r.edge = edges / double(degree);
  r.valid = std::isfinite(r.height) && std::isfinite(r.flatness);
  return r;
}

// Puts the outliers of `points` back onto the surface of their rings (see above);
// returns the number of vertices it moved (0: `points` unchanged).
inline std::size_t remove_impulses(const Indexed_mesh& mesh, std::vector<Eigen::Vector3d>& points)
{
  const std::size_t n = points.size();
  std::vector<Ring_height> rings(n);
  std::vector<double> residuals(n, 0.), sorted;
  std::vector<unsigned char> outlier(n, 0);
  std::size_t count = 0;
  // The height that the neighbours predict for v_i: the mean of their own heights (a
  // smooth surface changes its height above the rings slowly).
  auto predicted = [&](std::size_t i) {
    double sum = 0;
    std::size_t k = 0;
    for(std::size_t q = mesh.fan_begin[i]; q < mesh.fan_begin[i + 1]; ++q)
      if(rings[mesh.fan[q]].valid)
      {
        sum += rings[mesh.fan[q]].height * rings[mesh.fan[q]].normal.dot(rings[i].normal);
        ++k;
      }
    return k > 0 ? sum / double(k) : 0.;
  };
  for(std::size_t round = 0; round < impulse_rounds; ++round)
  {
    parallel_for(n, [&](std::size_t i) { rings[i] = ring_height(mesh, points, i); });
    sorted.clear();
    for(std::size_t i = 0; i < n; ++i)
      if(rings[i].valid)
      {
        residuals[i] = rings[i].height - predicted(i);
        sorted.push_back(std::abs(residuals[i]));
      }
    if(sorted.empty())
      break;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
    const double scale = sorted[sorted.size() / 2] / 0.6745;
    std::size_t found = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      const Ring_height& r = rings[i];
      const double d = std::abs(residuals[i]);
      const double h = std::abs(r.height);
      if(r.valid && !outlier[i] && h > impulse_flatness_ratio * r.flatness && h > impulse_floor * r.edge &&
         d > impulse_scale_ratio * scale && residuals[i] * r.height > 0)
      {
        outlier[i] = 1;
        ++found;
      }
    }
    if(round == 0 && double(found) < impulse_minimum_fraction * double(sorted.size()))
      return 0;
    count += found;
    // Every outlier found so far goes to the height its neighbours predict; in the first
    // round their heights still hold a part of the impulses, which the next rounds remove.
    for(std::size_t i = 0; i < n; ++i)
      if(outlier[i] && rings[i].valid)
        points[i] -= residuals[i] * rings[i].normal;
  }
  return count;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_IMPULSE_REMOVAL_H
