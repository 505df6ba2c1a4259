// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Mesh denoising via L0 minimization (He and Schaefer, SIGGRAPH 2013), a baseline of the
// denoising benchmark, written from the paper: the vertices p minimise
//   |p - p*|^2 + alpha |R p|^2 + lambda |D p|_0,
// p* the noisy input, D the paper's edge-based operator (one 3-vector per interior edge,
// zero where the edge's two triangles are coplanar), |.|_0 the number of edges where it
// is not zero, R the regularisation that keeps the triangles from degenerating. The L0
// term is handled by the paper's alternating optimisation with an auxiliary delta per
// edge: for fixed p, delta_e = (D p)_e where |(D p)_e|^2 >= lambda / beta, else 0 (the
// closed form of the subproblem); for fixed delta,
//   (I + alpha R^T R + beta D^T D) p = p* + beta D^T delta,
// one sparse system for the three coordinates. beta grows from beta_0 = 1e-3 by a factor
// kappa = sqrt(2) up to beta_max = 1e3 (40 rounds), alpha is halved every round. The
// paper's automatic parameters: lambda = 0.02 l^2 gamma and alpha_0 = 0.1 gamma, l the
// mean edge length and gamma the mean dihedral angle (the angle between the normals of
// the two triangles of an interior edge) of the noisy input, in degrees: in radians,
// lambda is so small that fandisk with 0.3 mean edge length of noise along the normals
// keeps 26.3 of its 28.7 degrees of MAD (5.1 in degrees; benchmark_denoising's seeds).

#ifndef CGAL_HEAT_DIFFUSION_BASELINES_L0_MINIMIZATION_H
#define CGAL_HEAT_DIFFUSION_BASELINES_L0_MINIMIZATION_H

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

struct L0_parameters
{
  double beta_0 = 1e-3, beta_max = 1e3, kappa = std::sqrt(2.);
  // The factors of the automatic lambda and alpha_0 (see above).
  double lambda_factor = 0.02, alpha_factor = 0.1;
};

// An interior edge p1 p3 with the opposite vertices p2 and p4 of its two triangles.
struct L0_edge
{
  std::array<std::size_t, 4> vertices;  // p1, p2, p3, p4
};

inline std::vector<L0_edge> interior_edges(const Face_mesh& fm)
{
  // The opposite vertex of each triangle side, keyed by the side's sorted vertices.
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::pair<std::size_t, std::size_t> > > sides;
  for(std::size_t f = 0; f < fm.triangles.size(); ++f)
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t a = fm.triangles[f][k], b = fm.triangles[f][(k + 1) % 3], c = fm.triangles[f][(k + 2) % 3];
      sides[std::minmax(a, b)].push_back({c, f});
    }
  std::vector<L0_edge> edges;
  for(const auto& side : sides)
    if(side.second.size() == 2)
      edges.push_back(L0_edge{{side.first.first, side.second[0].first, side.first.second, side.second[1].first}});
  return edges;
}

// The coefficients of the edge-based operator for triangles p1 p2 p3 and p1 p3 p4, from
// the areas S_123, S_134 of the triangles and the edge length l = |p3 - p1|:
//   ((S_123 (p4 - p3).(p3 - p1) + S_134 (p1 - p3).(p3 - p2)) / (l^2 (S_123 + S_134)),
//    S_134 / (S_123 + S_134),
//    (S_123 (p3 - p1).(p1 - p4) + S_134 (p2 - p1).(p1 - p3)) / (l^2 (S_123 + S_134)),
//    S_123 / (S_123 + S_134)).
// They sum to 0, and the combination of the four points vanishes when they are
// coplanar: the operator measures how far the edge is from flat.
inline std::array<double, 4> l0_edge_coefficients(const std::array<Eigen::Vector3d, 4>& p)
{
  const double s123 = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
  const double s134 = 0.5 * (p[2] - p[0]).cross(p[3] - p[0]).norm();
  const double l2 = (p[2] - p[0]).squaredNorm();
  const double denominator = l2 * (s123 + s134);
  if(!(denominator > 0))
    return {0., 0., 0., 0.};
  return {(s123 * (p[3] - p[2]).dot(p[2] - p[0]) + s134 * (p[0] - p[2]).dot(p[2] - p[1])) / denominator,
          s134 / (s123 + s134),
          (s123 * (p[2] - p[0]).dot(p[0] - p[3]) + s134 * (p[1] - p[0]).dot(p[0] - p[2])) / denominator,
          s123 / (s123 + s134)};
}

