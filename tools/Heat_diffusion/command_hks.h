// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion hks: the heat kernel signature and its maxima, the baseline the
// paper's Fig. 7 compares its features with.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_HKS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_HKS_H

#include "command_features.h"

#include <cmath>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

const char* const hks_help =
    "Usage: heat_diffusion hks MESH [-t T] [--sigma S] [-m M] [--c C] [-o OUT.ply] [--json] [--quiet]\n"
    "\n"
    "The heat kernel signature HKS(x, t) = sum_k exp(-lambda_k t) phi_k(x)^2 (Sun, Ovsjanikov\n"
    "and Guibas 2009) and its maxima: the vertices whose HKS is above that of every other\n"
    "vertex of their 2-ring and above C max HKS. The HKS is positive, so it has no concave\n"
    "features: it cannot tell convex from concave (compare with 'features').\n"
    "\n"
    "Options:\n"
    "  -t, --time T      the time t, on the mesh rescaled to area = vertex count (default 20).\n"
    "                    The truncated kernel is accurate for t >= 4 ln 10 / lambda_m only\n"
    "                    (17.8 on fandisk with m = 150): the tool warns below that bound\n"
    "  --sigma S         edge-weight width; 'inf' (default) is the plain Laplacian of the\n"
    "                    classical HKS, a finite sigma the edge-weighted kernel\n"
    "  -m M              number of eigenpairs (default 150)\n"
    "  --c C             the threshold c in [0, 1] (default 0.8)\n"
    "  --scale-invariant the scale-invariant kernel of the paper's eq. 14\n"
    "  -o OUT.ply        output (default: MESH's name with _hks.ply, in the current folder):\n"
    "                    a binary PLY with the vertex properties 'maximum' (1 at the maxima,\n"
    "                    red; 0 elsewhere, light grey) and 'hks'\n"
    "  --json            print a JSON summary on stdout: the maxima (0-based vertex indices\n"
    "                    in the order of the mesh file), the HKS range, t and its bound\n"
    "  --quiet           print nothing but errors (and the JSON summary if asked for)\n"
    "  -h, --help        this text\n";

inline int run_hks(int argc, char** argv)
{
  Arguments args({"--json", "--quiet", "--scale-invariant", "-h", "--help"},
                 {"-o", "--sigma", "-t", "--time", "-m", "--c"});
  args.parse(argc, argv, 2);
  if(args.flag("-h") || args.flag("--help"))
  {
    std::cout << hks_help;
    return success;
  }
  if(args.positional().size() != 1)
    throw Usage_error("hks takes exactly one MESH argument");
  if(args.has("-t") && args.has("--time"))
    throw Usage_error("give the time once, with -t or --time");
  const std::string input = args.positional()[0];
  const Diffusion_options options = parse_diffusion_options(args, "inf");
  const std::string time_option = args.has("-t") ? "-t" : "--time";
  const double t = parse_number(time_option, args.value(time_option, "20"), 0., true);
  const double c = parse_number("--c", args.value("--c", "0.8"), 0., false);
  if(c > 1)
    throw Usage_error("--c must be in [0, 1], not '" + args.value("--c", "") + "'");
  const std::string output = args.value("-o", default_output(input, "_hks.ply"));
  check_output_path(output, {input});
  const bool quiet = args.flag("--quiet");

  Stage_timer timer;
  Mesh mesh;
  read_triangle_mesh(input, mesh);
  timer.stop("read");
  const std::unique_ptr<Heat_kernel> kernel = make_heat_kernel(mesh, options, input, quiet);
  timer.stop("ncc_and_eigen_solve");

  auto hks = mesh.add_property_map<Mesh::Vertex_index, double>("v:hks_values", 0.).first;
  for(auto v : mesh.vertices())
    hks[v] = kernel->heat_kernel_signature(v, t);
  std::vector<Mesh::Vertex_index> maxima, minima;
  HD::detect_multiscale_features(mesh, hks, std::back_inserter(maxima), std::back_inserter(minima),
                                 HD::parameters::feature_threshold(c));
  std::vector<double> values(mesh.number_of_vertices()), is_maximum(mesh.number_of_vertices(), 0.);
  for(auto v : mesh.vertices())
    values[v.idx()] = hks[v];
  for(auto v : maxima)
    is_maximum[v.idx()] = 1.;
  mesh.remove_property_map(hks);
  timer.stop("hks_and_maxima");
  write_fields_ply(output, mesh, {{"maximum", is_maximum}, {"hks", values}}, 1.);
  timer.stop("write");

  // The truncated kernel needs e^(-lambda_m t) <= 1e-4 to be accurate.
  const double lambda_m = kernel->decay_rate(kernel->number_of_eigenpairs() - 1);
  const double t_min = lambda_m > 0 ? 4 * std::log(10.) / lambda_m : std::numeric_limits<double>::infinity();
  if(!quiet)
  {
    if(t < t_min)
      std::cerr << "warning: t = " << t << " is below 4 ln 10 / lambda_m = " << t_min
                << ": the truncated kernel is inaccurate there (larger -m or -t)\n";
    std::cerr << maxima.size() << " HKS maxima; written to " << output << "\n";
  }
  if(args.flag("--json"))
  {
    const Field_statistics range = statistics(values);
    Json_object summary;
    summary.string("command", "hks")
        .string("input", input)
        .string("output", output)
        .integer("vertices", (long long)mesh.number_of_vertices())
        .number("sigma", options.sigma)
        .number("t", t)
        .number("t_min", t_min)
        .integer("eigenpairs", (long long)kernel->number_of_eigenpairs())
        .boolean("scale_invariant", kernel->is_scale_invariant())
        .number("c", c)
        .object("hks", range.json())
        .raw("maxima", json_index_list(maxima))
        .object("timings_ms", timings_json(timer));
    std::cout << summary.str() << std::endl;
  }
  return success;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_HKS_H
