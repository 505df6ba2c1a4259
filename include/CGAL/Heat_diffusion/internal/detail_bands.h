// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The detail bands of a field by vertex index (paper, eq. 24) and their weighted
// re-synthesis (eq. 26), and the checks of their parameters.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DETAIL_BANDS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DETAIL_BANDS_H

#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/progress.h>
#include <CGAL/Heat_diffusion/parameters.h>

#include <CGAL/number_utils.h>

#include <Eigen/Core>

#include <cmath>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {


inline std::size_t checked_steps_per_level(double steps, const char* function)
{
  if(!(steps >= 1) || steps != std::floor(steps))
  {
    std::ostringstream os;
    os << function << ": steps_per_level must be a positive integer, not " << steps;
    throw_invalid_input(os.str());
  }
  return std::size_t(steps);
}

// Eq. 24 by vertex index: bands[j] = F^(j S) - F^((j+1) S) for j < levels, and
// bands[levels] = F^(levels S), the residual. The bands telescope, so their sum is
// the input up to rounding, and each band sums to zero because A_t conserves heat.
// `progress` sees every step; it cancels between two.
template <typename Diffusion>
std::vector<Eigen::VectorXd> decompose(const Diffusion& diffusion, const Eigen::VectorXd& field, std::size_t levels,
                                       std::size_t steps_per_level, const Progress& progress)
{
  std::vector<Eigen::VectorXd> bands;
  bands.reserve(levels + 1);
  Eigen::VectorXd current = field;
  for(std::size_t j = 0; j < levels; ++j)
  {
    const Progress level = progress.part(double(j) / double(levels), double(j + 1) / double(levels));
    Eigen::VectorXd next =
        diffusion.diffuse(current, steps_per_level, parameters::progress_callback(level.as_callback()));
    bands.push_back(current - next);
    current.swap(next);
  }
  bands.push_back(current);
  return bands;
}

// Eq. 26: sum_j w_j D^j + S^L, the residual being the last band.
inline Eigen::VectorXd synthesize(const std::vector<Eigen::VectorXd>& bands, const std::vector<double>& weights)
{
  Eigen::VectorXd result = bands.back();
  for(std::size_t j = 0; j < weights.size(); ++j)
    result += weights[j] * bands[j];
  return result;
}

template <typename WeightRange>
std::vector<double> checked_weights(const WeightRange& weights, const char* function)
{
  std::vector<double> result;
  for(const auto& w : weights)
  {
    result.push_back(CGAL::to_double(w));
    if(!std::isfinite(result.back()))
    {
      std::ostringstream os;
      os << function << ": weight " << result.size() - 1 << " is " << result.back() << ", not a finite number";
      throw_invalid_input(os.str());
    }
  }
  return result;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DETAIL_BANDS_H
