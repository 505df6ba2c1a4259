// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion features: multi-scale convex and concave features of a diffused field.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_FEATURES_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_FEATURES_H

#include "cli_output.h"
#include "command.h"
#include "diffusion_fields.h"
#include "diffusion_options.h"
#include "diffusion_setup.h"
#include "point_set_commands.h"
#include "point_set_options.h"

#include <CGAL/Heat_diffusion/multiscale_features.h>

#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

inline std::string json_index_list(const std::vector<Mesh::Vertex_index>& vertices)
{
  std::string s = "[";
  for(std::size_t i = 0; i < vertices.size(); ++i)
    s += (i ? ", " : "") + std::to_string(vertices[i].idx());
  return s + "]";
}

// Parses --c, the threshold of the feature criterion, in [0, 1]; empty if not given
// (the library's default).
inline std::optional<double> parse_feature_threshold(const Arguments& args)
{
  if(!args.has("--c"))
    return std::nullopt;
  const double c = parse_number("--c", args.value("--c", ""), 0., false);
  if(c > 1)
    throw Usage_error("--c must be in [0, 1], not '" + args.value("--c", "") + "'");
  return c;
}

inline std::string feature_threshold_help()
{
  return help_option("--c C", "the threshold c in [0, 1] (default " + format_number(HD::defaults::feature_threshold) +
                                  ")");
}

inline Diffusion_spec features_spec()
{
  Diffusion_spec spec;
  spec.steps_help = "the scales k, 0 to 1000000 (default " + spec.steps_default + ")";
  spec.field = true;
  return spec;
}

inline std::string features_help()
{
  return "Usage: heat_diffusion features MESH [--sigma S] [--time T] [--kernel K] [-m M]\n"
         "                               [--coarse N] [-k K1,K2,...] [--c C] [--field ns|FILE]\n"
         "                               [--scale-invariant] [-o PREFIX] [--json] [--quiet]\n"
         "       heat_diffusion features POINTS [--neighbors K] [--neighbor-radius R] [OPTIONS]\n"
         "\n"
         "Multi-scale feature detection (the paper's section 7). The field F^0 (the Normal\n"
         "Signature by default) is diffused to F^k = A_t^k F^0; at scale k, a vertex is a convex\n"
         "feature if F^k there is above F^k at every other vertex of its 2-ring and above\n"
         "C max F^k, a concave feature if it is below them all and below C min F^k.\n"
         "On POINTS (a file of points without faces, see ncc --help) the 2-ring is taken in the\n"
         "graph of the points' fans, the diffusion runs on their surface (no --coarse), and the\n"
         "outputs are PLYs of the points with 'feature', 'field' and the normals.\n"
         "\n"
         "Options:\n" +
         diffusion_options_help(features_spec()) +
         feature_threshold_help() +
         help_option("-o PREFIX",
                     "outputs PREFIX_k<K>.ply (default: MESH's name with _features, in the current folder): binary "
                     "PLYs with the vertex properties 'feature' (+1 convex, -1 concave, 0 else) and 'field' (F^k), "
                     "coloured red (convex), blue (concave) and light grey. All are written, or none") +
         help_option("--json", "print a JSON summary on stdout: the vertex indices of the convex and concave features "
                               "per k (0-based, in the order of the mesh file), the heat regions, the kernel and its "
                               "coarse level, and the time of each stage in milliseconds") +
         neighbourhood_options_help() + common_options_help() +
         "\nHeat regions that collapse to their vertex (the truncated kernel at small sigma and\n"
         "t) keep their heat and can make spurious features: the tool warns about them.\n";
}

// +1 at convex features, -1 at concave ones, 0 elsewhere: with write_fields_ply's
// colour map saturated at 1, red, blue and light grey.
inline std::vector<double> feature_labels(const std::vector<Mesh::Vertex_index>& convex,
                                          const std::vector<Mesh::Vertex_index>& concave, std::size_t n)
{
  std::vector<double> labels(n, 0.);
  for(auto v : convex)
    labels[v.idx()] = 1.;
  for(auto v : concave)
    labels[v.idx()] = -1.;
  return labels;
}

