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

#include <algorithm>
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

// The volumes enclosed by the closed components (every vertex has a closed fan) of
// `reference` and of `points`, and the centroids of the latter's solids, per component
// (indexed by the component's label, see vertex_components()).
struct Component_volumes
{
  std::vector<std::size_t> component;
  std::vector<unsigned char> closed;
  std::vector<double> reference_volume, volume;
  std::vector<Eigen::Vector3d> centroid;

  // The ratio of the two volumes of the component labelled c, or 0 if it is not closed
  // or if they are not both non-zero, finite and of the same sign.
  double ratio(std::size_t c) const
  {
    const double r = closed[c] && volume[c] != 0 ? reference_volume[c] / volume[c] : 0.;
    return r > 0 && std::isfinite(r) && std::isfinite(centroid[c].squaredNorm()) ? r : 0.;
  }
};

inline Component_volumes component_volumes(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& reference,
                                           const std::vector<Eigen::Vector3d>& points)
{
  const std::size_t n = points.size();
  Component_volumes result;
  result.component = vertex_components(mesh);
  result.closed.assign(n, 1);
  for(std::size_t v = 0; v < n; ++v)
    if(!mesh.fan_is_closed[v] || mesh.degree(v) == 0)
      result.closed[result.component[v]] = 0;
  // Six times the signed volumes, and six times the first moments of `points`' solids
  // (the sum over the tetrahedra (0, a, b, c) of their volume times their centroid).
  result.reference_volume.assign(n, 0.);
  result.volume.assign(n, 0.);
  result.centroid.assign(n, Eigen::Vector3d::Zero());
  for(const auto& t : mesh.triangles)
  {
    const std::size_t c = result.component[t[0]];
    result.reference_volume[c] += reference[t[0]].dot(reference[t[1]].cross(reference[t[2]]));
    const double v = points[t[0]].dot(points[t[1]].cross(points[t[2]]));
    result.volume[c] += v;
    result.centroid[c] += v * (points[t[0]] + points[t[1]] + points[t[2]]) / 4.;
  }
  for(std::size_t c = 0; c < n; ++c)
    if(result.volume[c] != 0)
      result.centroid[c] /= result.volume[c];
  return result;
}

// The largest relative change of volume from `reference` to `points` over the closed
// components (0 if there is none).
inline double largest_volume_change(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& reference,
                                    const std::vector<Eigen::Vector3d>& points)
{
  const Component_volumes volumes = component_volumes(mesh, reference, points);
  double change = 0;
  for(std::size_t c = 0; c < points.size(); ++c)
    if(volumes.component[c] == c && volumes.ratio(c) > 0)
      change = (std::max)(change, std::abs(1. / volumes.ratio(c) - 1.));
  return change;
}

// The largest factor by which restore_component_volumes() changes a component's
// volume. A component that the smoothing made this much smaller (or larger) has
// collapsed, not shrunk: scaling it back would blow it up about a centroid that the
// rounding of its near-zero volume decides (b9_mesh, whose small closed parts the flow
// flattens, at 0.3 mean edge length of noise along the normals: a vertex was sent 20700
// mean edge lengths away).
constexpr double largest_volume_restoration = 8.;

// Scales every closed component of `points` about its centroid so that it encloses the
// volume that it encloses in `reference`. Mean curvature flow shrinks a closed surface (a
// sphere of radius r by 2t/r in time t); the scaling undoes the shrinkage on average and
// changes no face normal. Components whose two volumes are not both non-zero, finite and
// of the same sign, whose volume changed by more than largest_volume_restoration, or
// whose centroid lies outside their bounding box (the centroid of a solid lies inside
// its convex hull: one outside is that of a volume near zero) are left as they are.
inline void restore_component_volumes(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& reference,
                                      std::vector<Eigen::Vector3d>& points)
{
  const Component_volumes volumes = component_volumes(mesh, reference, points);
  const std::size_t n = points.size();
  std::vector<Eigen::AlignedBox3d> boxes(n);
  for(std::size_t v = 0; v < n; ++v)
    boxes[volumes.component[v]].extend(points[v]);
  std::vector<double> scales(n, 0.);
  for(std::size_t c = 0; c < n; ++c)
    if(const double ratio = volumes.ratio(c); ratio > 0 && ratio <= largest_volume_restoration &&
                                              ratio >= 1. / largest_volume_restoration &&
                                              boxes[c].contains(volumes.centroid[c]))
      scales[c] = std::cbrt(ratio);
  for(std::size_t v = 0; v < n; ++v)
  {
    const std::size_t c = volumes.component[v];
    if(scales[c] > 0)
      points[v] = volumes.centroid[c] + scales[c] * (points[v] - volumes.centroid[c]);
  }
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_VOLUME_PRESERVATION_H
