// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// How Anisotropic_heat_diffusion turns the heat kernel into the diffusion operator.

#ifndef CGAL_HEAT_DIFFUSION_OPERATOR_NORMALIZATION_H
#define CGAL_HEAT_DIFFUSION_OPERATOR_NORMALIZATION_H

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionDiffusion
/// How `Anisotropic_heat_diffusion` makes the operator \f$ A_t \f$ from the heat kernel
/// values on the heat regions (the named parameter `operator_normalization`).
enum class Operator_normalization
{
  /// The default: the symmetric kernel matrix \f$ K \f$ on the symmetrised regions
  /// (\f$ K_{ij} \f$ is the mean of \f$ h_t(j, i) \f$ where \f$ i \in \Omega_j \f$ and of
  /// \f$ h_t(i, j) \f$ where \f$ j \in \Omega_i \f$, each taken as 0 where the region does not
  /// hold it), balanced: \f$ A_t = D K D \f$ with \f$ D \f$ diagonal and positive, so that
  /// every row and every column sums to 1. \f$ A_t \f$ is nonnegative, symmetric and doubly
  /// stochastic: the vertex sum of the heat is conserved, a constant field stays constant,
  /// every step is a convex combination of the old values (maximum principle), diffusion
  /// commutes with adding a constant, and no vertex is a sink.
  balanced,
  /// The paper's operator (eq. 16-18, with the sum over \f$ \Omega_j \f$ that conservation
  /// requires): \f$ A_t(i, j) = h_t(j, i) / \sum_{k \in \Omega_j} h_t(j, k) \f$. Every column
  /// sums to 1, so the vertex sum of the heat is conserved, but the rows do not: a
  /// constant field does not stay constant (on fandisk with `sigma` = 0.1, a field of
  /// ones spans [0.76, 1.22] after one step and grows spikes at vertices whose region
  /// collapsed, which receive heat and give none back). For reproducing the paper.
  columns
};

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_OPERATOR_NORMALIZATION_H
