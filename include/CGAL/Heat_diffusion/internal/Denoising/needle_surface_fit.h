// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The surface the denoising returns or starts from on meshes of needle triangles: the
// measure of how needle-like the faces are, the copy of such a mesh smoothed by the
// cotangent flow, and the vertex positions that best fit given face normals in one
// least-squares solve.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NEEDLE_SURFACE_FIT_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NEEDLE_SURFACE_FIT_H

#include <CGAL/Heat_diffusion/internal/Denoising/cotangent_flow.h>
#include <CGAL/Heat_diffusion/internal/Denoising/face_adjacency.h>
#include <CGAL/Heat_diffusion/internal/Denoising/noise_level.h>
#include <CGAL/Heat_diffusion/internal/Denoising/volume_preservation.h>
#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/sparse_cholesky.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Cholesky>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The median over the faces of 2 area / (longest edge)^2: the smallest altitude over
// the longest edge, 0.87 for an equilateral triangle, under 0.17 for a face whose
// smallest angle is under 10 degrees (a needle).
inline double median_face_aspect(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& points)
{
  std::vector<double> aspects;
  aspects.reserve(mesh.triangles.size());
  for(const auto& t : mesh.triangles)
  {
    const Eigen::Vector3d a = points[t[1]] - points[t[0]], b = points[t[2]] - points[t[1]],
                          c = points[t[0]] - points[t[2]];
    const double longest = (std::max)({a.squaredNorm(), b.squaredNorm(), c.squaredNorm()});
    const double aspect = longest > 0 ? a.cross(c).norm() / longest : 0.;
    if(std::isfinite(aspect))
      aspects.push_back(aspect);
  }
  if(aspects.empty())
    return 0.;
  std::nth_element(aspects.begin(), aspects.begin() + std::ptrdiff_t(aspects.size() / 2), aspects.end());
  return aspects[aspects.size() / 2];
}

// The preconditioner of conjugate gradients (an Eigen preconditioner) for a system
// whose unknowns are the three coordinates of each vertex in turn: the inverses of its
// 3 x 3 diagonal blocks. The terms n_f n_f^T of the normal fit couple a vertex's
// coordinates as strongly as its neighbours': the diagonal alone (Jacobi) ignores
// that, and conjugate gradients take about 1.6 times as many iterations with it
// (turbine at 0.1 mean edge length of noise: 356 against 217).
class Vertex_block_preconditioner
{
public:
  Vertex_block_preconditioner() = default;
  template <typename Matrix>
  explicit Vertex_block_preconditioner(const Matrix& matrix)
  {
    compute(matrix);
  }

  template <typename Matrix>
  Vertex_block_preconditioner& analyzePattern(const Matrix&)
  {
    return *this;
  }

  // The blocks of a symmetric positive definite matrix are positive definite; one that
  // is not numerically (the matrix is not what the fit builds) is left out (identity).
  template <typename Matrix>
  Vertex_block_preconditioner& factorize(const Matrix& matrix)
  {
    inverses_.assign(std::size_t(matrix.cols() / 3), Eigen::Matrix3d::Zero());
    for(Eigen::Index column = 0; column < 3 * Eigen::Index(inverses_.size()); ++column)
      for(typename Matrix::InnerIterator it(matrix, column); it; ++it)
        if(it.row() / 3 == column / 3)
          inverses_[std::size_t(column / 3)](it.row() % 3, column % 3) = it.value();
    for(Eigen::Matrix3d& block : inverses_)
    {
      const Eigen::LLT<Eigen::Matrix3d> cholesky(block);
      const Eigen::Matrix3d inverse = cholesky.solve(Eigen::Matrix3d::Identity());
      block = cholesky.info() == Eigen::Success && inverse.allFinite() ? inverse : Eigen::Matrix3d::Identity();
    }
    return *this;
  }

  template <typename Matrix>
  Vertex_block_preconditioner& compute(const Matrix& matrix)
  {
    return factorize(matrix);
  }

