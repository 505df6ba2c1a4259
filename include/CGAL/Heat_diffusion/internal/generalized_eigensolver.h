// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Smallest eigenpairs of the generalized problem L phi = lambda B phi, with L a
// graph Laplacian (symmetric positive semi-definite) and B a FEM mass matrix
// (symmetric positive definite).

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_GENERALIZED_EIGENSOLVER_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_GENERALIZED_EIGENSOLVER_H

#include <CGAL/Heat_diffusion/internal/shifted_cholesky.h>

#include <Eigen/Core>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>

#include <Spectra/SymEigsSolver.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <memory>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The eigenvalues as the heat kernels use them. L is positive semi-definite: the
// solver's tiny negative values are rounding noise of the zero eigenvalues. Clamping
// them keeps every decay rate >= 0, so exp(-rate t) never overflows (found by fuzzing: a
// mesh whose eigenvalues were all noise gave eq. 14 rates of -772 and an infinite kernel).
inline Eigen::VectorXd clamped_eigenvalues(const Eigen::VectorXd& eigenvalues) { return eigenvalues.cwiseMax(0.); }

// lambda_* of eq. 14, from ascending clamped eigenvalues: the first one clearly above the
// zero eigenvalues, which the solver returns as tiny values of either sign: one per
// connected component, and one per piece that a small sigma cuts off numerically (weights
// across sharp creases underflow). 1 if there is none.
inline double first_nonzero_eigenvalue(const Eigen::VectorXd& eigenvalues)
{
  const double tiny = 1e-8 * std::abs(eigenvalues[eigenvalues.size() - 1]);
  for(Eigen::Index k = 0; k < eigenvalues.size(); ++k)
    if(eigenvalues[k] > tiny)
      return eigenvalues[k];
  return 1.;
}

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
  // Of the last Lanczos window only (after a widening, the wider window's):
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
  Eigen::Index max_restarts = 40;      // per window (converging runs take 4 to 15)
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

// Subspace size: about 1.5 m measured faster than Spectra's customary 2 m + 1
// (less dense work per restart outweighs the few extra restarts); small m need
// a minimum number of spare vectors to restart effectively.
inline Eigen::Index automatic_subspace_dimension(Eigen::Index m, Eigen::Index n)
{
  const Eigen::Index ncv = std::max<Eigen::Index>(m + m / 2 + 1, m + 20);
  return std::min(ncv, n);
}

// The eigenpairs added to a window of wanted eigenvalues that ends inside a cluster
// (see compute_smallest_generalized_eigenpairs()).
constexpr Eigen::Index extra_window = 60;

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

  // (The running maximum: a widened window restarts its count of applications, and
  // the bar must not move back.)
  double reported = 0.;
  auto report = [&progress, &reported](double fraction) {
    reported = (std::max)(reported, fraction);
    if(progress && !progress(reported))
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

  // Progress: the number of operator applications is not known in advance; measured
  // runs needed 1.5-2 ncv of them (one full sweep, then a few restarts), which the
  // saturating curve 1 - exp(-a / ncv) maps to roughly 0.6-0.9.
  Index ncv = 0, applications = 0;
  const std::function<void()> on_application = [&]() {
    ++applications;
    if(progress && applications % 16 == 0)
      report(0.05 + 0.85 * (1. - std::exp(-double(applications) / double(ncv))));
  };
  impl::Transformed_operator<SparseMatrix> op(factor, permuted_B, on_application);

  // Lanczos stalls when its window of wanted eigenvalues ends inside a tight cluster:
  // at a small sigma, weak edges across the creases of a CAD mesh split it into nearly
  // disconnected patches, each with an eigenvalue near 0 (fandisk at sigma = 0.1 has
  // some 25, in [0, 1e-6] against a shift of 3e-3). A window that ends past the cluster
  // converges in a few restarts, and its first m pairs are the wanted ones: a window
  // that has not converged after max_restarts is widened once. A cluster wider than
  // that (hundreds of needle patches) is reported: truncating inside it would pick an
  // arbitrary part of it anyway.
  const Index windows[2] = {m, std::min(m + impl::extra_window, n / 3)};
  typedef Spectra::SymEigsSolver<impl::Transformed_operator<SparseMatrix>> Lanczos;
  std::unique_ptr<Lanczos> lanczos;
  for(const Index window : windows)
  {
    ncv = options.subspace_dimension > window ? std::min(options.subspace_dimension, n)
                                              : impl::automatic_subspace_dimension(window, n);
    applications = 0;
    lanczos.reset(new Lanczos(op, window, ncv));
    lanczos->init();
    // The nu = 1/(lambda - sigma) are all positive: the largest ones are the wanted ones.
    lanczos->compute(Spectra::SortRule::LargestAlge, options.max_restarts, options.tolerance,
                     Spectra::SortRule::LargestAlge);
    if(lanczos->info() == Spectra::CompInfo::Successful)
      break;
    if(window >= windows[1])
      throw std::runtime_error(
        "Heat_diffusion: the Lanczos eigensolver did not converge (m = " + std::to_string(m) +
        (window > m ? " eigenpairs, then " + std::to_string(window) : std::string(" eigenpairs")) +
        ", n = " + std::to_string(n) + ", ncv = " + std::to_string(ncv) +
        ", restarts = " + std::to_string(lanczos->num_iterations()) + ", shift = " + impl::to_short_string(shift) +
        "). The smallest eigenvalues form a cluster wider than the " +
        std::to_string(window) + " pairs computed: at this sigma, weak edges split the mesh into many nearly "
        "disconnected patches, each with an eigenvalue near 0. Remedies: a larger sigma, more eigenpairs than the "
        "patches, or the local heat kernel, which does not truncate the spectrum; also check that the mesh has "
        "no degenerate faces.");
  }

  // Back to the generalized problem: phi_perm = R^{-T} y.
  Eigen::MatrixXd Phi = lanczos->eigenvectors(m);
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
  result.iterations = lanczos->num_iterations();
  result.operator_applications = lanczos->num_operations();
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
