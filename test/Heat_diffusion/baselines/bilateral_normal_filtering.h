// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Bilateral Normal Filtering (Zheng, Fu, Au, Tai, "Bilateral Normal Filtering for
// Mesh Denoising", IEEE TVCG 2011), its local iterative scheme, a baseline of the
// denoising benchmark and test. Written from the paper.

#ifndef CGAL_HEAT_DIFFUSION_BASELINES_BILATERAL_NORMAL_FILTERING_H
#define CGAL_HEAT_DIFFUSION_BASELINES_BILATERAL_NORMAL_FILTERING_H

#include "face_normal_filtering.h"

namespace test_support {
namespace baselines {

// The paper's defaults: sigma_c the mean distance between adjacent face centroids,
// sigma_s = 0.35, 20 normal iterations, then 10 vertex iterations.
struct Bilateral_normal_filtering_parameters
{
  double sigma_c_multiple = 1.;
  double sigma_s = 0.35;
  std::size_t normal_iterations = 20;
  std::size_t vertex_iterations = 10;
};

// The local scheme: the normals are filtered `normal_iterations` times on the fixed
// noisy geometry, n_i <- normalise(sum_{j in N(i)} a_j W_c(|c_i - c_j|) W_s(|n_i - n_j|) n_j),
// N(i) the faces sharing a vertex with face i, W Gaussians; then the vertices are fit to
// the filtered normals.
template <typename Mesh>
void bilateral_normal_filtering(Mesh& mesh, const Bilateral_normal_filtering_parameters& p = {})
{
  if(!(p.sigma_c_multiple > 0) || !(p.sigma_s > 0))
    throw std::invalid_argument("bilateral_normal_filtering: the widths must be positive");
  Face_mesh fm = make_face_mesh(mesh);
  const double sigma_c = p.sigma_c_multiple * fm.mean_centroid_distance();
  if(!(sigma_c > 0))
    return;
  const double spatial = 1. / (2 * sigma_c * sigma_c), range = 1. / (2 * p.sigma_s * p.sigma_s);
  std::vector<Eigen::Vector3d> normals = fm.normals, next(normals.size());
  for(std::size_t it = 0; it < p.normal_iterations; ++it)
  {
    for(std::size_t f = 0; f < normals.size(); ++f)
    {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for(std::size_t g : fm.vertex_neighbours[f])
        sum += fm.areas[g] * std::exp(-(fm.centroids[f] - fm.centroids[g]).squaredNorm() * spatial -
                                      (normals[f] - normals[g]).squaredNorm() * range) *
               normals[g];
      next[f] = normalised_or(sum, normals[f]);
    }
    normals.swap(next);
  }
  update_vertices(fm, normals, p.vertex_iterations);
  write_points(fm, mesh);
}

} // namespace baselines
} // namespace test_support

#endif // CGAL_HEAT_DIFFUSION_BASELINES_BILATERAL_NORMAL_FILTERING_H
