// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion ncc: Normal-Controlled Coordinates and the Normal Signature.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_NCC_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_NCC_H

#include "cli_measures.h"
#include "cli_output.h"
#include "command.h"
#include "point_set_commands.h"
#include "point_set_options.h"

#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>

#include <iostream>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

const char* const ncc_help =
    "Usage: heat_diffusion ncc MESH [-o OUT.ply] [--normals area|pmp] [--json] [--quiet] [--no-repair]\n"
    "       heat_diffusion ncc POINTS [-o OUT.ply] [--neighbors K] [--neighbor-radius R] [--json] [--quiet]\n"
    "\n"
    "Computes the Normal-Controlled Coordinates (NCC) of every vertex and their Normal\n"
    "Signature NS = NCC . normal: a scale- and rotation-invariant scalar field, positive at\n"
    "convex vertices, negative at concave ones, zero on flat regions.\n"
    "\n"
    "POINTS is a file of points without faces (XYZ, PWN, or PLY or OFF without faces), with\n"
    "normals (nx, ny, nz) or without (then estimated and oriented). Each point's one-ring is\n"
    "its fan: the Delaunay triangulation of its neighbours projected on its tangent plane.\n"
    "The output is then a PLY of the points with 'ns' and the normals 'nx', 'ny', 'nz'.\n"
    "\n"
    "Options:\n"
    "  -o OUT.ply        output file (default: MESH's name with _ns.ply, in the current folder).\n"
    "                    A binary PLY with the per-vertex properties 'ns' (double) and\n"
    "                    red/green/blue: a diverging colour map, red convex (NS > 0), blue\n"
    "                    concave (NS < 0), white flat, saturated at the 98th percentile of |NS|.\n"
    "  --normals RULE    vertex normals: 'area' (default; the paper's MWAAT, face normals\n"
    "                    weighted by area) or 'pmp' (CGAL::Polygon_mesh_processing::\n"
    "                    compute_vertex_normals)\n"
    "  --json            print a JSON summary on stdout: input, output, vertex and face\n"
    "                    counts, triangulated faces, NS min/max/mean,\n"
    "                    and the time of each stage in milliseconds\n"
    "  --quiet           print nothing but errors (and the JSON summary if asked for)\n"
    "  -h, --help        this text\n";

inline std::string ncc_help_text() { return ncc_help + repair_option_help() + neighbourhood_options_help(); }

inline Command ncc_command()
{
  Command command;
  command.name = "ncc";
  command.overview = "ncc MESH     Normal-Controlled Coordinates and the Normal Signature (NS) of a mesh";
  command.valued = {"-o", "--normals"};
  command.point_sets = true;
  command.help = ncc_help_text;
  command.run = [](Run& r) {
    const std::string output = r.args.value("-o", default_output(r.input, "_ns.ply"));
    if(r.points)
      return ncc_on_points(r, output);
    const std::string normals = r.args.value("--normals", "area");  // the library's default rule
    if(normals != "area" && normals != "pmp")
      throw Usage_error("--normals must be 'area' or 'pmp', not '" + normals + "'");
    r.check_outputs({output});

    Mesh mesh;
    const std::size_t triangulated = r.read_mesh(mesh);
    std::vector<double> ns(mesh.number_of_vertices());
    for_input(r.input, [&] {
      auto compute = [&](const auto& np) {
        const HD::Normal_controlled_coordinates<Mesh> ncc(mesh, np);
        for(auto v : mesh.vertices())
          ns[v.idx()] = ncc.normal_signature(v);
      };
      if(!r.args.has("--normals"))
        compute(HD::parameters::default_values());
      else if(normals == "pmp")
        compute(HD::parameters::vertex_normal_rule(HD::Polygon_mesh_processing_vertex_normals()));
      else
        compute(HD::parameters::vertex_normal_rule(HD::Area_weighted_vertex_normals()));
    });
    r.timer.stop("ncc");

    write_fields_ply(output, mesh, r.with_origin({{"ns", ns}}));
    r.timer.stop("write");

    const Field_statistics s = statistics(ns);
    if(!r.quiet)
      std::cerr << r.input << ": " << mesh.number_of_vertices() << " vertices, NS in [" << s.min << ", " << s.max
                << "], written to " << output << "\n";
    r.summary.string("output", output)
        .string("normals", normals)
        .integer("vertices", static_cast<long long>(mesh.number_of_vertices()))
        .integer("faces", static_cast<long long>(mesh.number_of_faces()))
        .integer("triangulated_faces", static_cast<long long>(triangulated))
        .object("ns", s.json());
  };
  return command;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_NCC_H
