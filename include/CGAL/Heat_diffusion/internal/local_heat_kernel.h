// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The edge-weighted heat kernel without eigenpairs and without truncation of the
// spectrum: each column h_t(., j) = [exp(-t B^-1 L) B^-1] e_j is computed on a patch
// grown around v_j, by a Krylov subspace method.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_LOCAL_HEAT_KERNEL_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_LOCAL_HEAT_KERNEL_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Which mass matrix the local kernel uses. `consistent` is the FEM mass matrix B of
// eq. 11, the operator of the spectral kernel; `lumped` replaces it by its row sums
// (a diagonal matrix) and is kept to measure what lumping costs in accuracy.
enum class Local_kernel_mass { consistent, lumped };

// Columns of the heat kernel H_t = exp(-t B^-1 L) B^-1 of the pencil (L, B), one source
// at a time, without eigenpairs.
//
// Locality. On the surface rescaled to area = n, the column of v_j decays like a
// Gaussian of the distance to v_j: for t = 1 it is above 1e-5 of its peak on about 150
// vertices only, whatever the size of the mesh. The column is computed on a patch P
// around v_j with a zero (absorbing) condition outside: a ball of the diffusion metric
// below, whose radius grows with sqrt(t ln(1/tolerance)). The heat the patch loses
// through its border measures the truncation: the exact column carries a total heat
// 1^T B h = 1, so 1 - 1^T B_P h_P is checked against the tolerance, and the patch is
// enlarged when it is too small (a mesh whose sampling changes fast, say).
//
// Krylov subspace. With the lumped mass M = diag(B 1), S = M^-1/2 L_P M^-1/2 is
// symmetric and cheap to apply. Lanczos on S from e_j (with full reorthogonalisation,
// so that the basis stays orthonormal) gives an orthonormal Q and a tridiagonal
// T = Q^T S Q. The *consistent* pencil is then projected on V = M^-1/2 Q (a Galerkin,
// or Rayleigh-Ritz, step): L_V = T, B_V = Q^T (M^-1/2 B_P M^-1/2) Q, and
//   h_P = V exp(-t B_V^-1 L_V) B_V^-1 V^T e_j ,
// which is the Galerkin solution of B u' = -L u, B u(0) = e_j on span V. No linear
// system with B is ever solved, and the eigenvalues of M^-1 B lie in [1/4, 1] (they do
// on every triangle), so B_V is well conditioned. The subspace grows until the
// coefficients of its newest vectors fall below the tolerance. (Krylov with B^-1 L
// itself would need an inner solve with B at every step, 10-15 times the work.)
//
// Cost per column: O(k p) for the patch of p vertices and k Krylov vectors, plus O(k^3)
// for the projected problem; p grows like t, k like sqrt(t). Linear in n for fixed t.
class Local_heat_kernel
{
public:
  typedef Eigen::SparseMatrix<double> Sparse_matrix;

  // The relative accuracy aimed at by default: heat lost through the patch border,
  // and size of the newest Krylov coefficients, relative to the column.
  static constexpr double default_tolerance = 1e-5;

  // Everything one column needs, allocated once per thread and reused: the arrays of
  // size n are stamped with a generation instead of being cleared for every source.
  struct Workspace
  {
    std::vector<std::uint32_t> stamp;      // == generation: the vertex was reached for this source
    std::vector<std::uint32_t> local;      // its row in the patch (or not_in_patch)
    std::vector<double> distance;          // tentative Dijkstra distance
    std::uint32_t generation = 0;

    std::vector<std::uint32_t> patch;      // global indices of the patch, the source first
    std::vector<std::pair<double, std::uint32_t> > heap;
    // The patch matrices in compressed rows, symmetric scaled by M^-1/2: S and B~.
    std::vector<std::uint32_t> row_begin, column;
    std::vector<double> stiffness, mass;
    std::vector<double> inverse_root_mass;  // M^-1/2 on the patch
    std::vector<double> patch_mass_row_sum; // (B_P 1)_i, for the heat balance

    std::vector<double> basis, mass_times_basis;  // Q and B~ Q, column-major p x capacity
    std::vector<double> alpha, beta;
    Eigen::MatrixXd projected_mass;               // B_V, grown as vectors come
    std::vector<double> values;                   // the column on the patch

    // What the last column needed (for statistics and tests).
    std::size_t krylov_dimension = 0;
    std::size_t enlargements = 0;
    double heat_deficit = 0;
  };

  static constexpr std::uint32_t not_in_patch = (std::numeric_limits<std::uint32_t>::max)();

