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

#include <CGAL/Heat_diffusion/internal/parallel_for.h>
#include <CGAL/Heat_diffusion/internal/progress.h>
#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <limits>
#include <utility>
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

// Meshes of more than prepass_factor times the coarse vertex count are first brought
// to that size by the fast `decimate_by_rounds()`, then by Garland-Heckbert edge collapse.
#ifndef CGAL_HEAT_DIFFUSION_COARSE_PREPASS_FACTOR
#define CGAL_HEAT_DIFFUSION_COARSE_PREPASS_FACTOR 4
#endif
constexpr std::size_t prepass_factor = CGAL_HEAT_DIFFUSION_COARSE_PREPASS_FACTOR;

// The first, fast stage of the simplification of a large mesh: rounds of
// multiple-choice half-edge collapses (after Wu and Kobbelt, "Fast mesh decimation by
// multiple-choice techniques", 2002), with Garland-Heckbert plane quadrics as the
// cost. In each round every vertex u proposes its cheapest collapse u -> v onto a
// neighbour v, the proposals are sorted by cost and the cheaper half of them are
// applied greedily, skipping those whose cost a collapse of the same round has made
// stale; each round removes about a quarter of the vertices. There is no priority
// queue and no update of the costs of the two-ring after each collapse, which is
// where `Surface_mesh_simplification::edge_collapse()` spends its time, whatever the
// cost policy. Every kept vertex keeps its position on the input surface. A collapse
// is skipped when it violates the link condition, is an edge of a tetrahedron, moves a
// border vertex off the border, turns a face by more than 60 degrees or nearly
// flattens it.
//
// The proposals are computed in parallel, one slot per vertex, and listed in vertex
// order, so the result does not depend on the number of threads. Applying them is
// greedy and sequential, each collapse changing what the next may do. `progress`
// follows the vertices removed.
template <typename Mesh>
void decimate_by_rounds(Mesh& mesh, std::size_t target_vertices, const Progress& progress)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor Vertex;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor Halfedge;
  typedef std::array<double, 10> Quadric;  // upper triangle of a symmetric 4 x 4 matrix
  auto point = [&](Vertex v) {
    const auto& p = mesh.point(v);
    return Eigen::Vector3d(p.x(), p.y(), p.z());
  };
  auto add_plane = [](Quadric& q, const Eigen::Vector3d& n, double d, double w) {
    const double a[4] = {n.x(), n.y(), n.z(), d};
    int k = 0;
    for(int r = 0; r < 4; ++r)
      for(int c = r; c < 4; ++c)
        q[std::size_t(k++)] += w * a[r] * a[c];
  };
  auto error = [](const Quadric& q1, const Quadric& q2, const Eigen::Vector3d& x) {
    const double a[4] = {x.x(), x.y(), x.z(), 1.};
    double e = 0;
    int k = 0;
    for(int r = 0; r < 4; ++r)
      for(int c = r; c < 4; ++c, ++k)
        e += (r == c ? 1. : 2.) * (q1[std::size_t(k)] + q2[std::size_t(k)]) * a[r] * a[c];
    return e;
  };

  auto quadrics = mesh.template add_property_map<Vertex, Quadric>("v:hd_quadric", Quadric{}).first;
  auto stamp = mesh.template add_property_map<Vertex, std::size_t>("v:hd_stamp", 0).first;
  for(auto f : faces(mesh))
  {
    const Halfedge h = halfedge(f, mesh);
    const Vertex v[3] = {source(h, mesh), target(h, mesh), target(next(h, mesh), mesh)};
    const Eigen::Vector3d p0 = point(v[0]);
    const Eigen::Vector3d cross = (point(v[1]) - p0).cross(point(v[2]) - p0);
    const double norm = cross.norm();
    if(!(norm > 0))
      continue;
    const Eigen::Vector3d n = cross / norm;
    for(const Vertex u : v)  // weighted by the face area
      add_plane(quadrics[u], n, -n.dot(p0), 0.5 * norm);
  }

  // u -> v (the source of h goes to its target): allowed?
  auto is_valid = [&](Halfedge h) {
    const Vertex u = source(h, mesh), v = target(h, mesh);
    if(is_border(u, mesh) && !is_border(edge(h, mesh), mesh))
      return false;
    if(CGAL::is_tetrahedron(h, mesh) || !CGAL::Euler::does_satisfy_link_condition(edge(h, mesh), mesh))
      return false;
    const Eigen::Vector3d pu = point(u), pv = point(v);
    for(Halfedge g : halfedges_around_target(u, mesh))  // g: a -> u
    {
      if(is_border(g, mesh))
        continue;
      const Vertex a = source(g, mesh), b = target(next(g, mesh), mesh);  // face (a, u, b)
      if(a == v || b == v)
        continue;  // removed with the edge
      const Eigen::Vector3d pa = point(a), pb = point(b);
      const Eigen::Vector3d before = (pu - pa).cross(pb - pa), after = (pv - pa).cross(pb - pa);
      const double dot = before.dot(after);
      if(!(dot > 0.5 * before.norm() * after.norm()) || !(after.squaredNorm() > 1e-6 * before.squaredNorm()))
        return false;
    }
    return true;
  };

  const std::size_t initial = static_cast<std::size_t>(num_vertices(mesh));
  std::size_t live = initial;
  std::vector<std::pair<double, Halfedge> > best_of_vertex, proposals;
  for(std::size_t round = 1; live > target_vertices; ++round)
  {
    progress.report(double(initial - live) / double(initial - target_vertices),
                    "the simplification of the coarse level");
    // Removed elements are only flagged: compact once they outnumber the live ones,
    // so that a round costs O(live vertices).
    if(mesh.number_of_removed_vertices() > live)
      mesh.collect_garbage();
    const std::size_t slots = mesh.number_of_vertices() + mesh.number_of_removed_vertices();
    best_of_vertex.assign(slots, {std::numeric_limits<double>::infinity(), Halfedge()});
    parallel_for(slots, [&](std::size_t index) {
      const Vertex u(static_cast<typename Mesh::size_type>(index));
      if(mesh.is_removed(u))
        return;
      auto& best = best_of_vertex[index];
      const Eigen::Vector3d pu = point(u);
      for(Halfedge g : halfedges_around_source(u, mesh))  // g: u -> v
      {
        const Vertex v = target(g, mesh);
        const double cost = error(quadrics[u], quadrics[v], point(v)) + 1e-12 * (point(v) - pu).squaredNorm();
        if(cost < best.first)
          best = {cost, g};
      }
    });
    proposals.clear();
    for(const auto& proposal : best_of_vertex)
      if(proposal.first < std::numeric_limits<double>::infinity())
        proposals.push_back(proposal);
    std::sort(proposals.begin(), proposals.end(),
              [](const std::pair<double, Halfedge>& a, const std::pair<double, Halfedge>& b) { return a.first < b.first; });
    const std::size_t considered = (proposals.size() + 1) / 2;
    std::size_t collapsed = 0;
    for(std::size_t k = 0; k < considered && live > target_vertices; ++k)
    {
      const Halfedge h = proposals[k].second;
      if(mesh.is_removed(h))
        continue;
      const Vertex u = source(h, mesh), v = target(h, mesh);
      if(stamp[u] == round || stamp[v] == round || !is_valid(h))
        continue;
      const auto position = mesh.point(v);
      Quadric q = quadrics[u];
      for(std::size_t i = 0; i < q.size(); ++i)
        q[i] += quadrics[v][i];
      const Vertex kept = CGAL::Euler::collapse_edge(edge(h, mesh), mesh);
      mesh.point(kept) = position;
      quadrics[kept] = q;
      stamp[kept] = round;  // its quadric changed: its proposals wait for the next round
      --live;
      ++collapsed;
    }
    if(collapsed == 0)
      break;
  }
  mesh.remove_property_map(quadrics);
  mesh.remove_property_map(stamp);
  mesh.collect_garbage();
}

