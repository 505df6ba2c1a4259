// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Mesh total generalized variation (MeshTGV: Z. Liu, Y. Li, W. Wang, L. Liu, R. Chen,
// "Mesh Total Generalized Variation for Denoising", IEEE TVCG 28(12), 2022), a baseline
// of the denoising benchmark, written from the paper's description: the face normals N
// minimise a data term plus the second-order TGV of the normal field,
//   1/2 sum_f a_f |N_f - N0_f|^2 + alpha_1 sum_e l_e |(D N)_e - (G W)_e| + alpha_0 sum_e l_e d_e |(E W)_e|,
// over N and an auxiliary linear field W (a 3 x 3 matrix per face: N varies as
// N_f + W_f (x - c_f) around the centroid c_f). On an interior edge e between the faces
// f and g (length l_e, centroids d_e = c_g - c_f apart): (D N)_e = N_g - N_f is the jump
// of the normals, (G W)_e = (W_f + W_g) d_e / 2 the jump that the linear field predicts,
// (E W)_e = W_g - W_f the jump of the linear field. The first-order term locates the
// creases (where the normals jump beyond the linear prediction), the second the smoothly
// curved parts (where W is constant); the paper's discrete operators are not reproduced
// to the letter (its text was not at hand): this is a TGV^2 of piecewise constant face
// normals on the dual graph with the same roles. Solved as the paper does, by variable
// splitting and the augmented Lagrangian method (ADMM): P = D N - G W and Q = E W, the N
// subproblem a sparse system of the faces (factorised once), projected onto unit
// normals, the W subproblem a sparse system of 3 unknowns per face (factorised once,
// one solve per normal component), P and Q by vector shrinkage. Then the vertices are
// fitted to the normals by the update of Sun et al. 2007, as the paper does. Lengths in
// mean edge lengths and areas in mean face areas, so that the parameters do not depend
// on the scale of the mesh.

#ifndef CGAL_HEAT_DIFFUSION_BASELINES_MESH_TGV_H
#define CGAL_HEAT_DIFFUSION_BASELINES_MESH_TGV_H

#include "face_normal_filtering.h"

#include <CGAL/Heat_diffusion/internal/sparse_cholesky.h>

#include <Eigen/Sparse>

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace test_support {
namespace baselines {

// The paper's parameters are set per model and not at hand: these reproduce its figure
// for fandisk (the normals of its released result are 2.20 degrees from the clean
// ones; here 2.07 on CGAL's fandisk, the same model, with 0.3 mean edge length of
// Gaussian noise along the normals, benchmark_denoising's seed) and are used for every
// mesh. The penalty grows with the alphas: the projection of the normals onto the
// sphere in each iteration keeps the augmented Lagrangian from converging otherwise
// (fandisk: 11.5 degrees at alpha 2 with a penalty of 1, 3.2 with 8).
struct Mesh_tgv_parameters
{
  double alpha_1 = 1.;  // the first-order term: larger removes more noise
  double alpha_0 = 1.;  // the second-order term: larger flattens the curved parts' linear field
  double penalty = 4.;  // the augmented Lagrangian's penalty r (both constraints)
  std::size_t iterations = 150;
  std::size_t vertex_iterations = 20;
};

namespace internal {

struct Dual_edge
{
  std::size_t f, g;
  double length;      // l_e, in mean edge lengths
  Eigen::Vector3d d;  // c_g - c_f, in mean edge lengths
};

inline std::vector<Dual_edge> dual_edges(const Face_mesh& fm, double unit)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> first_face;
  std::vector<Dual_edge> edges;
  for(std::size_t f = 0; f < fm.triangles.size(); ++f)
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t a = fm.triangles[f][k], b = fm.triangles[f][(k + 1) % 3];
      const auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
      const auto found = first_face.find(key);
      if(found == first_face.end())
        first_face.emplace(key, f);
      else
        edges.push_back({found->second, f, (fm.points[a] - fm.points[b]).norm() / unit,
                         (fm.centroids[f] - fm.centroids[found->second]) / unit});
    }
  return edges;
}

inline Eigen::Vector3d shrink(const Eigen::Vector3d& x, double threshold)
{
  const double length = x.norm();
  return length > threshold ? Eigen::Vector3d((1. - threshold / length) * x) : Eigen::Vector3d::Zero();
}

} // namespace internal

