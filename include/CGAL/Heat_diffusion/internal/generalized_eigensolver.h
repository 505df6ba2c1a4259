// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Smallest eigenpairs of the generalized problem L phi = lambda B phi, with L a
// graph Laplacian (symmetric positive semi-definite) and B a FEM mass matrix
// (symmetric positive definite).

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_GENERALIZED_EIGENSOLVER_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_GENERALIZED_EIGENSOLVER_H

#include <Eigen/Core>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_HEAT_DIFFUSION_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <Spectra/SymEigsSolver.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Eigenpairs of L phi = lambda B phi, sorted by ascending eigenvalue.
// `eigenvectors` is n x m and B-orthonormal: Phi^T B Phi = I.
// The remaining members describe how the pairs were obtained (tests, benchmarks).
struct Generalized_eigenpairs
{
  Eigen::VectorXd eigenvalues;
  Eigen::MatrixXd eigenvectors;

  bool dense_solver = false;          // true: dense fallback, no Lanczos iteration
  double shift = 0.;                  // sigma of the factorised matrix L - sigma B
  Eigen::Index subspace_dimension = 0; // Lanczos basis size (Spectra's ncv)
  Eigen::Index iterations = 0;        // Lanczos restarts (Spectra's num_iterations())
  Eigen::Index operator_applications = 0;
  bool reorthonormalized = false;     // true: the final B-Gram matrix needed a correction
};

// Tuning knobs; the defaults are what the measurements on fandisk/armadillo favoured.
struct Generalized_eigensolver_options
{
  Eigen::Index subspace_dimension = 0; // 0: automatic (see `automatic_subspace_dimension`)
  double shift = 0.;                   // 0: automatic; an explicit value must be < 0
  double tolerance = 1e-10;            // Spectra's relative tolerance on the Ritz values
  Eigen::Index max_restarts = 300;
  Eigen::Index dense_size_threshold = 400;  // n <= this: dense solver
  double orthonormality_threshold = 1e-12;  // max|Phi^T B Phi - I| above this: Rayleigh-Ritz
};

// Thrown when the progress callback asks to stop.
class Generalized_eigensolver_cancelled : public std::runtime_error
{
public:
  Generalized_eigensolver_cancelled()
    : std::runtime_error("Heat_diffusion: generalized eigensolver cancelled by the progress callback")
  {}
};

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

// Simplicial by default: the supernodal factorisation and solves go through BLAS, and
// with Debian's reference BLAS they were slower.
// Define to 1 when CHOLMOD is linked against an optimised BLAS.
#ifndef CGAL_HEAT_DIFFUSION_CHOLMOD_SUPERNODAL
#define CGAL_HEAT_DIFFUSION_CHOLMOD_SUPERNODAL 0
#endif

