// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_HEAT_OPERATORS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_HEAT_OPERATORS_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/ncc_weights.h>
#include <CGAL/Heat_diffusion/internal/parallel_for.h>
#include <CGAL/Heat_diffusion/internal/vertex_block_matrix.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The stiffness matrix L and the mass matrix B of the edge-weighted heat equation
// B u' = -L u (paper, eq. 10-12), on the copy of the surface rescaled so that its
// total area equals the number of vertices (the paper's time scale, section 6: the mean
// vertex area is then 1, and t = 1 spreads heat over about one ring).
struct Heat_operators
{
  Eigen::SparseMatrix<double> stiffness;  // L = D - W, positive semi-definite (eq. 10 prints W - D)
  Eigen::SparseMatrix<double> mass;       // FEM mass matrix, eq. 11
  double area_scale = 1.;                 // rescaled area = area_scale * area of the normalised frame
};

// The factor beta_ij = (B_ii + B_jj) / 2 of the scale-invariant kernel (eq. 14), from
// the diagonal of B.
inline double scale_invariant_factor(const Eigen::VectorXd& mass_diagonal, std::size_t i, std::size_t j)
{
  return 0.5 * (mass_diagonal[Eigen::Index(i)] + mass_diagonal[Eigen::Index(j)]);
}

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

// The area of the triangle (a, b, c), computed from its vertices in increasing index
// order, so that every vertex of the triangle gets the same bits: B stays exactly
// symmetric although each column is assembled from its own vertex's fan.
inline double canonical_triangle_area(const Indexed_mesh& mesh, std::size_t a, std::size_t b, std::size_t c)
{
  if(a > b)
    std::swap(a, b);
  if(b > c)
    std::swap(b, c);
  if(a > b)
    std::swap(a, b);
  return 0.5 * mesh.cross_product(a, b, c).norm();
}

// `target_area`: the total area after rescaling; by default the number of vertices.
// The coarse level uses the fine mesh's vertex count, so that t keeps its meaning.
//
// Both matrices have the one-ring pattern (One_ring_pattern: column i lists v_i and its
// fan). They are written directly in compressed columns, each column by one thread from
// its fan (parallel, and the same bits on any number of threads), without the triplets
// and their sort (30 million of them at 1.6M vertices).
inline Heat_operators assemble_heat_operators(const Indexed_mesh& mesh, const Ncc_data& data, double sigma,
                                              double target_area = 0.)
{
  typedef Eigen::SparseMatrix<double>::StorageIndex Storage_index;
  const std::size_t n = mesh.number_of_vertices();
  Heat_operators ops;

  double total_area = 0;
  for(const auto& t : mesh.triangles)
    total_area += canonical_triangle_area(mesh, t[0], t[1], t[2]);
  ops.area_scale = (target_area > 0 ? target_area : double(n)) / total_area;

  const One_ring_pattern pattern(mesh);
  const Eigen::Index entries = checked_number_of_entries(pattern.rows.size());
  for(Eigen::SparseMatrix<double>* matrix : {&ops.stiffness, &ops.mass})
  {
    matrix->resize(Eigen::Index(n), Eigen::Index(n));
    matrix->resizeNonZeros(entries);
    for(std::size_t i = 0; i <= n; ++i)
      matrix->outerIndexPtr()[i] = Storage_index(pattern.begin[i]);
  }
  const double scale = ops.area_scale;
  parallel_for(n, [&](std::size_t i) {
    const std::size_t begin = pattern.begin[i], size = pattern.begin[i + 1] - begin;
    Storage_index* row = ops.stiffness.innerIndexPtr() + begin;
    double* stiffness = ops.stiffness.valuePtr() + begin;
    double* mass = ops.mass.valuePtr() + begin;
    for(std::size_t k = 0; k < size; ++k)
      row[k] = Storage_index(pattern.rows[begin + k]);
    const std::size_t self = pattern.place(i, i);
    std::fill(stiffness, stiffness + size, 0.);
    std::fill(mass, mass + size, 0.);
    const auto position = [&](std::size_t j) {
      return std::size_t(std::lower_bound(row, row + size, Storage_index(j)) - row);
    };
    // L = D - W (eq. 10 with the sign that makes heat flow from hot to cold), and B (eq. 11): B_ij = (|t_r| + |t_s|) / 12 over the
    // faces sharing edge ij, B_ii = (sum of the incident face areas) / 6.
    const std::size_t fan_begin = mesh.fan_begin[i], degree = mesh.degree(i);
    for(std::size_t f = 0; f < degree; ++f)
    {
      const std::size_t j = mesh.fan[fan_begin + f];
      const double w = ncc_edge_weight(data, i, j, sigma);
      stiffness[position(j)] -= w;
      stiffness[self] += w;
      // the triangle (u_f, i, u_f+1), the last one only in a closed fan
      if(f + 1 < degree || (mesh.fan_is_closed[i] && degree > 1))
      {
        const std::size_t next = mesh.fan[fan_begin + (f + 1) % degree];
        const double area = scale * canonical_triangle_area(mesh, j, i, next);
        mass[self] += area / 6.;
        mass[position(j)] += area / 12.;
        mass[position(next)] += area / 12.;
      }
    }
  });
  std::copy(ops.stiffness.innerIndexPtr(), ops.stiffness.innerIndexPtr() + entries, ops.mass.innerIndexPtr());
  return ops;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_HEAT_OPERATORS_H
