// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The normal update of the paper's denoising (eq. 22), made robust: used by
// denoise_mesh() with Denoising_method::signature_diffusion.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_SIGNATURE_NORMALS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_SIGNATURE_NORMALS_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The paper's n'_i = sum_j s_j n_j / sum_j s_j divides by a sum that vanishes wherever
// the signature changes sign across the ring (every noisy flat region), and flips the
// normal where the sum is negative. The normals of the closed one-ring {i} and N(i)
// are weighted by |s_j| instead: a convex combination of unit normals with
// non-negative weights, which stays inside the cone of the ring's normals and never
// divides by a signed sum. A ring whose weights all vanish, or whose weighted normals
// cancel, keeps the current normal.
inline std::vector<Eigen::Vector3d> signature_weighted_normals(const Indexed_mesh& mesh,
                                                               const std::vector<Eigen::Vector3d>& normals,
                                                               const Eigen::VectorXd& signature)
{
  const std::size_t n = mesh.number_of_vertices();
  std::vector<Eigen::Vector3d> result(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    double total_weight = std::abs(signature[Eigen::Index(i)]);
    Eigen::Vector3d sum = total_weight * normals[i];
    for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
    {
      const std::size_t j = mesh.fan[k];
      const double weight = std::abs(signature[Eigen::Index(j)]);
      sum += weight * normals[j];
      total_weight += weight;
    }
    // The sum of unit vectors weighted by w_j has length at most sum_j w_j; a tenth
    // of a percent of that means the normals nearly cancel (a spike).
    const double length = sum.norm();
    result[i] = length > 1e-3 * total_weight && length > 0 ? Eigen::Vector3d(sum / length) : normals[i];
  }
  return result;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_SIGNATURE_NORMALS_H
