// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Point-set denoising: the normals filtered on the neighbour graph with the range
// weights of the mesh denoiser (normal_filtering.h), each point moved along its own
// normal only, so that the pairs of neighbours fit the planes of their filtered normals.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_POINT_SET_FILTERING_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_POINT_SET_FILTERING_H

#include <CGAL/Heat_diffusion/internal/parallel_for.h>
#include <CGAL/Heat_diffusion/internal/progress.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

struct Point_set_filtering_options
{
  std::size_t iterations = 0;     // the most iterations
  std::size_t steps = 1;          // normal filtering steps per iteration
  double normal_sigma = 0;        // the range width; 0: automatic_point_normal_sigma()
  double displacement_limit = 1;  // the stop, in multiples of the noise level
};

struct Point_set_filtering_result
{
  std::vector<Eigen::Vector3d> points, normals;
  double noise_level = 0;  // normalised frame
  double normal_sigma = 0;
  std::size_t iterations = 0;
};

// neighbour j's normal turned to the side of normal `n`: the filter does not need the
// orientation to be consistent, and keeps each point's own.
inline Eigen::Vector3d aligned_normal(const Eigen::Vector3d& n, const Eigen::Vector3d& m)
{
  return n.dot(m) < 0 ? Eigen::Vector3d(-m) : m;
}

// One step of the bilateral filter of the normals on the neighbour graph:
// n_i <- normalise(sum_j exp(-|n_i - n_j|^2 / 2 sigma^2) n_j), over i and its neighbours.
inline std::vector<Eigen::Vector3d> filter_point_normals(const std::vector<std::vector<std::size_t> >& neighbours,
                                                         const std::vector<Eigen::Vector3d>& normals, double sigma)
{
  const std::size_t n = normals.size();
  std::vector<Eigen::Vector3d> result(n);
  const double scale = 1. / (2. * sigma * sigma);
  parallel_for(n, [&](std::size_t i) {
    const Eigen::Vector3d& ni = normals[i];
    Eigen::Vector3d sum = ni;
    for(std::size_t j : neighbours[i])
    {
      const Eigen::Vector3d nj = aligned_normal(ni, normals[j]);
      sum += std::exp(-(ni - nj).squaredNorm() * scale) * nj;
    }
    result[i] = sum.normalized();
  });
  return result;
}

// The normal of the plane fitted to each point and its neighbours (weighted least
// squares), on the side of `previous`; the weights are the range weights of the normal
// filter on `previous`, so that a fit near a crease keeps to its own side.
// The planes of the neighbourhoods (each point with its neighbours) against the normals:
// the first point whose neighbourhood lies on a line to double precision (n if none),
// where no plane fits and the filter fits planes; and the median over the points of the
// unoriented angle, in degrees, between a point's normal and its neighbourhood's plane
// normal (the direction of least variance), small for normals of the points' surface
// whatever their noise, and large for normals that lie in it.
struct Neighbourhood_planes
{
  std::size_t first_collinear = 0;
  double median_tilt = 0;
};

