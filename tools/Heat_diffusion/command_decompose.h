// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion decompose: detail bands and residual of a field (paper, eq. 24-25).

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DECOMPOSE_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DECOMPOSE_H

#include "cli_arguments.h"
#include "cli_measures.h"
#include "cli_output.h"
#include "command.h"
#include "diffusion_fields.h"
#include "diffusion_options.h"
#include "diffusion_setup.h"
#include "point_set_applications.h"

#include <CGAL/Heat_diffusion/decomposition.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

// A decomposition spec: -k is the number of steps of one level, also spelled
// --steps-per-level.
inline Diffusion_spec level_spec(std::size_t library_default = HD::defaults::decomposition_steps_per_level)
{
  Diffusion_spec spec;
  spec.steps = Diffusion_spec::single_step;
  const std::string steps_default = std::to_string(library_default);
  spec.steps_default = steps_default;
  spec.steps_help = "diffusion steps of one level, 1 to 1000000 (default " + steps_default +
                    "); --steps-per-level S is the same";
  return spec;
}

// The steps per level: -k or --steps-per-level (not both), from 1 to 1000000; empty if
// neither is given (the library's default).
inline std::optional<std::size_t> parse_steps_per_level(const Arguments& args, const Diffusion_options& o)
{
  if(args.has("-k") && args.has("--steps-per-level"))
    throw Usage_error("give the steps per level once, with -k or --steps-per-level");
  if(args.has("--steps-per-level"))
    return parse_count("--steps-per-level", args.value("--steps-per-level", ""), 1, maximum_steps);
  if(o.step_count && *o.step_count == 0)
    throw Usage_error("-k must be a whole number from 1 to 1000000 here (the steps of one level), not '0'");
  return o.step_count;
}

inline Diffusion_spec decompose_spec()
{
  Diffusion_spec spec = level_spec();
  spec.sigma_note = "the paper's Fig. 9 uses 0.5";
  spec.field = true;
  return spec;
}

inline std::string decompose_help()
{
  return "Usage: heat_diffusion decompose MESH [--levels L] [-k S] [--sigma S] [--time T]\n"
         "                                [--kernel K] [-m M] [--coarse N] [--field ns|FILE]\n"
         "                                [--scale-invariant] [-o PREFIX] [--json] [--quiet]\n"
         "       heat_diffusion decompose POINTS [--neighbors K] [--neighbor-radius R] [OPTIONS]\n"
         "\n"
         "Hierarchical decomposition of a field (the paper's eq. 24): S = D^1 + ... + D^L + S^L with\n"
         "D^j = F^((j-1)s) - F^(js) and the residual S^L = F^(Ls), where F^k = A_t^k S is the\n"
         "heat-conserving diffusion and s the steps per level. D^1 holds the finest details.\n"
         "Every band sums to zero (eq. 25), up to rounding.\n"
         "On POINTS (a file of points without faces, see ncc --help) the diffusion runs on the\n"
         "surface of the points' fans (no --coarse); the outputs are PLYs of the points with\n"
         "'field' and the normals (CGAL::Heat_diffusion::decompose_point_set_field).\n"
         "\n"
         "Options:\n" +
         help_option("--levels L", "number of detail bands, 1 to 1000 (default " +
                                       std::to_string(HD::defaults::detail_levels) + ")") +
         diffusion_options_help(decompose_spec()) +
         help_option("-o PREFIX", "outputs PREFIX_band<j>.ply for j = 1..L and PREFIX_residual.ply (default: MESH's "
                                  "name with _decomposed, in the current folder): binary PLYs with the vertex "
                                  "property 'field', each with its own diverging colour scale. All are written, or "
                                  "none") +
         help_option("--json", "print a JSON summary on stdout: per band its sum, its sum relative to sum |S|, and "
                               "its L2 norm; the total heat of S and of the residual; the kernel and its coarse "
                               "level; the time of each stage in milliseconds") +
         neighbourhood_options_help() + common_options_help();
}

inline Command decompose_command()
{
  Command command;
  command.name = "decompose";
  command.overview = "decompose MESH Detail bands and residual of the NS (or a field), each band of sum 0";
  command.valued = {"--levels", "--steps-per-level"};
  command.diffusion = decompose_spec();
  command.point_sets = true;
  command.help = decompose_help;
  command.run = [](Run& r) {
    const Diffusion_options& o = r.diffusion;
    const std::size_t levels =
        parse_count("--levels", r.args.value("--levels", std::to_string(HD::defaults::detail_levels)), 1, 1000);
    const std::optional<std::size_t> steps_per_level = parse_steps_per_level(r.args, o);
    const std::string prefix = r.args.value("-o", default_output(r.input, "_decomposed"));
    std::vector<std::string> outputs;
    for(std::size_t j = 1; j <= levels; ++j)
      outputs.push_back(prefix + "_band" + std::to_string(j) + ".ply");
    outputs.push_back(prefix + "_residual.ply");
    if(r.points)
      return decompose_on_points(r, levels, steps_per_level, prefix, outputs);
    r.check_outputs(outputs, {o.field});

    Mesh mesh;
    r.read_mesh(mesh);
    const Diffusion_setup setup = make_diffusion(mesh, o, r.input, r.timer);
    const Diffusion& diffusion = *setup.diffusion;

    typedef Mesh::Property_map<Mesh::Vertex_index, double> Field_map;
    const Eigen::VectorXd f0 = initial_field(o.field, mesh, diffusion);
    Field_map field = mesh.add_property_map<Mesh::Vertex_index, double>("v:decompose_input", 0.).first;
    for(auto v : mesh.vertices())
      field[v] = f0[Eigen::Index(diffusion.vertex_index(v))];
    std::vector<Field_map> bands;
    for(std::size_t j = 1; j <= levels; ++j)
      bands.push_back(mesh.add_property_map<Mesh::Vertex_index, double>("v:band" + std::to_string(j), 0.).first);
    Field_map residual = mesh.add_property_map<Mesh::Vertex_index, double>("v:residual", 0.).first;
    for_input(r.input,
              [&] { HD::decompose_field(diffusion, field, bands, residual, HD::parameters::steps_per_level(steps_per_level)); });
    const std::size_t steps_used = steps_per_level.value_or(HD::defaults::decomposition_steps_per_level);
    r.timer.stop("decomposition");

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
    Output_files files;
    for(std::size_t j = 0; j < values.size(); ++j)
      write_fields_ply(files, outputs[j], mesh, r.with_origin({{"field", values[j]}}));
    files.commit();
    r.timer.stop("write");

    const Band_summary summary = band_summary(input_values, values, outputs);
    note_automatic_coarse(o, mesh.number_of_vertices(), setup.kernel ? setup.kernel->coarse_vertex_count() : 0);
    warn_about_collapsed_regions(diffusion, o);
    if(!r.quiet)
      std::cerr << levels << " bands of " << steps_used << " steps; largest |band sum| / sum |S| = "
                << summary.worst_relative_sum << "\nwritten to " << prefix << "_band*.ply and " << outputs.back() << "\n";
    r.summary.string("field", o.field)
        .object("outputs", summary.names)
        .integer("vertices", (long long)mesh.number_of_vertices());
    add_diffusion_json(r.summary, o, mesh.number_of_vertices(), setup.kernel.get(), &diffusion,
                       steps_per_level ? std::vector<std::string>{"steps_per_level"} : std::vector<std::string>{});
    r.summary.integer("levels", (long long)levels)
        .integer("steps_per_level", (long long)steps_used)
        .object("heat_regions", heat_region_json(diffusion.region_statistics()));
    summary.add_to(r.summary);
  };
  return command;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DECOMPOSE_H
