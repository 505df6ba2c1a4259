// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the messages and JSON summaries report of a result: the range and mean of a
// field, the sums of detail bands, distances between vertex positions.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_CLI_MEASURES_H
#define CGAL_HEAT_DIFFUSION_TOOLS_CLI_MEASURES_H

#include "cli_json.h"

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <string>
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

// What decompose reports of its bands: per band its sum, that sum relative to sum |S|
// and its L2 norm; the outputs; the total heat of S and of the residual.
struct Band_summary
{
  Json_object bands, names;
  double total_heat = 0, residual_heat = 0;
  double worst_relative_sum = 0;  // the largest |band sum| / sum |S|

  // "total_heat", "residual_heat" and "bands" (names go to "outputs" where the caller says).
  void add_to(Json_object& summary) const
  {
    summary.number("total_heat", total_heat).number("residual_heat", residual_heat).object("bands", bands);
  }
};

// The summary of the bands and residual `values` (the residual last) of the field
// `input`, written to `outputs` (in the same order).
inline Band_summary band_summary(const std::vector<double>& input, const std::vector<std::vector<double> >& values,
                                 const std::vector<std::string>& outputs)
{
  Band_summary s;
  double absolute_sum = 0;
  for(double x : input)
  {
    absolute_sum += std::abs(x);
    s.total_heat += x;
  }
  for(std::size_t j = 0; j + 1 < values.size(); ++j)
  {
    double sum = 0, squares = 0;
    for(double x : values[j])
    {
      sum += x;
      squares += x * x;
    }
    const double relative = absolute_sum > 0 ? std::abs(sum) / absolute_sum : 0.;
    s.worst_relative_sum = (std::max)(s.worst_relative_sum, relative);
    Json_object b;
    b.number("sum", sum).number("relative_sum", relative).number("l2_norm", std::sqrt(squares));
    s.bands.object(std::to_string(j + 1), b);
    s.names.string(std::to_string(j + 1), outputs[j]);
  }
  s.names.string("residual", outputs.back());
  for(double x : values.back())
    s.residual_heat += x;
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