// Tells `progress` how far Garland-Heckbert edge collapse has come, every 1024 collapses.
template <typename Mesh>
struct Collapse_progress : CGAL::Surface_mesh_simplification::Edge_collapse_visitor_base<Mesh>
{
  typedef CGAL::Surface_mesh_simplification::Edge_collapse_visitor_base<Mesh> Base;
  const Progress* progress;
  std::size_t expected, done = 0;

  Collapse_progress(const Progress& p, std::size_t expected_collapses) : progress(&p), expected(expected_collapses) {}
  void OnCollapsed(const typename Base::Profile&, const typename Base::vertex_descriptor&)
  {
    if(++done % 1024 == 0 && expected > 0)
      progress->report((std::min)(1., double(done) / double(expected)), "the simplification of the coarse level");
  }
};

// Simplifies `fine` to about `target_vertices` vertices by Garland-Heckbert edge
// collapse (plane quadrics), which keeps the sharp creases that the anisotropic
// kernel is about, and builds the prolongation. Meshes of more than four times the
// target first go down to four times the target by `decimate_by_rounds()`. `K` is the
// kernel of the simplified copy (a template parameter, so that the simplification is
// compiled only where a coarse level is built).
template <typename K = CGAL::Exact_predicates_inexact_constructions_kernel>
Coarse_level make_coarse_level(const Indexed_mesh& fine, std::size_t target_vertices,
                               const Progress& progress = Progress())
{
  typedef CGAL::Surface_mesh<typename K::Point_3> Mesh;
  typedef typename Mesh::Vertex_index Vertex;
  namespace SMS = CGAL::Surface_mesh_simplification;
  namespace PMP = CGAL::Polygon_mesh_processing;

  // The progress bar's shares of the stages follow their shares of the time on large
  // meshes, where the rounds take most of it.
  constexpr double copy_end = 0.1, rounds_end = 0.7, prolongation_begin = 0.85;
  progress.report(0., "the simplification of the coarse level");
  Mesh mesh;
  std::vector<Vertex> ids;
  ids.reserve(fine.number_of_vertices());
  for(const Eigen::Vector3d& p : fine.points)
    ids.push_back(mesh.add_vertex(typename K::Point_3(p.x(), p.y(), p.z())));
  for(const auto& t : fine.triangles)
    if(mesh.add_face(ids[t[0]], ids[t[1]], ids[t[2]]) == Mesh::null_face())
      throw_invalid_input("coarse level: the mesh cannot be copied for simplification");
  std::vector<Vertex>().swap(ids);

  const bool staged = fine.number_of_vertices() > prepass_factor * target_vertices;
  if(staged)
    decimate_by_rounds(mesh, prepass_factor * target_vertices, progress.part(copy_end, rounds_end));

  // An edge collapse removes one vertex and (Euler, closed or not) about three edges.
  const std::size_t current = mesh.number_of_vertices();
  const std::size_t removed = current > target_vertices ? current - target_vertices : 0;
  const std::size_t target_edges = mesh.number_of_edges() > 3 * removed ? mesh.number_of_edges() - 3 * removed : 3;
  SMS::Count_stop_predicate<Mesh> stop(target_edges);
  SMS::GarlandHeckbert_plane_policies<Mesh, K> policies(mesh);
  const Progress collapse_progress = progress.part(staged ? rounds_end : copy_end, prolongation_begin);
  collapse_progress.report(0., "the simplification of the coarse level");
  SMS::edge_collapse(mesh, stop,
                     CGAL::parameters::get_cost(policies.get_cost())
                         .get_placement(policies.get_placement())
                         .visitor(Collapse_progress<Mesh>(collapse_progress, removed)));
  mesh.collect_garbage();
  progress.report(prolongation_begin, "the simplification of the coarse level");

  Coarse_level level;
  level.mesh = make_indexed_mesh(mesh, mesh.points(), get(CGAL::vertex_index, mesh));

  // Prolongation: closest point on the coarse mesh, in the frame of the fine mesh
  // (the simplified copy was made from the fine mesh's normalised points).
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;
  Tree tree;
  PMP::build_AABB_tree(mesh, tree);
  tree.accelerate_distance_queries();  // built now: the queries below run in parallel
  std::vector<Eigen::Triplet<double> > entries(3 * fine.number_of_vertices());
  parallel_for(fine.number_of_vertices(), [&](std::size_t i) {
    const Eigen::Vector3d& p = fine.points[i];
    const auto location = PMP::locate_with_AABB_tree(typename K::Point_3(p.x(), p.y(), p.z()), tree, mesh);
    const auto h = halfedge(location.first, mesh);
    const Vertex corners[3] = {source(h, mesh), target(h, mesh), target(next(h, mesh), mesh)};
    // Clamp rounding noise so that rows are convex combinations summing to 1.
    double w[3], sum = 0;
    for(int k = 0; k < 3; ++k)
      sum += (w[k] = (std::max)(0., double(location.second[k])));
    for(int k = 0; k < 3; ++k)
      entries[3 * i + std::size_t(k)] =
          Eigen::Triplet<double>(int(i), int(corners[k].idx()), sum > 0 ? w[k] / sum : 1. / 3.);
  });
  level.prolongation.resize(Eigen::Index(fine.number_of_vertices()), Eigen::Index(level.mesh.number_of_vertices()));
  level.prolongation.setFromTriplets(entries.begin(), entries.end());
  progress.report(1., "the prolongation of the coarse level");
  return level;
}

#ifdef CGAL_HEAT_DIFFUSION_EXTERN_TEMPLATES
extern template Coarse_level make_coarse_level<CGAL::Exact_predicates_inexact_constructions_kernel>(
    const Indexed_mesh&, std::size_t, const Progress&);
#endif

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_COARSE_LEVEL_H