// Denoises `fm.points` in place. The operator's coefficients are those of the noisy
// input, fixed for the whole optimisation (the system's matrix then keeps its pattern:
// one symbolic factorisation, one numerical factorisation per round). Returns the number
// of rounds.
inline std::size_t l0_minimization(Face_mesh& fm, const L0_parameters& parameters = L0_parameters())
{
  namespace HDI = CGAL::Heat_diffusion::internal;
  const std::size_t n = fm.points.size();
  const std::vector<L0_edge> edges = interior_edges(fm);
  if(n == 0 || edges.empty())
    return 0;
  fm.update_geometry();
  // The mean edge length and the mean dihedral angle of the input.
  double length_sum = 0, angle_sum = 0;
  for(const L0_edge& e : edges)
  {
    const std::array<Eigen::Vector3d, 4> p = {fm.points[e.vertices[0]], fm.points[e.vertices[1]],
                                              fm.points[e.vertices[2]], fm.points[e.vertices[3]]};
    length_sum += (p[2] - p[0]).norm();
    const Eigen::Vector3d n1 = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    const Eigen::Vector3d n2 = (p[2] - p[0]).cross(p[3] - p[0]).normalized();
    // p2 and p4 lie on either side of p1 p3: the triangles p1 p2 p3 and p1 p3 p4 have
    // the same orientation, and equal normals where the edge is flat.
    const double c = (std::max)(-1., (std::min)(1., n1.dot(n2)));
    if(std::isfinite(c))
      angle_sum += std::acos(c);
  }
  const double mean_length = length_sum / double(edges.size());
  const double gamma = angle_sum / double(edges.size()) * (180. / 3.14159265358979323846);
  const double lambda = parameters.lambda_factor * mean_length * mean_length * gamma;
  double alpha = parameters.alpha_factor * gamma;

  typedef Eigen::SparseMatrix<double> Matrix;
  std::vector<Eigen::Triplet<double> > d_entries, r_entries;
  for(std::size_t k = 0; k < edges.size(); ++k)
  {
    const L0_edge& e = edges[k];
    const std::array<double, 4> c = l0_edge_coefficients({fm.points[e.vertices[0]], fm.points[e.vertices[1]],
                                                          fm.points[e.vertices[2]], fm.points[e.vertices[3]]});
    for(std::size_t j = 0; j < 4; ++j)
    {
      d_entries.emplace_back(Eigen::Index(k), Eigen::Index(e.vertices[j]), c[j]);
      r_entries.emplace_back(Eigen::Index(k), Eigen::Index(e.vertices[j]), j % 2 == 0 ? 1. : -1.);
    }
  }
  Matrix d(Eigen::Index(edges.size()), Eigen::Index(n)), r(Eigen::Index(edges.size()), Eigen::Index(n));
  d.setFromTriplets(d_entries.begin(), d_entries.end());
  r.setFromTriplets(r_entries.begin(), r_entries.end());
  const Matrix dtd = Matrix(d.transpose() * d), rtr = Matrix(r.transpose() * r);
  const Eigen::Index size = Eigen::Index(n);
  Matrix identity(size, size);
  identity.setIdentity();

  Eigen::MatrixXd input(Eigen::Index(n), 3), p(Eigen::Index(n), 3);
  for(std::size_t i = 0; i < n; ++i)
    input.row(Eigen::Index(i)) = fm.points[i].transpose();
  p = input;
  HDI::Sparse_cholesky cholesky;
  HDI::configure_cholesky(cholesky, Eigen::Index(n));
  std::size_t rounds = 0;
  for(double beta = parameters.beta_0; beta <= parameters.beta_max; beta *= parameters.kappa, alpha *= 0.5)
  {
    // delta: the hard threshold of D p.
    Eigen::MatrixXd delta = d * p;
    for(Eigen::Index k = 0; k < delta.rows(); ++k)
      if(delta.row(k).squaredNorm() < lambda / beta)
        delta.row(k).setZero();
    // p: the linear system.
    const Matrix system = identity + alpha * rtr + beta * dtd;
    if(rounds == 0)
      cholesky.analyzePattern(system);
    cholesky.factorize(system);
    if(cholesky.info() != Eigen::Success)
      throw std::runtime_error("l0_minimization: the factorisation failed");
    const Eigen::MatrixXd right = input + beta * (d.transpose() * delta);
    p = cholesky.solve(right);
    ++rounds;
  }
  for(std::size_t i = 0; i < n; ++i)
    fm.points[i] = p.row(Eigen::Index(i)).transpose();
  fm.update_geometry();
  return rounds;
}

} // namespace baselines
} // namespace test_support

#endif // CGAL_HEAT_DIFFUSION_BASELINES_L0_MINIMIZATION_H
