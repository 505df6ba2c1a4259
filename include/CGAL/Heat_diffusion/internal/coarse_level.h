// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_COARSE_LEVEL_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_COARSE_LEVEL_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <Eigen/Sparse>

#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The coarse level of the paper's multi-resolution path (section 6, eq. 21): a
// simplified copy of the mesh, on which the eigenpairs are computed, and the
// prolongation P that carries a coarse vertex function to the fine vertices by the
// barycentric coordinates of each fine vertex's closest point on the coarse mesh.
struct Coarse_level
{
  Indexed_mesh mesh;                        // the coarse mesh
  Eigen::SparseMatrix<double> prolongation; // fine vertices x coarse vertices, rows sum to 1
};

// Simplifies `fine` to about `target_vertices` vertices by Garland-Heckbert edge
// collapse (plane quadrics), which keeps the sharp creases that the anisotropic
// kernel is about, and builds the prolongation.
inline Coarse_level make_coarse_level(const Indexed_mesh& fine, std::size_t target_vertices)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  typedef Mesh::Vertex_index Vertex;
  namespace SMS = CGAL::Surface_mesh_simplification;
  namespace PMP = CGAL::Polygon_mesh_processing;

  Mesh mesh;
  std::vector<Vertex> ids;
  ids.reserve(fine.number_of_vertices());
  for(const Eigen::Vector3d& p : fine.points)
    ids.push_back(mesh.add_vertex(K::Point_3(p.x(), p.y(), p.z())));
  for(const auto& t : fine.triangles)
    if(mesh.add_face(ids[t[0]], ids[t[1]], ids[t[2]]) == Mesh::null_face())
      throw_invalid_input("coarse level: the mesh cannot be copied for simplification");

  // An edge collapse removes one vertex and (Euler, closed or not) about three edges.
  const std::size_t removed = fine.number_of_vertices() > target_vertices ? fine.number_of_vertices() - target_vertices : 0;
  const std::size_t target_edges = mesh.number_of_edges() > 3 * removed ? mesh.number_of_edges() - 3 * removed : 3;
  SMS::Count_stop_predicate<Mesh> stop(target_edges);
  SMS::GarlandHeckbert_plane_policies<Mesh, K> policies(mesh);
  SMS::edge_collapse(mesh, stop,
                     CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
  mesh.collect_garbage();

  Coarse_level level;
  level.mesh = make_indexed_mesh(mesh, mesh.points(), get(CGAL::vertex_index, mesh));

  // Prolongation: closest point on the coarse mesh, in the frame of the fine mesh
  // (the simplified copy was made from the fine mesh's normalised points).
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;
  Tree tree;
  PMP::build_AABB_tree(mesh, tree);
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(3 * fine.number_of_vertices());
  for(std::size_t i = 0; i < fine.number_of_vertices(); ++i)
  {
    const Eigen::Vector3d& p = fine.points[i];
    const auto location = PMP::locate_with_AABB_tree(K::Point_3(p.x(), p.y(), p.z()), tree, mesh);
    const auto h = halfedge(location.first, mesh);
    const Vertex corners[3] = {source(h, mesh), target(h, mesh), target(next(h, mesh), mesh)};
    // Clamp rounding noise so that rows are convex combinations summing to 1.
    double w[3], sum = 0;
    for(int k = 0; k < 3; ++k)
      sum += (w[k] = (std::max)(0., double(location.second[k])));
    for(int k = 0; k < 3; ++k)
      entries.emplace_back(int(i), int(corners[k].idx()), sum > 0 ? w[k] / sum : 1. / 3.);
  }
  level.prolongation.resize(Eigen::Index(fine.number_of_vertices()), Eigen::Index(level.mesh.number_of_vertices()));
  level.prolongation.setFromTriplets(entries.begin(), entries.end());
  return level;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_COARSE_LEVEL_H
