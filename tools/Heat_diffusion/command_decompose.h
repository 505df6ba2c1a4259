// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion decompose: detail bands and residual of a field (paper, eq. 24-25).

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DECOMPOSE_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DECOMPOSE_H

#include "command_features.h"

#include <CGAL/Heat_diffusion/decomposition.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

const char* const decompose_help =
    "Usage: heat_diffusion decompose MESH [--levels L] [--steps-per-level S] [--sigma S] [--time T]\n"
    "                                [-m M] [--field ns|FILE] [--scale-invariant] [-o PREFIX] [--json] [--quiet]\n"
    "\n"
    "Hierarchical decomposition of a field (the paper's eq. 24): S = D^1 + ... + D^L + S^L with\n"
    "D^j = F^((j-1)s) - F^(js) and the residual S^L = F^(Ls), where F^k = A_t^k S is the\n"
    "heat-conserving diffusion and s the steps per level. D^1 holds the finest details.\n"
    "Every band sums to zero (eq. 25), up to rounding.\n"
    "\n"
    "Options:\n"
    "  --levels L          number of detail bands (default 3)\n"
    "  --steps-per-level S diffusion steps of one level (default 5)\n"
    "  --sigma S           edge-weight width (default 0.1; the paper's Fig. 9 uses 0.5)\n"
    "  --time T            time of one step (default 1)\n"
    "  -m M                number of eigenpairs (default 150)\n"
    "  --field F           'ns' (default): the Normal Signature; or a text file with one number\n"
    "                      per vertex, in the order of the mesh file's vertices\n"
    "  --scale-invariant   the scale-invariant kernel of the paper's eq. 14\n"
    "  -o PREFIX           outputs PREFIX_band<j>.ply for j = 1..L and PREFIX_residual.ply\n"
    "                      (default: MESH's name with _decomposed, in the current folder):\n"
    "                      binary PLYs with the vertex property 'field', each with its own\n"
    "                      diverging colour scale\n"
    "  --json              print a JSON summary on stdout: per band its sum, its sum relative\n"
    "                      to sum |S|, and its L2 norm; the total heat of S and of the residual\n"
    "  --quiet             print nothing but errors (and the JSON summary if asked for)\n"
    "  -h, --help          this text\n";

