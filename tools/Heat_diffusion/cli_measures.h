// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the messages and JSON summaries report of a result: the range and mean of a
// field, distances between vertex positions.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_CLI_MEASURES_H
#define CGAL_HEAT_DIFFUSION_TOOLS_CLI_MEASURES_H

#include "cli_json.h"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace heat_diffusion_cli {

// The range and mean of a field.
struct Field_statistics
{
  double min = 0, max = 0, mean = 0;
  Json_object json() const
  {
    Json_object o;
    o.number("min", min).number("max", max).number("mean", mean);
    return o;
  }
};

inline Field_statistics statistics(const std::vector<double>& values)
{
  Field_statistics s;
  if(values.empty())
    return s;
  s.min = *std::min_element(values.begin(), values.end());
  s.max = *std::max_element(values.begin(), values.end());
  double sum = 0;
  for(double v : values)
    sum += v;
  s.mean = sum / double(values.size());
  return s;
}

// The distance between two points, without overflow or underflow (coordinates near
// 1e300 or 1e-300 square to infinity or zero).
template <typename Point>
double point_distance(const Point& p, const Point& q)
{
  return std::hypot(CGAL::to_double(p.x()) - CGAL::to_double(q.x()), CGAL::to_double(p.y()) - CGAL::to_double(q.y()),
                    CGAL::to_double(p.z()) - CGAL::to_double(q.z()));
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_CLI_MEASURES_H
