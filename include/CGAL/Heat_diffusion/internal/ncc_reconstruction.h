// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The least-squares positions whose NCC match a Normal Signature (eq. 23), on the
// package's one representation of a surface: a mesh's Indexed_mesh or a point set's
// (internal/point_set_surface.h).

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_NCC_RECONSTRUCTION_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_NCC_RECONSTRUCTION_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/ncc_weights.h>
#include <CGAL/Heat_diffusion/internal/sparse_cholesky.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The positions V' (n x 3, in the normalised frame of `mesh`) minimising
//   || N V' - (s n' + t) ||^2 + sum_i (w^2 / a_i) || v'_i - v_i ||^2,
// N and the tangential parts t from `data` (the current surface), s the target Normal
// Signature, n' the target normals, w the anchor weight (dividing by a_i gives both terms
// the unit of an NCC). With s the current signature and n' the current normals, V' = V.
// `where` names the caller in the errors.
inline Eigen::MatrixXd reconstruct_positions(const Indexed_mesh& mesh, const Ncc_data& data,
                                             const Eigen::VectorXd& signature,
                                             const std::vector<Eigen::Vector3d>& target_normals,
                                             double anchor_weight, const char* where)
{
  const std::size_t n = mesh.number_of_vertices();
  const Eigen::Index size = static_cast<Eigen::Index>(n);
  Eigen::MatrixXd target(size, 3), anchors(size, 3);
  Eigen::VectorXd squared_anchor_weights(size);
  for(std::size_t i = 0; i < n; ++i)
  {
    target.row(Eigen::Index(i)) = (signature[Eigen::Index(i)] * target_normals[i] + data.tangential_part[i]).transpose();
    anchors.row(Eigen::Index(i)) = mesh.points[i].transpose();
    squared_anchor_weights[Eigen::Index(i)] = anchor_weight * anchor_weight / data.areas[i];
  }
  const Eigen::SparseMatrix<double> N = ncc_operator_matrix(mesh, data);
  Eigen::SparseMatrix<double> anchor_matrix(N.rows(), N.cols());
  anchor_matrix.setIdentity();
  anchor_matrix.diagonal() = squared_anchor_weights;
  const Eigen::SparseMatrix<double> normal_matrix = Eigen::SparseMatrix<double>(N.transpose() * N) + anchor_matrix;
  Sparse_cholesky cholesky;
  factorize_or_throw(cholesky, normal_matrix, "the reconstruction system N^T N + W^2");
  const Eigen::MatrixXd rhs = N.transpose() * target + squared_anchor_weights.asDiagonal() * anchors;
  Eigen::MatrixXd solution = cholesky.solve(rhs);
  if(cholesky.info() != Eigen::Success || !solution.allFinite())
    throw std::runtime_error(std::string("CGAL::Heat_diffusion: ") + where + ": the solve failed");
  return solution;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_NCC_RECONSTRUCTION_H
