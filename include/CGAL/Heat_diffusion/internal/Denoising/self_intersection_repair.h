// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The last step of denoise_mesh(): the faces that a denoised mesh makes intersect each
// other are untangled by local smoothing.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_SELF_INTERSECTION_REPAIR_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_SELF_INTERSECTION_REPAIR_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/Denoising/volume_preservation.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <Eigen/Core>

#include <algorithm>
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

// Bounds the number of rounds.
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
        next[i] = points[i] + factor * (fan_mean(mesh, points, i) - points[i]);
    points = next;
    if(!step.taubin)
      break;
  }
}

// The pairs of faces of `tm` that intersect, as Polygon_mesh_processing::
// self_intersections() finds them, less the pairs (f, f) by which it reports degenerate
// faces; kept up to date as the vertices move. The first search covers the whole mesh;
// the next ones only the faces that moved and those whose boxes overlap theirs. A pair
// of faces that did not move keeps its status, and a pair with a face that moved is
// among those searched, so the pairs are always those of a search of the whole mesh,
// at a cost that follows the size of the tangle rather than the mesh's.
template <typename TriangleMesh, typename VertexPointMap, typename GeomTraits, typename VertexIndex>
class Intersecting_face_pairs
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef Box_intersection_d::Box_with_info_d<double, 3, face_descriptor, Box_intersection_d::ID_FROM_BOX_ADDRESS>
      Box;

public:
  typedef std::pair<face_descriptor, face_descriptor> Face_pair;

  Intersecting_face_pairs(const TriangleMesh& tm, VertexPointMap vertex_point_map, const GeomTraits& traits,
                          const VertexIndex& vertex_index)
    : tm_(tm), vertex_point_map_(vertex_point_map), traits_(traits), vertex_index_(vertex_index),
      face_index_(get_initialized_face_index_map(tm, parameters::default_values()))
  {
    for(const face_descriptor f : faces(tm))
    {
      face_index_bound_ = (std::max)(face_index_bound_, std::size_t(get(face_index_, f)) + 1);
      ++number_of_faces_;
    }
  }

  // The intersecting pairs of `tm`, whose vertices are at `points` (indexed by
  // `vertex_index`; the caller has put them into `tm`).
  const std::vector<Face_pair>& update(const std::vector<Eigen::Vector3d>& points)
  {
    std::vector<face_descriptor> moved;
    if(searched_points_.size() == points.size())
      for(const face_descriptor f : faces(tm_))
        for(const halfedge_descriptor h : halfedges_around_face(halfedge(f, tm_), tm_))
        {
          const std::size_t i = vertex_index_(target(h, tm_));
          if(points[i] != searched_points_[i])
          {
            moved.push_back(f);
            break;
          }
        }
    // A first search, or one after most faces moved, covers the whole mesh.
    if(searched_points_.size() != points.size() || 4 * moved.size() > number_of_faces_)
    {
      pairs_.clear();
      search(faces(tm_));
    }
    else if(!moved.empty())
    {
      const std::vector<unsigned char> near = faces_near(moved);
      std::vector<face_descriptor> searched;
      for(const face_descriptor f : faces(tm_))
        if(near[get(face_index_, f)])
          searched.push_back(f);
      pairs_.erase(std::remove_if(pairs_.begin(), pairs_.end(),
                                  [&](const Face_pair& pair) {
                                    return near[get(face_index_, pair.first)] && near[get(face_index_, pair.second)];
                                  }),
                   pairs_.end());
      search(searched);
    }
    searched_points_ = points;
    return pairs_;
  }

private:
  Bbox_3 box(const face_descriptor f) const
  {
    Bbox_3 result;
    for(const halfedge_descriptor h : halfedges_around_face(halfedge(f, tm_), tm_))
      result += get(vertex_point_map_, target(h, tm_)).bbox();
    return result;
  }

  // Flags, by face index, the faces of `moved` and those whose boxes overlap theirs.
  std::vector<unsigned char> faces_near(const std::vector<face_descriptor>& moved) const
  {
    std::vector<Box> moved_boxes, candidates;
    Bbox_3 around;
    for(const face_descriptor f : moved)
    {
      moved_boxes.emplace_back(box(f), f);
      around += moved_boxes.back().bbox();
    }
    for(const face_descriptor f : faces(tm_))
    {
      const Bbox_3 b = box(f);
      if(do_overlap(b, around))
        candidates.emplace_back(b, f);
    }
    std::vector<unsigned char> near(face_index_bound_, 0);
    for(const face_descriptor f : moved)
      near[get(face_index_, f)] = 1;
    box_intersection_d(moved_boxes.begin(), moved_boxes.end(), candidates.begin(), candidates.end(),
                       [&](const Box& a, const Box& b) {
                         near[get(face_index_, a.info())] = 1;
                         near[get(face_index_, b.info())] = 1;
                       });
    return near;
  }

  // Sequential: on two cores, PMP's parallel search was the slower on every mesh measured
  // (see the user manual).
  template <typename FaceRange>
  void search(const FaceRange& range)
  {
    std::vector<Face_pair> found;
    Polygon_mesh_processing::self_intersections<Sequential_tag>(
        range, tm_, std::back_inserter(found),
        CGAL::parameters::vertex_point_map(vertex_point_map_).geom_traits(traits_));
    for(const Face_pair& pair : found)
      if(pair.first != pair.second)
        pairs_.push_back(pair);
  }

  const TriangleMesh& tm_;
  VertexPointMap vertex_point_map_;
  GeomTraits traits_;
  VertexIndex vertex_index_;  // a copy: a temporary callable may be passed
  typename GetInitializedFaceIndexMap<TriangleMesh, parameters::Default_named_parameters>::const_type face_index_;
  std::size_t face_index_bound_ = 0, number_of_faces_ = 0;
  std::vector<Eigen::Vector3d> searched_points_;  // where the vertices were at the last search
  std::vector<Face_pair> pairs_;
};

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
  Intersecting_face_pairs<TriangleMesh, VertexPointMap, GeomTraits, VertexIndex> intersecting(
      tm, vertex_point_map, traits, vertex_index);
  std::vector<unsigned char> marked;
  // Puts `points` into `tm` and marks the vertices of its intersecting faces; returns the
  // number of intersecting pairs. Degenerate faces are not counted: the collinear
  // vertices of a CAD export's slivers are not a tangle, and smoothing them would bend a
  // flat part.
  auto find_intersections = [&]() {
    write_back(points);
    const auto& pairs = intersecting.update(points);
    marked.assign(n, 0);
    for(const auto& pair : pairs)
      for(const face_descriptor f : {pair.first, pair.second})
        for(const halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
          marked[vertex_index(target(h, tm))] = 1;
    return pairs.size();
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
