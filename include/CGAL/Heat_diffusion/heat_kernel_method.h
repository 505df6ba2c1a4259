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
  /// rational approximation of the matrix exponential (three complex poles, one patch
  /// and one factorisation per cluster of 32 sources), with no eigenpairs and no
  /// truncation of the spectrum: relative error below \f$ 10^{-4} \f$ for t in [0.5, 4]
  /// on CGAL's fandisk and armadillo, where building \f$ A_t \f$ this way is 1.1 to 9.5
  /// times faster than the spectral path, eigen solve included (see the user manual). The right choice
  /// for small t, where the truncated kernel is too flat.
  local
};

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_HEAT_KERNEL_METHOD_H
