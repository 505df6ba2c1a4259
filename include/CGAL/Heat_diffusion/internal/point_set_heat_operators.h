// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The stiffness L and the mass B of a point set's surface (internal/point_set_surface.h):
// the operators of internal/heat_operators.h on the union of the points' fans.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_POINT_SET_HEAT_OPERATORS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_POINT_SET_HEAT_OPERATORS_H

#include <CGAL/Heat_diffusion/internal/heat_operators.h>
#include <CGAL/Heat_diffusion/internal/point_set_surface.h>
#include <CGAL/Heat_diffusion/internal/vertex_block_matrix.h>

#include <Eigen/Sparse>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// L = D - W over the edges of the neighbour graph, with the weights of eq. 10 from the
// NCC (ncc_edge_weight(), as on a mesh), and the FEM mass B of eq. 11 summed over the
// fans' triangles, each with its weight (Sharp and Crane's 1/3 per fan that holds it),
// on the surface rescaled to total area n (the paper's time scale). Both are
// symmetric by construction (each edge's weight and each triangle's terms are computed
// once and written at (i, j) and (j, i) in the same order); L's rows sum to 0 up to
// rounding; B is positive definite (every point's fan has a triangle of positive area).
// They have the pattern of the graph (One_ring_pattern of surface.mesh), as a mesh's
// have that of its one-rings, which the local kernel reads.
inline Heat_operators assemble_point_set_heat_operators(const Point_set_surface& surface, double sigma)
{
  const Indexed_mesh& mesh = surface.mesh;
  const std::size_t n = mesh.number_of_vertices();
  Heat_operators ops;
  double total_area = 0;
  for(std::size_t t = 0; t < mesh.triangles.size(); ++t)
    total_area += surface.triangle_weights[t] *
                  canonical_triangle_area(mesh, mesh.triangles[t][0], mesh.triangles[t][1], mesh.triangles[t][2]);
  ops.area_scale = double(n) / total_area;

  typedef Eigen::Triplet<double> Triplet;
  std::vector<Triplet> stiffness, mass;
  checked_number_of_entries(mesh.fan.size() + n);
  stiffness.reserve(mesh.fan.size() + n);
  mass.reserve(9 * mesh.triangles.size());
  std::vector<double> degree(n, 0.);
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t q = mesh.fan_begin[i]; q < mesh.fan_begin[i + 1]; ++q)
    {
      const std::size_t j = mesh.fan[q];
      if(j < i)
        continue;
      const double w = ncc_edge_weight(surface.ncc, i, j, sigma);
      stiffness.emplace_back(int(i), int(j), -w);
      stiffness.emplace_back(int(j), int(i), -w);
      degree[i] += w;
      degree[j] += w;
    }
  for(std::size_t i = 0; i < n; ++i)
    stiffness.emplace_back(int(i), int(i), degree[i]);
  for(std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    const auto& c = mesh.triangles[t];
    const double area = ops.area_scale * surface.triangle_weights[t] * canonical_triangle_area(mesh, c[0], c[1], c[2]);
    for(int a = 0; a < 3; ++a)
      for(int b = 0; b < 3; ++b)
        mass.emplace_back(int(c[a]), int(c[b]), a == b ? area / 6. : area / 12.);
  }
  ops.stiffness.resize(Eigen::Index(n), Eigen::Index(n));
  ops.mass.resize(Eigen::Index(n), Eigen::Index(n));
  ops.stiffness.setFromTriplets(stiffness.begin(), stiffness.end());
  ops.mass.setFromTriplets(mass.begin(), mass.end());
  return ops;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_POINT_SET_HEAT_OPERATORS_H