template <typename SparseMatrix>
class Shifted_cholesky
{
public:
  Shifted_cholesky(const SparseMatrix& K, double shift)
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

// Subspace size: about 1.5 m measured faster than Spectra's customary 2 m + 1
// (less dense work per restart outweighs the few extra restarts); small m need
// a minimum number of spare vectors to restart effectively.
inline Eigen::Index automatic_subspace_dimension(Eigen::Index m, Eigen::Index n)
{
  const Eigen::Index ncv = std::max<Eigen::Index>(m + m / 2 + 1, m + 20);
  return std::min(ncv, n);
}

// Shift sigma < 0, relative to the scale of the smallest nonzero eigenvalue.
//
// A zero shift fails: L is singular (one zero eigenvalue per connected component), so
// L - 0*B cannot be factorised. Any sigma < 0 makes K = L - sigma B positive definite.
// Its magnitude matters for speed and accuracy:
// - in terms of nu = 1/(lambda - sigma), the wanted part of the spectrum is
//   1/|sigma| (null space, converges at once) and 1/(lambda_k + |sigma|); the closer
//   sigma is to 0, the more the wanted nonzero lambda_k are spread apart relative to
//   the unwanted ones, and the fewer restarts Lanczos needs (fandisk, m = 150: 8
//   restarts with |sigma| ~ lambda_m, 4 with |sigma| ~ lambda_2);
// - but cond(K) ~ lambda_max / |sigma| grows, and the back-transformed vectors lose
//   accuracy accordingly.
// |sigma| of the order of the first nonzero eigenvalue lambda_2 gets (nearly) all of
// the speed-up while keeping cond(K) ~ n. lambda_2 is estimated without any solve:
// Weyl's law on a surface makes the eigenvalue count grow linearly, lambda_k ~
// 2 (k/n) * mean eigenvalue, and the mean eigenvalue trace(B^{-1} L)/n is approximated
// by the mean of L_ii / B_ii (exact for a lumped mass). Only the order of magnitude
// matters; the estimate is invariant under scaling of L, of B, and of the mesh.
template <typename SparseMatrix>
double automatic_shift(const SparseMatrix& L, const SparseMatrix& B)
{
  const Eigen::Index n = L.rows();
  const Eigen::VectorXd L_diagonal = L.diagonal();
  const Eigen::VectorXd B_diagonal = B.diagonal();
  double sum_ratio = 0.;
  for(Eigen::Index i = 0; i < n; ++i)
    if(B_diagonal[i] > 0.)
      sum_ratio += std::abs(L_diagonal[i]) / B_diagonal[i];
  const double mean_eigenvalue = sum_ratio / double(n);
  const double shift = -2. / double(n) * mean_eigenvalue;
  // L == 0 (no edges) or garbage diagonals: any negative shift is valid then.
  if(!(shift < 0.) || !std::isfinite(shift))
    return -1.;
  return shift;
}

// Dense fallback for small problems or when m is a sizeable fraction of n, where the
// Lanczos iteration gains nothing and Spectra requires m < ncv <= n anyway.
template <typename SparseMatrix>
Generalized_eigenpairs dense_generalized_eigenpairs(const SparseMatrix& L, const SparseMatrix& B, Eigen::Index m)
{
  const Eigen::MatrixXd Ld = Eigen::MatrixXd(L);
  const Eigen::MatrixXd Bd = Eigen::MatrixXd(B);
  // Ax_lBx: B = C C^T and the standard problem C^{-1} L C^{-T}; the eigenvectors come
  // back as C^{-T} (orthonormal vectors), i.e. already B-orthonormal.
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
    Ld, Bd, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if(solver.info() != Eigen::Success)
    throw std::runtime_error(
      "Heat_diffusion: dense generalized eigensolver failed (n = " + std::to_string(L.rows()) +
      "); B must be symmetric positive definite.");
  Generalized_eigenpairs result;
  result.dense_solver = true;
  result.eigenvalues = solver.eigenvalues().head(m);     // ascending
  result.eigenvectors = solver.eigenvectors().leftCols(m);
  return result;
}

} // namespace generalized_eigensolver_impl

