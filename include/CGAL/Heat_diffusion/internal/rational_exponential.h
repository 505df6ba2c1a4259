// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Rational approximations of exp(-x) on [0, inf) by two or three complex poles.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_RATIONAL_EXPONENTIAL_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_RATIONAL_EXPONENTIAL_H

#include <array>
#include <cstddef>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

struct Exponential_pole
{
  double pole_real, pole_imag, residue_real, residue_imag;
};

// A rational approximation of exp(-x) on [0, inf) used by the local kernel:
//   exp(-x) ~ sum_k Re( a_k / (-x - z_k) ),
// one term per pole z_k with Im z_k > 0 (its conjugate is accounted for by the real
// part). The poles are those of the Caratheodory-Fejer approximation of type (2K, 2K)
// (Trefethen, Weideman and Schmelzer 2006), the residues a_k a fit without a constant
// term, so that r(inf) = 0: of least maximum error for two poles
// (scripts/rational_exponential_poles.py computes the poles and those residues), from a
// Lawson iteration for three. Each pole costs a complex factorisation per patch and a complex
// solve per column, so the kernel takes the approximation with the fewest poles that
// its tolerance allows (Local_heat_kernel::exponential_for()).
struct Rational_exponential
{
  static constexpr std::size_t maximum_number_of_poles = 3;

  std::array<Exponential_pole, maximum_number_of_poles> poles;
  std::size_t number_of_poles;
  double maximum_error;  // max |r(x) - exp(-x)| on [0, inf) (checked by test_local_heat_kernel)

  // r(x), for tests.
  double operator()(double x) const
  {
    double sum = 0;
    for(std::size_t k = 0; k < number_of_poles; ++k)
    {
      // Re(a / w), w = -x - z
      const Exponential_pole& p = poles[k];
      const double wr = -x - p.pole_real, wi = -p.pole_imag;
      sum += (p.residue_real * wr + p.residue_imag * wi) / (wr * wr + wi * wi);
    }
    return sum;
  }
};

// Type (6, 6): three poles, error 1.5e-6 (the residues of a Lawson iteration, which
// the package has used since its first local kernel; the least maximum error fit gives
// 1.4e-6).
inline const Rational_exponential& three_pole_exponential()
{
  static const Rational_exponential r = {
      {{{2.40060293892545, 1.1931293084021366, -1.1587937012299794314, -8.5730404167499296624},
        {-1.7819882759326164, 6.196512467349581, -0.16700572322229976563, -0.213022846594453875},
        {1.1585525717103486, 3.614772600820088, 1.3265003633611509662, 2.9033265650419489995}}},
      3,
      1.5e-6};
  return r;
}

// Type (4, 4): two poles, error 1.26e-4 (1.2526e-4, rounded up: the error chooses the
// approximation).
inline const Rational_exponential& two_pole_exponential()
{
  static const Rational_exponential r = {
      {{{1.5484005705394408, 1.1918258539276163, -0.12871410918322748, -3.8059479834000292},
        {-0.36783831439980225, 3.6581332720632673, 0.14872391516270786, 0.90323034086009713},
        {0., 0., 0., 0.}}},
      2,
      1.26e-4};
  return r;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_RATIONAL_EXPONENTIAL_H
