// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The implicit mean curvature flow with the cotangent operator that denoise_mesh() uses
// where normal filtering cannot (meshes of needles, eroded thin walls), and the rule that
// ends it: the flow stops when what it has removed stops looking like noise.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_COTANGENT_FLOW_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_COTANGENT_FLOW_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/sparse_cholesky.h>
#include <CGAL/Heat_diffusion/internal/vertex_block_matrix.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The barycentric vertex masses of `points`: a third of the area of each incident
// triangle. A vertex without area (isolated, or on degenerate faces only) keeps a small
// mass, so that the systems built on them stay definite and leave it where it is.
inline std::vector<double> barycentric_masses(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& points)
{
  const std::size_t n = points.size();
  std::vector<double> masses(n, 0.);
  for(const auto& t : mesh.triangles)
  {
    const double area = 0.5 * (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).norm();
    if(std::isfinite(area))
      for(int c = 0; c < 3; ++c)
        masses[t[c]] += area / 3.;
  }
  double total = 0;
  for(double m : masses)
    total += m;
  const double floor = n > 0 && total > 0 ? 1e-6 * total / double(n) : 1.;
  for(double& m : masses)
    m = (std::max)(m, floor);
  return masses;
}

// Adds the cotangent stiffness matrix of `points` (the Dirichlet energy of the piecewise
// linear interpolant: positive semi-definite whatever the angles, needles included) to
// `matrix`. Corners of a degenerate triangle add nothing.
inline void add_cotangent_stiffness(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& points,
                                    Vertex_block_matrix<1>& matrix)
{
  for(const auto& t : mesh.triangles)
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t k = t[c], i = t[(c + 1) % 3], j = t[(c + 2) % 3];
      const Eigen::Vector3d a = points[i] - points[k], b = points[j] - points[k];
      const double sine = a.cross(b).norm();
      if(!(sine > 1e-12 * a.norm() * b.norm()))
        continue;
      const double w = 0.5 * a.dot(b) / sine;  // half the cotangent of the angle at k
      if(!std::isfinite(w))
        continue;
      matrix.at(i, i) += w;
      matrix.at(j, j) += w;
      matrix.at(i, j) -= w;
      matrix.at(j, i) -= w;
    }
}

// The cotangent stiffness matrix of `points` (see above) and their barycentric masses.
inline void cotangent_stiffness(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& points,
                                Eigen::SparseMatrix<double>& stiffness, std::vector<double>& masses)
{
  Vertex_block_matrix<1> matrix(mesh);
  add_cotangent_stiffness(mesh, points, matrix);
  stiffness = std::move(matrix.matrix());
  masses = barycentric_masses(mesh, points);
}

// The implicit mean curvature flow of a surface with the cotangent operator L and the
// barycentric masses M of its points p: `steps` steps of time t / steps each,
// (M + (t / steps) L) x_{k+1} = M x_k from x_0 = p, a smoothing of the positions that
// does not depend on the shape of the triangles (the operator converges to the
// Laplace-Beltrami operator on needles as on well-shaped triangles). One factorisation
// serves all the steps of a time, and the ordering of the first serves all the times
// and all the points of the mesh (restart()).
class Cotangent_flow
{
public:
  Cotangent_flow(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& points)
    : mesh_(mesh), stiffness_(mesh)
  {
    const std::size_t n = points.size();
    // M + (t / steps) L has the pattern of L, which has every diagonal entry: its values
    // are written in place for each time, without a new matrix.
    system_ = stiffness_.matrix();
    diagonal_.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      diagonal_[i] = stiffness_.place(i, i);
    configure_cholesky(cholesky_, Eigen::Index(n));
    restart(points);
  }

