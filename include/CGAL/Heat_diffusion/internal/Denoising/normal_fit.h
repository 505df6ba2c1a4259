// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The vertex positions that best fit given face normals, in one least-squares solve:
// conjugate gradients on the system applied face by face, preconditioned by each
// vertex's 3 x 3 block.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NORMAL_FIT_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NORMAL_FIT_H

#include <CGAL/Heat_diffusion/internal/Denoising/cotangent_flow.h>
#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/sparse_cholesky.h>
#include <CGAL/Heat_diffusion/internal/vertex_block_matrix.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {
class Normal_fit_system;
} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

// Normal_fit_system is a matrix-free operator of Eigen's iterative solvers, which
// take it for a sparse matrix.
namespace Eigen {
namespace internal {
template <>
struct traits<CGAL::Heat_diffusion::internal::Normal_fit_system> : public traits<Eigen::SparseMatrix<double> >
{
};
} // namespace internal
} // namespace Eigen

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The matrix of the normal fit (see fit_vertices_to_normals_least_squares()),
// A = sum_f a_f sum_{edges ij of f} E_ij^T n_f n_f^T E_ij + diag(w_i) (x) I_3, where
// E_ij x = x_j - x_i and the unknowns are the three coordinates of each vertex in turn,
// applied face by face without being assembled: face f adds
// a_f (n_f . (2 x_i - x_j - x_k)) n_f at each of its corners i. A product reads each
// face's normal, area and corners once, where the assembled matrix has a 3 x 3 block,
// and an index per entry, for each vertex and each of its neighbours.
class Normal_fit_system : public Eigen::EigenBase<Normal_fit_system>
{
public:
  typedef double Scalar;
  typedef double RealScalar;
  typedef int StorageIndex;
  enum
  {
    ColsAtCompileTime = Eigen::Dynamic,
    MaxColsAtCompileTime = Eigen::Dynamic,
    IsRowMajor = false
  };

  // The faces whose area is not positive and finite add nothing. `mesh`, `normals` and
  // `anchor_weights` are kept by reference.
  Normal_fit_system(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& normals,
                    const std::vector<double>& areas, const std::vector<double>& anchor_weights)
      : mesh_(mesh), normals_(normals), areas_(areas), anchor_weights_(anchor_weights)
  {
    for(double& area : areas_)
      if(!(area > 0) || !std::isfinite(area))
        area = 0;
  }

  Eigen::Index rows() const { return Eigen::Index(3 * anchor_weights_.size()); }
  Eigen::Index cols() const { return rows(); }

  template <typename Rhs>
  Eigen::Product<Normal_fit_system, Rhs, Eigen::AliasFreeProduct> operator*(const Eigen::MatrixBase<Rhs>& x) const
  {
    return Eigen::Product<Normal_fit_system, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
  }

  // y += A x.
  template <typename Result, typename Vector>
  void add_product(Result& y, const Vector& x) const
  {
    for(std::size_t f = 0; f < areas_.size(); ++f)
    {
      if(areas_[f] == 0)
        continue;
      const auto& t = mesh_.triangles[f];
      const Eigen::Vector3d& n = normals_[f];
      double s[3];
      for(int c = 0; c < 3; ++c)
        s[c] = n.dot(x.template segment<3>(Eigen::Index(3 * t[c])));
      const double sum = s[0] + s[1] + s[2];
      for(int c = 0; c < 3; ++c)
        y.template segment<3>(Eigen::Index(3 * t[c])) += (areas_[f] * (3. * s[c] - sum)) * n;
    }
    for(std::size_t i = 0; i < anchor_weights_.size(); ++i)
      y.template segment<3>(Eigen::Index(3 * i)) += anchor_weights_[i] * x.template segment<3>(Eigen::Index(3 * i));
  }

