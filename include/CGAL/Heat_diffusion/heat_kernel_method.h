// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The choice of the heat kernel behind Anisotropic_heat_diffusion.

#ifndef CGAL_HEAT_DIFFUSION_HEAT_KERNEL_METHOD_H
#define CGAL_HEAT_DIFFUSION_HEAT_KERNEL_METHOD_H

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionDiffusion
/// How `Anisotropic_heat_diffusion` evaluates the edge-weighted heat kernel
/// \f$ h_t = \exp(-t B^{-1} L) B^{-1} \f$ that its heat regions and \f$ A_t \f$ are made of
/// (the named parameter `kernel_method`).
enum class Heat_kernel_method
{
  /// The paper's kernel (eq. 20): the m smallest generalized eigenpairs, computed once
  /// by `Edge_weighted_heat_kernel`. Accurate only for
  /// \f$ t \gtrsim 4\ln 10/\lambda_m \f$ (about 18 on fandisk and 74 on armadillo with
  /// m = 150); the right choice for large t, and the one that gives the heat kernel
  /// signature and the global smoothing.
  spectral,
  /// Each column \f$ h_t(\cdot, j) \f$ computed on a patch grown around \f$ v_j \f$ by a
  /// Lanczos approximation of the matrix exponential, with no eigenpairs and no
  /// truncation of the spectrum: relative error below \f$ 10^{-3} \f$ at any t (measured
  /// \f$ 2 \cdot 10^{-4} \f$ and below for t in [0.5, 4]), at a cost per vertex that grows
  /// like \f$ t^{3/2} \f$. The right choice for small t, where the truncated kernel is
  /// too flat (see the user manual).
  local
};

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_HEAT_KERNEL_METHOD_H