  Local_heat_kernel(const Indexed_mesh& mesh, const Sparse_matrix& stiffness, const Sparse_matrix& mass,
                    double time, double tolerance = default_tolerance,
                    Local_kernel_mass mass_kind = Local_kernel_mass::consistent)
    : mesh_(mesh), stiffness_(stiffness), mass_(mass), time_(time), tolerance_(tolerance), mass_kind_(mass_kind)
  {
    const std::size_t n = mesh.number_of_vertices();
    lumped_mass_.assign(n, 0.);
    for(Eigen::Index j = 0; j < mass.outerSize(); ++j)
      for(Sparse_matrix::InnerIterator it(mass, j); it; ++it)
        lumped_mass_[std::size_t(it.row())] += it.value();
    // The Gaussian tail of the column beyond distance r is about exp(-r^2 / (c t)) of
    // its heat, with c = 6 for unit weights in the metric of diffusion_length().
    initial_radius_ = radius_factor * std::sqrt(time * std::log(1. / tolerance));
  }

  double time() const { return time_; }
  double tolerance() const { return tolerance_; }

  Workspace make_workspace() const
  {
    Workspace w;
    const std::size_t n = mesh_.number_of_vertices();
    w.stamp.assign(n, 0);
    w.local.assign(n, not_in_patch);
    w.distance.assign(n, 0.);
    return w;
  }

  // Computes h_t(i, j) for i in a patch around j. Afterwards `value(w, i)` is h_t(i, j)
  // (0 outside the patch), and w.patch / w.values list the patch.
  void compute_column(std::size_t j, Workspace& w) const
  {
    double radius = initial_radius_;
    w.enlargements = 0;
    for(;;)
    {
      grow_patch(j, radius, w);
      const bool whole_component = w.heap.empty();
      solve_on_patch(w);
      if(w.heat_deficit <= tolerance_ || whole_component)
        return;
      radius *= 1.25;
      ++w.enlargements;
    }
  }

  static double value(const Workspace& w, std::size_t i)
  {
    if(w.stamp[i] != w.generation || w.local[i] == not_in_patch)
      return 0.;
    return w.values[w.local[i]];
  }

private:
  static constexpr double radius_factor = 2.5;

  // Length of the edge ij in the metric in which the kernel spreads like a Gaussian of
  // unit diffusivity: a random walk with rate w_ij / m_i moves about sqrt(m / w) per
  // unit time. The patch ignores the weights (w = 1): with a small sigma, B still
  // couples the vertices that L separates, so heat crosses sharp creases through the
  // mass matrix.
  double diffusion_length(std::size_t i, std::size_t k) const
  {
    return std::sqrt(0.5 * (lumped_mass_[i] + lumped_mass_[k]));
  }

  void next_generation(Workspace& w) const
  {
    if(++w.generation == 0)  // wrapped around: the stamps would lie
    {
      std::fill(w.stamp.begin(), w.stamp.end(), 0u);
      w.generation = 1;
    }
  }

  // The patch: the vertices at distance <= radius from j (Dijkstra over the edges of L),
  // in the order they are reached. Leaves the heap non-empty if vertices remain outside.
  void grow_patch(std::size_t j, double radius, Workspace& w) const
  {
    next_generation(w);
    w.patch.clear();
    w.heap.clear();
    auto reach = [&](std::size_t i, double d) {
      if(w.stamp[i] != w.generation)
      {
        w.stamp[i] = w.generation;
        w.local[i] = not_in_patch;
        w.distance[i] = d;
      }
      else if(d < w.distance[i])
        w.distance[i] = d;
      else
        return;
      w.heap.emplace_back(-d, std::uint32_t(i));
      std::push_heap(w.heap.begin(), w.heap.end());
    };
    reach(j, 0.);
    while(!w.heap.empty())
    {
      const double d = -w.heap.front().first;
      const std::size_t i = w.heap.front().second;
      if(d > radius)
        break;
      std::pop_heap(w.heap.begin(), w.heap.end());
      w.heap.pop_back();
      if(w.local[i] != not_in_patch || d > w.distance[i])
        continue;  // a stale entry
      w.local[i] = std::uint32_t(w.patch.size());
      w.patch.push_back(std::uint32_t(i));
      for(Sparse_matrix::InnerIterator it(stiffness_, Eigen::Index(i)); it; ++it)
      {
        const std::size_t k = std::size_t(it.row());
        if(k != i && (w.stamp[k] != w.generation || w.local[k] == not_in_patch))
          reach(k, d + diffusion_length(i, k));
      }
    }
    // drop stale entries, so that an empty heap means "nothing left outside"
    while(!w.heap.empty())
    {
      const std::size_t i = w.heap.front().second;
      if(w.local[i] == not_in_patch)
        break;
      std::pop_heap(w.heap.begin(), w.heap.end());
      w.heap.pop_back();
    }
  }