// Smallest m eigenpairs of L phi = lambda B phi.
//
// L: symmetric positive semi-definite (graph Laplacian, possibly several connected
// components, i.e. several zero eigenvalues); B: symmetric positive definite.
// Both matrices must store both triangles. m is clamped to n.
// `progress(fraction)` is called now and then with an estimate in [0, 1]; returning
// false aborts with Generalized_eigensolver_cancelled.
// Throws std::runtime_error if K = L - sigma B is not positive definite or if Lanczos
// does not converge, std::invalid_argument on inconsistent sizes.
template <typename SparseMatrix>
Generalized_eigenpairs
compute_smallest_generalized_eigenpairs(const SparseMatrix& L,
                                        const SparseMatrix& B,
                                        Eigen::Index m,
                                        const std::function<bool(double fraction_done)>& progress,
                                        const Generalized_eigensolver_options& options)
{
  namespace impl = generalized_eigensolver_impl;
  using Index = Eigen::Index;

  const Index n = L.rows();
  if(L.cols() != n || B.rows() != n || B.cols() != n)
    throw std::invalid_argument("Heat_diffusion: L and B must be square matrices of the same size");
  m = std::min(std::max<Index>(m, 0), n);
  if(m == 0)
  {
    Generalized_eigenpairs empty;
    empty.eigenvectors.resize(n, 0);
    return empty;
  }

  auto report = [&progress](double fraction) {
    if(progress && !progress(fraction))
      throw Generalized_eigensolver_cancelled();
  };
  report(0.);

  if(n <= options.dense_size_threshold || 3 * m >= n)
  {
    Generalized_eigenpairs result = impl::dense_generalized_eigenpairs(L, B, m);
    report(1.);
    return result;
  }

  const double shift = options.shift != 0. ? options.shift : impl::automatic_shift(L, B);
  if(!(shift < 0.))
    throw std::invalid_argument("Heat_diffusion: the eigensolver shift must be negative");

  SparseMatrix K = L - shift * B;
  K.makeCompressed();
  const impl::Shifted_cholesky<SparseMatrix> factor(K, shift);
  report(0.05);

  const auto& P = factor.permutation();
  SparseMatrix permuted_B;
  permuted_B = B.twistedBy(P);   // P B P^T

  const Index ncv = options.subspace_dimension > m
                      ? std::min(options.subspace_dimension, n)
                      : impl::automatic_subspace_dimension(m, n);

  // Progress: the number of operator applications is not known in advance; measured
  // runs needed 1.5-2 ncv of them (one full sweep, then a few restarts), which the
  // saturating curve 1 - exp(-a / ncv) maps to roughly 0.6-0.9.
  Index applications = 0;
  const std::function<void()> on_application = [&]() {
    ++applications;
    if(progress && applications % 16 == 0)
      report(0.05 + 0.85 * (1. - std::exp(-double(applications) / double(ncv))));
  };

  impl::Transformed_operator<SparseMatrix> op(factor, permuted_B, on_application);
  Spectra::SymEigsSolver<impl::Transformed_operator<SparseMatrix>> lanczos(op, m, ncv);
  lanczos.init();
  // The nu = 1/(lambda - sigma) are all positive: the largest ones are the wanted ones.
  lanczos.compute(Spectra::SortRule::LargestAlge, options.max_restarts, options.tolerance,
                  Spectra::SortRule::LargestAlge);
  if(lanczos.info() != Spectra::CompInfo::Successful)
    throw std::runtime_error(
      "Heat_diffusion: the Lanczos eigensolver did not converge (m = " + std::to_string(m) +
      " eigenpairs, n = " + std::to_string(n) + ", ncv = " + std::to_string(ncv) +
      ", restarts = " + std::to_string(lanczos.num_iterations()) + ", shift = " +
      impl::to_short_string(shift) + "). Remedies: request fewer eigenpairs, enlarge the subspace "
      "(subspace_dimension) or max_restarts, or check that the mesh has no degenerate faces.");

  // Back to the generalized problem: phi_perm = R^{-T} y.
  Eigen::MatrixXd Phi = lanczos.eigenvectors(m);
  factor.solve_upper_in_place(Phi.data(), m);

  // Verify B-orthonormality. In exact arithmetic the Ritz vectors y are orthonormal and
  // their residuals orthogonal to the Krylov space, which makes Phi^T B Phi diagonal;
  // rounding in the solves (amplified by cond(K)^{1/2}) and near-degenerate eigenvalues
  // (one zero eigenvalue per connected component) can spoil that, so measure it.
  Eigen::MatrixXd BPhi = permuted_B * Phi;
  Eigen::MatrixXd gram = Phi.transpose() * BPhi;
  if(!(gram.diagonal().minCoeff() > 0.) || !gram.allFinite())
    throw std::runtime_error("Heat_diffusion: the eigenvectors have no positive B-norm; "
                             "B must be symmetric positive definite.");
  const Eigen::VectorXd inv_norms = gram.diagonal().cwiseSqrt().cwiseInverse();
  Phi = Phi * inv_norms.asDiagonal();
  BPhi = BPhi * inv_norms.asDiagonal();
  gram = inv_norms.asDiagonal() * gram * inv_norms.asDiagonal();
  const double orthonormality_error = (gram - Eigen::MatrixXd::Identity(m, m)).cwiseAbs().maxCoeff();

  SparseMatrix permuted_L;
  permuted_L = L.twistedBy(P);
  Eigen::MatrixXd LPhi = permuted_L * Phi;

  Generalized_eigenpairs result;
  if(!(orthonormality_error <= options.orthonormality_threshold))
  {
    // Rayleigh-Ritz on span(Phi): B-orthonormalises and, within clusters, picks the
    // best vectors; costs two extra n x m x m products, hence only when needed.
    const Eigen::MatrixXd projected_L = Phi.transpose() * LPhi;
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(
      0.5 * (projected_L + projected_L.transpose()), 0.5 * (gram + gram.transpose()),
      Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
    if(ritz.info() != Eigen::Success)
      throw std::runtime_error("Heat_diffusion: Rayleigh-Ritz step of the eigensolver failed");
    result.eigenvalues = ritz.eigenvalues();
    Phi = Phi * ritz.eigenvectors();
    result.reorthonormalized = true;
  }
  else
  {
    // Rayleigh quotients: more accurate than 1/nu + sigma, which cancels catastrophically
    // for the zero eigenvalue(s).
    result.eigenvalues = (Phi.cwiseProduct(LPhi)).colwise().sum().transpose();
    std::vector<Index> order(static_cast<std::size_t>(m));
    std::iota(order.begin(), order.end(), Index(0));
    std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
      return result.eigenvalues[a] < result.eigenvalues[b];
    });
    if(!std::is_sorted(order.begin(), order.end()))
    {
      Eigen::VectorXd values(m);
      Eigen::MatrixXd vectors(n, m);
      for(Index j = 0; j < m; ++j)
      {
        values[j] = result.eigenvalues[order[j]];
        vectors.col(j) = Phi.col(order[j]);
      }
      result.eigenvalues.swap(values);
      Phi.swap(vectors);
    }
  }

  result.eigenvectors = P.transpose() * Phi;   // back to the caller's vertex numbering
  result.shift = shift;
  result.subspace_dimension = ncv;
  result.iterations = lanczos.num_iterations();
  result.operator_applications = lanczos.num_operations();
  report(1.);
  return result;
}

template <typename SparseMatrix>
Generalized_eigenpairs
compute_smallest_generalized_eigenpairs(const SparseMatrix& L,
                                        const SparseMatrix& B,
                                        Eigen::Index m,
                                        const std::function<bool(double fraction_done)>& progress = {})
{
  return compute_smallest_generalized_eigenpairs(L, B, m, progress, Generalized_eigensolver_options());
}

#ifdef CGAL_HEAT_DIFFUSION_EXTERN_TEMPLATES
extern template Generalized_eigenpairs compute_smallest_generalized_eigenpairs<Eigen::SparseMatrix<double>>(
    const Eigen::SparseMatrix<double>&, const Eigen::SparseMatrix<double>&, Eigen::Index,
    const std::function<bool(double)>&, const Generalized_eigensolver_options&);
extern template Generalized_eigenpairs compute_smallest_generalized_eigenpairs<Eigen::SparseMatrix<double>>(
    const Eigen::SparseMatrix<double>&, const Eigen::SparseMatrix<double>&, Eigen::Index,
    const std::function<bool(double)>&);
#endif

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_GENERALIZED_EIGENSOLVER_H
