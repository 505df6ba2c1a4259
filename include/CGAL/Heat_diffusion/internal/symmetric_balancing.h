// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_SYMMETRIC_BALANCING_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_SYMMETRIC_BALANCING_H

#include <CGAL/Heat_diffusion/internal/parallel_for.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The balancing of a symmetric nonnegative matrix K with a positive diagonal: a
// positive diagonal D with D K D doubly stochastic, and the correction of the
// diagonal that makes its row sums 1 to rounding.
struct Symmetric_balancing
{
  Eigen::VectorXd scaling;     // d, the diagonal of D
  Eigen::VectorXd correction;  // c = 1 - (D K D 1): A = D K D + diag(c) sums to 1 by rows and columns
  std::size_t iterations = 0;  // products with K
  double residual = 0;         // max |(D K D 1)_i - 1| before the correction
};

// Symmetric Sinkhorn-Knopp iteration, damped: d_i <- d_i r_i^(-2/3), r = D K D 1, from
// `initial_scaling` (the undamped first step from d = 1 is d = (K 1)^(-1/2); a caller
// that knows K 1 approximately saves that product).
// Near the solution the error e of log d evolves as e <- ((1 - a) I - a P) e, with
// P = D K D and a the exponent; P's spectrum lies in [-1, 1] and, for a heat kernel
// (positive definite, large diagonal), mostly in [0, 1], where a = 2/3 contracts every
// mode at least three times per iteration (a = 1/2, the undamped symmetric iteration,
// only twice: its slow modes are the rough ones, mu near 0). The iteration stops at
// max |r_i - 1| <= tolerance, and not before the correction c = 1 - r leaves the
// diagonal d_i^2 K_ii + c_i nonnegative (a nearly flat kernel on large regions has a
// small diagonal); c makes the row sums 1 to rounding, and since A is symmetric its
// column sums too. A matrix with a positive diagonal has total support, hence a
// balancing, so the loop converges; it throws rather than loop on input that breaks
// that (a zero or non-finite row sum).
//
// `scaled_row_sums(d, r)` writes r = D K D 1 (any parallel product); every other step
// is elementwise and parallel, so the cost is that of the products.
template <typename ScaledRowSums>
Symmetric_balancing balance_symmetric_matrix(Eigen::VectorXd initial_scaling, const Eigen::VectorXd& diagonal,
                                             const ScaledRowSums& scaled_row_sums, double tolerance,
                                             std::size_t maximum_iterations)
{
  const std::size_t n = std::size_t(initial_scaling.size());
  Symmetric_balancing result;
  result.scaling = std::move(initial_scaling);
  Eigen::VectorXd& d = result.scaling;
  Eigen::VectorXd r(static_cast<Eigen::Index>(n));
  const double exponent = 2. / 3.;
  for(;;)
  {
    scaled_row_sums(d, r);
    ++result.iterations;
    double worst = 0;
    bool nonnegative = true;
    for(Eigen::Index i = 0; i < r.size(); ++i)
    {
      if(!(r[i] > 0) || !std::isfinite(r[i]))
        throw std::runtime_error("CGAL::Heat_diffusion: the balancing of A_t met a row with sum " +
                                 std::to_string(r[i]) + " at vertex " + std::to_string(i));
      worst = (std::max)(worst, std::abs(r[i] - 1.));
      nonnegative = nonnegative && d[i] * d[i] * diagonal[i] + (1. - r[i]) >= 0;
    }
    result.residual = worst;
    if(worst <= tolerance && nonnegative)
      break;
    if(result.iterations >= maximum_iterations)
      throw std::runtime_error("CGAL::Heat_diffusion: the balancing of A_t did not converge in " +
                               std::to_string(maximum_iterations) + " iterations (residual " + std::to_string(worst) +
                               ")");
    parallel_for(n, [&](std::size_t i) { d[Eigen::Index(i)] *= std::pow(r[Eigen::Index(i)], -exponent); });
  }
  result.correction = Eigen::VectorXd::Ones(Eigen::Index(n)) - r;
  return result;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_SYMMETRIC_BALANCING_H