  void extract_patch_matrices(Workspace& w) const
  {
    const std::size_t p = w.patch.size();
    w.row_begin.assign(1, 0);
    w.column.clear();
    w.stiffness.clear();
    w.mass.clear();
    w.inverse_root_mass.resize(p);
    w.patch_mass_row_sum.assign(p, 0.);
    for(std::size_t a = 0; a < p; ++a)
      w.inverse_root_mass[a] = 1. / std::sqrt(lumped_mass_[w.patch[a]]);
    // L and B are symmetric with the same pattern (the mesh edges and the diagonal):
    // column a of each is row a.
    for(std::size_t a = 0; a < p; ++a)
    {
      const Eigen::Index g = Eigen::Index(w.patch[a]);
      Sparse_matrix::InnerIterator l(stiffness_, g), b(mass_, g);
      for(; l; ++l)
      {
        const std::size_t k = std::size_t(l.row());
        while(b && b.row() < l.row())
          ++b;
        const double mass_value = (b && b.row() == l.row()) ? b.value() : 0.;
        if(w.stamp[k] != w.generation || w.local[k] == not_in_patch)
          continue;
        const std::uint32_t c = w.local[k];
        const double scale = w.inverse_root_mass[a] * w.inverse_root_mass[c];
        w.column.push_back(c);
        w.stiffness.push_back(l.value() * scale);
        w.mass.push_back(mass_value * scale);
        w.patch_mass_row_sum[a] += mass_value;
      }
      w.row_begin.push_back(std::uint32_t(w.column.size()));
    }
  }

  // y = A x for the patch matrix A (`values` = w.stiffness or w.mass).
  static void multiply(const Workspace& w, const std::vector<double>& values, const double* x, double* y)
  {
    const std::size_t p = w.patch.size();
    for(std::size_t a = 0; a < p; ++a)
    {
      double sum = 0;
      for(std::uint32_t e = w.row_begin[a]; e < w.row_begin[a + 1]; ++e)
        sum += values[e] * x[w.column[e]];
      y[a] = sum;
    }
  }

  // Krylov dimension at which convergence is first checked, then every `check_step`.
  std::size_t first_check() const
  {
    return std::size_t(8 + std::ceil(4. * std::sqrt(time_)));
  }
  static constexpr std::size_t check_step = 4;

  void solve_on_patch(Workspace& w) const
  {
    extract_patch_matrices(w);
    const std::size_t p = w.patch.size();
    std::size_t capacity = (std::min)(p, first_check() + 2 * check_step);
    w.basis.assign(p * capacity, 0.);
    w.mass_times_basis.assign(p * capacity, 0.);
    w.alpha.clear();
    w.beta.clear();
    w.basis[0] = 1.;  // q_1 = e_j: the source is the first vertex of the patch
    std::size_t k = 0;   // vectors in the basis
    std::size_t next_check = (std::min)(first_check(), p);
    Eigen::VectorXd coefficients;
    std::vector<double> residual(p);
    for(;;)
    {
      // Lanczos step on q_k (0-based index k): residual = S q_k - alpha q_k - beta q_k-1,
      // then reorthogonalised against the whole basis.
      const double* q = &w.basis[k * p];
      multiply(w, w.stiffness, q, residual.data());
      double alpha = 0;
      for(std::size_t a = 0; a < p; ++a)
        alpha += q[a] * residual[a];
      w.alpha.push_back(alpha);
      multiply(w, w.mass, q, &w.mass_times_basis[k * p]);
      ++k;
      // Classical Gram-Schmidt against the whole basis (which also removes alpha q_k
      // and beta q_k-1), repeated when it cancelled much of the vector (Kahan-Parlett:
      // twice is enough).
      Eigen::Map<Eigen::VectorXd> r(residual.data(), Eigen::Index(p));
      Eigen::Map<const Eigen::MatrixXd> Q(w.basis.data(), Eigen::Index(p), Eigen::Index(k));
      const double before = r.norm();
      r -= Q * (Q.transpose() * r).eval();
      double beta = r.norm();
      if(beta < 0.7 * before)
      {
        r -= Q * (Q.transpose() * r).eval();
        beta = r.norm();
      }
      const bool exhausted = k == p || !(beta > 1e-12 * (std::abs(alpha) + (w.beta.empty() ? 0. : w.beta.back())));

      if(k == next_check || exhausted)
      {
        const double change = solve_projected(w, k, coefficients);
#ifdef LHK_DEBUG
        std::cerr << "  k " << k << " change " << change << " p " << p << "\n";
#endif
        if(change <= tolerance_ || exhausted)
          break;
        next_check = (std::min)(k + check_step, p);
      }
      if(k == capacity)
      {
        capacity = (std::min)(p, 2 * capacity);
        w.basis.resize(p * capacity, 0.);
        w.mass_times_basis.resize(p * capacity, 0.);
      }
      w.beta.push_back(beta);
      Eigen::Map<Eigen::VectorXd>(&w.basis[k * p], Eigen::Index(p)) = r / beta;
    }
    w.krylov_dimension = k;

    // h_P = M^-1/2 Q c, and the heat it carries, 1^T B_P h_P.
    w.values.assign(p, 0.);
    Eigen::Map<Eigen::VectorXd> h(w.values.data(), Eigen::Index(p));
    h = Eigen::Map<const Eigen::MatrixXd>(w.basis.data(), Eigen::Index(p), Eigen::Index(k)) * coefficients;
    double heat = 0;
    for(std::size_t a = 0; a < p; ++a)
    {
      w.values[a] *= w.inverse_root_mass[a];
      heat += w.patch_mass_row_sum[a] * w.values[a];
    }
    w.heat_deficit = std::abs(1. - heat);
  }

