// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_HEAT_OPERATORS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_HEAT_OPERATORS_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/ncc_weights.h>

#include <Eigen/Sparse>

#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The stiffness matrix L and the mass matrix B of the edge-weighted heat equation
// B u' = -L u (paper, eq. 10-12), on the copy of the surface rescaled so that its
// total area equals the number of vertices (NOTES 6: t = 1 is then about one ring).
struct Heat_operators
{
  Eigen::SparseMatrix<double> stiffness;  // L = D - W, positive semi-definite (NOTES 5)
  Eigen::SparseMatrix<double> mass;       // FEM mass matrix, eq. 11
  double area_scale = 1.;                 // rescaled area = area_scale * area of the normalised frame
};

// Edge weight w_ij = exp(-|delta_i - delta_j|^2 / sigma^2) from the NCC (eq. 10);
// sigma = +infinity gives the plain (unweighted, w = 1) graph Laplacian.
inline double ncc_edge_weight(const Ncc_data& data, std::size_t i, std::size_t j, double sigma)
{
  if(std::isinf(sigma))
    return 1.;
  const Eigen::Vector3d di = data.signature[i] * data.normals[i];
  const Eigen::Vector3d dj = data.signature[j] * data.normals[j];
  return std::exp(-(di - dj).squaredNorm() / (sigma * sigma));
}

// `target_area`: the total area after rescaling; by default the number of vertices.
// The coarse level uses the fine mesh's vertex count, so that t keeps its meaning.
inline Heat_operators assemble_heat_operators(const Indexed_mesh& mesh, const Ncc_data& data, double sigma,
                                              double target_area = 0.)
{
  const std::size_t n = mesh.number_of_vertices();
  Heat_operators ops;

  double total_area = 0;
  std::vector<double> face_areas(mesh.triangles.size());
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const auto& t = mesh.triangles[f];
    face_areas[f] = 0.5 * (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]).norm();
    total_area += face_areas[f];
  }
  ops.area_scale = (target_area > 0 ? target_area : double(n)) / total_area;

  // B (eq. 11): B_ij = (|t_r| + |t_s|) / 12 over the faces sharing edge ij, and
  // B_ii = (sum of incident face areas) / 6; assembled face by face.
  std::vector<Eigen::Triplet<double> > mass_entries;
  mass_entries.reserve(9 * mesh.triangles.size());
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const auto& t = mesh.triangles[f];
    const double a = face_areas[f] * ops.area_scale;
    for(int r = 0; r < 3; ++r)
      for(int c = 0; c < 3; ++c)
        mass_entries.emplace_back(int(t[r]), int(t[c]), r == c ? a / 6. : a / 12.);
  }
  ops.mass.resize(Eigen::Index(n), Eigen::Index(n));
  ops.mass.setFromTriplets(mass_entries.begin(), mass_entries.end());

  // L = D - W over the mesh edges. Each edge is seen from both ends through the fans,
  // and contributes once to each off-diagonal entry.
  std::vector<Eigen::Triplet<double> > stiffness_entries;
  stiffness_entries.reserve(mesh.fan.size() + n);
  for(std::size_t i = 0; i < n; ++i)
  {
    double diagonal = 0;
    for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
    {
      const std::size_t j = mesh.fan[k];
      const double w = ncc_edge_weight(data, i, j, sigma);
      stiffness_entries.emplace_back(int(i), int(j), -w);
      diagonal += w;
    }
    stiffness_entries.emplace_back(int(i), int(i), diagonal);
  }
  ops.stiffness.resize(Eigen::Index(n), Eigen::Index(n));
  ops.stiffness.setFromTriplets(stiffness_entries.begin(), stiffness_entries.end());
  return ops;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_HEAT_OPERATORS_H
