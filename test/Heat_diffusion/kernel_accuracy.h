// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The measures of the local kernel's accuracy budget, shared by test_local_heat_kernel
// and benchmark_kernel_accuracy: how much of each kernel column the heat regions leave
// out, and how far the columns of one A_t lie from another's.

#ifndef CGAL_HEAT_DIFFUSION_TEST_KERNEL_ACCURACY_H
#define CGAL_HEAT_DIFFUSION_TEST_KERNEL_ACCURACY_H

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/internal/heat_operators.h>
#include <CGAL/Heat_diffusion/internal/local_heat_kernel.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace kernel_accuracy {

// The reference kernel's tolerance: the tightest that the heat balance of its
// single-precision substitutions (rounding up to 5e-7) can check.
constexpr double reference_tolerance = 2e-6;
// The local kernel's earlier default tolerance (three poles), kept reachable.
constexpr double previous_tolerance = 1e-4;

struct Summary
{
  double mean = 0, percentile_99 = 0, largest = 0;
};

inline Summary summarize(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  Summary s;
  for(double v : values)
    s.mean += v;
  s.mean /= double(values.size());
  s.percentile_99 = values[(std::min)(values.size() - 1, std::size_t(0.99 * double(values.size())))];
  s.largest = values.back();
  return s;
}

// The part of the reference kernel's columns that their heat regions leave out:
// sum_{i not in R_j} m_i |h_ij| / sum_i m_i |h_ij| (m: the lumped mass), over every
// `stride`-th source. `columns` is A_t normalised by columns (Operator_normalization::
// columns) from the local kernel, whose column patterns are the heat regions.
template <typename Diffusion>
Summary heat_outside_regions(const Diffusion& columns, std::size_t stride = 8)
{
  namespace HD = CGAL::Heat_diffusion;
  const HD::internal::Indexed_mesh& mesh = columns.normal_controlled_coordinates().indexed_mesh();
  const HD::internal::Heat_operators operators =
      HD::internal::assemble_heat_operators(mesh, columns.normal_controlled_coordinates().data(), columns.sigma());
  const HD::internal::Local_heat_kernel kernel(mesh, operators.stiffness, operators.mass, columns.time(),
                                               reference_tolerance);
  const Eigen::VectorXd lumped = operators.mass * Eigen::VectorXd::Ones(operators.mass.cols());
  const Eigen::SparseMatrix<double>& A = columns.operator_matrix();
  auto workspace = kernel.make_workspace();
  std::vector<double> outside;
  std::vector<unsigned char> in_region(mesh.number_of_vertices(), 0);
  const std::vector<std::size_t>& order = kernel.source_order();
  for(std::size_t s = 0; s < order.size(); s += stride)
  {
    const std::size_t j = order[s];
    kernel.compute_column(j, workspace);
    for(Eigen::SparseMatrix<double>::InnerIterator it(A, Eigen::Index(j)); it; ++it)
      in_region[std::size_t(it.row())] = 1;
    double total = 0, inside = 0;
    for(std::uint32_t i : HD::internal::Local_heat_kernel::patch(workspace))
    {
      const double heat = lumped[Eigen::Index(i)] * std::abs(HD::internal::Local_heat_kernel::value(workspace, i));
      total += heat;
      if(in_region[i])
        inside += heat;
    }
    for(Eigen::SparseMatrix<double>::InnerIterator it(A, Eigen::Index(j)); it; ++it)
      in_region[std::size_t(it.row())] = 0;
    outside.push_back(1. - inside / total);
  }
  return summarize(outside);
}

// ||a_j - r_j||_1 / ||r_j||_1 over the columns j of A and of the reference R.
inline Summary column_distances(const Eigen::SparseMatrix<double>& A, const Eigen::SparseMatrix<double>& R)
{
  const Eigen::SparseMatrix<double> difference = A - R;
  std::vector<double> distance;
  for(Eigen::Index j = 0; j < A.cols(); ++j)
  {
    double d = 0, r = 0;
    for(Eigen::SparseMatrix<double>::InnerIterator it(difference, j); it; ++it)
      d += std::abs(it.value());
    for(Eigen::SparseMatrix<double>::InnerIterator it(R, j); it; ++it)
      r += std::abs(it.value());
    distance.push_back(d / r);
  }
  return summarize(distance);
}

} // namespace kernel_accuracy

#endif // CGAL_HEAT_DIFFUSION_TEST_KERNEL_ACCURACY_H
