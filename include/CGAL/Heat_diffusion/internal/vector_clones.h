// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The vector types and the target clones of the local kernel's factorisation and
// substitutions.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_VECTOR_CLONES_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_VECTOR_CLONES_H

#include <cstring>

// The factorisation and the forward and back substitutions are the largest part of the
// local kernel's time, and they vectorise. A compiler's default target is the baseline
// x86-64 (SSE2); with GCC 11 or later on x86-64 Linux (GNU ifunc) they are also compiled
// for the x86-64-v4 (AVX-512) and x86-64-v3 (AVX2 and FMA) levels, and the code of the
// highest level the processor has is chosen at run time. Define
// CGAL_HEAT_DIFFUSION_NO_TARGET_CLONES to compile the baseline alone. (The sanitizer build
// of the tests uses clang, so it runs the baseline.)
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 && defined(__x86_64__) && defined(__linux__) && \
    !defined(CGAL_HEAT_DIFFUSION_NO_TARGET_CLONES)
#define CGAL_HEAT_DIFFUSION_VECTOR_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#define CGAL_HEAT_DIFFUSION_HAS_VECTOR_CLONES
#else
#define CGAL_HEAT_DIFFUSION_VECTOR_CLONES
#endif

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Vectors (GCC's and Clang's vector extensions) of 256 bits where they fit one AVX
// register: in the x86-64-v3 and v4 clones, or when the compiler targets AVX; and of 512
// bits where they fit an AVX-512 register. The factorisation updates the poles of a row
// at once in four doubles (most of the factorisation's time), and the substitutions,
// in single precision, run over whole passes in vectors of eight or sixteen floats.
// Elsewhere (other compilers, a baseline build, the baseline clone, or
// CGAL_HEAT_DIFFUSION_NO_VECTOR_EXTENSIONS), plain loops that the compiler vectorises
// itself: GCC's SSE2 code for the vectors was much slower. (The vectors are passed
// by reference: by value, they would change the calling convention between the baseline
// code and its clone.)
#if defined(__GNUC__) && (defined(__AVX__) || defined(CGAL_HEAT_DIFFUSION_HAS_VECTOR_CLONES)) && \
    !defined(CGAL_HEAT_DIFFUSION_NO_VECTOR_EXTENSIONS)
#define CGAL_HEAT_DIFFUSION_VECTOR_EXTENSIONS
typedef double Four_doubles __attribute__((vector_size(4 * sizeof(double))));
typedef float Eight_floats __attribute__((vector_size(8 * sizeof(float))));
typedef float Sixteen_floats __attribute__((vector_size(16 * sizeof(float))));

// (unaligned: the rows of the blocks and of the factor need not start on a vector)
template <typename Vector, typename Scalar>
inline void load_vector(Vector& x, const Scalar* p)
{
  std::memcpy(&x, p, sizeof x);
}
template <typename Vector, typename Scalar>
inline void store_vector(Scalar* p, const Vector& x)
{
  std::memcpy(p, &x, sizeof x);
}

// Whether the code runs with AVX: always when compiled for it, else when the processor
// runs the x86-64-v3 clone (the baseline clone takes the plain loops).
inline bool vector_registers_of_256_bits()
{
#ifdef __AVX__
  return true;
#else
  static const bool x86_64_v3 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return x86_64_v3;
#endif
}

// Whether vectors of 512 bits fit a register: always when compiled for AVX-512,
// else when the processor runs the x86-64-v4 clone. (Where this would disagree with
// the choice of the clone, the code stays right, only slower.)
inline bool vector_registers_of_512_bits()
{
#if defined(__AVX512F__)
  return true;
#elif defined(CGAL_HEAT_DIFFUSION_HAS_VECTOR_CLONES)
  static const bool x86_64_v4 = vector_registers_of_256_bits() && __builtin_cpu_supports("avx512f") &&
                                __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") &&
                                __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512cd");
  return x86_64_v4;
#else
  return false;
#endif
}
#endif

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_VECTOR_CLONES_H
