// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A subcommand of the tool as one table entry (its name, options, help and work), and
// what every subcommand does alike: parsing its command line, --help, the shared
// diffusion options, checking its outputs, reading its mesh, the JSON summary.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_H

#include "cli_arguments.h"
#include "cli_errors.h"
#include "cli_json.h"
#include "cli_output.h"
#include "cli_progress.h"
#include "diffusion_options.h"
#include "mesh_input.h"
#include "mesh_repair.h"
#include "point_set_input.h"

#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace heat_diffusion_cli {

namespace HD = CGAL::Heat_diffusion;

// The JSON account of a repair: its counts, the vertices of the result, and the input
// vertices that became several ("copies": {"input vertex": [its vertices in the result]}).
inline Json_object repair_json(const Repair_report& r, std::size_t vertices)
{
  std::map<std::size_t, std::vector<std::size_t> > copies;
  for(std::size_t v = 0; v < r.origin.size(); ++v)
    copies[r.origin[v]].push_back(v);
  std::string list;
  for(const auto& entry : copies)
    if(entry.second.size() > 1)
    {
      list += (list.empty() ? "\"" : ", \"") + std::to_string(entry.first) + "\": [";
      for(std::size_t i = 0; i < entry.second.size(); ++i)
        list += (i ? ", " : "") + std::to_string(entry.second[i]);
      list += "]";
    }
  Json_object o;
  o.integer("points_merged", (long long)r.points_merged)
      .integer("polygons_removed", (long long)r.polygons_removed)
      .integer("faces_reoriented", (long long)r.faces_reoriented)
      .integer("vertices_split", (long long)r.vertices_split)
      .integer("isolated_vertices_removed", (long long)r.isolated_vertices_removed)
      .integer("degenerate_faces_removed", (long long)r.degenerate_faces_removed)
      .integer("polygons_triangulated", (long long)r.polygons_triangulated)
      .integer("vertices", (long long)vertices)
      .boolean("vertices_as_in_the_file", r.keeps_vertices())
      .raw("copies", "{" + list + "}");
  return o;
}

// One run of a subcommand: its parsed command line and what it reports.
struct Run
{
  explicit Run(Arguments arguments) : args(std::move(arguments)), input(args.positional()[0]) {}

  Arguments args;
  std::string input;            // the subcommand's one argument, the input mesh (or point set)
  bool points = false;          // the input holds points without faces (holds_points_only())
  Diffusion_options diffusion;  // the shared diffusion options (their defaults if it takes none)
  bool json = false, quiet = false;
  Stage_timer timer;
  // The --json summary: "command" and "input", then the subcommand's members; the
  // timings of the stages are added last.
  Json_object summary;

  // Refuses, before any work, outputs that would overwrite the input mesh or one of
  // `other_inputs`, or that exist and are not regular files.
  void check_outputs(const std::vector<std::string>& outputs, const std::vector<std::string>& other_inputs = {}) const
  {
    std::vector<std::string> inputs(1, input);
    inputs.insert(inputs.end(), other_inputs.begin(), other_inputs.end());
    for(const std::string& output : outputs)
      check_output_path(output, inputs);
  }

  // Reads the input mesh (stage "read"), repaired unless --no-repair is given; returns
  // the number of faces triangulated. A repair is reported: a line on stderr, "repair"
  // in the JSON summary, and, where it renumbered the vertices, their input vertex in the
  // PLY outputs (with_origin()).
  std::size_t read_mesh(Mesh& mesh)
  {
    timer.start();
    const std::size_t triangulated = read_triangle_mesh(input, mesh, args.flag("--no-repair") ? nullptr : &repair);
    timer.stop("read");
    if(repair.changed())
    {
      if(!quiet)
        std::cerr << input << ": repaired: " << repair_summary(repair)
                  << (repair.keeps_vertices() ? ""
                                              : "; the vertices are renumbered: the PLY outputs' property 'origin' "
                                                "and --json's \"repair\" map them to the file's")
                  << "\n";
      summary.object("repair", repair_json(repair, mesh.number_of_vertices()));
    }
    return triangulated;
  }

