// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion enhance: shape editing by reweighting the detail bands of the Normal
// Signature and reconstructing (paper, eq. 26 and Fig. 10).

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_ENHANCE_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_ENHANCE_H

#include "cli_arguments.h"
#include "cli_measures.h"
#include "cli_output.h"
#include "command.h"
#include "command_decompose.h"  // level_spec, parse_steps_per_level
#include "diffusion_options.h"
#include "diffusion_setup.h"
#include "point_set_applications.h"

#include <CGAL/Heat_diffusion/decomposition.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <array>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

// Parses a comma-separated list of finite numbers ("1,3,3"), at most 1000 of them.
inline std::vector<double> parse_weights(const std::string& text)
{
  std::vector<double> weights;
  std::stringstream ss(text);
  std::string item;
  while(std::getline(ss, item, ','))
  {
    char* end = nullptr;
    const double w = std::strtod(item.c_str(), &end);
    if(item.empty() || *end != '\0' || !std::isfinite(w))
      throw Usage_error("--weights takes a comma-separated list of numbers, not '" + text + "'");
    weights.push_back(w);
  }
  if(weights.empty())
    throw Usage_error("--weights needs at least one weight");
  if(weights.size() > 1000)
    throw Usage_error("--weights takes at most 1000 weights (one per level)");
  return weights;
}

// The variance of the Normal Signature of `mesh`.
inline double normal_signature_variance(const Mesh& mesh)
{
  const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
  double sum = 0, squares = 0;
  for(auto v : mesh.vertices())
  {
    const double s = ncc.normal_signature(v);
    sum += s;
    squares += s * s;
  }
  const double n = double(mesh.number_of_vertices());
  return squares / n - (sum / n) * (sum / n);
}

// The weights "1,3,3" of a list of them.
inline std::string weight_list_text(const std::array<double, 3>& weights)
{
  std::string text;
  for(double w : weights)
    text += (text.empty() ? "" : ",") + format_number(w);
  return text;
}

// -k as filter_shape() takes it; the help states its default steps per level.
inline Diffusion_spec enhance_spec() { return level_spec(HD::defaults::shape_filter_steps_per_level); }

inline std::string enhance_help()
{
  return "Usage: heat_diffusion enhance MESH [--weights W1,W2,...] [-k S] [--sigma S] [--time T]\n"
         "                              [--kernel K] [-m M] [--coarse N] [--scale-invariant]\n"
         "                              [--anchor-weight A] [-o OUT] [--json] [--quiet]\n"
         "       heat_diffusion enhance POINTS [--neighbors K] [--neighbor-radius R] [OPTIONS]\n"
         "\n"
         "Shape editing (the paper's Fig. 10): the Normal Signature is decomposed into L detail\n"
         "bands D^1..D^L (finest first) and a residual S^L, as 'decompose' does; the signature\n"
         "w_1 D^1 + ... + w_L D^L + S^L is rebuilt with the given weights, and the vertices are\n"
         "moved to match it (least-squares reconstruction, eq. 23). The paper's enhancement filter\n"
         "is 1,3,3, its smoothing filter 0,0,1; weights all 1 return the input.\n"
         "On POINTS (a file of points without faces, see ncc --help) the points move along their\n"
         "normals on the surface of their fans (CGAL::Heat_diffusion::filter_point_set_shape, no\n"
         "--coarse); the output is a PLY of the points, with the file's normals if it has some.\n"
         "\n"
         "Options:\n" +
         help_option("--weights W,...", "one weight per band, finest first; their number is L (default " +
                                            weight_list_text(HD::defaults::enhancement_weights) + ")") +
         diffusion_options_help(enhance_spec()) +
         help_option("--anchor-weight A", "weight of the positional anchors of the reconstruction (default " +
                                              format_number(HD::defaults::shape_filter_anchor_weight) +
                                              "); smaller lets the shape move further") +
         help_option("-o OUT", "the edited mesh, .off, .obj, .ply or .stl (default: MESH's name with _enhanced.off, "
                               "in the current folder); for POINTS a .ply (default: _enhanced.ply)") +
         help_option("--json", "print a JSON summary on stdout: the variance of the NS before and after, the largest "
                               "vertex displacement relative to the bounding-box diagonal, the kernel and its coarse "
                               "level, and the time of each stage") +
         neighbourhood_options_help() + common_options_help();
}