  // The coefficients c of h_P = M^-1/2 Q c in the basis of the first k vectors, and
  // the relative size of the newest ones (the convergence estimate).
  double solve_projected(Workspace& w, std::size_t k, Eigen::VectorXd& c) const
  {
    const std::size_t p = w.patch.size();
    const Eigen::Index K = Eigen::Index(k);
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(K, K);
    for(Eigen::Index a = 0; a < K; ++a)
    {
      T(a, a) = w.alpha[std::size_t(a)];
      if(a + 1 < K)
        T(a, a + 1) = T(a + 1, a) = w.beta[std::size_t(a)];
    }
    const double source_scale = w.inverse_root_mass[0];  // V^T e_j = M_jj^-1/2 e_1
    if(mass_kind_ == Local_kernel_mass::lumped)
    {
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(T);
      const Eigen::VectorXd decay = (-time_ * eigen.eigenvalues().array()).exp();
      c = eigen.eigenvectors() * (decay.asDiagonal() * eigen.eigenvectors().row(0).transpose()) * source_scale;
    }
    else
    {
      const Eigen::Map<const Eigen::MatrixXd> Q(w.basis.data(), Eigen::Index(p), K);
      const Eigen::Map<const Eigen::MatrixXd> BQ(w.mass_times_basis.data(), Eigen::Index(p), K);
      Eigen::MatrixXd projected_mass = Q.transpose() * BQ;
      projected_mass = 0.5 * (projected_mass + projected_mass.transpose()).eval();
      const Eigen::LLT<Eigen::MatrixXd> cholesky(projected_mass);
      const auto C = cholesky.matrixL();
      // S_V = C^-1 T C^-T; exp(-t B_V^-1 T) B_V^-1 = C^-T exp(-t S_V) C^-1.
      const Eigen::MatrixXd X = C.solve(T);
      Eigen::MatrixXd S = C.solve(X.transpose());
      S = 0.5 * (S + S.transpose()).eval();
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(S);
      const Eigen::VectorXd decay = (-time_ * eigen.eigenvalues().array()).exp();
      Eigen::VectorXd x = Eigen::VectorXd::Unit(K, 0);
      x = C.solve(x);
      const Eigen::VectorXd y = eigen.eigenvectors() * (decay.asDiagonal() * (eigen.eigenvectors().transpose() * x));
      c = cholesky.matrixU().solve(y) * source_scale;
    }
    const double newest = K >= 2 ? std::hypot(c[K - 1], c[K - 2]) : std::abs(c[K - 1]);
    return newest / c.norm();
  }

  const Indexed_mesh& mesh_;
  const Sparse_matrix& stiffness_;
  const Sparse_matrix& mass_;
  double time_;
  double tolerance_;
  Local_kernel_mass mass_kind_;
  std::vector<double> lumped_mass_;
  double initial_radius_ = 0;
};

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_LOCAL_HEAT_KERNEL_H
