// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A_t as the diffusion keeps it and applies it: the kernel values on the heat regions,
// normalised by columns (the paper) or balanced to be doubly stochastic.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DIFFUSION_OPERATOR_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DIFFUSION_OPERATOR_H

#include <CGAL/Heat_diffusion/internal/Column_group_matrix.h>
#include <CGAL/Heat_diffusion/internal/progress.h>
#include <CGAL/Heat_diffusion/internal/symmetric_balancing.h>
#include <CGAL/Heat_diffusion/operator_normalization.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <cstddef>
#include <utility>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// With Operator_normalization::columns, `kernel_matrix()` is A_t itself (each column
// divided by its sum); with Operator_normalization::balanced, it is the matrix H of the
// kernel values, K = (H + H^T) / 2, and A_t = D K D + diag(c) once balance() has found
// the scaling D and the correction c.
class Diffusion_operator
{
public:
  typedef Eigen::SparseMatrix<double> Sparse_matrix;

  // The scratch of one product with A_t (see Column_group_matrix).
  struct Product_scratch
  {
    Eigen::VectorXd partial, gathered;
  };

  explicit Diffusion_operator(Operator_normalization normalization = Operator_normalization::balanced)
    : normalization_(normalization)
  {}

  Operator_normalization normalization() const { return normalization_; }
  bool is_balanced() const { return normalization_ == Operator_normalization::balanced; }
  // The stored kernel values (internal::build_heat_regions() fills them).
  Column_group_matrix& kernel_matrix() { return matrix_; }
  // The number of products with K that the balancing took (0 by columns).
  std::size_t balancing_iterations() const { return balancing_iterations_; }

  Product_scratch make_scratch() const
  {
    const Eigen::Index group_rows = Eigen::Index(matrix_.number_of_group_rows());
    return Product_scratch{Eigen::VectorXd(group_rows), Eigen::VectorXd(is_balanced() ? group_rows : 0)};
  }

  // next = A_t current
  void apply(const Eigen::VectorXd& current, Eigen::VectorXd& next, Product_scratch& scratch) const
  {
    if(is_balanced())
      matrix_.multiply_symmetric_part(current, next, scaling_, correction_, scratch.partial, scratch.gathered);
    else
      matrix_.multiply(current, next, scratch.partial);
  }

  // A_t in compressed columns: the stored matrix itself (columns), or
  // D ((K + K^T) / 2) D + diag(c) made of the stored kernel matrix K (balanced).
  Sparse_matrix column_major() const
  {
    Sparse_matrix kernel = matrix_.column_major();
    if(!is_balanced())
      return kernel;
    const Sparse_matrix transposed = kernel.transpose();
    Sparse_matrix result = 0.5 * (kernel + transposed);
    for(Eigen::Index j = 0; j < result.outerSize(); ++j)
      for(Sparse_matrix::InnerIterator it(result, j); it; ++it)
      {
        it.valueRef() = scaling_[it.row()] * it.value() * scaling_[j];
        if(it.row() == j)
          it.valueRef() += correction_[j];
      }
    return result;
  }

  // Balances the kernel matrix K (see Operator_normalization::balanced) until
  // max_i |(D K D 1)_i - 1| <= tolerance. `column_sums` are those of the kernel values H
  // (K = (H + H^T) / 2): the regions are nearly symmetric, so they are nearly K's row
  // sums, and S^(-1/2) is nearly the first, undamped step of the iteration, without its
  // product. `peaks` are the diagonal of K.
  void balance(const Eigen::VectorXd& column_sums, const Eigen::VectorXd& peaks, double tolerance,
               std::size_t maximum_iterations, const Progress& progress)
  {
    progress.report(0., "the balancing of A_t");
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(column_sums.size()), none;
    Product_scratch scratch = make_scratch();
    Symmetric_balancing balancing = balance_symmetric_matrix(
        column_sums.cwiseSqrt().cwiseInverse(), peaks,
        [&](const Eigen::VectorXd& d, Eigen::VectorXd& row_sums) {
          matrix_.multiply_symmetric_part(ones, row_sums, d, none, scratch.partial, scratch.gathered);
        },
        tolerance, maximum_iterations);
    scaling_ = std::move(balancing.scaling);
    correction_ = std::move(balancing.correction);
    balancing_iterations_ = balancing.iterations;
    progress.report(1., "the balancing of A_t");
  }

private:
  Operator_normalization normalization_;
  Column_group_matrix matrix_;            // A_t (columns), or the kernel values H (balanced)
  Eigen::VectorXd scaling_, correction_;  // balanced: A_t = D ((H + H^T) / 2) D + diag(correction)
  std::size_t balancing_iterations_ = 0;
};

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DIFFUSION_OPERATOR_H
