// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Volume preservation after a smoothing flow (Desbrun, Meyer, Schroeder and Barr,
// "Implicit fairing of irregular meshes using diffusion and curvature flow", 1999):
// each closed component is scaled uniformly to the volume it had before.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_VOLUME_PRESERVATION_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_VOLUME_PRESERVATION_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The connected components of the mesh's triangles: a label per vertex (vertices
// without a triangle get their own).
inline std::vector<std::size_t> vertex_components(const Indexed_mesh& mesh)
{
  std::vector<std::size_t> parent(mesh.number_of_vertices());
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto root = [&](std::size_t v) {
    while(parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for(const auto& t : mesh.triangles)
    for(int c = 1; c < 3; ++c)
      parent[root(t[c])] = root(t[0]);
  for(std::size_t v = 0; v < parent.size(); ++v)
    parent[v] = root(v);
  return parent;
}

// Scales every closed component of `points` (every vertex of it has a closed fan) about
// its centroid so that it encloses the volume that it encloses in `reference`. Mean
// curvature flow shrinks a closed surface (a sphere of radius r by 2t/r in time t); the
// scaling undoes the shrinkage on average and changes no face normal. Components whose
// two volumes are not both non-zero, finite and of the same sign are left as they are.
inline void restore_component_volumes(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& reference,
                                      std::vector<Eigen::Vector3d>& points)
{
  const std::size_t n = points.size();
  const std::vector<std::size_t> component = vertex_components(mesh);
  std::vector<unsigned char> closed(n, 1);
  for(std::size_t v = 0; v < n; ++v)
    if(!mesh.fan_is_closed[v] || mesh.degree(v) == 0)
      closed[component[v]] = 0;
  // Six times the signed volumes, and six times the first moments of `points`' solids
  // (the sum over the tetrahedra (0, a, b, c) of their volume times their centroid).
  std::vector<double> reference_volume(n, 0.), volume(n, 0.);
  std::vector<Eigen::Vector3d> moment(n, Eigen::Vector3d::Zero());
  for(const auto& t : mesh.triangles)
  {
    const std::size_t c = component[t[0]];
    reference_volume[c] += reference[t[0]].dot(reference[t[1]].cross(reference[t[2]]));
    const double v = points[t[0]].dot(points[t[1]].cross(points[t[2]]));
    volume[c] += v;
    moment[c] += v * (points[t[0]] + points[t[1]] + points[t[2]]) / 4.;
  }
  std::vector<double> scale(n, 1.);
  for(std::size_t c = 0; c < n; ++c)
  {
    if(component[c] != c || !closed[c])
      continue;
    const double ratio = reference_volume[c] / volume[c];
    if(ratio > 0 && std::isfinite(ratio) && std::isfinite(moment[c].squaredNorm()))
      scale[c] = std::cbrt(ratio);
  }
  for(std::size_t v = 0; v < n; ++v)
  {
    const std::size_t c = component[v];
    if(scale[c] != 1.)
    {
      const Eigen::Vector3d center = moment[c] / volume[c];
      points[v] = center + scale[c] * (points[v] - center);
    }
  }
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_VOLUME_PRESERVATION_H
