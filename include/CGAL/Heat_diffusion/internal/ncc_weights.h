// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_NCC_WEIGHTS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_NCC_WEIGHTS_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/parallel_for.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Everything the NCC operator (paper, eq. 6) is made of, in the normalised frame.
struct Ncc_data
{
  std::vector<double> weights;           // omega_ij, aligned with Indexed_mesh::fan; sum to 1 per vertex
  std::vector<double> areas;             // mixed Voronoi areas a_i
  std::vector<Eigen::Vector3d> normals;  // unit vertex normals n_i
  std::vector<double> signature;         // NS s_i; the NCC is s_i n_i
  std::vector<Eigen::Vector3d> tangential_part;  // of row i of N V: boundary and uniform-weight vertices, else rounding
};

// The mixed Voronoi areas of Meyer, Desbrun, Schroeder and Barr (2002) of the three
// corners of the triangle (p0, p1, p2): the Voronoi region inside a non-obtuse
// triangle, the midpoint rule inside an obtuse one. They sum to its area.
inline std::array<double, 3> mixed_voronoi_corner_areas(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                                        const Eigen::Vector3d& p2)
{
  const Eigen::Vector3d e0 = p2 - p1, e1 = p0 - p2, e2 = p1 - p0;  // e_k opposite to vertex k
  const double double_area = e0.cross(e1).norm();
  const double area = 0.5 * double_area;
  // cot of the angle at vertex k, from the two edges that meet there
  const double d0 = -e1.dot(e2), d1 = -e2.dot(e0), d2 = -e0.dot(e1);
  if(d0 < 0 || d1 < 0 || d2 < 0)
    return {d0 < 0 ? 0.5 * area : 0.25 * area, d1 < 0 ? 0.5 * area : 0.25 * area,
            d2 < 0 ? 0.5 * area : 0.25 * area};
  const double cot0 = d0 / double_area, cot1 = d1 / double_area, cot2 = d2 / double_area;
  return {(e1.squaredNorm() * cot1 + e2.squaredNorm() * cot2) / 8.,
          (e2.squaredNorm() * cot2 + e0.squaredNorm() * cot0) / 8.,
          (e0.squaredNorm() * cot0 + e1.squaredNorm() * cot1) / 8.};
}

