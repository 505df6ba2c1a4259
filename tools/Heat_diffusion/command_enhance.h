// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion enhance: shape editing by reweighting the detail bands of the Normal
// Signature and reconstructing (paper, eq. 26 and Fig. 10).

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_ENHANCE_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_ENHANCE_H

#include "cli_support.h"
#include "command_decompose.h"  // level_spec, parse_steps_per_level
#include "diffusion_options.h"

#include <CGAL/Heat_diffusion/decomposition.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>

#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cmath>
#include <iomanip>
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

// The defaults of filter_shape(): 2 steps per level.
inline Diffusion_spec enhance_spec() { return level_spec("2"); }

inline std::string enhance_help()
{
  return "Usage: heat_diffusion enhance MESH [--weights W1,W2,...] [-k S] [--sigma S] [--time T]\n"
         "                              [--kernel K] [-m M] [--coarse N] [--scale-invariant]\n"
         "                              [--anchor-weight A] [-o OUT] [--json] [--quiet]\n"
         "\n"
         "Shape editing (the paper's Fig. 10): the Normal Signature is decomposed into L detail\n"
         "bands D^1..D^L (finest first) and a residual S^L, as 'decompose' does; the signature\n"
         "w_1 D^1 + ... + w_L D^L + S^L is rebuilt with the given weights, and the vertices are\n"
         "moved to match it (least-squares reconstruction, eq. 23). The paper's enhancement filter\n"
         "is 1,3,3 (the default), its smoothing filter 0,0,1; weights all 1 return the input.\n"
         "\n"
         "Options:\n" +
         help_option("--weights W,...", "one weight per band, finest first; their number is L (default 1,3,3)") +
         diffusion_options_help(enhance_spec()) +
         help_option("--anchor-weight A", "weight of the positional anchors of the reconstruction (default 0.03); "
                                          "smaller lets the shape move further") +
         help_option("-o OUT", "the edited mesh, .off, .obj, .ply or .stl (default: MESH's name with _enhanced.off, "
                               "in the current folder)") +
         help_option("--json", "print a JSON summary on stdout: the variance of the NS before and after, the largest "
                               "vertex displacement relative to the bounding-box diagonal, the kernel and its coarse "
                               "level, and the time of each stage") +
         common_options_help();
}

inline int run_enhance(int argc, char** argv)
{
  const Diffusion_spec spec = enhance_spec();
  Arguments args = diffusion_arguments(spec, {}, {"--weights", "--steps-per-level", "--anchor-weight"});
  if(!args.parse_command(argc, argv, "enhance", "MESH", enhance_help()))
    return success;
  const std::string input = args.positional()[0];
  const Diffusion_options o = parse_diffusion_options(args, spec);
  const std::vector<double> weights = parse_weights(args.value("--weights", "1,3,3"));
  const std::size_t steps_per_level = parse_steps_per_level(args, o);
  const double anchor_weight = parse_number("--anchor-weight", args.value("--anchor-weight", "0.03"), 0., true);
  const std::string output = args.value("-o", default_output(input, "_enhanced.off"));
  mesh_format(output);
  check_output_path(output, {input});

  Stage_timer timer;
  Mesh mesh;
  read_triangle_mesh(input, mesh);
  timer.stop("read");
  const Mesh original = mesh;
  const double input_variance = for_input(input, [&] { return normal_signature_variance(mesh); });
  timer.stop("ncc");
  Progress_bar progress("eigen solve", !o.quiet);
  for_input(input, [&] {
    with_diffusion_parameters(o, progress, [&](const auto& np) {
      HD::filter_shape(mesh, weights,
                       HD::parameters::combine(np, HD::parameters::steps_per_level(steps_per_level),
                                               HD::parameters::anchor_weight(anchor_weight)));
    });
  });
  progress.finish();
  timer.stop("filter_shape");
  // Measured before writing: a failure leaves no output.
  const double output_variance = for_input(input, [&] { return normal_signature_variance(mesh); });
  double displacement = 0;
  for(auto v : mesh.vertices())
    displacement = (std::max)(displacement, point_distance(mesh.point(v), original.point(v)));
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(original);
  const double diagonal = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin());
  const double relative_displacement = diagonal > 0 ? displacement / diagonal : 0.;
  write_mesh(output, mesh);
  timer.stop("write");

  note_automatic_coarse(o, mesh.number_of_vertices(), expected_coarse_vertex_count(o, mesh.number_of_vertices()));
  if(!o.quiet)
    std::cerr << "NS variance " << input_variance << " -> " << output_variance << "; largest displacement "
              << relative_displacement << " of the diagonal\nwritten to " << output << "\n";
  if(o.json)
  {
    std::string weight_list = "[";
    for(std::size_t j = 0; j < weights.size(); ++j)
    {
      std::ostringstream os;
      os << std::setprecision(17) << weights[j];
      weight_list += (j ? ", " : "") + os.str();
    }
    Json_object summary;
    summary.string("command", "enhance")
        .string("input", input)
        .string("output", output)
        .integer("vertices", (long long)mesh.number_of_vertices())
        .raw("weights", weight_list + "]")
        .integer("steps_per_level", (long long)steps_per_level);
    add_diffusion_json(summary, o, mesh.number_of_vertices(), nullptr);
    summary.number("anchor_weight", anchor_weight)
        .number("ns_variance_before", input_variance)
        .number("ns_variance_after", output_variance)
        .number("max_displacement_relative", relative_displacement)
        .object("timings_ms", timings_json(timer));
    std::cout << summary.str() << std::endl;
  }
  return success;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_ENHANCE_H
