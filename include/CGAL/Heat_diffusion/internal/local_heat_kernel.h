// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The edge-weighted heat kernel without eigenpairs and without truncation of the
// spectrum: each column h_t(., j) = [exp(-t B^-1 L) B^-1] e_j is computed on a patch
// grown around v_j, by a Krylov subspace method.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_LOCAL_HEAT_KERNEL_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_LOCAL_HEAT_KERNEL_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The vertices in breadth-first order, one connected component after the other:
// consecutive entries are close on the mesh.
inline std::vector<std::size_t> breadth_first_order(const Indexed_mesh& mesh)
{
  const std::size_t n = mesh.number_of_vertices();
  std::vector<std::size_t> order;
  order.reserve(n);
  std::vector<unsigned char> seen(n, 0);
  for(std::size_t s = 0; s < n; ++s)
  {
    if(seen[s])
      continue;
    seen[s] = 1;
    std::size_t q = order.size();
    order.push_back(s);
    for(; q < order.size(); ++q)
    {
      const std::size_t i = order[q];
      for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
        if(!seen[mesh.fan[k]])
        {
          seen[mesh.fan[k]] = 1;
          order.push_back(mesh.fan[k]);
        }
    }
  }
  return order;
}

// Which mass matrix the local kernel uses. `consistent` is the FEM mass matrix B of
// eq. 11, the operator of the spectral kernel; `lumped` replaces it by its row sums
// M = diag(B 1). Lumping changes the kernel by 2 to 37 % for t in [0.5, 4] on CGAL's
// meshes (8 to 32 % at t = 1; see the user manual), far more than the tolerance, so
// the package uses `consistent`; `lumped` is kept to measure that difference.
enum class Local_kernel_mass { consistent, lumped };

// Columns of the heat kernel H_t = exp(-t B^-1 L) B^-1 of the pencil (L, B), one source
// at a time, without eigenpairs and without truncating the spectrum.
//
// Locality. On the surface rescaled to area = n, the column of v_j decays like a
// Gaussian of the distance to v_j: for t = 1 it is above 1e-4 of its peak on a few
// hundred vertices only, whatever the size of the mesh. The column is computed on a
// patch P around v_j with a zero (absorbing) condition outside: a ball of the metric of
// diffusion_length(), whose radius grows with sqrt(t ln(1/tolerance)). The heat lost
// through the border of the patch measures the truncation: the exact column carries
// the total heat 1^T B h = 1, so |1 - 1^T B_P h_P| is checked against the tolerance and
// the patch is enlarged until it passes (where the sampling changes fast, say).
//
// Krylov subspace. B^-1 L is self-adjoint in the inner product of B, so Lanczos in that
// inner product, started from B_P^-1 e_j, gives a B_P-orthonormal V and a tridiagonal
// T = V^T L_P V with h_P ~ |B_P^-1 e_j|_B V exp(-tT) e_1. Each step solves with B_P,
// through a sparse Cholesky factorisation of the patch. (Krylov subspaces of cheaper
// operators -- the lumped M^-1 L, or B^-1 replaced by a few Chebyshev or Neumann
// terms -- projected on the consistent pencil, stall at 1e-4 to 5e-3: the consistent
// kernel is not a function of those operators on an irregular mesh.) No
// reorthogonalisation: Lanczos approximations of f(A) b are stable under the loss of
// orthogonality (Druskin and Knizhnerman 1991; Musco, Musco and Sidford 2018). The
// subspace grows until the coefficients of the newest vectors fall below the tolerance.
//
// Cost per column: a sparse factorisation of the p x p patch and k steps of O(p)
// (k = 20 to 30 at t = 1); p grows like t, k like sqrt(t). Linear in n for fixed t.
class Local_heat_kernel
{
public:
  typedef Eigen::SparseMatrix<double> Sparse_matrix;

  // The relative accuracy aimed at by default: heat lost through the patch border, and
  // size of the newest Krylov coefficients, relative to the column.
  static constexpr double default_tolerance = 1e-4;

  // Everything one column needs, allocated once per thread and reused: the arrays of
  // size n are stamped with a generation instead of being cleared for every source.
  struct Workspace
  {
    std::vector<std::uint32_t> stamp;  // == generation: the vertex was reached for this source
    std::vector<std::uint32_t> local;  // its row in the patch (or not_in_patch)
    std::vector<double> distance;      // tentative Dijkstra distance
    std::uint32_t generation = 0;

