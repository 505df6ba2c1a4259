// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The construction of A_t from a heat kernel's columns, and the diffusion steps with it,
// on any Indexed_mesh layout: a mesh's (Anisotropic_heat_diffusion, both kernels) or a
// point set's (Point_set_anisotropic_heat_diffusion).

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DIFFUSION_CONSTRUCTION_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DIFFUSION_CONSTRUCTION_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/diffusion_operator.h>
#include <CGAL/Heat_diffusion/internal/heat_operators.h>
#include <CGAL/Heat_diffusion/internal/heat_regions.h>
#include <CGAL/Heat_diffusion/internal/kernel_columns.h>
#include <CGAL/Heat_diffusion/internal/local_heat_kernel.h>
#include <CGAL/Heat_diffusion/internal/progress.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The groups of sources of the spectral kernels (which share no work): enough columns
// for a group's rows to be few per column.
constexpr std::size_t spectral_group_size = 64;

// The balancing stops at max_i |(D K D 1)_i - 1| <= balancing_tolerance; the correction
// of the diagonal then makes the sums 1 to rounding. The tolerance only bounds how far
// A_t is from D K D exactly: at most the local kernel's own error (1e-2 by default, 1e-4
// at the earlier default), and the balancing's products are a few per cent of the
// construction of A_t at any size.
constexpr double balancing_tolerance = 1e-4;
constexpr std::size_t maximum_balancing_iterations = 1000;

struct Diffusion_construction_options
{
  double threshold;                        // tau(t)
  std::size_t maximum_region_size;         // regions stop growing at this many vertices
  double local_kernel_tolerance;           // of Local_heat_kernel
  std::size_t group_size = spectral_group_size;  // the groups of sources without a kernel's own grouping
  double balancing_tolerance = internal::balancing_tolerance;  // at which the balancing stops
  std::size_t maximum_balancing_iterations = internal::maximum_balancing_iterations;
};

// The heat regions and the kernel values on them (build_heat_regions()), into the
// operator's kernel matrix.
template <typename Columns, typename Statistics>
void compute_heat_regions(const Columns& columns, const Indexed_mesh& mesh, const std::vector<std::size_t>& order,
                          const std::vector<std::size_t>& group_begin, const Diffusion_construction_options& options,
                          const Progress& progress, Diffusion_operator& diffusion_operator, Statistics& statistics,
                          Eigen::VectorXd& column_sums, Eigen::VectorXd& peaks)
{
  const bool balanced = diffusion_operator.is_balanced();
  const Heat_region_options region_options{options.threshold, options.maximum_region_size, !balanced,
                                           options.group_size};
  // (the balancing takes a few products with K: a small part of the whole)
  build_heat_regions(columns, mesh, order, group_begin, region_options, balanced ? progress.part(0., 0.95) : progress,
                     diffusion_operator.kernel_matrix(), statistics, column_sums, peaks);
}

// A_t from the kernel values: their matrix made ready for products and, balanced,
// balanced.
inline void complete_diffusion_operator(const Eigen::VectorXd& column_sums, const Eigen::VectorXd& peaks,
                                        const Diffusion_construction_options& options, const Progress& progress,
                                        Diffusion_operator& diffusion_operator)
{
  diffusion_operator.kernel_matrix().finish();
  if(diffusion_operator.is_balanced())
    diffusion_operator.balance(column_sums, peaks, options.balancing_tolerance, options.maximum_balancing_iterations,
                               progress.part(0.95, 1.));
}

// A_t of the local kernel at time t on L and B.
// (takes the operators: L and B live only while the kernel's columns are computed, and
// are freed, with the kernel, before A_t is completed: A_t is all the diffusion needs)
template <typename Statistics>
void build_local_diffusion_operator(const Indexed_mesh& mesh, Heat_operators operators, double t,
                                    const Diffusion_construction_options& options, const Progress& progress,
                                    Diffusion_operator& diffusion_operator, Statistics& statistics)
{
  Eigen::VectorXd column_sums, peaks;
  {
    const Local_heat_kernel kernel(mesh, operators.stiffness, operators.mass, t, options.local_kernel_tolerance);
    // Sources cluster after cluster: consecutive sources share their patch and its
    // factorisations.
    compute_heat_regions(Local_columns{kernel}, mesh, kernel.source_order(), kernel.cluster_begin(), options,
                         progress, diffusion_operator, statistics, column_sums, peaks);
  }
  // (swapped with empty matrices: an assignment would keep their memory)
  Eigen::SparseMatrix<double>().swap(operators.stiffness);
  Eigen::SparseMatrix<double>().swap(operators.mass);
  complete_diffusion_operator(column_sums, peaks, options, progress, diffusion_operator);
}

// The fields F^k = A_t^k F^0 for every k of `steps` (in any order), in one pass.
inline std::vector<Eigen::VectorXd> diffuse_steps(const Diffusion_operator& diffusion_operator,
                                                  const Eigen::VectorXd& field, const std::vector<std::size_t>& steps,
                                                  const Progress& progress)
{
  std::vector<Eigen::VectorXd> result(steps.size());
  const std::size_t last = steps.empty() ? 0 : *std::max_element(steps.begin(), steps.end());
  Eigen::VectorXd current = field, next(field.size());
  Diffusion_operator::Product_scratch scratch = diffusion_operator.make_scratch();
  for(std::size_t k = 0;; ++k)
  {
    for(std::size_t s = 0; s < steps.size(); ++s)
      if(steps[s] == k)
        result[s] = current;
    if(k == last)
      break;
    diffusion_operator.apply(current, next, scratch);
    current.swap(next);
    progress.report(double(k + 1) / double(last), "the diffusion");
  }
  return result;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DIFFUSION_CONSTRUCTION_H