  // The 3 x 3 blocks of A on its diagonal: sum over the faces f at i of 2 a_f n_f n_f^T
  // (i is on two edges of f), plus w_i I.
  std::vector<Eigen::Matrix3d> diagonal_blocks() const
  {
    std::vector<Eigen::Matrix3d> blocks(anchor_weights_.size());
    for(std::size_t i = 0; i < blocks.size(); ++i)
      blocks[i] = anchor_weights_[i] * Eigen::Matrix3d::Identity();
    for(std::size_t f = 0; f < areas_.size(); ++f)
      if(areas_[f] != 0)
      {
        const Eigen::Matrix3d block = (2. * areas_[f]) * normals_[f] * normals_[f].transpose();
        for(std::size_t i : mesh_.triangles[f])
          blocks[i] += block;
      }
    return blocks;
  }

  // A in compressed columns.
  Eigen::SparseMatrix<double> assembled() const
  {
    Vertex_block_matrix<3> matrix(mesh_);
    for(std::size_t f = 0; f < areas_.size(); ++f)
    {
      if(areas_[f] == 0)
        continue;
      const auto& t = mesh_.triangles[f];
      const Eigen::Matrix3d block = areas_[f] * normals_[f] * normals_[f].transpose();
      for(int e = 0; e < 3; ++e)
      {
        const std::size_t i = t[e], j = t[(e + 1) % 3];
        matrix.add(i, i, block);
        matrix.add(j, j, block);
        matrix.add(i, j, -block);
        matrix.add(j, i, -block);
      }
    }
    for(std::size_t i = 0; i < anchor_weights_.size(); ++i)
      matrix.add(i, i, anchor_weights_[i] * Eigen::Matrix3d::Identity());
    return std::move(matrix.matrix());
  }

private:
  const Indexed_mesh& mesh_;
  const std::vector<Eigen::Vector3d>& normals_;
  std::vector<double> areas_;
  const std::vector<double>& anchor_weights_;
};

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

// The product of Normal_fit_system with a vector, as Eigen's solvers compute it.
namespace Eigen {
namespace internal {
template <typename Rhs>
struct generic_product_impl<CGAL::Heat_diffusion::internal::Normal_fit_system, Rhs, SparseShape, DenseShape,
                            GemvProduct>
    : generic_product_impl_base<CGAL::Heat_diffusion::internal::Normal_fit_system, Rhs,
                                generic_product_impl<CGAL::Heat_diffusion::internal::Normal_fit_system, Rhs> >
{
  typedef typename Product<CGAL::Heat_diffusion::internal::Normal_fit_system, Rhs>::Scalar Scalar;

  // dst += alpha A rhs
  template <typename Dest>
  static void scaleAndAddTo(Dest& dst, const CGAL::Heat_diffusion::internal::Normal_fit_system& lhs, const Rhs& rhs,
                            const Scalar& alpha)
  {
    if(alpha == Scalar(1))
      lhs.add_product(dst, rhs);
    else
    {
      Matrix<double, Dynamic, 1> product = Matrix<double, Dynamic, 1>::Zero(dst.rows());
      lhs.add_product(product, rhs);
      dst += alpha * product;
    }
  }
};
} // namespace internal
} // namespace Eigen

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The preconditioner of conjugate gradients (an Eigen preconditioner) for the normal
// fit: the inverses of the 3 x 3 blocks of each vertex on the diagonal. The terms
// n_f n_f^T couple a vertex's coordinates as strongly as its neighbours': the diagonal
// alone (Jacobi) ignores that, and conjugate gradients take about 1.6 times as many
// iterations with it (turbine at 0.1 mean edge length of noise: 356 against 217).
class Vertex_block_preconditioner
{
public:
  Vertex_block_preconditioner() = default;
  explicit Vertex_block_preconditioner(const Normal_fit_system& system) { compute(system); }

  Vertex_block_preconditioner& analyzePattern(const Normal_fit_system&) { return *this; }

  // The blocks are positive definite where the system is; one that is not numerically
  // is left out (identity).
  Vertex_block_preconditioner& factorize(const Normal_fit_system& system)
  {
    inverses_ = system.diagonal_blocks();
    for(Eigen::Matrix3d& block : inverses_)
    {
      const Eigen::LLT<Eigen::Matrix3d> cholesky(block);
      const Eigen::Matrix3d inverse = cholesky.solve(Eigen::Matrix3d::Identity());
      block = cholesky.info() == Eigen::Success && inverse.allFinite() ? inverse : Eigen::Matrix3d::Identity();
    }
    return *this;
  }

