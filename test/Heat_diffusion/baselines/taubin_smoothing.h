// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Taubin's lambda|mu smoothing (Taubin, "A signal processing approach to fair surface
// design", SIGGRAPH 1995), a baseline of the denoising benchmark.

#ifndef CGAL_HEAT_DIFFUSION_BASELINES_TAUBIN_SMOOTHING_H
#define CGAL_HEAT_DIFFUSION_BASELINES_TAUBIN_SMOOTHING_H

#include "face_normal_filtering.h"

namespace test_support {
namespace baselines {

// One lambda|mu pair of steps with the umbrella (uniform) Laplacian,
// v <- v + lambda L(v), then v <- v + mu L(v); the paper's example values
// lambda = 0.5, mu = -0.53 (pass band k_PB = 1/lambda + 1/mu of about 0.1).
inline void taubin_iteration(Face_mesh& fm, double lambda = 0.5, double mu = -0.53)
{
  const std::size_t n = fm.points.size();
  std::vector<std::vector<std::size_t> > neighbours(n);
  for(const auto& t : fm.triangles)
    for(std::size_t k = 0; k < 3; ++k)
    {
      neighbours[t[k]].push_back(t[(k + 1) % 3]);
      neighbours[t[(k + 1) % 3]].push_back(t[k]);
    }
  for(auto& ring : neighbours)
  {
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  }
  std::vector<Eigen::Vector3d> next(n);
  for(double factor : {lambda, mu})
  {
    for(std::size_t i = 0; i < n; ++i)
    {
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for(std::size_t j : neighbours[i])
        mean += fm.points[j];
      next[i] = neighbours[i].empty() ? fm.points[i]
                                      : Eigen::Vector3d(fm.points[i] + factor * (mean / double(neighbours[i].size()) - fm.points[i]));
    }
    fm.points.swap(next);
  }
}

} // namespace baselines
} // namespace test_support

#endif // CGAL_HEAT_DIFFUSION_BASELINES_TAUBIN_SMOOTHING_H
