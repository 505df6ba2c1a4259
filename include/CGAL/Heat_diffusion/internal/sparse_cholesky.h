// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_SPARSE_CHOLESKY_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_SPARSE_CHOLESKY_H

#include <Eigen/Sparse>
#ifdef CGAL_HEAT_DIFFUSION_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Define to 1 when CHOLMOD is linked against an optimised BLAS: every factorisation is
// then supernodal. By default, CHOLMOD's supernodal factorisation (which works through
// BLAS) is used only for systems of least_supernodal_size unknowns or more, and the
// simplicial one below that.
#ifndef CGAL_HEAT_DIFFUSION_CHOLMOD_SUPERNODAL
#define CGAL_HEAT_DIFFUSION_CHOLMOD_SUPERNODAL 0
#endif

// The sparse Cholesky factorisation of the package: CHOLMOD's when the build found
// SuiteSparse (CGAL_HEAT_DIFFUSION_USE_CHOLMOD, set by the CMake target), Eigen's
// SimplicialLDLT otherwise. Both read the lower triangle.
#ifdef CGAL_HEAT_DIFFUSION_USE_CHOLMOD
typedef Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> Sparse_cholesky;
#else
typedef Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> Sparse_cholesky;
#endif

// The supernodal factorisation works on dense blocks through BLAS, which pays once the
// blocks are large. With Debian's reference BLAS the two factorisations of the implicit
// cotangent flow's system M + tL break even at about this size, the supernodal one
// slower below it and faster above (`benchmark_scale_curve --cholesky` measures both;
// the user manual gives the figures).
constexpr Eigen::Index least_supernodal_size = 400000;

// Chooses the factorisation of `cholesky` for systems of `size` unknowns; called before
// the first factorisation. Failures are reported through info(), not printed.
inline void configure_cholesky(Sparse_cholesky& cholesky, Eigen::Index size)
{
#ifdef CGAL_HEAT_DIFFUSION_USE_CHOLMOD
  const bool supernodal = CGAL_HEAT_DIFFUSION_CHOLMOD_SUPERNODAL != 0 || size >= least_supernodal_size;
  cholesky.setMode(supernodal ? Eigen::CholmodSupernodalLLt : Eigen::CholmodSimplicialLLt);
  cholesky.cholmod().print = 0;
#else
  static_cast<void>(cholesky);
  static_cast<void>(size);
#endif
}

// Factorises the symmetric positive definite `matrix`, or throws std::runtime_error
// saying which `system` failed.
inline void factorize_or_throw(Sparse_cholesky& cholesky, const Eigen::SparseMatrix<double>& matrix,
                               const std::string& system)
{
  configure_cholesky(cholesky, matrix.rows());
  cholesky.compute(matrix);
  if(cholesky.info() != Eigen::Success)
    throw std::runtime_error("CGAL::Heat_diffusion: the sparse Cholesky factorisation of " + system +
                             " failed (the matrix is not numerically positive definite)");
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_SPARSE_CHOLESKY_H