  Vertex_block_preconditioner& compute(const Normal_fit_system& system) { return factorize(system); }

  template <typename Vector>
  Eigen::VectorXd solve(const Vector& b) const
  {
    Eigen::VectorXd x(b.size());
    for(std::size_t i = 0; i < inverses_.size(); ++i)
      x.segment<3>(Eigen::Index(3 * i)) = inverses_[i] * b.template segment<3>(Eigen::Index(3 * i));
    return x;
  }

  Eigen::ComputationInfo info() const { return Eigen::Success; }

private:
  std::vector<Eigen::Matrix3d> inverses_;
};

// The vertex positions that best fit the face normals `normals` in one solve:
// x = argmin sum_f a_f sum_{edges ij of f} (n_f . (x_j - x_i))^2 + lambda sum_i m_i |x_i - y_i|^2,
// a_f the areas and m_i the barycentric masses of `anchors` (y), a sparse symmetric
// positive definite system of 3n unknowns. The explicit update of Sun et al. moves a
// vertex by a fraction of its faces' misfit per step, and needs hundreds of steps where
// the faces are needles; the solve fits all the faces at once. The anchors hold the
// tangential positions, which the normals leave free, and the scale. Both terms are
// lengths to the fourth power: lambda has no unit. Returns false, leaving `points`
// untouched, if neither the iterative solve nor the factorisation succeeds.
inline bool fit_vertices_to_normals_least_squares(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& normals,
                                                  const std::vector<Eigen::Vector3d>& anchors, double lambda,
                                                  std::vector<Eigen::Vector3d>& points)
{
  const std::size_t n = anchors.size();
  std::vector<double> areas(mesh.triangles.size());
  for(std::size_t f = 0; f < areas.size(); ++f)
  {
    const auto& t = mesh.triangles[f];
    areas[f] = 0.5 * (anchors[t[1]] - anchors[t[0]]).cross(anchors[t[2]] - anchors[t[0]]).norm();
  }
  std::vector<double> anchor_weights = barycentric_masses(mesh, anchors);
  for(double& weight : anchor_weights)
    weight *= lambda;
  const Normal_fit_system system(mesh, normals, areas, anchor_weights);
  Eigen::VectorXd rhs(Eigen::Index(3 * n));
  for(std::size_t i = 0; i < n; ++i)
    rhs.segment<3>(Eigen::Index(3 * i)) = anchor_weights[i] * anchors[i];
  // Conjugate gradients from the anchors, to a relative residual of 1e-10: a few hundred
  // products on CGAL's needle meshes, cheaper than the sparse Cholesky factorisation of
  // this 3n system (its fill-in is large), with the same MAD to four digits there; the
  // factorisation if they do not converge.
  Eigen::VectorXd x(Eigen::Index(3 * n));
  for(std::size_t i = 0; i < n; ++i)
    x.segment<3>(Eigen::Index(3 * i)) = anchors[i];
  Eigen::ConjugateGradient<Normal_fit_system, Eigen::Lower | Eigen::Upper, Vertex_block_preconditioner> iterative;
  iterative.setTolerance(1e-10);
  iterative.setMaxIterations(Eigen::Index(2000));
  iterative.compute(system);
  x = iterative.solveWithGuess(rhs, Eigen::VectorXd(x));
  if(iterative.info() != Eigen::Success || !x.allFinite())
  {
    const Eigen::SparseMatrix<double> matrix = system.assembled();
    Sparse_cholesky cholesky;
    configure_cholesky(cholesky, matrix.rows());
    cholesky.compute(matrix);
    if(cholesky.info() != Eigen::Success)
      return false;
    x = cholesky.solve(rhs);
    if(cholesky.info() != Eigen::Success || !x.allFinite())
      return false;
  }
  points.resize(n);
  for(std::size_t i = 0; i < n; ++i)
    points[i] = x.segment<3>(Eigen::Index(3 * i));
  return true;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NORMAL_FIT_H