// Returns the filtered face normals of `fm` (its geometry unchanged).
inline std::vector<Eigen::Vector3d> mesh_tgv_normals(const Face_mesh& fm, const Mesh_tgv_parameters& p)
{
  namespace HDI = CGAL::Heat_diffusion::internal;
  typedef Eigen::Triplet<double> T;
  const std::size_t m = fm.triangles.size();
  double unit = 0, mean_area = 0;
  for(const auto& t : fm.triangles)
    for(std::size_t k = 0; k < 3; ++k)
      unit += (fm.points[t[k]] - fm.points[t[(k + 1) % 3]]).norm() / double(3 * m);
  for(double a : fm.areas)
    mean_area += a / double(m);
  if(!(unit > 0) || !(mean_area > 0))
    return fm.normals;
  const std::vector<internal::Dual_edge> edges = internal::dual_edges(fm, unit);
  const std::size_t ne = edges.size();
  const double r = p.penalty;

  // N subproblem: (A + r D^T D) N = A N0 + r D^T (G W + P + lambda_1 / r).
  std::vector<T> triplets;
  for(std::size_t f = 0; f < m; ++f)
    triplets.emplace_back(Eigen::Index(f), Eigen::Index(f), fm.areas[f] / mean_area);
  for(const auto& e : edges)
  {
    triplets.emplace_back(Eigen::Index(e.f), Eigen::Index(e.f), r);
    triplets.emplace_back(Eigen::Index(e.g), Eigen::Index(e.g), r);
    triplets.emplace_back(Eigen::Index(e.f), Eigen::Index(e.g), -r);
    triplets.emplace_back(Eigen::Index(e.g), Eigen::Index(e.f), -r);
  }
  Eigen::SparseMatrix<double> normal_system(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
  normal_system.setFromTriplets(triplets.begin(), triplets.end());
  HDI::Sparse_cholesky normal_solver;
  HDI::factorize_or_throw(normal_solver, normal_system, "MeshTGV's normal system");

  // W subproblem, per normal component k (w^k_f: row k of W_f, 3 unknowns per face):
  // (r G^T G + r E^T E + epsilon) w^k = r G^T (D N - P - lambda_1 / r)_k + r E^T (Q + lambda_2 / r)_k.
  triplets.clear();
  for(const auto& e : edges)
  {
    // G: (w_f + w_g) . d / 2; E: w_g - w_f, per coordinate.
    const Eigen::Matrix3d dd = 0.25 * r * e.d * e.d.transpose();
    for(int a = 0; a < 3; ++a)
      for(int b = 0; b < 3; ++b)
        for(std::size_t x : {e.f, e.g})
          for(std::size_t y : {e.f, e.g})
            triplets.emplace_back(Eigen::Index(3 * x + a), Eigen::Index(3 * y + b), dd(a, b));
    for(int a = 0; a < 3; ++a)
    {
      triplets.emplace_back(Eigen::Index(3 * e.f + a), Eigen::Index(3 * e.f + a), r);
      triplets.emplace_back(Eigen::Index(3 * e.g + a), Eigen::Index(3 * e.g + a), r);
      triplets.emplace_back(Eigen::Index(3 * e.f + a), Eigen::Index(3 * e.g + a), -r);
      triplets.emplace_back(Eigen::Index(3 * e.g + a), Eigen::Index(3 * e.f + a), -r);
    }
  }
  for(std::size_t i = 0; i < 3 * m; ++i)
    triplets.emplace_back(Eigen::Index(i), Eigen::Index(i), 1e-8 * r);
  Eigen::SparseMatrix<double> field_system(static_cast<Eigen::Index>(3 * m), static_cast<Eigen::Index>(3 * m));
  field_system.setFromTriplets(triplets.begin(), triplets.end());
  HDI::Sparse_cholesky field_solver;
  HDI::factorize_or_throw(field_solver, field_system, "MeshTGV's field system");

  std::vector<Eigen::Vector3d> normals = fm.normals;
  std::vector<Eigen::Matrix3d> field(m, Eigen::Matrix3d::Zero());
  std::vector<Eigen::Vector3d> P(ne, Eigen::Vector3d::Zero()), lambda_1(ne, Eigen::Vector3d::Zero());
  std::vector<Eigen::Matrix3d> Q(ne, Eigen::Matrix3d::Zero()), lambda_2(ne, Eigen::Matrix3d::Zero());
  auto predicted = [&](const internal::Dual_edge& e) { return Eigen::Vector3d(0.5 * (field[e.f] + field[e.g]) * e.d); };
  Eigen::MatrixXd right(static_cast<Eigen::Index>(m), 3), field_right(static_cast<Eigen::Index>(3 * m), 3);
  for(std::size_t it = 0; it < p.iterations; ++it)
  {
    // N
    for(std::size_t f = 0; f < m; ++f)
      right.row(Eigen::Index(f)) = (fm.areas[f] / mean_area) * fm.normals[f].transpose();
    for(std::size_t k = 0; k < ne; ++k)
    {
      const auto& e = edges[k];
      const Eigen::Vector3d target = r * (predicted(e) + P[k]) + lambda_1[k];  // r (G W + P + lambda_1 / r)
      right.row(Eigen::Index(e.g)) += target.transpose();
      right.row(Eigen::Index(e.f)) -= target.transpose();
    }
    const Eigen::MatrixXd solved = normal_solver.solve(right);
    for(std::size_t f = 0; f < m; ++f)
      normals[f] = normalised_or(solved.row(Eigen::Index(f)).transpose(), normals[f]);
    // W
    field_right.setZero();
    for(std::size_t k = 0; k < ne; ++k)
    {
      const auto& e = edges[k];
      const Eigen::Vector3d jump = normals[e.g] - normals[e.f] - P[k] - lambda_1[k] / r;  // D N - P - lambda_1 / r
      const Eigen::Matrix3d target = Q[k] + lambda_2[k] / r;
      for(int c = 0; c < 3; ++c)  // normal component
        for(int a = 0; a < 3; ++a)
        {
          const double g = 0.5 * r * jump[c] * e.d[a];
          field_right(Eigen::Index(3 * e.f + a), c) += g;
          field_right(Eigen::Index(3 * e.g + a), c) += g;
          field_right(Eigen::Index(3 * e.g + a), c) += r * target(c, a);
          field_right(Eigen::Index(3 * e.f + a), c) -= r * target(c, a);
        }
    }
    const Eigen::MatrixXd field_solved = field_solver.solve(field_right);
    for(std::size_t f = 0; f < m; ++f)
      for(int c = 0; c < 3; ++c)
        for(int a = 0; a < 3; ++a)
          field[f](c, a) = field_solved(Eigen::Index(3 * f + a), c);
    // P, Q, multipliers
    for(std::size_t k = 0; k < ne; ++k)
    {
      const auto& e = edges[k];
      const Eigen::Vector3d first = normals[e.g] - normals[e.f] - predicted(e);
      P[k] = internal::shrink(first - lambda_1[k] / r, p.alpha_1 * e.length / r);
      const Eigen::Matrix3d second = field[e.g] - field[e.f];
      const Eigen::Matrix3d shifted = second - lambda_2[k] / r;
      const double norm = shifted.norm(), threshold = p.alpha_0 * e.length * e.d.norm() / r;
      Q[k] = norm > threshold ? Eigen::Matrix3d((1. - threshold / norm) * shifted) : Eigen::Matrix3d::Zero();
      lambda_1[k] += r * (P[k] - first);
      lambda_2[k] += r * (Q[k] - second);
    }
  }
  return normals;
}

template <typename Mesh>
void mesh_tgv(Mesh& mesh, const Mesh_tgv_parameters& p = {})
{
  if(!(p.alpha_1 > 0) || !(p.alpha_0 > 0) || !(p.penalty > 0))
    throw std::invalid_argument("mesh_tgv: the parameters must be positive");
  Face_mesh fm = make_face_mesh(mesh);
  const std::vector<Eigen::Vector3d> normals = mesh_tgv_normals(fm, p);
  update_vertices(fm, normals, p.vertex_iterations);
  write_points(fm, mesh);
}

} // namespace baselines
} // namespace test_support

#endif // CGAL_HEAT_DIFFUSION_BASELINES_MESH_TGV_H
