// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Guided Mesh Normal Filtering (Zhang, Deng, Zhang, Bouaziz, Liu, "Guided Mesh
// Normal Filtering", Pacific Graphics 2015), its local iterative scheme, a baseline of
// the denoising benchmark and test. Written from the paper.

#ifndef CGAL_HEAT_DIFFUSION_BASELINES_GUIDED_NORMAL_FILTERING_H
#define CGAL_HEAT_DIFFUSION_BASELINES_GUIDED_NORMAL_FILTERING_H

#include "face_normal_filtering.h"

#include <limits>

namespace test_support {
namespace baselines {

// The paper's defaults: the filter's neighbourhood is the faces within twice the mean
// distance between adjacent face centroids (reached over shared vertices), sigma_s
// that mean distance, sigma_r = 0.35, 20 iterations of normal filtering each followed by
// 10 vertex iterations.
struct Guided_normal_filtering_parameters
{
  double radius_multiple = 2.;
  double sigma_s_multiple = 1.;
  double sigma_r = 0.35;
  std::size_t normal_iterations = 20;
  std::size_t vertex_iterations = 10;
};

namespace internal {

// The faces whose centroid lies within `radius` of the centroid of f, found by a
// breadth-first search over shared vertices (the paper's geometric neighbourhood),
// f included.
inline std::vector<std::size_t> faces_within(const Face_mesh& fm, std::size_t f, double radius,
                                             std::vector<std::size_t>& stamp)
{
  std::vector<std::size_t> result(1, f);
  stamp[f] = f;
  for(std::size_t k = 0; k < result.size(); ++k)
    for(std::size_t g : fm.vertex_neighbours[result[k]])
    {
      if(stamp[g] == f)
        continue;
      stamp[g] = f;
      if((fm.centroids[g] - fm.centroids[f]).norm() <= radius)
        result.push_back(g);
    }
  return result;
}

} // namespace internal

// Each iteration computes, for every face f, its guidance normal: among the patches
// P_g = {g} u N(g) (N the faces sharing a vertex) that contain f, the one with the
// smallest consistency measure H(P) = Phi(P) R(P) -- Phi the largest difference
// between two normals of P, R the largest normal difference across an interior edge of
// P over (epsilon + their sum) -- gives the area-weighted mean normal of P. Then
// n_f <- normalise(sum_{j} a_j W_s(|c_f - c_j|) W_r(|g_f - g_j|) n_j) over the
// neighbourhood, and the vertices are fit to the filtered normals.
template <typename Mesh>
void guided_normal_filtering(Mesh& mesh, const Guided_normal_filtering_parameters& p = {})
{
  if(!(p.radius_multiple > 0) || !(p.sigma_s_multiple > 0) || !(p.sigma_r > 0))
    throw std::invalid_argument("guided_normal_filtering: the radius and the widths must be positive");
  Face_mesh fm = make_face_mesh(mesh);
  const std::size_t m = fm.triangles.size();
  const double radius = p.radius_multiple * fm.mean_centroid_distance();
  if(!(radius > 0))
    return;
  // The neighbourhoods are those of the input (the reference implementation too).
  std::vector<std::vector<std::size_t> > neighbourhood(m);
  {
    std::vector<std::size_t> stamp(m, std::numeric_limits<std::size_t>::max());
    for(std::size_t f = 0; f < m; ++f)
      neighbourhood[f] = internal::faces_within(fm, f, radius, stamp);
  }
  std::vector<double> measure(m);
  std::vector<Eigen::Vector3d> patch_normal(m), guidance(m), filtered(m);
  std::vector<std::size_t> patch;
  for(std::size_t it = 0; it < p.normal_iterations; ++it)
  {
    const double sigma_s = p.sigma_s_multiple * fm.mean_centroid_distance();
    if(!(sigma_s > 0))
      break;
    const std::vector<Eigen::Vector3d>& n = fm.normals;
    for(std::size_t f = 0; f < m; ++f)
    {
      patch.assign(1, f);
      patch.insert(patch.end(), fm.vertex_neighbours[f].begin(), fm.vertex_neighbours[f].end());
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      double largest = 0;
      for(std::size_t a = 0; a < patch.size(); ++a)
      {
        mean += fm.areas[patch[a]] * n[patch[a]];
        for(std::size_t b = a + 1; b < patch.size(); ++b)
          largest = (std::max)(largest, (n[patch[a]] - n[patch[b]]).norm());
      }
      // Interior edges: edge-adjacent pairs with both faces in the patch (sorted for
      // the lookup; each pair counted once).
      std::vector<std::size_t> sorted = patch;
      std::sort(sorted.begin(), sorted.end());
      double edge_sum = 0, edge_max = 0;
      for(std::size_t a : patch)
        for(std::size_t b : fm.edge_neighbours[a])
          if(a < b && std::binary_search(sorted.begin(), sorted.end(), b))
          {
            const double d = (n[a] - n[b]).norm();
            edge_sum += d;
            edge_max = (std::max)(edge_max, d);
          }
      measure[f] = largest * edge_max / (edge_sum + 1e-9);
      patch_normal[f] = normalised_or(mean, n[f]);
    }
    for(std::size_t f = 0; f < m; ++f)
    {
      std::size_t best = f;
      for(std::size_t g : fm.vertex_neighbours[f])
        if(measure[g] < measure[best])
          best = g;
      guidance[f] = patch_normal[best];
    }
    const double spatial = 1. / (2 * sigma_s * sigma_s), range = 1. / (2 * p.sigma_r * p.sigma_r);
    for(std::size_t f = 0; f < m; ++f)
    {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for(std::size_t g : neighbourhood[f])
        sum += fm.areas[g] * std::exp(-(fm.centroids[f] - fm.centroids[g]).squaredNorm() * spatial -
                                      (guidance[f] - guidance[g]).squaredNorm() * range) *
               n[g];
      filtered[f] = normalised_or(sum, n[f]);
    }
    update_vertices(fm, filtered, p.vertex_iterations);
  }
  write_points(fm, mesh);
}

} // namespace baselines
} // namespace test_support

#endif // CGAL_HEAT_DIFFUSION_BASELINES_GUIDED_NORMAL_FILTERING_H
