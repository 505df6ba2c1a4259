// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The generalized eigen solver's linear algebra: the Cholesky factor of the shifted
// matrix K = L - sigma B (CHOLMOD's when it is linked, else Eigen's SimplicialLDLT)
// and the standard symmetric operator R^-1 P B P^T R^-T it turns
// L phi = lambda B phi into, for Spectra's Lanczos iteration.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_SHIFTED_CHOLESKY_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_SHIFTED_CHOLESKY_H

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_HEAT_DIFFUSION_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <CGAL/Heat_diffusion/internal/sparse_cholesky.h>

#include <cstring>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {
namespace generalized_eigensolver_impl {

using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

inline std::string to_short_string(double x)
{
  std::ostringstream out;
  out << x;   // std::to_string would print small shifts as 0.000000
  return out.str();
}

inline std::runtime_error not_positive_definite_error(double shift)
{
  return std::runtime_error(
    "Heat_diffusion: the shifted matrix L - sigma*B (sigma = " + to_short_string(shift) +
    ") is not positive definite, so it cannot be Cholesky-factorised. L must be symmetric "
    "positive semi-definite (graph Laplacian D - W with positive weights, both triangles "
    "stored) and B symmetric positive definite (mass matrix of a mesh without degenerate "
    "faces); check for negative weights, NaNs or zero-area faces.");
}

// Cholesky factor of K = L - sigma B in permuted form  P K P^T = R R^T,  R lower triangular.
// Only the two triangular solves with R are needed: they turn the generalized problem
// into a standard one (see `Transformed_operator`).
#ifdef CGAL_HEAT_DIFFUSION_USE_CHOLMOD

// Eigen's CHOLMOD wrappers only expose full solves with K; the transformation needs the
// triangular factor itself, which CholmodBase keeps as a protected member.
template <typename SparseMatrix>
class Cholmod_llt
  : public Eigen::CholmodBase<SparseMatrix, Eigen::Lower, Cholmod_llt<SparseMatrix>>
{
public:
  explicit Cholmod_llt(bool supernodal)
  {
    // A non-positive-definite K is reported through info()/minor; keep CHOLMOD from
    // also printing its own warning on stdout.
    this->m_cholmod.print = 0;
    // Always LL^T (final_ll), never LDL^T, so that the factor is R itself.
    this->m_cholmod.final_asis = supernodal ? 1 : 0;
    this->m_cholmod.final_ll = 1;
    this->m_cholmod.supernodal = supernodal ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
  }

  const cholmod_factor* factor() const { return this->m_cholmodFactor; }
  cholmod_common* common() const { return &this->m_cholmod; }
};

template <typename SparseMatrix>
class Shifted_cholesky
{
public:
  Shifted_cholesky(const SparseMatrix& K, double shift)
    // Simplicial unless CGAL_HEAT_DIFFUSION_CHOLMOD_SUPERNODAL (see sparse_cholesky.h):
    // the spectral kernel factorises the coarse level of large meshes.
    : m_llt(CGAL_HEAT_DIFFUSION_CHOLMOD_SUPERNODAL != 0)
  {
    m_llt.compute(K);
    const cholmod_factor* F = m_llt.factor();
    if(m_llt.info() != Eigen::Success || F == nullptr || !F->is_ll || F->minor != F->n)
      throw not_positive_definite_error(shift);

    // CHOLMOD factors K(Perm, Perm): (P x)[i] = x[Perm[i]]. Eigen's permutation applies
    // (P x)[indices[i]] = x[i], hence indices = Perm^{-1}.
    const int n = static_cast<int>(F->n);
    const int* perm = static_cast<const int*>(F->Perm);
    m_P.resize(n);
    for(int i = 0; i < n; ++i)
      m_P.indices()[perm[i]] = i;
  }

  ~Shifted_cholesky()
  {
    cholmod_common* c = m_llt.common();
    if(m_X) cholmod_free_dense(&m_X, c);
    if(m_Y) cholmod_free_dense(&m_Y, c);
    if(m_E) cholmod_free_dense(&m_E, c);
  }

  Shifted_cholesky(const Shifted_cholesky&) = delete;
  Shifted_cholesky& operator=(const Shifted_cholesky&) = delete;

  const Permutation& permutation() const { return m_P; }