  template <typename Vector>
  Eigen::VectorXd solve(const Vector& b) const
  {
    Eigen::VectorXd x = b;
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
  Eigen::SparseMatrix<double> unused;
  std::vector<double> masses;
  cotangent_stiffness(mesh, anchors, unused, masses);
  std::vector<Eigen::Triplet<double> > triplets;
  triplets.reserve(mesh.triangles.size() * 3 * 36 + 3 * n);
  for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
  {
    const auto& t = mesh.triangles[f];
    const double area = 0.5 * (anchors[t[1]] - anchors[t[0]]).cross(anchors[t[2]] - anchors[t[0]]).norm();
    if(!(area > 0) || !std::isfinite(area))
      continue;
    const Eigen::Matrix3d block = area * normals[f] * normals[f].transpose();
    for(int e = 0; e < 3; ++e)
    {
      const Eigen::Index i = Eigen::Index(3 * t[e]), j = Eigen::Index(3 * t[(e + 1) % 3]);
      for(int r = 0; r < 3; ++r)
        for(int c = 0; c < 3; ++c)
        {
          triplets.emplace_back(i + r, i + c, block(r, c));
          triplets.emplace_back(j + r, j + c, block(r, c));
          triplets.emplace_back(i + r, j + c, -block(r, c));
          triplets.emplace_back(j + r, i + c, -block(r, c));
        }
    }
  }
  Eigen::VectorXd rhs(Eigen::Index(3 * n));
  for(std::size_t i = 0; i < n; ++i)
    for(int r = 0; r < 3; ++r)
    {
      triplets.emplace_back(Eigen::Index(3 * i + r), Eigen::Index(3 * i + r), lambda * masses[i]);
      rhs[Eigen::Index(3 * i + r)] = lambda * masses[i] * anchors[i][r];
    }
  Eigen::SparseMatrix<double> system{Eigen::Index(3 * n), Eigen::Index(3 * n)};
  system.setFromTriplets(triplets.begin(), triplets.end());
  // Conjugate gradients from the anchors, to a relative residual of 1e-10: a few hundred
  // sparse products on CGAL's needle meshes, cheaper than the sparse Cholesky
  // factorisation of this 3n system (its fill-in is large), with the same MAD to four
  // digits there; the factorisation if they do not converge.
  Eigen::VectorXd x(Eigen::Index(3 * n));
  for(std::size_t i = 0; i < n; ++i)
    x.segment<3>(Eigen::Index(3 * i)) = anchors[i];
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper, Vertex_block_preconditioner>
      iterative;
  iterative.setTolerance(1e-10);
  iterative.setMaxIterations(Eigen::Index(2000));
  iterative.compute(system);
  if(iterative.info() == Eigen::Success)
    x = iterative.solveWithGuess(rhs, Eigen::VectorXd(x));
  if(iterative.info() != Eigen::Success || !x.allFinite())
  {
    Sparse_cholesky cholesky;
    configure_cholesky(cholesky, system.rows());
    cholesky.compute(system);
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

// Needle meshes (curved surfaces only). A face's normal moves by about the noise over
// its smallest altitude, that is over a times its longest edge, a = 2 area / longest
// edge^2 its aspect (0.87 for an equilateral triangle): where the median aspect a is
// below needle_reference_aspect, the normals are mostly noise, and filtering them
// cannot recover the surface. The needle factor
// nu = (needle_reference_aspect / a)^2 - 1 (0 on well-shaped meshes) grows with the
// square of that amplification of the noise of the normals. There the positions are
// smoothed with the cotangent operator, whose result does not depend on the triangles'
// shape, for the time needle_smoothing_time nu eps^2 (eps the noise level along the
// smoothed normals, see plane_fit_noise_level).
// From nu = 1 on, a smoothed surface, rescaled to the input's volume, is the result
// (this one, the flow stopped by its residual, or their blend: see
// smooth_needle_mesh()); below, the vertices are fitted to its normals in one
// least-squares solve anchored to the input (weight needle_fit_anchor_weight), and the
// normal filter goes on from there. The smoothed surface alone was measured against
// that fit followed by the filter with the benchmark's seeds, at 0.1, 0.3 and 0.5 mean
// edge length of noise along the normals: rotor_small 9.29, 17.4, 25.8 degrees against
// 18.5, 26.1, 32.9; blade 6.65 and 11.2 against 9.71 and 16.5 at 0.3 and 0.5 (at 0.1 it
// is piecewise flat). The aspect is measured on the pilot surface (the input smoothed
// for the time of one squared mean edge length), because noise along the normals alone
// makes well-shaped faces look thin. The constants were chosen on CGAL's needle meshes
// (blade, rotor_small, anchor) for the fit followed by the filter, and checked not to
// change the organic ones (elephant, bunny: nu = 0; armadillo: 0 to 0.03). The stop's
// noise level moves from that of plane_fit_noise_level along the input's normals
// (nu = 0, unchanged behaviour) to that along the smoothed normals (nu >= 1), which is
// the better estimate on needles.
constexpr double needle_reference_aspect = 0.5;
constexpr double needle_smoothing_time = 2.;
constexpr double needle_fit_anchor_weight = 0.01;

// How needle-like a mesh is (see needle_reference_aspect): the needle factor nu, the
// noise level eps along the normals of the pilot surface (plane_fit_noise_level), and
// the time needle_smoothing_time nu eps^2 of its smoothed copy. On a mesh that is not
// one of needles the factor is 0 and the rest 0; a failed estimate leaves `noise` and
// `copy_time` 0. `flow` is the Cotangent_flow of the input.
struct Needle_measure
{
  double factor = 0;
  double noise = 0;
  double copy_time = 0;
};

inline Needle_measure measure_needles(const Indexed_mesh& mesh, const Face_adjacency& adjacency, Cotangent_flow& flow)
{
  Needle_measure result;
  const double mean_edge = mean_edge_length(mesh);
  std::vector<Eigen::Vector3d> pilot;
  if(!(mean_edge > 0) || !std::isfinite(mean_edge) || !flow.smooth(mean_edge * mean_edge, 1, pilot))
    return result;
  const double aspect = median_face_aspect(mesh, pilot);
  if(!(aspect > 0))
    return result;
  const double ratio = needle_reference_aspect / aspect;
  result.factor = (std::max)(0., ratio * ratio - 1.);
  if(result.factor == 0)
    return result;
  const double noise = plane_fit_noise_level(mesh, adjacency, mesh.points, &pilot);
  if(!(noise > 0) || !std::isfinite(noise))
    return result;
  result.noise = noise;
  result.copy_time = needle_smoothing_time * result.factor * noise * noise;
  return result;
}

// The smoothed copy of a mesh of needles: the input smoothed by `flow` (its
// Cotangent_flow) for the copy's time. Returns false, leaving `copy` untouched, if
// there is no such time or the flow fails.
inline bool needle_copy(const Needle_measure& needles, Cotangent_flow& flow, std::vector<Eigen::Vector3d>& copy)
{
  return needles.copy_time > 0 && flow.smooth(needles.copy_time, flow_substeps, copy);
}

// The weight of the needle copy against W, the flow stopped by its residual, where the
// copy's time is the longer and the copy does not shrink the shape (see
// smooth_needle_mesh()). At W's stop the residual's neighbour correlation is
// whiteness_correlation; the fraction f of it that the residual's components along the
// normals of W keep (residual_neighbour_correlation() along them) says what correlates
// it: the sliding of the vertices along the needles (f near 0: the stop came early, and
// the copy's longer time removes more noise) or removed shape (f near 1: the copy would
// remove more shape). The weight is 1 for f <= needle_copy_sliding_fraction, 0 for
// f >= 1, linear between; 0 if the residual is not correlated at all. Measured with the
// benchmark's seeds (f, then the MAD of the copy and of the result): blade, f 0.45 at
// most on its 8 noisy rows, keeps the copy (mean 4.85 degrees; W alone 6.11), and its
// clean mesh (f 1.2 at the stop's shortest time) goes from 1.77 to 0.00;
// couplingdown at 0.1 along the normals and in random directions (f 1.02 and 1.16)
// from 18.91 and 20.66 to 15.76 and 14.89; rotor_small (f 0.58 to 1.09) from a mean of
// 14.51 over its 8 noisy rows to 13.93 (at 0.1 along the normals 10.27 to 8.02, at 0.5
// 20.50 to 20.83). With bounds of 1/5 or 1/2 instead of 1/3, and 0.9 or 1.1 instead of
// 1, no row moves by more than 0.2 degrees.
constexpr double needle_copy_sliding_fraction = 1. / 3;

inline double needle_copy_weight(const Indexed_mesh& mesh, const Face_adjacency& adjacency,
                                 const std::vector<Eigen::Vector3d>& stopped)
{
  const double correlation = residual_neighbour_correlation(mesh, mesh.points, stopped);
  if(!(correlation > 0))
    return 0.;
  std::vector<Eigen::Vector3d> normals;
  area_weighted_normals(mesh, adjacency, stopped, normals);
  const double fraction = residual_neighbour_correlation(mesh, mesh.points, stopped, &normals) / correlation;
  return std::clamp((1. - fraction) / (1. - needle_copy_sliding_fraction), 0., 1.);
}

// The result on a mesh of needles with nu >= 1: a smoothed copy of the input, rescaled
// to its volume (restore_component_volumes()). It is the flow W stopped when its
// residual turns correlated (smooth_until_residual_is_correlated(), `noise` the input's
// noise level eps), or, where the needle copy's time is the longer and the copy does not
// shrink the shape (`shrinks`, a predicate on the copy's points), a blend of the copy and
// W (needle_copy_weight()): the residual's stop is a lower bound, since on needles the
// flow also slides the vertices along the surface, which correlates the residual without
// removing shape (blade: the copy's time is 94 to 183 eps^2, the stop's 26 to 66). The
// copy of a mesh whose parts are a few faces thick, or whose needles span curved holes,
// shrinks them (anchor and cheese, where the noise estimate also counts the shape: eps'
// reads 0.36 to 0.61 mean edge length whatever the noise); W is then the relinearised
// flow (see relinearised_steps), or, if that fails, the flow with the input's operator.
// Measured with the benchmark's seeds, mean MAD over the six noisy rows (0.1, 0.3, 0.5,
// both directions), against the copy for nu >= 2, its blend with weight nu - 1 with the
// filter for 1 <= nu < 2, and the copy's time halved while it shrank the shape: anchor
// 30.3 degrees against 39.1, cheese 20.2 against 36.9, b9_mesh (nu 1.05 to 2.1) 23.0
// against 26.1, turbine in random directions at 0.3 and 0.5 (nu 1.3 and 1.9) 8.13 and
// 10.96 against 19.2 and 22.8. Returns false, leaving `result` untouched, if the flow
// with the input's operator fails.
template <typename Shrinks>
bool smooth_needle_mesh(const Indexed_mesh& mesh, const Face_adjacency& adjacency, double noise,
                        const Needle_measure& needles, Cotangent_flow& flow, const Shrinks& shrinks,
                        std::vector<Eigen::Vector3d>& result)
{
  std::vector<Eigen::Vector3d> smoothed, copy, relinearised;
  double time = 0;
  if(!smooth_until_residual_is_correlated(mesh, noise, flow, smoothed, time))
    return false;
  if(needles.copy_time > time && needle_copy(needles, flow, copy))
  {
    if(!shrinks(copy))
    {
      const double weight = needle_copy_weight(mesh, adjacency, smoothed);
      for(std::size_t i = 0; i < smoothed.size(); ++i)
        smoothed[i] = weight * copy[i] + (1. - weight) * smoothed[i];
    }
    else if(smooth_relinearised_until_residual_is_correlated(mesh, noise, flow, relinearised, time))
      smoothed.swap(relinearised);
  }
  restore_component_volumes(mesh, mesh.points, smoothed);
  result.swap(smoothed);
  return true;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NEEDLE_SURFACE_FIT_H