  // The per-vertex fields of a PLY output, with "origin", the file's vertex of each
  // vertex, where the repair renumbered them.
  std::vector<std::pair<std::string, std::vector<double> > >
  with_origin(std::vector<std::pair<std::string, std::vector<double> > > fields) const
  {
    if(repair.changed() && !repair.keeps_vertices())
      fields.emplace_back("origin", std::vector<double>(repair.origin.begin(), repair.origin.end()));
    return fields;
  }

  Repair_report repair;  // what the repair of the input changed (nothing, if it needed none)
};

// A subcommand: what it states of its own; run_command() does the rest.
struct Command
{
  std::string name;
  std::string overview;             // its line in the tool's --help
  std::string argument = "MESH";    // what its one argument is, for the usage error
  std::vector<std::string> flags;   // its own options without a value ...
  std::vector<std::string> valued;  // ... and with one (the shared ones come with `diffusion`)
  std::optional<Diffusion_spec> diffusion;  // the shared diffusion options it takes, if any
  // Whether it runs on point sets too (then with --neighbors and --neighbor-radius), and
  // does so itself where Run::points is set; the others refuse a point set.
  bool point_sets = false;
  // Adapts `diffusion` to the subcommand's own options before the shared ones are parsed
  // (denoise: the defaults of its --method), and refuses those that do not apply.
  std::function<void(const Arguments&, Diffusion_spec&)> adapt_diffusion;
  std::function<std::string()> help;  // its --help text
  std::function<void(Run&)> run;      // its work, given the parsed shared options
};

// The subcommands that run on point sets (Command::point_sets), for the messages.
const char* const point_set_commands = "ncc, diffuse, features, decompose, enhance and denoise";

// Runs `command` on the command line argv[2..]: the shared options, --help and the
// JSON summary here, the rest in command.run.
inline int run_command(const Command& command, int argc, char** argv)
{
  std::vector<std::string> flags = command.flags, valued = command.valued;
  if(command.point_sets)
    valued.insert(valued.end(), {"--neighbors", "--neighbor-radius"});
  Arguments args = [&] {
    if(command.diffusion)
      return diffusion_arguments(*command.diffusion, flags, valued);
    for(const char* f : {"--json", "--quiet", "--no-repair", "-h", "--help"})
      flags.push_back(f);
    return Arguments(flags, valued);
  }();
  if(!args.parse_command(argc, argv, command.name, command.argument, command.help()))
    return success;

  Run run(std::move(args));
  run.json = run.args.flag("--json");
  run.quiet = run.args.flag("--quiet");
  if(command.diffusion)
  {
    Diffusion_spec spec = *command.diffusion;
    if(command.adapt_diffusion)
      command.adapt_diffusion(run.args, spec);
    run.diffusion = parse_diffusion_options(run.args, spec);
  }
  run.points = holds_points_only(run.input);
  if(run.points && !command.point_sets)
    throw Input_error(run.input + ": this file holds points and no faces: '" + command.name +
                      "' needs a triangle mesh (" + point_set_commands + " run on point sets)");
  if(!run.points && (run.args.has("--neighbors") || run.args.has("--neighbor-radius")))
    throw Usage_error(std::string(run.args.has("--neighbors") ? "--neighbors" : "--neighbor-radius") +
                      " concerns point sets: " + run.input + " is read as a mesh");
  run.summary.string("command", command.name).string("input", run.input);
  command.run(run);
  if(run.json)
  {
    run.summary.object("timings_ms", timings_json(run.timer));
    std::cout << run.summary.str() << std::endl;
  }
  return success;
}

// The outputs PREFIX_k<K>.ply of the steps K.
inline std::vector<std::string> step_outputs(const std::string& prefix, const std::vector<std::size_t>& steps)
{
  std::vector<std::string> outputs;
  for(std::size_t k : steps)
    outputs.push_back(prefix + "_k" + std::to_string(k) + ".ply");
  return outputs;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_H