  // x <- R^{-1} x (columns of an n x k column-major block)
  void solve_lower_in_place(double* x, Eigen::Index ncols) const { solve(CHOLMOD_L, x, ncols); }
  // x <- R^{-T} x
  void solve_upper_in_place(double* x, Eigen::Index ncols) const { solve(CHOLMOD_Lt, x, ncols); }

private:
  void solve(int sys, double* x, Eigen::Index ncols) const
  {
    const cholmod_factor* F = m_llt.factor();
    cholmod_dense b;
    b.nrow = F->n;
    b.ncol = static_cast<size_t>(ncols);
    b.nzmax = b.nrow * b.ncol;
    b.d = b.nrow;
    b.x = x;
    b.z = nullptr;
    b.xtype = CHOLMOD_REAL;
    b.dtype = CHOLMOD_DOUBLE;
    // cholmod_solve2 keeps its output and workspace between calls: no allocation per step.
    if(!cholmod_solve2(sys, const_cast<cholmod_factor*>(F), &b, nullptr, &m_X, nullptr, &m_Y,
                       &m_E, m_llt.common()))
      throw std::runtime_error("Heat_diffusion: CHOLMOD triangular solve failed");
    std::memcpy(x, m_X->x, sizeof(double) * b.nzmax);
  }

  Cholmod_llt<SparseMatrix> m_llt;
  Permutation m_P;
  mutable cholmod_dense* m_X = nullptr;
  mutable cholmod_dense* m_Y = nullptr;
  mutable cholmod_dense* m_E = nullptr;
};

#else // Eigen's SimplicialLDLT

template <typename SparseMatrix>
class Shifted_cholesky
{
public:
  Shifted_cholesky(const SparseMatrix& K, double shift)
  {
    m_ldlt.compute(K);
    if(m_ldlt.info() != Eigen::Success)
      throw not_positive_definite_error(shift);
    // SimplicialLDLT only reports exactly zero pivots; an indefinite K shows up as
    // non-positive entries of D, which must be rejected before taking their square roots.
    const Eigen::VectorXd& D = m_ldlt.vectorD();
    if(!(D.minCoeff() > 0.) || !D.allFinite())
      throw not_positive_definite_error(shift);
    // P K P^T = L D L^T  =>  R = L D^{1/2}
    m_inv_sqrt_D = D.cwiseSqrt().cwiseInverse();
  }

  const Permutation& permutation() const { return m_ldlt.permutationP(); }

  void solve_lower_in_place(double* x, Eigen::Index ncols) const
  {
    Eigen::Map<Eigen::MatrixXd> X(x, m_inv_sqrt_D.size(), ncols);
    m_ldlt.matrixL().solveInPlace(X);
    X = m_inv_sqrt_D.asDiagonal() * X;
  }

  void solve_upper_in_place(double* x, Eigen::Index ncols) const
  {
    Eigen::Map<Eigen::MatrixXd> X(x, m_inv_sqrt_D.size(), ncols);
    X = m_inv_sqrt_D.asDiagonal() * X;
    m_ldlt.matrixU().solveInPlace(X);
  }

private:
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> m_ldlt;
  Eigen::VectorXd m_inv_sqrt_D;
};

#endif // CGAL_HEAT_DIFFUSION_USE_CHOLMOD

// Standard symmetric operator A = R^{-1} (P B P^T) R^{-T}, with P K P^T = R R^T.
//
// Why this instead of Spectra's SymGEigsShiftSolver<..., GEigsMode::ShiftInvert>:
// L phi = lambda B phi  <=>  K phi = (lambda - sigma) B phi  <=>  A y = nu y with
// y = R^T P phi and nu = 1 / (lambda - sigma). The eigenvalues nu are the same as in
// shift-invert mode, so Lanczos converges identically, but the Krylov basis is now
// Euclidean-orthonormal: Spectra's reorthogonalisation no longer needs B products
// (5-6 per step in generalized mode); one B product per
// application remains, for the same two triangular solves a K solve costs anyway.
// Everything runs in the permuted numbering, so no permutation is applied per step.
template <typename SparseMatrix>
class Transformed_operator
{
public:
  using Scalar = double;

  Transformed_operator(const Shifted_cholesky<SparseMatrix>& factor, const SparseMatrix& permuted_B,
                       const std::function<void()>& on_application)
    : m_factor(factor), m_B(permuted_B), m_on_application(on_application),
      m_tmp(permuted_B.rows())
  {}

  Eigen::Index rows() const { return m_B.rows(); }
  Eigen::Index cols() const { return m_B.cols(); }

  void perform_op(const double* x_in, double* y_out) const
  {
    Eigen::Map<const Eigen::VectorXd> x(x_in, m_B.cols());
    Eigen::Map<Eigen::VectorXd> y(y_out, m_B.rows());
    m_tmp = x;
    m_factor.solve_upper_in_place(m_tmp.data(), 1);
    // Column-major on purpose: Eigen multi-threads a row-major product under OpenMP,
    // and a fork/join per Lanczos step costs more than it saves on few cores.
    y.noalias() = m_B * m_tmp;
    m_factor.solve_lower_in_place(y.data(), 1);
    if(m_on_application)
      m_on_application();
  }

private:
  const Shifted_cholesky<SparseMatrix>& m_factor;
  const SparseMatrix& m_B;
  const std::function<void()>& m_on_application;
  mutable Eigen::VectorXd m_tmp;
};

} // namespace generalized_eigensolver_impl
} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_SHIFTED_CHOLESKY_H