    std::vector<std::uint32_t> patch;  // global indices of the patch, the source first
    std::vector<std::pair<double, std::uint32_t> > heap;
    std::vector<Eigen::Triplet<double> > entries;
    Sparse_matrix stiffness, mass;     // L_P and B_P
    Eigen::VectorXd lumped_mass;       // diag(B 1) on the patch (the global row sums)
    std::unique_ptr<Eigen::SimplicialLDLT<Sparse_matrix, Eigen::Lower, Eigen::AMDOrdering<int> > > cholesky;

    Eigen::MatrixXd basis, mass_times_basis;  // V and B_P V, p x capacity
    std::vector<double> alpha, beta;
    Eigen::VectorXd work, coefficients;
    std::vector<double> values;               // the column on the patch

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
    // The column beyond distance r holds about exp(-r^2 / (6 t)) of its heat (unit
    // weights, in the metric of diffusion_length()). At small t the part B^-1 e_j, which
    // decays like (2 - sqrt 3)^r, can reach farther, and it crosses the creases that a
    // small sigma closes to L: no heat flows there, so the heat balance cannot see it.
    const double log_tolerance = std::log(1. / tolerance);
    initial_radius_ = (std::max)(radius_factor * std::sqrt(time * log_tolerance),
                                 log_tolerance / std::log(2. + std::sqrt(3.)));
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
    w.cholesky = std::make_unique<typename decltype(w.cholesky)::element_type>();
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
  static constexpr double radius_factor = 2.8;

  // Length of the edge ik in the metric in which the kernel spreads like a Gaussian:
  // a random walk with rates w_ik / m_i moves about sqrt(m / w) per unit time. The
  // patch ignores the weights (w = 1): with a small sigma, B still couples the
  // vertices that L separates, and heat crosses sharp creases through the mass matrix.
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
  // in the order they are reached. Leaves the heap empty iff no vertex is left outside.
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
      if(d > radius && w.local[i] == not_in_patch)
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
  }

  // L_P and B_P: the rows and columns of the patch (a zero condition outside).
  void extract_patch_matrices(Workspace& w) const
  {
    const Eigen::Index p = Eigen::Index(w.patch.size());
    w.lumped_mass.resize(p);
    for(int pass = 0; pass < 2; ++pass)
    {
      const Sparse_matrix& global = pass == 0 ? stiffness_ : mass_;
      w.entries.clear();
      for(Eigen::Index a = 0; a < p; ++a)
      {
        for(Sparse_matrix::InnerIterator it(global, Eigen::Index(w.patch[std::size_t(a)])); it; ++it)
        {
          const std::size_t k = std::size_t(it.row());
          if(w.stamp[k] == w.generation && w.local[k] != not_in_patch)
            w.entries.emplace_back(int(w.local[k]), int(a), it.value());
        }
        w.lumped_mass[a] = lumped_mass_[w.patch[std::size_t(a)]];
      }
      Sparse_matrix& local = pass == 0 ? w.stiffness : w.mass;
      local.resize(p, p);
      local.setFromTriplets(w.entries.begin(), w.entries.end());
    }
  }

  // x <- B_P^-1 x (or M^-1 x for the lumped kernel).
  void solve_mass(Workspace& w, Eigen::VectorXd& x) const
  {
    if(mass_kind_ == Local_kernel_mass::lumped)
      x.array() /= w.lumped_mass.array();
    else
      x = w.cholesky->solve(x);
  }

  // Krylov dimension at which convergence is first checked, then every check_step.
  std::size_t first_check() const { return std::size_t(12 + std::ceil(6. * std::sqrt(time_))); }
  static constexpr std::size_t check_step = 4;

