// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shared by the point-set tests: the vertices of a mesh as a point set with the mesh's
// NCC normals, in the order of the NCC's vertex_index(), so that a point's index is its
// vertex's in the mesh's operators.

#ifndef CGAL_HEAT_DIFFUSION_TEST_MESH_VERTICES_AS_POINTS_H
#define CGAL_HEAT_DIFFUSION_TEST_MESH_VERTICES_AS_POINTS_H

#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>

#include <CGAL/Point_set_3.h>

#include <vector>

namespace test_support {

template <typename Mesh>
CGAL::Point_set_3<typename Mesh::Point> mesh_vertices_as_points(
    const Mesh& mesh, const CGAL::Heat_diffusion::Normal_controlled_coordinates<Mesh>& ncc)
{
  std::vector<typename Mesh::Vertex_index> by_index(mesh.number_of_vertices());
  for(auto v : mesh.vertices())
    by_index[ncc.vertex_index(v)] = v;
  CGAL::Point_set_3<typename Mesh::Point> points;
  points.add_normal_map();
  for(auto v : by_index)
    points.insert(mesh.point(v), ncc.normal(v));
  return points;
}

} // namespace test_support

#endif // CGAL_HEAT_DIFFUSION_TEST_MESH_VERTICES_AS_POINTS_H
