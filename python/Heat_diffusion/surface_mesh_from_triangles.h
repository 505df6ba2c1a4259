// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The Python module's Surface_mesh from V and F in one pass over the triangles.
//
// Adding the faces one by one (Surface_mesh::add_face, i.e. CGAL::Euler::add_face)
// searches the halfedges around each corner and checks and re-links border fans for
// every face: on a large mesh that is a noticeable part of what a Python call costs,
// work the tool does while reading its file, outside what it times. When the triangles
// form an oriented 2-manifold (with or without boundary), the halfedge structure that
// add_face builds face after face is determined by the triangles and their order:
// this builds that same structure directly (same edge, halfedge and face numbers, same
// next/prev links, same vertex halfedges), so that the package sees the same mesh and
// computes the same bits. Any other input (an edge with three faces or two faces along
// it in the same direction, a vertex whose faces form several fans) is declined, and the
// caller adds the faces one by one as before, which gives the same mesh or the same
// error as before.

#ifndef CGAL_HEAT_DIFFUSION_PYTHON_SURFACE_MESH_FROM_TRIANGLES_H
#define CGAL_HEAT_DIFFUSION_PYTHON_SURFACE_MESH_FROM_TRIANGLES_H

#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace cgal_heat_diffusion_python {

// Builds into the empty `mesh` the n vertices of `points` (n x 3, row-major) and the
// m triangles of `triangles` (m x 3 vertex indices in [0, n), each with three
// different vertices), exactly as n calls of add_vertex() then m calls of add_face()
// in order would. Returns false, leaving `mesh` empty, if the triangles are not an
// oriented 2-manifold: then add_face() decides (it refuses some such faces, and builds
// others that the package rejects later). Linear in n + m.
template <typename Point>
bool build_manifold_surface_mesh(const double* points, std::size_t n, const std::uint32_t* triangles,
                                 std::size_t m, CGAL::Surface_mesh<Point>& mesh)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::size_type size_type;
  typedef typename Mesh::Vertex_index Vertex;
  typedef typename Mesh::Halfedge_index Halfedge;
  typedef typename Mesh::Face_index Face;
  const std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();

  // Corner c = 3 f + i of face f is the halfedge triangles[c] -> triangles[next(c)].
  const std::size_t corners = 3 * m;
  if(n >= none || corners >= std::size_t(none) / 2)
    return false;
  auto next_corner = [](std::size_t c) { return c % 3 == 2 ? c - 2 : c + 1; };

  // The corners of each edge, bucketed by the edge's smaller vertex and sorted by its
  // larger vertex, then by corner: an edge's corners are adjacent, its first corner
  // (in face order) first.
  std::vector<std::uint32_t> bucket_begin(n + 1, 0);
  for(std::size_t c = 0; c < corners; ++c)
  {
    const std::uint32_t a = triangles[c], b = triangles[next_corner(c)];
    ++bucket_begin[(a < b ? a : b) + 1];
  }
  std::partial_sum(bucket_begin.begin(), bucket_begin.end(), bucket_begin.begin());
  // (larger vertex, corner with the top bit set if it runs from the larger vertex)
  const std::uint32_t downward = std::uint32_t(1) << 31;
  std::vector<std::pair<std::uint32_t, std::uint32_t> > bucket(corners);
  {
    std::vector<std::uint32_t> fill(bucket_begin.begin(), bucket_begin.end() - 1);
    for(std::size_t c = 0; c < corners; ++c)
    {
      const std::uint32_t a = triangles[c], b = triangles[next_corner(c)];
      bucket[fill[a < b ? a : b]++] =
          a < b ? std::make_pair(b, std::uint32_t(c)) : std::make_pair(a, std::uint32_t(c) | downward);
    }
  }
  // partner[c]: the other corner of c's edge, or none (a border edge). Corners are
  // filled in increasing order, so each bucket is sorted by corner already; a stable
  // insertion sort by the larger vertex keeps that order within an edge.
  std::vector<std::uint32_t> partner(corners, none);
  std::vector<unsigned char> first(corners, 0);
  for(std::size_t v = 0; v < n; ++v)
  {
    auto* begin = bucket.data() + bucket_begin[v];
    auto* end = bucket.data() + bucket_begin[v + 1];
    for(auto* p = begin + 1; p < end; ++p)
      for(auto* q = p; q > begin && q[-1].first > q[0].first; --q)
        std::swap(q[-1], q[0]);
    for(auto* p = begin; p < end;)
    {
      auto* q = p + 1;
      while(q < end && q->first == p->first)
        ++q;
      if(q - p > 2)
        return false;  // three or more faces on an edge
      first[p->second & ~downward] = 1;
      if(q - p == 2)
      {
        // Two faces must run along their edge in opposite directions.
        if((p[0].second & downward) == (p[1].second & downward))
          return false;
        partner[p[0].second & ~downward] = p[1].second & ~downward;
        partner[p[1].second & ~downward] = p[0].second & ~downward;
      }
      p = q;
    }
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t> >().swap(bucket);
  std::vector<std::uint32_t>().swap(bucket_begin);

  // Edges numbered by their first corner, as add_face creates them; the halfedge of
  // the first corner is the edge's first halfedge, as add_edge(source, target) makes it.
  std::vector<std::uint32_t> halfedge_of(corners);
  std::size_t edges = 0;
  for(std::size_t c = 0; c < corners; ++c)
    if(first[c])
    {
      halfedge_of[c] = std::uint32_t(2 * edges);
      if(partner[c] != none)
        halfedge_of[partner[c]] = std::uint32_t(2 * edges + 1);
      ++edges;
    }
  std::vector<unsigned char>().swap(first);

  // Border halfedges (opposite a corner without partner): one into and one out of a
  // vertex at most, else its faces form several fans.
  std::vector<std::uint32_t> border_in(n, none), border_out(n, none);
  for(std::size_t c = 0; c < corners; ++c)
    if(partner[c] == none)
    {
      const std::uint32_t border = halfedge_of[c] ^ 1u;  // triangles[next(c)] -> triangles[c]
      const std::uint32_t from = triangles[next_corner(c)], to = triangles[c];
      if(border_out[from] != none || border_in[to] != none)
        return false;
      border_out[from] = border;
      border_in[to] = border;
    }

  // One fan per vertex. Face (v, x, y) adds the link edge x -> y to v's link; with each
  // halfedge in one face at most (checked above), a link is made of paths and cycles,
  // and v is manifold if its link is one of them. Each link is walked within its own
  // short list (bucketed by vertex), which stays in cache.
  {
    std::vector<std::uint32_t> link_begin(n + 1, 0);
    for(std::size_t c = 0; c < corners; ++c)
      ++link_begin[triangles[c] + 1];
    std::partial_sum(link_begin.begin(), link_begin.end(), link_begin.begin());
    std::vector<std::pair<std::uint32_t, std::uint32_t> > link(corners);
    {
      std::vector<std::uint32_t> fill(link_begin.begin(), link_begin.end() - 1);
      for(std::size_t f = 0; f < m; ++f)
      {
        const std::uint32_t* t = triangles + 3 * f;
        link[fill[t[0]]++] = std::make_pair(t[1], t[2]);
        link[fill[t[1]]++] = std::make_pair(t[2], t[0]);
        link[fill[t[2]]++] = std::make_pair(t[0], t[1]);
      }
    }
    for(std::size_t v = 0; v < n; ++v)
    {
      const auto* begin = link.data() + link_begin[v];
      const auto* end = link.data() + link_begin[v + 1];
      if(begin == end)
        continue;  // isolated: add_face() leaves it so too, and the package rejects it
      // Forwards from the first link edge to the end of its path or around its cycle,
      // then backwards to the start of the path (on a cycle, back at the last edge).
      const std::size_t size = std::size_t(end - begin);
      std::size_t visited = 1;
      const auto* last = begin;
      while(visited <= size)
      {
        const auto* successor = begin;
        while(successor < end && successor->first != last->second)
          ++successor;
        if(successor == end || successor == begin)
          break;
        last = successor;
        ++visited;
      }
      const auto* first_edge = begin;
      while(visited <= size)
      {
        const auto* predecessor = begin;
        while(predecessor < end && predecessor->second != first_edge->first)
          ++predecessor;
        if(predecessor == end || predecessor == last)
          break;
        first_edge = predecessor;
        ++visited;
      }
      if(visited != size)
        return false;
    }
  }

  mesh.resize(size_type(n), size_type(edges), size_type(m));
  for(std::size_t i = 0; i < n; ++i)
    mesh.point(Vertex(size_type(i))) = Point(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
  // An interior vertex keeps the halfedge into it of its last face, which add_face()
  // leaves there when that face closes its fan; a border vertex has its border
  // halfedge, as add_face() adjusts it.
  for(std::size_t f = 0; f < m; ++f)
  {
    const Face face{size_type(f)};
    for(std::size_t i = 0; i < 3; ++i)
    {
      const std::size_t c = 3 * f + i, d = next_corner(c);
      const Halfedge h(size_type(halfedge_of[c]));
      mesh.set_target(h, Vertex(size_type(triangles[d])));
      mesh.set_face(h, face);
      mesh.set_next(h, Halfedge(size_type(halfedge_of[d])));
      mesh.set_halfedge(Vertex(size_type(triangles[d])), h);
      if(partner[c] == none)
      {
        const Halfedge border(size_type(halfedge_of[c] ^ 1u));
        mesh.set_target(border, Vertex(size_type(triangles[c])));
        mesh.set_face(border, Mesh::null_face());
      }
    }
    mesh.set_halfedge(face, Halfedge(size_type(halfedge_of[3 * f + 2])));
  }
  for(std::size_t v = 0; v < n; ++v)
    if(border_in[v] != none)
    {
      mesh.set_halfedge(Vertex(size_type(v)), Halfedge(size_type(border_in[v])));
      mesh.set_next(Halfedge(size_type(border_in[v])), Halfedge(size_type(border_out[v])));
    }

  return true;
}

} // namespace cgal_heat_diffusion_python

#endif // CGAL_HEAT_DIFFUSION_PYTHON_SURFACE_MESH_FROM_TRIANGLES_H
