// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The choice of the heat kernel behind Anisotropic_heat_diffusion.

#ifndef CGAL_HEAT_DIFFUSION_HEAT_KERNEL_METHOD_H
#define CGAL_HEAT_DIFFUSION_HEAT_KERNEL_METHOD_H

#include <CGAL/Heat_diffusion/parameters.h>

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
  /// \f$ t \gtrsim 4\ln 10/\lambda_m \f$ (with m = 150: 18 on fandisk and 75 on armadillo
  /// with `sigma` = 1, 178 and 1015 with `sigma` = 0.1); the right choice for large t, and
  /// the one that gives the heat kernel signature and the global smoothing.
  spectral,
  /// Each column \f$ h_t(\cdot, j) \f$ computed on a patch grown around \f$ v_j \f$ by a
  /// rational approximation of the matrix exponential (two complex poles at the default
  /// `local_kernel_tolerance`, three below about 5e-4; one patch and one factorisation per pole
  /// and cluster of 96 sources), with no eigenpairs and no truncation of the spectrum:
  /// relative error of a column below \f$ 10^{-2} \f$ (\f$ 10^{-4} \f$ with
  /// `local_kernel_tolerance(1e-4)`) for t in [0.5, 4] on CGAL's fandisk and armadillo,
  /// where building \f$ A_t \f$ this way is faster than the spectral path, eigen solve
  /// included (the user manual gives the measured times and the accuracy budget).
  /// The right choice for small t, where the truncated kernel is too flat.
  local,
  /// The default: `spectral` when the eigenpairs are asked for (the named parameter
  /// `number_of_eigenpairs` or `coarse_vertex_count` is given, or
  /// `scale_invariant_kernel(true)`, which needs the eigenvalues), `local` otherwise.
  /// The local kernel is the more accurate: its error was below \f$ 10^{-4} \f$ at every t
  /// measured (0.5 to 4), while the truncated kernel is accurate only from
  /// \f$ t \approx 4\ln 10/\lambda_m \f$ on, which was 0.35 to 0.43 n/m with `sigma` = 1
  /// and 4.1 to 5.9 n/m with the default `sigma` = 0.1 on CGAL's fandisk, armadillo and
  /// elephant (n vertices, m eigenpairs; 1500 n/m on bull, whose weights nearly cut it
  /// into pieces). Its cost grows with t, that of the spectral kernel does not: for
  /// large t, ask for the spectral kernel.
  automatic
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The rule of Heat_kernel_method::automatic, on whether the caller asks for eigenpairs:
// spectral if it does, else local. Apart from the named parameters below so that code
// that knows what was asked for at run time only (the command-line tool) applies it too.
inline Heat_kernel_method choose_kernel_method(Heat_kernel_method requested, bool eigenpairs_requested)
{
  if(requested != Heat_kernel_method::automatic)
    return requested;
  return eigenpairs_requested ? Heat_kernel_method::spectral : Heat_kernel_method::local;
}

// The method that the named parameters `np` of a call select: their `kernel_method`, and
// for Heat_kernel_method::automatic (the default), spectral if they ask for eigenpairs,
// else local.
template <typename NamedParameters>
Heat_kernel_method resolve_kernel_method(const NamedParameters& np, bool scale_invariant)
{
  return choose_kernel_method(parameter_value(np, internal_np::kernel_method, Heat_kernel_method::automatic),
                              is_given(np, internal_np::number_of_eigenpairs) ||
                                  is_given(np, internal_np::coarse_vertex_count) || scale_invariant);
}

// Whether named parameters of type `NamedParameters` can select the spectral kernel:
// `kernel_method` is given (its value is known at run time only) or the eigenpairs are
// asked for. When they cannot, the constructors that take them do not compile the
// spectral path (the eigen solver and the coarse level): a program that uses only the
// local kernel does not pay for it.
template <typename NamedParameters>
constexpr bool can_select_spectral_kernel =
    !parameters::is_default_parameter<NamedParameters, internal_np::kernel_method_t>::value ||
    !parameters::is_default_parameter<NamedParameters, internal_np::number_of_eigenpairs_t>::value ||
    !parameters::is_default_parameter<NamedParameters, internal_np::coarse_vertex_count_t>::value ||
    !parameters::is_default_parameter<NamedParameters, internal_np::scale_invariant_kernel_t>::value;

} // namespace internal
/// \endcond

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_HEAT_KERNEL_METHOD_H