  // The flow from `points`, other positions of the mesh's vertices: the operator of
  // `points` replaces the previous one, on the same pattern and with the same ordering.
  void restart(const std::vector<Eigen::Vector3d>& points)
  {
    stiffness_.set_zero();
    add_cotangent_stiffness(mesh_, points, stiffness_);
    const std::vector<double> masses = barycentric_masses(mesh_, points);
    const Eigen::Index n = Eigen::Index(points.size());
    masses_.resize(n);
    start_.resize(n, 3);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      masses_[i] = masses[std::size_t(i)];
      start_.row(i) = points[std::size_t(i)].transpose();
    }
  }

  // What the flow removes first: M^-1 L p for the points p it starts from. Whatever the
  // steps, the flow for a time t is p - t M^-1 L p + O(t^2), so the residual of short
  // times points this way.
  std::vector<Eigen::Vector3d> initial_residual() const
  {
    const Eigen::MatrixXd velocity = stiffness_.matrix() * start_;
    std::vector<Eigen::Vector3d> result(std::size_t(start_.rows()));
    for(std::size_t i = 0; i < result.size(); ++i)
      result[i] = velocity.row(Eigen::Index(i)).transpose() / masses_[Eigen::Index(i)];
    return result;
  }

  // The flow for `time` in `steps` steps, written to `result`. Returns false, leaving
  // `result` untouched, if the factorisation or a solve fails.
  bool smooth(double time, std::size_t steps, std::vector<Eigen::Vector3d>& result)
  {
    const std::size_t n = std::size_t(start_.rows());
    steps = (std::max)(steps, std::size_t(1));
    const double step_time = time / double(steps);
    const double* stiffness = stiffness_.matrix().valuePtr();
    double* values = system_.valuePtr();
    for(Eigen::Index k = 0; k < system_.nonZeros(); ++k)
      values[k] = step_time * stiffness[k];
    for(std::size_t i = 0; i < n; ++i)
      values[diagonal_[i]] += masses_[Eigen::Index(i)];
    if(!analyzed_)
    {
      cholesky_.analyzePattern(system_);
      analyzed_ = true;
    }
    cholesky_.factorize(system_);
    if(cholesky_.info() != Eigen::Success)
      return false;
    x_ = start_;
    for(std::size_t step = 0; step < steps && cholesky_.info() == Eigen::Success; ++step)
    {
      right_side_ = masses_.asDiagonal() * x_;
      x_ = cholesky_.solve(right_side_);
    }
    if(cholesky_.info() != Eigen::Success || !x_.allFinite())
      return false;
    result.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      result[i] = x_.row(Eigen::Index(i)).transpose();
    return true;
  }

private:
  const Indexed_mesh& mesh_;
  Vertex_block_matrix<1> stiffness_;
  Eigen::SparseMatrix<double> system_;  // M + (t / steps) L, on the pattern of stiffness_
  std::vector<std::size_t> diagonal_;   // the places of the diagonal entries among the values
  Eigen::VectorXd masses_;
  Eigen::MatrixXd start_, x_, right_side_;
  Sparse_cholesky cholesky_;
  bool analyzed_ = false;
};

// The smoothings that denoise (the smoothed copy of a mesh of needles, and the flow of
// thin walls in filter_normals()) take this many implicit steps of the same total time:
// they smooth the shape's low frequencies as one step does (by 1 - t lambda to first
// order) but damp the noise's high ones far more ((1 + t lambda / K)^-K against
// (1 + t lambda)^-1), for K - 1 more solves with the same factorisation. Measured with
// the benchmark's seeds on the 42 noisy rows (0.1, 0.3, 0.5, both directions) of blade,
// rotor_small, anchor, cheese, couplingdown, turbine and b9_mesh (with the times that
// preceded whiteness_correlation): mean MAD 25.3 degrees with one step, 23.1 with 4,
// 22.9 with 8, 22.9 with 16; blade at 0.5 along the normals 11.2, 4.60, 4.45, 4.41.
constexpr std::size_t flow_substeps = 8;

// The sum over the directed edges ij of r_i . r_j over the sum of (|r_i|^2 + |r_j|^2) / 2,
// for per-vertex residuals r that are vectors or numbers.
template <typename Residual>
double neighbour_correlation(const Indexed_mesh& mesh, const std::vector<Residual>& r)
{
  auto dot = [](const Residual& a, const Residual& b) {
    if constexpr(std::is_arithmetic_v<Residual>)
      return a * b;
    else
      return a.dot(b);
  };
  double products = 0, squares = 0;
  for(std::size_t i = 0; i < r.size(); ++i)
    for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
    {
      const std::size_t j = mesh.fan[k];
      products += dot(r[i], r[j]);
      squares += 0.5 * (dot(r[i], r[i]) + dot(r[j], r[j]));
    }
  return squares > 0 ? products / squares : 0.;
}