inline Command enhance_command()
{
  Command command;
  command.name = "enhance";
  command.overview = "enhance MESH   Shape editing: reweighted NS detail bands, e.g. --weights 1,3,3";
  command.valued = {"--weights", "--steps-per-level", "--anchor-weight"};
  command.diffusion = enhance_spec();
  command.point_sets = true;
  command.help = enhance_help;
  command.run = [](Run& r) {
    const Diffusion_options& o = r.diffusion;
    const std::vector<double> weights =
        parse_weights(r.args.value("--weights", weight_list_text(HD::defaults::enhancement_weights)));
    const std::optional<std::size_t> steps_per_level = parse_steps_per_level(r.args, o);
    const std::optional<double> anchor_weight =
        r.args.has("--anchor-weight")
            ? std::optional<double>(parse_number("--anchor-weight", r.args.value("--anchor-weight", ""), 0., true))
            : std::nullopt;
    const std::string output =
        r.args.value("-o", default_output(r.input, r.points ? "_enhanced.ply" : "_enhanced.off"));
    if(r.points)
      return enhance_on_points(r, weights, steps_per_level, anchor_weight, output);
    mesh_format(output);
    r.check_outputs({output});

    Mesh mesh;
    r.read_mesh(mesh);
    const Mesh original = mesh;
    const double input_variance = for_input(r.input, [&] { return normal_signature_variance(mesh); });
    r.timer.stop("ncc");
    // The steps per level and the anchor weight as given, or empty (filter_shape()'s own
    // defaults): one instantiation of it, not one per combination of options given.
    Progress_bar progress("eigen solve", !r.quiet);
    for_input(r.input, [&] {
      with_diffusion_parameters(o, progress, [&](const auto& np) {
        HD::filter_shape(mesh, weights,
                         HD::parameters::combine(np, HD::parameters::steps_per_level(steps_per_level),
                                                 HD::parameters::anchor_weight(anchor_weight)));
      });
    });
    progress.finish();
    r.timer.stop("filter_shape");
    // Measured before writing: a failure leaves no output.
    const double output_variance = for_input(r.input, [&] { return normal_signature_variance(mesh); });
    double displacement = 0;
    for(auto v : mesh.vertices())
      displacement = (std::max)(displacement, point_distance(mesh.point(v), original.point(v)));
    const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(original);
    const double diagonal = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin());
    const double relative_displacement = diagonal > 0 ? displacement / diagonal : 0.;
    write_mesh(output, mesh);
    r.timer.stop("write");

    note_automatic_coarse(o, mesh.number_of_vertices(), expected_coarse_vertex_count(o, mesh.number_of_vertices()));
    if(!r.quiet)
      std::cerr << "NS variance " << input_variance << " -> " << output_variance << "; largest displacement "
                << relative_displacement << " of the diagonal\nwritten to " << output << "\n";
    r.summary.string("output", output)
        .integer("vertices", (long long)mesh.number_of_vertices())
        .raw("weights", number_list_json(weights))
        .integer("steps_per_level",
                 (long long)steps_per_level.value_or(HD::defaults::shape_filter_steps_per_level));
    std::vector<std::string> own_given;
    if(steps_per_level)
      own_given.push_back("steps_per_level");
    if(anchor_weight)
      own_given.push_back("anchor_weight");
    add_diffusion_json(r.summary, o, mesh.number_of_vertices(), nullptr, nullptr, own_given);
    r.summary.number("anchor_weight", anchor_weight.value_or(HD::defaults::shape_filter_anchor_weight))
        .number("ns_variance_before", input_variance)
        .number("ns_variance_after", output_variance)
        .number("max_displacement_relative", relative_displacement);
  };
  return command;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_ENHANCE_H
