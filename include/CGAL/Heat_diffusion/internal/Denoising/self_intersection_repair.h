// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The last step of denoise_mesh(): the faces that a denoised mesh makes intersect each
// other are untangled by local smoothing.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_SELF_INTERSECTION_REPAIR_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_SELF_INTERSECTION_REPAIR_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/Denoising/volume_preservation.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/tags.h>

#include <Eigen/Core>

#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// A round of untangling is kept only if it removes at least this fraction of the
// intersecting face pairs. The folds that noise in random directions leaves (faces
// turned over within the surface) go in one or two rounds: fandisk at 0.5 mean edge
// length of noise in random directions, 479 pairs, then 4, then 0. Pairs that survive
// are between walls closer than the noise, which smoothing separates only by
// flattening the part: anchor at 0.5 along the normals, 284, 196, 191, 183, ... pairs
// while its MAD rose from 46 to 53 degrees; its second round is not kept.
constexpr double least_untangled_fraction = 0.25;

// Bounds the number of rounds (each finds the intersections of the whole mesh again).
constexpr std::size_t untangling_rounds = 10;

// One round's smoothing of the marked vertices: `rings` rings of neighbours added to
// them, then one umbrella step (each vertex moved halfway to the mean of its
// neighbours) or, with `taubin`, Taubin's pair of steps (the second of factor -0.53,
// which undoes the first's shrinkage).
struct Untangling_step
{
  std::size_t rings;
  bool taubin;
};

inline void smooth_marked_vertices(const Indexed_mesh& mesh, std::vector<unsigned char> marked,
                                   const Untangling_step& step, std::vector<Eigen::Vector3d>& points)
{
  const std::size_t n = points.size();
  for(std::size_t ring = 0; ring < step.rings; ++ring)
  {
    std::vector<unsigned char> grown = marked;
    for(std::size_t i = 0; i < n; ++i)
      if(marked[i])
        for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
          grown[mesh.fan[k]] = 1;
    marked.swap(grown);
  }
  std::vector<Eigen::Vector3d> next = points;
  for(const double factor : {0.5, -0.53})
  {
    for(std::size_t i = 0; i < n; ++i)
      if(marked[i] && mesh.degree(i) > 0)
      {
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
          mean += points[mesh.fan[k]];
        next[i] = points[i] + factor * (mean / double(mesh.degree(i)) - points[i]);
      }
    points = next;
    if(!step.taubin)
      break;
  }
}

// Untangles the faces of `tm` that intersect each other once its vertices are at
// `points` (the frame of `mesh`; `write_back(points)` puts them into `tm`, which
// `vertex_point_map` reads). Each round marks the vertices of the intersecting faces
// and tries the steps of local smoothing from the gentlest (the marked vertices alone,
// one umbrella step) to the strongest (one ring more, Taubin's pair); it keeps the
// first that removes least_untangled_fraction of the pairs, and ends when none does.
// Ends with `tm` at `points`.
template <typename TriangleMesh, typename VertexPointMap, typename GeomTraits, typename VertexIndex,
          typename WriteBack>
void untangle_self_intersections(const TriangleMesh& tm, VertexPointMap vertex_point_map, const GeomTraits& traits,
                                 const Indexed_mesh& mesh, const VertexIndex& vertex_index,
                                 const WriteBack& write_back, std::vector<Eigen::Vector3d>& points)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t n = points.size();
  for(const Eigen::Vector3d& p : points)
    if(!p.allFinite())
    {
      write_back(points);  // puts the finite ones
      return;
    }
  std::vector<unsigned char> marked;
  // Puts `points` into `tm` and marks the vertices of its intersecting faces; returns the
  // number of intersecting pairs. Degenerate faces, which self_intersections() reports
  // as pairs (f, f), are not counted: the collinear vertices of a CAD export's slivers
  // are not a tangle, and smoothing them would bend a flat part.
  auto find_intersections = [&]() {
    write_back(points);
    std::vector<std::pair<face_descriptor, face_descriptor> > pairs;
    Polygon_mesh_processing::self_intersections<Parallel_if_available_tag>(
        tm, std::back_inserter(pairs), CGAL::parameters::vertex_point_map(vertex_point_map).geom_traits(traits));
    marked.assign(n, 0);
    std::size_t count = 0;
    for(const auto& pair : pairs)
    {
      if(pair.first == pair.second)
        continue;
      ++count;
      for(const face_descriptor f : {pair.first, pair.second})
        for(const halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
          marked[vertex_index(target(h, tm))] = 1;
    }
    return count;
  };
  std::size_t remaining = find_intersections();
  if(remaining == 0)
    return;
  const std::vector<Eigen::Vector3d> tangled = points;
  for(std::size_t round = 0; round < untangling_rounds && remaining > 0; ++round)
  {
    const std::vector<Eigen::Vector3d> before = points;
    const std::vector<unsigned char> round_marked = marked;
    bool kept = false;
    for(const Untangling_step step : {Untangling_step{0, false}, Untangling_step{0, true}, Untangling_step{1, false},
                                      Untangling_step{1, true}})
    {
      smooth_marked_vertices(mesh, round_marked, step, points);
      const std::size_t found = find_intersections();
      if(double(found) <= (1. - least_untangled_fraction) * double(remaining))
      {
        remaining = found;
        kept = true;
        break;
      }
      points = before;
    }
    if(!kept)
      break;
  }
  // The smoothing shrinks the thin parts where it separates walls (anchor at 0.3 along
  // the normals: -1.5 % of volume). The closed components are scaled back to their
  // volumes before the rounds, unless that makes more pairs intersect: each component is
  // scaled about its own centroid, and in an assembly whose parts touch (b9_mesh at 0.1
  // along the normals) that turns 3 intersecting pairs into 12.
  if(points != tangled)
  {
    std::vector<Eigen::Vector3d> untangled = points;
    restore_component_volumes(mesh, tangled, points);
    if(find_intersections() > remaining)
      points.swap(untangled);
  }
  write_back(points);
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_SELF_INTERSECTION_REPAIR_H