// The correlation of the residual r = p - q of a smoothing between neighbours
// (neighbour_correlation()), between -1 and 1. Noise is independent from vertex to vertex: while the flow removes noise, its
// residual is white (a correlation near 0, slightly negative); once it removes shape,
// which is smooth, the residual turns correlated (towards 1). 0 for equal point sets.
// With `normals` (per vertex, not necessarily of unit length), the same for the
// residual's components r_i . n_i / |n_i| along them, which ignore the moves within the
// surface.
inline double residual_neighbour_correlation(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& p,
                                             const std::vector<Eigen::Vector3d>& q,
                                             const std::vector<Eigen::Vector3d>* normals = nullptr)
{
  if(normals == nullptr)
  {
    std::vector<Eigen::Vector3d> residual(p.size());
    for(std::size_t i = 0; i < p.size(); ++i)
      residual[i] = p[i] - q[i];
    return neighbour_correlation(mesh, residual);
  }
  std::vector<double> along(p.size());
  for(std::size_t i = 0; i < p.size(); ++i)
  {
    const double length = (*normals)[i].norm();
    along[i] = length > 0 ? (p[i] - q[i]).dot((*normals)[i]) / length : 0.;
  }
  return neighbour_correlation(mesh, along);
}

// The neighbour correlation of what `flow` removes first
// (Cotangent_flow::initial_residual()): negative on noise, positive where the flow
// removes shape from the start (see rough_shape_margin).
inline double initial_residual_correlation(const Indexed_mesh& mesh, const Cotangent_flow& flow)
{
  return neighbour_correlation(mesh, flow.initial_residual());
}

// The time of the flow. The time that removes the noise and keeps the shape varies by a
// factor of 30 in units of eps^2 (eps the noise level along the normals,
// plane_fit_noise_level) from mesh to mesh: with the benchmark's seeds, at 0.1 to 0.5
// mean edge length of noise, the best of the times eps^2, 2 eps^2, ..., 256 eps^2 is eps^2
// to 4 eps^2 on CGAL's cheese, anchor and b9_mesh at 0.1, 32 eps^2 to 64 eps^2 on
// turbine with noise in random directions; no fixed multiple, nor the time of the
// needle copy halved while it shrinks the shape, comes near it on all of them. The
// correlation of the residual at the best time is nearly constant instead: 0.2 to 0.45
// on every mesh but blade. The flow therefore runs the times eps^2, 2 eps^2, ... until
// the correlation reaches whiteness_correlation, and ends at the time interpolated (in
// log time) where it crosses it, between 2^-flow_time_doublings and 2^flow_time_doublings
// eps^2; it goes down from eps^2 if the residual is already correlated there (clean
// meshes whose noise estimate reads the shape: the shortest time leaves them as they
// are). Mean MAD per mesh over its six noisy rows (0.1, 0.3, 0.5 along the normals and
// in random directions), the flow alone, at the crossing (interpolated between the
// times of the grid) against the best time of the grid: turbine 8.36 and 8.01 degrees,
// cheese 23.97 and 23.70, anchor 34.82 and 32.60, couplingdown 23.79 and 23.58, b9_mesh
// 23.15 and 21.89, rotor_small 15.22 and 14.56. The optimum is broad: at 0.25 and 0.35 turbine
// gives 8.60 and 8.16, cheese 25.0 and 24.4, couplingdown 24.0 and 24.0. (On blade,
// whose needles the flow also moves along the surface, the correlation at the best
// time is 0.6 to 0.8: the stop gives 6.42 there, the needle copy's time 4.85.)
constexpr double whiteness_correlation = 0.3;
constexpr int flow_time_doublings = 8;