inline int run_decompose(int argc, char** argv)
{
  Arguments args({"--json", "--quiet", "--scale-invariant", "-h", "--help"},
                 {"-o", "--sigma", "--time", "-m", "--levels", "--steps-per-level", "--field"});
  args.parse(argc, argv, 2);
  if(args.flag("-h") || args.flag("--help"))
  {
    std::cout << decompose_help;
    return success;
  }
  if(args.positional().size() != 1)
    throw Usage_error("decompose takes exactly one MESH argument");
  const std::string input = args.positional()[0];
  const Diffusion_options options = parse_diffusion_options(args);
  const double levels = parse_number("--levels", args.value("--levels", "3"), 1., false);
  const double steps_per_level = parse_number("--steps-per-level", args.value("--steps-per-level", "5"), 1., false);
  if(levels != std::floor(levels) || levels > 1000)
    throw Usage_error("--levels must be an integer between 1 and 1000");
  if(steps_per_level != std::floor(steps_per_level) || steps_per_level > 1000000)
    throw Usage_error("--steps-per-level must be an integer between 1 and 1000000");
  const std::string field_source = args.value("--field", "ns");
  const std::string prefix = args.value("-o", fs::path(input).stem().string() + "_decomposed");
  std::vector<std::string> outputs;
  for(std::size_t j = 1; j <= std::size_t(levels); ++j)
    outputs.push_back(prefix + "_band" + std::to_string(j) + ".ply");
  outputs.push_back(prefix + "_residual.ply");
  for(const std::string& output : outputs)
    check_output_path(output, {input, field_source});
  const bool quiet = args.flag("--quiet");

  Stage_timer timer;
  Mesh mesh;
  read_triangle_mesh(input, mesh);
  timer.stop("read");
  const std::unique_ptr<Heat_kernel> kernel = make_heat_kernel(mesh, options, input, quiet);
  timer.stop("ncc_and_eigen_solve");
  const HD::Anisotropic_heat_diffusion<Mesh> diffusion(*kernel, options.time);
  timer.stop("operator");

  typedef Mesh::Property_map<Mesh::Vertex_index, double> Field_map;
  const Eigen::VectorXd f0 = initial_field(field_source, mesh, *kernel);
  Field_map field = mesh.add_property_map<Mesh::Vertex_index, double>("v:decompose_input", 0.).first;
  for(auto v : mesh.vertices())
    field[v] = f0[Eigen::Index(kernel->vertex_index(v))];
  std::vector<Field_map> bands;
  for(std::size_t j = 1; j <= std::size_t(levels); ++j)
    bands.push_back(mesh.add_property_map<Mesh::Vertex_index, double>("v:band" + std::to_string(j), 0.).first);
  Field_map residual = mesh.add_property_map<Mesh::Vertex_index, double>("v:residual", 0.).first;
  HD::decompose_field(diffusion, field, bands, residual,
                      HD::parameters::steps_per_level(std::size_t(steps_per_level)));
  timer.stop("decomposition");

  // The PLYs get copies of the values: the mesh they write must not carry the maps.
  std::vector<std::vector<double> > values;
  for(const Field_map& map : bands)
    values.emplace_back(map.begin(), map.end());
  values.emplace_back(residual.begin(), residual.end());
  const std::vector<double> input_values(field.begin(), field.end());
  for(Field_map& map : bands)
    mesh.remove_property_map(map);
  mesh.remove_property_map(residual);
  mesh.remove_property_map(field);
  for(std::size_t j = 0; j < values.size(); ++j)
    write_fields_ply(outputs[j], mesh, {{"field", values[j]}});
  timer.stop("write");

  double absolute_sum = 0, total_heat = 0;
  for(double x : input_values)
  {
    absolute_sum += std::abs(x);
    total_heat += x;
  }
  Json_object band_json, files;
  double worst_relative_sum = 0;
  for(std::size_t j = 0; j + 1 < values.size(); ++j)
  {
    double sum = 0, squares = 0;
    for(double x : values[j])
    {
      sum += x;
      squares += x * x;
    }
    const double relative = absolute_sum > 0 ? std::abs(sum) / absolute_sum : 0.;
    worst_relative_sum = (std::max)(worst_relative_sum, relative);
    Json_object b;
    b.number("sum", sum).number("relative_sum", relative).number("l2_norm", std::sqrt(squares));
    band_json.object(std::to_string(j + 1), b);
    files.string(std::to_string(j + 1), outputs[j]);
  }
  files.string("residual", outputs.back());
  double residual_heat = 0;
  for(double x : values.back())
    residual_heat += x;

  warn_about_collapsed_regions(diffusion.region_statistics(), quiet);
  if(!quiet)
    std::cerr << std::size_t(levels) << " bands of " << std::size_t(steps_per_level)
              << " steps; largest |band sum| / sum |S| = " << worst_relative_sum << "\nwritten to " << prefix
              << "_band*.ply and " << outputs.back() << "\n";
  if(args.flag("--json"))
  {
    Json_object summary;
    summary.string("command", "decompose")
        .string("input", input)
        .string("field", field_source)
        .object("outputs", files)
        .integer("vertices", (long long)mesh.number_of_vertices())
        .number("sigma", options.sigma)
        .number("time", options.time)
        .integer("eigenpairs", (long long)kernel->number_of_eigenpairs())
        .integer("levels", (long long)levels)
        .integer("steps_per_level", (long long)steps_per_level)
        .object("heat_regions", heat_region_json(diffusion.region_statistics()))
        .number("total_heat", total_heat)
        .number("residual_heat", residual_heat)
        .object("bands", band_json)
        .object("timings_ms", timings_json(timer));
    std::cout << summary.str() << std::endl;
  }
  return success;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DECOMPOSE_H