inline Neighbourhood_planes neighbourhood_planes(const std::vector<Eigen::Vector3d>& p,
                                                 const std::vector<std::vector<std::size_t> >& neighbours,
                                                 const std::vector<Eigen::Vector3d>& normals)
{
  const std::size_t n = p.size();
  std::vector<char> collinear(n, 0);
  std::vector<double> tilt(n, 0.);
  parallel_for(n, [&](std::size_t i) {
    Eigen::Vector3d mean = p[i];
    for(std::size_t j : neighbours[i])
      mean += p[j];
    mean /= double(neighbours[i].size() + 1);
    Eigen::Matrix3d covariance = (p[i] - mean) * (p[i] - mean).transpose();
    for(std::size_t j : neighbours[i])
      covariance += (p[j] - mean) * (p[j] - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    // (the second largest variance is rounding against the largest)
    collinear[i] = !(solver.eigenvalues()[1] > 1e-20 * solver.eigenvalues()[2]);
    const double c = std::abs(solver.eigenvectors().col(0).normalized().dot(normals[i].normalized()));
    tilt[i] = std::acos((std::min)(c, 1.)) * 180. / 3.14159265358979323846;
  });
  Neighbourhood_planes result;
  result.first_collinear = std::size_t(std::find(collinear.begin(), collinear.end(), char(1)) - collinear.begin());
  if(n > 0)
  {
    std::nth_element(tilt.begin(), tilt.begin() + std::ptrdiff_t(n / 2), tilt.end());
    result.median_tilt = tilt[n / 2];
  }
  return result;
}

inline std::vector<Eigen::Vector3d> fitted_point_normals(const std::vector<Eigen::Vector3d>& q,
                                                         const std::vector<std::vector<std::size_t> >& neighbours,
                                                         const std::vector<Eigen::Vector3d>& previous, double sigma)
{
  const std::size_t n = q.size();
  std::vector<Eigen::Vector3d> result(n);
  const double scale = 1. / (2. * sigma * sigma);
  parallel_for(n, [&](std::size_t i) {
    const Eigen::Vector3d& ni = previous[i];
    std::vector<double> w(neighbours[i].size());
    double total = 1;
    Eigen::Vector3d mean = q[i];
    for(std::size_t a = 0; a < w.size(); ++a)
    {
      const std::size_t j = neighbours[i][a];
      w[a] = std::exp(-(ni - aligned_normal(ni, previous[j])).squaredNorm() * scale);
      total += w[a];
      mean += w[a] * q[j];
    }
    mean /= total;
    Eigen::Matrix3d covariance = (q[i] - mean) * (q[i] - mean).transpose();
    for(std::size_t a = 0; a < w.size(); ++a)
    {
      const Eigen::Vector3d e = q[neighbours[i][a]] - mean;
      covariance += w[a] * e * e.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    result[i] = aligned_normal(ni, solver.eigenvectors().col(0).normalized());
  });
  return result;
}

// The offsets along the normals that make each pair of neighbours (i, j) fit the plane
// of their mean normal m_ij, m_ij . (q_j - x_i - delta_i n_i) = 0, for x_i: the weighted
// least-squares offset of x_i alone, sum_j w_ij (m_ij . n_i) r_ij / sum_j w_ij (m_ij . n_i)^2,
// with the range weights of the normal filter. The chord between two points of a sphere
// is orthogonal to their mean normal: a sphere is a fixed point (the planes of the
// neighbours' own normals would inflate it), and a point's offset from a curved surface
// is measured without the curvature's bias.
inline std::vector<double> normal_offsets(const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Vector3d>& q,
                                          const std::vector<std::vector<std::size_t> >& neighbours,
                                          const std::vector<Eigen::Vector3d>& normals, double sigma)
{
  const std::size_t n = q.size();
  std::vector<double> offset(n, 0.);
  const double scale = 1. / (2. * sigma * sigma);
  parallel_for(n, [&](std::size_t i) {
    const Eigen::Vector3d& ni = normals[i];
    double numerator = 0, denominator = 0;
    for(std::size_t j : neighbours[i])
    {
      const Eigen::Vector3d nj = aligned_normal(ni, normals[j]);
      const double w = std::exp(-(ni - nj).squaredNorm() * scale);
      const Eigen::Vector3d m = (ni + nj).normalized();
      const double c = m.dot(ni);
      numerator += w * c * m.dot(q[j] - x[i]);
      denominator += w * c * c;
    }
    if(denominator > 0)
      offset[i] = numerator / denominator;
  });
  return offset;
}

// The noise level of points x against the surface of the points q (x itself or a
// denoised copy): the median of the offsets' magnitudes divided by 0.6745 (and by
// sqrt(1 + 1/k) when q is x, k the neighbour count: the neighbours have noise of their own);
// about the standard deviation of Gaussian noise along the normals.
inline double point_set_noise_level(const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Vector3d>& q,
                                    const std::vector<std::vector<std::size_t> >& neighbours,
                                    const std::vector<Eigen::Vector3d>& normals, double sigma, bool same)
{
  const std::size_t n = x.size();
  if(n == 0)
    return 0.;
  std::vector<double> offset = normal_offsets(x, q, neighbours, normals, sigma);
  for(std::size_t i = 0; i < n; ++i)
    offset[i] = std::abs(offset[i]) / (same ? std::sqrt(1. + 1. / double(neighbours[i].size())) : 1.);
  std::nth_element(offset.begin(), offset.begin() + std::ptrdiff_t(n / 2), offset.end());
  return offset[n / 2] / 0.6745;
}

// The range width where the user gives none, from the tilt that the noise gives the
// normals, the ratio r of the noise level to the median distance of a point to its
// neighbours: 0.25 up to r = 0.2, 0.5 from r = 0.33, linear between. Narrow widths keep creases
// sharp where the normals are reliable; wider ones keep strong noise from being frozen
// into false creases (the mesh denoiser's widths, normal_widths.h, follow the same
// reasoning). The line was fitted on fandisk and armadillo with
// benchmark_point_set_denoising: 0.25 was best at noise of 0.25 % of the diagonal on 20000
// points (r = 0.1), 0.5 at 1 % (r = 0.3 to 0.33, the noise level being underestimated).
inline double automatic_point_normal_sigma(const std::vector<Eigen::Vector3d>& p,
                                           const std::vector<std::vector<std::size_t> >& neighbours,
                                           double noise_level)
{
  const std::size_t n = p.size();
  std::vector<double> spread(n);
  parallel_for(n, [&](std::size_t i) {
    double sum = 0;
    for(std::size_t j : neighbours[i])
      sum += (p[j] - p[i]).norm();
    spread[i] = sum / double(neighbours[i].size());
  });
  std::nth_element(spread.begin(), spread.begin() + std::ptrdiff_t(n / 2), spread.end());
  const double r = spread[n / 2] > 0 ? noise_level / spread[n / 2] : 0.;
  return 0.25 + 0.25 * std::clamp((r - 0.2) / (0.33 - 0.2), 0., 1.);
}

// The filter, on points in the normalised frame with their neighbours and unit normals.
// Each iteration filters the normals `steps` times, then moves each point along its
// normal by half its offset (both points of a pair move). The iterations stop where the
// root mean square displacement along the normals reaches displacement_limit times the
// noise level (the last one cut back to reach it), or where the points stop moving.
// The result's displacement of each point is along the point's result normal.
inline Point_set_filtering_result filter_point_set(const std::vector<Eigen::Vector3d>& p,
                                                   const std::vector<std::vector<std::size_t> >& neighbours,
                                                   const std::vector<Eigen::Vector3d>& input_normals,
                                                   const Point_set_filtering_options& options,
                                                   const Progress& progress)
{
  const std::size_t n = p.size();
  Point_set_filtering_result result;
  result.points = p;
  result.normals = input_normals;
  if(n == 0 || options.iterations == 0)
    return result;
  // (the first estimate without range weights: the noisy normals are no guide yet)
  result.noise_level =
      point_set_noise_level(p, p, neighbours, input_normals, std::numeric_limits<double>::infinity(), true);
  const double sigma = options.normal_sigma > 0 ? options.normal_sigma
                                                : automatic_point_normal_sigma(p, neighbours, result.noise_level);
  result.normal_sigma = sigma;
  double target = options.displacement_limit * result.noise_level;
  if(!(target > 0))
    return result;
  // t: each point's signed displacement along its current normal
  std::vector<double> t(n, 0.);
  std::vector<Eigen::Vector3d>& normals = result.normals;
  std::vector<Eigen::Vector3d> q = p;
  auto rms = [&](const std::vector<double>& x) {
    double sum = 0;
    for(double v : x)
      sum += v * v;
    return std::sqrt(sum / double(n));
  };
  for(std::size_t iteration = 0; iteration < options.iterations; ++iteration)
  {
    // From the second iteration on, the normals start from the planes fitted to the
    // points moved so far: filtered again and again without them, they would drift
    // towards facets (measured: the error grows with the iterations).
    if(iteration > 0)
      normals = fitted_point_normals(q, neighbours, normals, 1.5 * sigma);
    for(std::size_t step = 0; step < options.steps; ++step)
      normals = filter_point_normals(neighbours, normals, sigma);
    const std::vector<double> offset = normal_offsets(q, q, neighbours, normals, sigma);
    std::vector<double> next(n);
    // the displacement so far projected on the new normal: no point slides
    for(std::size_t i = 0; i < n; ++i)
    {
      t[i] = normals[i].dot(q[i] - p[i]);
      next[i] = t[i] + 0.5 * offset[i];
    }
    const double before = rms(t);
    double after = rms(next);
    if(after > target)
    {
      // The noise of the input measured again, against the surface of the points moved so
      // far: the first estimate, along normals that tilt with strong noise, is low (about
      // half the true level at noise of a neighbourhood's radius); the iterations go on
      // while it grows by more than 5 %.
      const double level = point_set_noise_level(p, q, neighbours, normals, sigma, false);
      if(level > 1.05 * result.noise_level)
      {
        result.noise_level = level;
        target = options.displacement_limit * level;
      }
    }
    double fraction = 1;
    if(after > target && after > before)
    {
      // the root mean square of (1 - f) t + f next is target: a quadratic in f, with
      // before <= target < after (before > target only where a projection grew it)
      double a = 0, b = 0, c = 0;
      for(std::size_t i = 0; i < n; ++i)
      {
        const double d = next[i] - t[i];
        a += d * d;
        b += 2 * t[i] * d;
        c += t[i] * t[i];
      }
      c -= target * target * double(n);
      const double discriminant = b * b - 4 * a * c;
      fraction = a > 0 && discriminant >= 0 ? std::clamp((-b + std::sqrt(discriminant)) / (2 * a), 0., 1.) : 0.;
    }
    double moved = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      const double value = t[i] + fraction * (next[i] - t[i]);
      moved = (std::max)(moved, std::abs(value - t[i]));
      t[i] = value;
      q[i] = p[i] + t[i] * normals[i];
    }
    result.iterations = iteration + 1;
    progress.report(double(iteration + 1) / double(options.iterations), "denoise_point_set");
    if(fraction < 1 || moved <= 1e-12 * result.noise_level)
      break;
  }
  result.points = q;
  return result;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_POINT_SET_FILTERING_H
