// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The columns h_t(., j) of the heat kernel, as the heat regions read them: one
// evaluator per way of computing the kernel, all with the same small interface.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_KERNEL_COLUMNS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_KERNEL_COLUMNS_H

#include <CGAL/Heat_diffusion/internal/heat_operators.h>
#include <CGAL/Heat_diffusion/internal/local_heat_kernel.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The interface of a column evaluator `Columns`, which `build_heat_regions()` uses:
//   typename Columns::Workspace            the scratch of one thread
//   Workspace make_workspace() const
//   void prepare(std::size_t j, Workspace&) const    before the values of column j
//   double operator()(std::size_t j, std::size_t i, Workspace&) const    h_t(j, i)
//   bool relative() const                   the threshold is relative to the peak h_t(j, j)
//                                           (eq. 14's kernel) rather than absolute
// prepare() may do the work of a whole group of sources (the local kernel's clusters):
// the sources come group after group.

// `dot` times the scale-invariant kernel's factor beta_ij (eq. 14), or `dot` itself
// when `mass_diagonal` is null (the plain kernel).
inline double kernel_factor(const Eigen::VectorXd* mass_diagonal, std::size_t i, std::size_t j, double dot)
{
  return mass_diagonal != nullptr ? scale_invariant_factor(*mass_diagonal, i, j) * dot : dot;
}

// The spectral kernel: h_t(j, i) = (beta_ij) Psi_i . Psi_j with Psi = Phi exp(-rate t / 2),
// row-major, so that an evaluation reads two contiguous rows.
struct Spectral_columns
{
  struct Workspace {};
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> psi;
  const Eigen::VectorXd* mass_diagonal;  // eq. 14, or null

  bool relative() const { return mass_diagonal != nullptr; }
  Workspace make_workspace() const { return Workspace(); }
  void prepare(std::size_t, Workspace&) const {}
  double operator()(std::size_t j, std::size_t i, Workspace&) const
  {
    return kernel_factor(mass_diagonal, i, j, psi.row(Eigen::Index(i)).dot(psi.row(Eigen::Index(j))));
  }
};

// The same kernel from the factors of a coarse level, eigenvectors = P C: then
// psi_i = sum_a P(i, a) psi^c_a with psi^c = C exp(-rate t / 2) (coarse x m), and
// h_t(j, i) = sum_a P(i, a) (psi^c_a . psi_j). The fine vertices of a region share a
// few coarse vertices, whose dot products with psi_j are computed once per source:
// no n x m copy of the eigenvectors, and far fewer m-long dot products.
struct Coarse_spectral_columns
{
  struct Workspace
  {
    Eigen::VectorXd psi_j;
    std::vector<double> dots;  // psi^c_a . psi_j, valid where stamp[a] == generation
    std::vector<std::size_t> stamp;
    std::size_t generation = 0;
  };
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> psi;  // coarse x m
  const Eigen::SparseMatrix<double, Eigen::RowMajor>* prolongation;
  const Eigen::VectorXd* mass_diagonal;  // eq. 14, or null

  bool relative() const { return mass_diagonal != nullptr; }
  Workspace make_workspace() const
  {
    Workspace w;
    w.psi_j.resize(psi.cols());
    w.dots.assign(std::size_t(psi.rows()), 0.);
    w.stamp.assign(std::size_t(psi.rows()), 0);
    return w;
  }
  void prepare(std::size_t j, Workspace& w) const
  {
    w.psi_j.setZero();
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(*prolongation, Eigen::Index(j)); it; ++it)
      w.psi_j.noalias() += it.value() * psi.row(it.index()).transpose();
    ++w.generation;
  }
  // (computes the dot products of the coarse vertices of v_i on first use: hence the
  // workspace is not const)
  double operator()(std::size_t j, std::size_t i, Workspace& w) const
  {
    double dot = 0;
    for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(*prolongation, Eigen::Index(i)); it; ++it)
    {
      const std::size_t a = std::size_t(it.index());
      if(w.stamp[a] != w.generation)
      {
        w.dots[a] = psi.row(it.index()).dot(w.psi_j);
        w.stamp[a] = w.generation;
      }
      dot += it.value() * w.dots[a];
    }
    return kernel_factor(mass_diagonal, i, j, dot);
  }
};

// The local kernel: h_t(j, i) = h_t(i, j) from the column of v_j, computed on its patch
// by prepare(), with the patches and factorisations of v_j's cluster.
struct Local_columns
{
  typedef Local_heat_kernel::Workspace Workspace;
  const Local_heat_kernel& kernel;

  static constexpr bool relative() { return false; }  // the absolute threshold

  Workspace make_workspace() const { return kernel.make_workspace(); }
  void prepare(std::size_t j, Workspace& w) const { kernel.compute_column(j, w); }
  double operator()(std::size_t, std::size_t i, Workspace& w) const { return Local_heat_kernel::value(w, i); }
};

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_KERNEL_COLUMNS_H
