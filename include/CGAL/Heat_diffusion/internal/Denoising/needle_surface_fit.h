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
#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/sparse_cholesky.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/IterativeLinearSolvers>
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
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                           Eigen::DiagonalPreconditioner<double> >
      iterative;
  iterative.setTolerance(1e-10);
  iterative.setMaxIterations(Eigen::Index(2000));
  iterative.compute(system);
  if(iterative.info() == Eigen::Success)
    x = iterative.solveWithGuess(rhs, Eigen::VectorXd(x));
  if(iterative.info() != Eigen::Success || !x.allFinite())
  {
    Sparse_cholesky cholesky;
    silence(cholesky);
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
// nu = (needle_reference_aspect / a)^2 - 1 (0 on well-shaped meshes) grows with the square of that amplification of the noise
// of the normals. There the positions are smoothed with the cotangent operator, whose
// result does not depend on the triangles' shape, for the time
// needle_smoothing_time nu eps^2 (eps the noise level along the smoothed normals, see plane_fit_noise_level).
// From nu = 1 on, a smoothed surface, rescaled to the input's volume, is the result
// (this one or the flow stopped by its residual, see filter_normals()); below, the
// vertices are fitted to its normals in one least-squares solve
// anchored to the input (weight needle_fit_anchor_weight), and the normal filter goes
// on from there. The smoothed surface alone was measured against that fit followed by
// the filter with the benchmark's seeds, at 0.1, 0.3 and 0.5 mean edge length of noise
// along the normals: rotor_small 9.29, 17.4, 25.8 degrees against 18.5, 26.1, 32.9;
// blade 6.65 and 11.2 against 9.71 and 16.5 at 0.3 and 0.5 (at 0.1 it is piecewise
// flat). The aspect is measured on the pilot surface (the input smoothed for the time
// of one squared mean edge length), because noise along the normals alone makes
// well-shaped faces look thin. The constants were chosen on CGAL's needle meshes (blade,
// rotor_small, anchor) for the fit followed by the filter, and checked not to change
// the organic ones (elephant, bunny: nu = 0; armadillo: 0 to 0.03). The stop's noise
// level moves from that of plane_fit_noise_level along the input's normals (nu = 0,
// unchanged behaviour) to that along the smoothed normals (nu >= 1), which is the
// better estimate on needles.
constexpr double needle_reference_aspect = 0.5;
constexpr double needle_smoothing_time = 2.;
constexpr double needle_fit_anchor_weight = 0.01;

// The smoothed copy of a mesh of needles (see needle_reference_aspect): the needle
// factor nu, the noise level eps along the normals of the pilot surface
// (plane_fit_noise_level), and the input smoothed with the cotangent operator for the
// time needle_smoothing_time nu eps^2 (`time`). On a mesh that is not one of needles the factor
// is 0 and the rest is left empty; a failed estimate leaves `noise` 0, a failed
// smoothing `points` empty.
struct Needle_smoothing
{
  double factor = 0;
  double noise = 0;
  double time = 0;
  std::vector<Eigen::Vector3d> points;
};

inline Needle_smoothing smooth_needle_mesh(const Indexed_mesh& mesh, const Face_adjacency& adjacency)
{
  Needle_smoothing result;
  const double mean_edge = mean_edge_length(mesh);
  std::vector<Eigen::Vector3d> pilot;
  if(!(mean_edge > 0) || !std::isfinite(mean_edge) ||
     !implicit_smoothing(mesh, mesh.points, mean_edge * mean_edge, pilot))
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
  result.time = needle_smoothing_time * result.factor * noise * noise;
  implicit_smoothing(mesh, mesh.points, result.time, result.points, flow_substeps);
  return result;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NEEDLE_SURFACE_FIT_H
