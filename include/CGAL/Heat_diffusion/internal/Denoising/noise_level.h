// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Estimates of the noise level of a mesh, in lengths local to each vertex: the
// scale on which denoise_mesh() stops its filters.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NOISE_LEVEL_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NOISE_LEVEL_H

#include <CGAL/Heat_diffusion/internal/Denoising/face_adjacency.h>
#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The noise level of `points`: the median over the interior vertices of the distance
// of v_i, along its area-weighted normal, from the mean of its neighbours, divided by
// sqrt(1 + 1/degree) (the neighbours' own noise) and by 0.6745 (the median of |X| for
// a standard Gaussian X). Independent noise of standard deviation e along the normals
// gives about e; a piecewise flat surface without noise gives 0, a smooth one a small
// multiple of its curvature times the squared edge length. Each vertex is measured
// against its own neighbours only, so uneven edge lengths do not bias it.
// If `directions` is given, the normal of v_i is the area-weighted normal of those
// positions (a smoothed copy of `points`) instead of that of `points`. On needle
// triangles the normal of the noisy fan follows the noise of the neighbours (a thin fan
// tilts with them), so that the distance along it misses much of the noise: the
// estimate along the noisy normals is about half the true level on a mesh of needles,
// and close to it along the normals of a smoothed copy.
inline double plane_fit_noise_level(const Indexed_mesh& mesh, const Face_adjacency& adjacency,
                                    const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<Eigen::Vector3d>* directions = nullptr)
{
  std::vector<Eigen::Vector3d> normals;
  area_weighted_normals(mesh, adjacency, directions != nullptr ? *directions : points, normals);
  const std::size_t n = mesh.number_of_vertices();
  std::vector<double> distances;
  distances.reserve(n);
  for(int pass = 0; pass < 2 && distances.empty(); ++pass)  // boundary vertices only if there is nothing else
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t degree = mesh.degree(i);
      if(degree < 3 || (pass == 0 && !mesh.fan_is_closed[i]))
        continue;
      const Eigen::Vector3d& normal = normals[i];
      const double length = normal.norm();
      if(!(length > 0))
        continue;
      const double d = std::abs(normal.dot(points[i] - fan_mean(mesh, points, i))) / length;
      if(std::isfinite(d))
        distances.push_back(d / std::sqrt(1. + 1. / double(degree)));
    }
  if(distances.empty())
    return 0.;
  std::nth_element(distances.begin(), distances.begin() + std::ptrdiff_t(distances.size() / 2), distances.end());
  return distances[distances.size() / 2] / 0.6745;
}

// The noise level of `points` from second differences: the median over the vertices
// whose neighbours are all interior of the distance, along the area-weighted normal of
// v_i, of ((I - W)^2 p)_i from 0, W the uniform average over the one-ring, divided by
// the norm of row i of (I - W)^2 (the factor by which that operator scales independent
// noise at v_i) and by 0.6745. Like plane_fit_noise_level it reads about e for
// independent noise of standard deviation e along the normals, but the first difference
// (I - W) p of a smooth surface, its curvature times the squared edge length, is itself
// smooth and cancels in the second: on the clean meshes it reads 0.044 mean edge length
// on elephant and 0.060 on armadillo (plane_fit_noise_level: 0.15 and 0.11), and with
// 0.1 mean edge length of noise along the normals 1.10 and 1.17 times the noise
// (plane_fit_noise_level: 1.67 and 1.40).
inline double second_difference_noise_level(const Indexed_mesh& mesh, const Face_adjacency& adjacency,
                                            const std::vector<Eigen::Vector3d>& points)
{
  const std::size_t n = mesh.number_of_vertices();
  std::vector<Eigen::Vector3d> first(n, Eigen::Vector3d::Zero());
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t degree = mesh.degree(i);
    if(degree == 0)
      continue;
    first[i] = points[i] - fan_mean(mesh, points, i);
  }
  std::vector<Eigen::Vector3d> normals;
  area_weighted_normals(mesh, adjacency, points, normals);
  std::vector<double> distances;
  std::vector<std::pair<std::size_t, double> > row;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t degree = mesh.degree(i);
    if(degree < 3 || !mesh.fan_is_closed[i])
      continue;
    bool interior = true;
    for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
      interior = interior && mesh.fan_is_closed[mesh.fan[k]] && mesh.degree(mesh.fan[k]) >= 3;
    if(!interior)
      continue;
    const Eigen::Vector3d& normal = normals[i];
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    // Row i of (I - W)^2 = I - 2W + W^2.
    row.clear();
    row.push_back({i, 1.});
    for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
    {
      const std::size_t j = mesh.fan[k];
      mean += first[j];
      row.push_back({j, -2. / double(degree)});
      const double w = 1. / (double(degree) * double(mesh.degree(j)));
      for(std::size_t l = mesh.fan_begin[j]; l < mesh.fan_begin[j + 1]; ++l)
        row.push_back({mesh.fan[l], w});
    }
    std::sort(row.begin(), row.end());
    double squares = 0, sum = 0;
    for(std::size_t k = 0; k < row.size(); ++k)
    {
      sum += row[k].second;
      if(k + 1 == row.size() || row[k + 1].first != row[k].first)
      {
        squares += sum * sum;
        sum = 0;
      }
    }
    const double length = normal.norm();
    if(!(length > 0))
      continue;
    const double d = std::abs(normal.dot(first[i] - mean / double(degree))) / (length * std::sqrt(squares));
    if(std::isfinite(d))
      distances.push_back(d);
  }
  if(distances.empty())
    return 0.;
  std::nth_element(distances.begin(), distances.begin() + std::ptrdiff_t(distances.size() / 2), distances.end());
  return distances[distances.size() / 2] / 0.6745;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NOISE_LEVEL_H