// Mixed Voronoi areas of the vertices. They sum to the total area, and are positive
// since no face has zero area.
inline std::vector<double> mixed_voronoi_areas(const Indexed_mesh& mesh)
{
  std::vector<double> areas(mesh.number_of_vertices(), 0.);
  for(const auto& t : mesh.triangles)
  {
    const std::array<double, 3> corner =
        mixed_voronoi_corner_areas(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    for(int k = 0; k < 3; ++k)
      areas[t[k]] += corner[k];
  }
  return areas;
}

// The normalised NCC weights omega_ij of one vertex (paper, eq. 3), written to
// `weights` (size = degree).
//
// Mean value weights of the neighbours projected onto the tangent plane, with
// signed angles (orientation given by the normal) so that folded fans keep their
// meaning. On an interior vertex they reproduce linear functions of the tangent
// plane, which is what makes the differential coordinate parallel to the normal
// (paper, appendix). An open (boundary) fan has one angle less. Where the mean
// value weights are undefined (a neighbour projecting onto the vertex, or weights
// that nearly cancel on a badly folded fan), uniform weights are used instead. A
// fan folded over the vertex has a negative sum of weights; normalised, the
// weights keep their linear precision, so only a sum close to 0 is rejected.
inline void ncc_weights(const Indexed_mesh& mesh, std::size_t i, const Eigen::Vector3d& n, double* weights)
{
  const std::size_t begin = mesh.fan_begin[i], d = mesh.degree(i);
  const bool closed = mesh.fan_is_closed[i] != 0;

  // Tangent-plane projections of the edges, in an orthonormal basis (t1, t2) of the plane.
  const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  Eigen::Matrix<double, 2, Eigen::Dynamic> q(2, d);
  for(std::size_t k = 0; k < d; ++k)
  {
    const Eigen::Vector3d e = mesh.points[mesh.fan[begin + k]] - mesh.points[i];
    q(0, k) = e.dot(t1);
    q(1, k) = e.dot(t2);
  }

  // tan(alpha_k / 2) for the angle between q_k and q_k+1, signed positive for the
  // orientation of a well-shaped fan: the triangle (u_k, v, u_k+1) turns clockwise
  // around n seen from v, i.e. cross(q_k+1, q_k) points along +n (= t1 x t2).
  const std::size_t number_of_angles = closed ? d : d - 1;
  Eigen::VectorXd tan_half(number_of_angles);
  for(std::size_t k = 0; k < number_of_angles; ++k)
  {
    const Eigen::Vector2d a = q.col(k), b = q.col((k + 1) % d);
    const double sine = b.x() * a.y() - b.y() * a.x();
    tan_half[k] = sine / (a.norm() * b.norm() + a.dot(b));
  }
  Eigen::Map<Eigen::VectorXd> w(weights, Eigen::Index(d));
  for(std::size_t k = 0; k < d; ++k)
  {
    double sum = 0;
    if(k < number_of_angles)
      sum += tan_half[k];
    if(closed || k > 0)
      sum += tan_half[(k + d - 1) % d];
    w[k] = sum / q.col(k).norm();
  }
  if(!w.allFinite() || !(std::abs(w.sum()) > 0.1 * w.cwiseAbs().sum()))
    w.setConstant(1.);
  w /= w.sum();
}

// Weights, areas and NCC of every vertex. Parallel over vertices.
//
// The differential coordinate r_i = sum_j omega_ij (v_i - v_j) / sqrt(a_i) (a row
// of N V) is parallel to n_i on interior vertices up to rounding. On boundary
// vertices it has a tangential part: the NCC is its normal component
// (s_i n_i, s_i = r_i . n_i), and the tangential part is kept aside so that the
// reconstruction can hold it fixed (it is local parameterisation, not shape).
//
// `areas` are the a_i; a mesh's are its mixed_voronoi_areas(), a point set's those of
// each point's own fan (internal/point_set_surface.h).
inline Ncc_data compute_ncc_data(const Indexed_mesh& mesh, std::vector<Eigen::Vector3d> normals,
                                 std::vector<double> areas)
{
  const std::size_t n = mesh.number_of_vertices();
  Ncc_data data;
  data.areas = std::move(areas);
  data.normals = std::move(normals);
  data.weights.assign(mesh.fan.size(), 0.);
  data.signature.assign(n, 0.);
  data.tangential_part.assign(n, Eigen::Vector3d::Zero());
  parallel_for(n, [&](std::size_t i) {
    double* w = data.weights.data() + mesh.fan_begin[i];
    ncc_weights(mesh, i, data.normals[i], w);
    // summed from edge vectors for accuracy
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    for(std::size_t k = 0; k < mesh.degree(i); ++k)
      r -= w[k] * (mesh.points[mesh.fan[mesh.fan_begin[i] + k]] - mesh.points[i]);
    r /= std::sqrt(data.areas[i]);
    data.signature[i] = r.dot(data.normals[i]);
    data.tangential_part[i] = r - data.signature[i] * data.normals[i];
  });
  return data;
}

inline Ncc_data compute_ncc_data(const Indexed_mesh& mesh, std::vector<Eigen::Vector3d> normals)
{
  return compute_ncc_data(mesh, std::move(normals), mixed_voronoi_areas(mesh));
}

// N in the normalised frame of `mesh`: N_ii = a_i^(-1/2), N_ij = -omega_ij a_i^(-1/2)
// over mesh.fan (a point set's weights are 0 at the graph neighbours outside the point's
// own fan), so that N V = s n + tangential part, row by row.
inline Eigen::SparseMatrix<double> ncc_operator_matrix(const Indexed_mesh& mesh, const Ncc_data& data)
{
  const std::size_t n = mesh.number_of_vertices();
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(mesh.fan.size() + n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const double inverse_root_area = 1. / std::sqrt(data.areas[i]);
    entries.emplace_back(int(i), int(i), inverse_root_area);
    for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
      entries.emplace_back(int(i), int(mesh.fan[k]), -data.weights[k] * inverse_root_area);
  }
  Eigen::SparseMatrix<double> N(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  N.setFromTriplets(entries.begin(), entries.end());
  return N;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_NCC_WEIGHTS_H
