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

// The sparse Cholesky factorisation of the package: CHOLMOD's supernodal LLT when
// the build found SuiteSparse (CGAL_HEAT_DIFFUSION_USE_CHOLMOD, set by the
// CMake target), Eigen's SimplicialLDLT otherwise. Both read the lower triangle.
#ifdef CGAL_HEAT_DIFFUSION_USE_CHOLMOD
typedef Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> Sparse_cholesky;
#else
typedef Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> Sparse_cholesky;
#endif

// Factorises the symmetric positive definite `matrix`, or throws std::runtime_error
// saying which `system` failed.
inline void factorize_or_throw(Sparse_cholesky& cholesky, const Eigen::SparseMatrix<double>& matrix,
                               const std::string& system)
{
  cholesky.compute(matrix);
  if(cholesky.info() != Eigen::Success)
    throw std::runtime_error("CGAL::Heat_diffusion: the sparse Cholesky factorisation of " + system +
                             " failed (the matrix is not numerically positive definite)");
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_SPARSE_CHOLESKY_H
