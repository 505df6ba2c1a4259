// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The options of the subcommands that run on point sets (all but hks): the
// neighbourhoods of the points' fans, and the refusal of the option that concerns
// meshes only.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_OPTIONS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_OPTIONS_H

#include "cli_arguments.h"
#include "cli_errors.h"
#include "diffusion_options.h"

#include <CGAL/Heat_diffusion/parameter_defaults.h>
#include <CGAL/Heat_diffusion/parameters.h>
#include <CGAL/Named_function_parameters.h>

#include <optional>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

namespace HD = CGAL::Heat_diffusion;

// The largest neighbour count: far beyond what a fan needs (a one-ring has about 6
// points), and bounded so that the neighbour lists (n k indices) and the triangulations
// of k points, one per point, stay within what a run of a large point set can afford.
constexpr double maximum_neighbors = 1000;

// --neighbors K and --neighbor-radius R, as given (empty: not given).
struct Neighbourhood_options
{
  std::optional<unsigned int> k;
  std::optional<double> radius;
  // The library's default of the subcommand (denoise has its own).
  unsigned int default_k = HD::defaults::number_of_neighbors;

  // The k passed to the library: the one given, or the subcommand's default.
  unsigned int k_or_default() const { return k.value_or(default_k); }
  // The library's names of the options given, for the JSON summary.
  std::vector<std::string> given() const
  {
    std::vector<std::string> names;
    if(k)
      names.push_back("k");
    if(radius)
      names.push_back("neighbor_radius");
    return names;
  }
};

// Parses --neighbors (2 to maximum_neighbors; 0, no limit, only with a radius) and
// --neighbor-radius (a number > 0).
inline Neighbourhood_options parse_neighbourhood(const Arguments& args)
{
  Neighbourhood_options nb;
  if(args.has("--neighbor-radius"))
    nb.radius = parse_number("--neighbor-radius", args.value("--neighbor-radius", ""), 0., true);
  if(args.has("--neighbors"))
  {
    const std::string text = args.value("--neighbors", "");
    nb.k = unsigned(parse_count("--neighbors", text, 0, maximum_neighbors));
    if(*nb.k < 2 && !(nb.radius && *nb.k == 0))
      throw Usage_error("--neighbors must be at least 2 (0, for no limit, only with --neighbor-radius), not '" +
                        text + "'");
  }
  return nb;
}

// Calls `f` with the named parameters of the neighbourhood: CGAL's neighbor_radius if
// it is given, else none.
template <typename Function>
auto with_neighbourhood(const Neighbourhood_options& nb, Function&& f)
{
  if(nb.radius)
    return f(CGAL::parameters::neighbor_radius(*nb.radius));
  return f(HD::parameters::default_values());
}

// The help of the two options; `role` says what the neighbours are for, `default_k` is
// the subcommand's default neighbour count.
inline std::string neighbourhood_options_help(
    unsigned int default_k = HD::defaults::number_of_neighbors,
    const std::string& role = "whose Delaunay triangulation on the tangent plane makes its fan")
{
  return help_option("--neighbors K", "point sets only: the neighbours of each point " + role +
                                          ", 2 to 1000 (default " + std::to_string(default_k) +
                                          "); with --neighbor-radius, at most that many of those within the radius "
                                          "(0: all)") +
         help_option("--neighbor-radius R",
                     "point sets only: the neighbours within the distance R (in the file's units) instead of the K "
                     "nearest");
}

// Refuses, on a point set, the option that concerns meshes only: --coarse (the spectral
// kernel of a point set has the eigenpairs of the points' own L and B).
inline void refuse_mesh_only_diffusion_options(const Diffusion_options& o)
{
  if(o.coarse)
    throw Usage_error("--coarse simplifies a mesh: on a point set the spectral kernel has the eigenpairs of the "
                      "points' own L and B, without a coarse level");
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_OPTIONS_H