inline Command features_command()
{
  Command command;
  command.name = "features";
  command.overview = "features MESH  Convex and concave features of the diffused NS (or a field) at scales k";
  command.valued = {"--c"};
  command.diffusion = features_spec();
  command.point_sets = true;
  command.help = features_help;
  command.run = [](Run& r) {
    const Diffusion_options& o = r.diffusion;
    const std::optional<double> c = parse_feature_threshold(r.args);
    const std::string prefix = r.args.value("-o", default_output(r.input, "_features"));
    const std::vector<std::string> outputs = step_outputs(prefix, o.steps);
    if(r.points)
      return features_on_points(r, c, prefix, outputs);
    r.check_outputs(outputs, {o.field});

    Mesh mesh;
    r.read_mesh(mesh);
    const Diffusion_setup setup = make_diffusion(mesh, o, r.input, r.timer);
    const Diffusion& diffusion = *setup.diffusion;

    // The fields F^k once (with a progress bar), then the features of each: the
    // criterion of detect_multiscale_features(diffusion, ...) applied to F^k as given.
    const Eigen::VectorXd f0 = initial_field(o.field, mesh, diffusion);
    const std::vector<Eigen::VectorXd> fields = diffuse_fields(diffusion, f0, o.steps, o, r.input);
    r.timer.stop("diffusion");
    std::vector<std::vector<Mesh::Vertex_index> > convex(o.steps.size()), concave(o.steps.size());
    std::vector<std::vector<double> > values;
    auto field = mesh.add_property_map<Mesh::Vertex_index, double>("v:diffused_field", 0.).first;
    for(std::size_t s = 0; s < o.steps.size(); ++s)
    {
      values.push_back(in_mesh_order(fields[s], mesh, diffusion));
      for(auto v : mesh.vertices())
        field[v] = values[s][v.idx()];
      for_input(r.input, [&] {
        HD::detect_multiscale_features(mesh, field, std::back_inserter(convex[s]), std::back_inserter(concave[s]),
                                       HD::parameters::feature_threshold(c));
      });
    }
    mesh.remove_property_map(field);
    r.timer.stop("features");

    Output_files files;
    Json_object per_scale, names;
    for(std::size_t s = 0; s < o.steps.size(); ++s)
    {
      write_fields_ply(files, outputs[s], mesh,
                       r.with_origin({{"feature", feature_labels(convex[s], concave[s], mesh.number_of_vertices())},
                                      {"field", values[s]}}),
                       1.);
      Json_object scale;
      scale.raw("convex", json_index_list(convex[s])).raw("concave", json_index_list(concave[s]));
      per_scale.object(std::to_string(o.steps[s]), scale);
      names.string(std::to_string(o.steps[s]), outputs[s]);
    }
    files.commit();
    r.timer.stop("write");

    note_automatic_coarse(o, mesh.number_of_vertices(), setup.kernel ? setup.kernel->coarse_vertex_count() : 0);
    warn_about_collapsed_regions(diffusion, o);
    if(!r.quiet)
    {
      for(std::size_t s = 0; s < o.steps.size(); ++s)
        std::cerr << "k = " << o.steps[s] << ": " << convex[s].size() << " convex, " << concave[s].size()
                  << " concave features\n";
      std::cerr << "written to " << prefix << "_k*.ply\n";
    }
    r.summary.string("field", o.field).object("outputs", names).integer("vertices", (long long)mesh.number_of_vertices());
    add_diffusion_json(r.summary, o, mesh.number_of_vertices(), setup.kernel.get(), &diffusion,
                       c ? std::vector<std::string>{"feature_threshold"} : std::vector<std::string>{});
    r.summary.number("c", c.value_or(HD::defaults::feature_threshold))
        .object("heat_regions", heat_region_json(diffusion.region_statistics()))
        .object("features", per_scale);
  };
  return command;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_FEATURES_H
