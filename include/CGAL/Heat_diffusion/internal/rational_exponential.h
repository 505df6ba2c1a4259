// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A rational approximation of exp(-x) on [0, inf) by three complex poles.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_RATIONAL_EXPONENTIAL_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_RATIONAL_EXPONENTIAL_H

#include <array>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The rational approximation of exp(-x) on [0, inf) used by the local kernel:
//   exp(-x) ~ sum_k Re( a_k / (-x - z_k) ),
// one term per pole z_k with Im z_k >= 0 (its conjugate is accounted for by the real
// part). The poles are those of the Caratheodory-Fejer approximation of type (6, 6)
// (Trefethen, Weideman and Schmelzer 2006), the residues a_k a least-squares fit with
// Lawson weights without a constant term, so that r(inf) = 0. Maximum error on
// [0, inf): 1.5e-6 (checked by test_local_heat_kernel).
struct Exponential_pole
{
  double pole_real, pole_imag, residue_real, residue_imag;
};

inline const std::array<Exponential_pole, 3>& exponential_poles()
{
  static const std::array<Exponential_pole, 3> poles = {{
      {2.40060293892545, 1.1931293084021366, -1.1587937012299794314, -8.5730404167499296624},
      {-1.7819882759326164, 6.196512467349581, -0.16700572322229976563, -0.213022846594453875},
      {1.1585525717103486, 3.614772600820088, 1.3265003633611509662, 2.9033265650419489995}}};
  return poles;
}

// r(x) of exponential_poles(), for tests.
inline double rational_exponential(double x)
{
  double sum = 0;
  for(const Exponential_pole& p : exponential_poles())
  {
    // Re(a / w), w = -x - z
    const double wr = -x - p.pole_real, wi = -p.pole_imag;
    sum += (p.residue_real * wr + p.residue_imag * wi) / (wr * wr + wi * wi);
  }
  return sum;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_RATIONAL_EXPONENTIAL_H
