// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The errors of the package: every message starts with "CGAL::Heat_diffusion: " and
// then names the function or class that rejects its input.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_ERRORS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_ERRORS_H

#include <cmath>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Throws std::invalid_argument with the package prefix, so that every message of
// the package says where it comes from.
[[noreturn]] inline void throw_invalid_input(const std::string& what)
{
  throw std::invalid_argument("CGAL::Heat_diffusion: " + what);
}

// The width sigma of the edge weights exp(-|d_i - d_j|^2 / sigma^2): positive, or
// infinite (isotropic weights). `where` names the caller in the message.
inline double checked_sigma(double sigma, const char* where)
{
  if(!(sigma > 0) || std::isnan(sigma))
    throw_invalid_input(std::string(where) + ": sigma must be positive");
  return sigma;
}

// A parameter that must be positive and finite (a time, a weight).
inline double checked_positive(double x, const char* where, const char* name)
{
  if(!(x > 0) || !std::isfinite(x))
    throw_invalid_input(std::string(where) + ": " + name + " must be positive and finite");
  return x;
}

// The local kernel's tolerance (`local_kernel_tolerance`): in (0, 1).
inline double checked_kernel_tolerance(double tolerance, const char* where)
{
  if(!(tolerance > 0 && tolerance < 1))
    throw_invalid_input(std::string(where) + ": local_kernel_tolerance must be in (0, 1)");
  return tolerance;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_ERRORS_H