  void solve_on_patch(Workspace& w) const
  {
    extract_patch_matrices(w);
    const Eigen::Index p = Eigen::Index(w.patch.size());
    if(mass_kind_ == Local_kernel_mass::consistent)
    {
      w.cholesky->compute(w.mass);
      if(w.cholesky->info() != Eigen::Success)
        throw std::runtime_error("CGAL::Heat_diffusion: the factorisation of a local mass matrix failed");
    }
    Eigen::Index capacity = (std::min)(p, Eigen::Index(first_check() + 2 * check_step));
    w.basis.resize(p, capacity);
    w.mass_times_basis.resize(p, capacity);
    w.alpha.clear();
    w.beta.clear();

    // v_1 = B_P^-1 e_j / beta_0 with beta_0 = |B_P^-1 e_j|_B = sqrt(e_j^T B_P^-1 e_j).
    w.work = Eigen::VectorXd::Unit(p, 0);
    solve_mass(w, w.work);
    const double initial_norm = std::sqrt(w.work[0]);
    w.basis.col(0) = w.work / initial_norm;
    w.mass_times_basis.col(0) = Eigen::VectorXd::Unit(p, 0) / initial_norm;

    Eigen::Index k = 0;  // vectors in the basis
    Eigen::Index next_check = (std::min)(Eigen::Index(first_check()), p);
    Eigen::VectorXd stiffness_times_v(p);
    for(;;)
    {
      // w = B^-1 L v_k - alpha v_k - beta v_k-1, and B w alongside (no extra product).
      stiffness_times_v.noalias() = w.stiffness * w.basis.col(k);
      const double alpha = w.basis.col(k).dot(stiffness_times_v);
      w.alpha.push_back(alpha);
      w.work = stiffness_times_v;
      solve_mass(w, w.work);
      w.work -= alpha * w.basis.col(k);
      Eigen::VectorXd mass_times_work = stiffness_times_v - alpha * w.mass_times_basis.col(k);
      if(k > 0)
      {
        w.work -= w.beta.back() * w.basis.col(k - 1);
        mass_times_work -= w.beta.back() * w.mass_times_basis.col(k - 1);
      }
      ++k;
      const double beta = std::sqrt((std::max)(0., w.work.dot(mass_times_work)));
      const bool exhausted = k == p || !(beta > 1e-12 * std::abs(alpha));
      if(k == next_check || exhausted)
      {
        const double newest = solve_projected(w, k, initial_norm);
        if(newest <= tolerance_ || exhausted)
          break;
        next_check = (std::min)(k + Eigen::Index(check_step), p);
      }
      if(k == capacity)
      {
        capacity = (std::min)(p, 2 * capacity);
        w.basis.conservativeResize(p, capacity);
        w.mass_times_basis.conservativeResize(p, capacity);
      }
      w.beta.push_back(beta);
      w.basis.col(k) = w.work / beta;
      w.mass_times_basis.col(k) = mass_times_work / beta;
    }
    w.krylov_dimension = std::size_t(k);

    // h_P = V c, and the heat it carries, 1^T B_P h_P = (B_P V c) summed.
    w.values.resize(std::size_t(p));
    Eigen::Map<Eigen::VectorXd> h(w.values.data(), p);
    h.noalias() = w.basis.leftCols(k) * w.coefficients;
    const double heat = (w.mass_times_basis.leftCols(k) * w.coefficients).sum();
    w.heat_deficit = std::abs(1. - heat);
  }

  // The coefficients c = beta_0 exp(-tT) e_1 in the basis of the first k vectors, and
  // the relative size of the newest two (the convergence estimate).
  double solve_projected(Workspace& w, Eigen::Index k, double initial_norm) const
  {
    Eigen::VectorXd diagonal(k), subdiagonal((std::max)(k - 1, Eigen::Index(1)));
    for(Eigen::Index a = 0; a < k; ++a)
      diagonal[a] = w.alpha[std::size_t(a)];
    for(Eigen::Index a = 0; a + 1 < k; ++a)
      subdiagonal[a] = w.beta[std::size_t(a)];
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen;
    eigen.computeFromTridiagonal(diagonal, subdiagonal.head(k - 1), Eigen::ComputeEigenvectors);
    const Eigen::VectorXd decay = (-time_ * eigen.eigenvalues().array()).exp();
    w.coefficients =
        eigen.eigenvectors() * (decay.asDiagonal() * eigen.eigenvectors().row(0).transpose()) * initial_norm;
    const double newest = k >= 2 ? std::hypot(w.coefficients[k - 1], w.coefficients[k - 2])
                                 : std::abs(w.coefficients[k - 1]);
    return newest / w.coefficients.norm();
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