// Noise below the roughness of the shape. What the flow removes first from noisy
// vertices (Cotangent_flow::initial_residual(), the limit of the residual's direction as
// t -> 0) is the noise's Laplacian, correlated negatively between neighbours: -0.06 to
// -0.19 on the benchmark's noisy rows (0.1 to 0.5 mean edge length, both directions) of
// blade, rotor_small, couplingdown, anchor, cheese and turbine, the meshes whose result
// is this flow, and -0.01 to -0.09 on b9_mesh from 0.3 on. Where it is positive, what
// the flow removes from the start is mostly shape: the noise is at or below the
// roughness of a coarse tessellation of curved surfaces, which the noise estimate reads
// as noise (CGAL's b9_mesh, a CAD export of needles: eps 2.0 and 3.1 times the noise at
// 0.1 mean edge length along the normals and in random directions; 0.068 and 0.053 there,
// 0.004 to 0.024 at 0.2). The flow then stops where the correlation has risen by
// rough_shape_margin above that level, if that comes before whiteness_correlation.
// Measured with the benchmark's seeds, the result of denoise_mesh() on b9_mesh at 0.1
// along the normals and in random directions, then 0.2, then clean, with the level of
// the shortest time 2^-flow_time_doublings eps^2 in place of the limit (0.070 and 0.057
// at 0.1; one more flow per stop): 15.3, 13.7, 20.8, 18.5 and 10.9 degrees without the
// margin; 12.5, 8.81, 20.5, 16.8 and 1.98 with a margin of 0.03; 12.7, 9.11, 20.5, 16.3
// and 3.40 with 0.05; 13.0, 9.55, 20.5, 16.3 and 4.66 with 0.07; 13.4, 10.3, 20.5, 16.6
// and 6.23 with 0.1 (the best of the flow's times: 12.6, 8.81, 20.5, 16.8). The results
// on the other meshes of the benchmark do not change (their correlation is negative; the
// clean meshes that reach the flow, b9_mesh aside, have one above whiteness_correlation
// at the shortest time, and keep it).
constexpr double rough_shape_margin = 0.05;

// Where the needle copy shrinks the shape (meshes whose parts are a few faces thick, or
// whose needles span curved holes: CGAL's anchor and cheese), the flow that replaces it
// takes this many steps, each with the operator of the points it starts from: the
// cotangent weights of noisy needles are noise themselves (a needle's small angles
// change by a large factor under noise of a fraction of its small altitude), and those
// of the partly smoothed surface are not. Measured with the benchmark's seeds, mean MAD
// over the 8 noisy rows (0.1 to 0.5, both directions), stopped at whiteness_correlation:
// anchor 28.5 degrees and cheese 19.2, against 32.6 and 23.2 with the operator of the
// input; with 2 and 4 steps 28.6 and 29.1, 20.5 and 18.7; with 8 steps the factorisation
// fails on cheese from 0.2 noise on (collapsed triangles), and the stop then ends early
// (22.2). Elsewhere the input's operator is kept: the relinearised flow fails at every
// step on b9_mesh, and overshoots on turbine (0.3 along the normals: 9.34 degrees at
// best, against 8.27).
constexpr std::size_t relinearised_steps = 3;

// The relinearised flow: `steps` implicit steps of time t / steps, each with the
// operator of the points it starts from (the semi-implicit mean curvature flow of
// Desbrun et al. 1999), instead of the operator of the input for all of them. `flow` is
// the flow of `mesh` from the points it starts from, which takes the first step;
// `later_steps` takes the others, restarted from the points of each. It is made at the
// first later step and kept from call to call, so that the ordering of its
// factorisation is computed once. Returns false, leaving `result` untouched, if a
// factorisation or a solve fails.
inline bool relinearised_smoothing(const Indexed_mesh& mesh, Cotangent_flow& flow,
                                   std::optional<Cotangent_flow>& later_steps, double time, std::size_t steps,
                                   std::vector<Eigen::Vector3d>& result)
{
  steps = (std::max)(steps, std::size_t(1));
  std::vector<Eigen::Vector3d> current, next;
  if(!flow.smooth(time / double(steps), 1, current))
    return false;
  for(std::size_t step = 1; step < steps; ++step)
  {
    if(later_steps)
      later_steps->restart(current);
    else
      later_steps.emplace(mesh, current);
    if(!later_steps->smooth(time / double(steps), 1, next))
      return false;
    current.swap(next);
  }
  result.swap(current);
  return true;
}

// The input smoothed by `flow` (a callable (time, result) -> bool, false if it failed),
// for the time at which the residual's neighbour correlation reaches
// whiteness_correlation, or less where `initial_correlation`, that of what the flow
// removes first, is positive (see rough_shape_margin), `noise` the noise level eps;
// `time` receives that time. A time at which the flow fails counts as one past the
// crossing. Returns false, leaving `result` untouched, if the flow fails at every time it
// tries.
template <typename Flow>
bool smooth_until_residual_is_correlated(const Indexed_mesh& mesh, double noise, double initial_correlation,
                                         Flow&& flow, std::vector<Eigen::Vector3d>& result, double& time)
{
  struct Sample
  {
    int exponent = 0;
    bool done = false;  // the flow succeeded
    double correlation = 0;
    std::vector<Eigen::Vector3d> points;
  };
  const double threshold = initial_correlation > 0
                               ? (std::min)(whiteness_correlation, initial_correlation + rough_shape_margin)
                               : whiteness_correlation;
  auto white = [&](const Sample& sample) { return sample.done && sample.correlation < threshold; };
  auto sample_at = [&](int exponent, Sample& sample) {
    sample.exponent = exponent;
    sample.done = flow(std::ldexp(noise * noise, exponent), sample.points);
    if(sample.done)
      sample.correlation = residual_neighbour_correlation(mesh, mesh.points, sample.points);
  };
  auto keep = [&](Sample& sample) {
    time = std::ldexp(noise * noise, sample.exponent);
    result.swap(sample.points);
    return true;
  };
  // From k = 0, up while the residual is white (below the threshold), down while it is
  // not; the crossing lies between the white sample and the other one, a factor of 2
  // above it, interpolated in log time where both correlations are known.
  Sample previous, current;
  sample_at(0, current);
  const int direction = white(current) ? 1 : -1;
  for(;;)
  {
    if(current.exponent + direction < -flow_time_doublings || current.exponent + direction > flow_time_doublings)
      return current.done ? keep(current) : false;  // no crossing: the extreme time
    std::swap(previous, current);
    sample_at(previous.exponent + direction, current);
    if(white(current) == white(previous))
      continue;
    Sample& white_sample = white(current) ? current : previous;
    const Sample& other = white(current) ? previous : current;
    if(other.done)
    {
      // (the white sample is the shorter time)
      const double fraction =
          (threshold - white_sample.correlation) / (other.correlation - white_sample.correlation);
      const double crossing = std::ldexp(noise * noise, white_sample.exponent) * std::exp2(fraction);
      std::vector<Eigen::Vector3d> interpolated;
      if(flow(crossing, interpolated))
      {
        time = crossing;
        result.swap(interpolated);
        return true;
      }
    }
    return keep(white_sample);
  }
}

// The input smoothed by `flow`, the Cotangent_flow of the input, in flow_substeps steps,
// stopped by its residual (see above).
inline bool smooth_until_residual_is_correlated(const Indexed_mesh& mesh, double noise, Cotangent_flow& flow,
                                                std::vector<Eigen::Vector3d>& result, double& time)
{
  return smooth_until_residual_is_correlated(
      mesh, noise, initial_residual_correlation(mesh, flow),
      [&](double t, std::vector<Eigen::Vector3d>& smoothed) { return flow.smooth(t, flow_substeps, smoothed); },
      result, time);
}

// The input smoothed by the relinearised flow in relinearised_steps steps, stopped by its
// residual (see above); `flow` is the Cotangent_flow of the input, which takes the first
// step, and so removes the same first.
inline bool smooth_relinearised_until_residual_is_correlated(const Indexed_mesh& mesh, double noise,
                                                             Cotangent_flow& flow,
                                                             std::vector<Eigen::Vector3d>& result, double& time)
{
  std::optional<Cotangent_flow> later_steps;
  return smooth_until_residual_is_correlated(
      mesh, noise, initial_residual_correlation(mesh, flow),
      [&](double t, std::vector<Eigen::Vector3d>& smoothed) {
        return relinearised_smoothing(mesh, flow, later_steps, t, relinearised_steps, smoothed);
      },
      result, time);
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_COTANGENT_FLOW_H
