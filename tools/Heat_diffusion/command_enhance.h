// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion enhance: shape editing by reweighting the detail bands of the Normal
// Signature and reconstructing (paper, eq. 26 and Fig. 10).

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_ENHANCE_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_ENHANCE_H

#include "command_features.h"

#include <CGAL/Heat_diffusion/decomposition.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>

#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/PLY.h>
#include <CGAL/boost/graph/IO/STL.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cctype>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

// Parses a comma-separated list of finite numbers ("1,3,3").
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
  return weights;
}

// The mesh format of an output path, from its extension.
inline std::string mesh_format(const std::string& path)
{
  std::string extension = fs::path(path).extension().string();
  for(char& ch : extension)
    ch = char(std::tolower(static_cast<unsigned char>(ch)));
  if(extension != ".off" && extension != ".obj" && extension != ".ply" && extension != ".stl")
    throw Usage_error("the output " + path + " must end in .off, .obj, .ply or .stl");
  return extension;
}

// Writes a mesh atomically, with 17 significant digits in the text formats.
inline void write_mesh(const std::string& path, const Mesh& mesh)
{
  const std::string format = mesh_format(path);
  write_atomically(path, [&](std::ostream& os) {
    const auto np = CGAL::parameters::stream_precision(17);
    if(format == ".off")
      return CGAL::IO::write_OFF(os, mesh, np);
    if(format == ".obj")
      return CGAL::IO::write_OBJ(os, mesh, np);
    if(format == ".ply")
      return CGAL::IO::write_PLY(os, mesh, "written by CGAL Heat_diffusion", CGAL::parameters::use_binary_mode(true));
    return CGAL::IO::write_STL(os, mesh, CGAL::parameters::use_binary_mode(true));
  });
}

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

const char* const enhance_help =
    "Usage: heat_diffusion enhance MESH [--weights W1,W2,...] [--steps-per-level S] [--sigma S]\n"
    "                              [--time T] [-m M] [--anchor-weight A] [-o OUT] [--json] [--quiet]\n"
    "\n"
    "Shape editing (the paper's Fig. 10): the Normal Signature is decomposed into L detail\n"
    "bands D^1..D^L (finest first) and a residual S^L, as 'decompose' does; the signature\n"
    "w_1 D^1 + ... + w_L D^L + S^L is rebuilt with the given weights, and the vertices are\n"
    "moved to match it (least-squares reconstruction, eq. 23). The paper's enhancement filter\n"
    "is 1,3,3 (the default), its smoothing filter 0,0,1; weights all 1 return the input.\n"
    "\n"
    "Options:\n"
    "  --weights W,...     one weight per band, finest first; their number is L (default 1,3,3)\n"
    "  --steps-per-level S diffusion steps of one level (default 5)\n"
    "  --sigma S           edge-weight width (default 0.1)\n"
    "  --time T            time of one step (default 1)\n"
    "  -m M                number of eigenpairs (default 150)\n"
    "  --anchor-weight A   weight of the positional anchors of the reconstruction (default 1);\n"
    "                      smaller lets the shape move further\n"
    "  -o OUT              the edited mesh, .off, .obj, .ply or .stl (default: MESH's name with\n"
    "                      _enhanced.off, in the current folder)\n"
    "  --json              print a JSON summary on stdout: the variance of the NS before and\n"
    "                      after, the largest vertex displacement relative to the bounding-box\n"
    "                      diagonal, and the time of each stage\n"
    "  --quiet             print nothing but errors (and the JSON summary if asked for)\n"
    "  -h, --help          this text\n";

inline int run_enhance(int argc, char** argv)
{
  Arguments args({"--json", "--quiet", "-h", "--help"},
                 {"-o", "--sigma", "--time", "-m", "--weights", "--steps-per-level", "--anchor-weight"});
  args.parse(argc, argv, 2);
  if(args.flag("-h") || args.flag("--help"))
  {
    std::cout << enhance_help;
    return success;
  }
  if(args.positional().size() != 1)
    throw Usage_error("enhance takes exactly one MESH argument");
  const std::string input = args.positional()[0];
  const Diffusion_options options = parse_diffusion_options(args);
  const std::vector<double> weights = parse_weights(args.value("--weights", "1,3,3"));
  const double steps_per_level = parse_number("--steps-per-level", args.value("--steps-per-level", "5"), 1., false);
  if(steps_per_level != std::floor(steps_per_level) || steps_per_level > 1000000)
    throw Usage_error("--steps-per-level must be an integer between 1 and 1000000");
  const double anchor_weight = parse_number("--anchor-weight", args.value("--anchor-weight", "1"), 0., true);
  const std::string output = args.value("-o", default_output(input, "_enhanced.off"));
  mesh_format(output);
  check_output_path(output, {input});
  const bool quiet = args.flag("--quiet");

  Stage_timer timer;
  Mesh mesh;
  read_triangle_mesh(input, mesh);
  timer.stop("read");
  const Mesh original = mesh;
  const double input_variance = normal_signature_variance(mesh);
  Progress_bar progress("eigen solve", !quiet && isatty(STDERR_FILENO));
  try
  {
    HD::filter_shape(mesh, weights,
                     HD::parameters::combine(HD::parameters::sigma(options.sigma), HD::parameters::time(options.time),
                                             HD::parameters::number_of_eigenpairs(options.eigenpairs),
                                             HD::parameters::steps_per_level(std::size_t(steps_per_level)),
                                             HD::parameters::anchor_weight(anchor_weight),
                                             HD::parameters::progress_callback(std::ref(progress))));
  }
  catch(const std::invalid_argument& e)
  {
    throw Input_error(input + ": " + e.what());
  }
  timer.stop("filter_shape");
  write_mesh(output, mesh);
  timer.stop("write");

  const double output_variance = normal_signature_variance(mesh);
  double displacement = 0;
  for(auto v : mesh.vertices())
    displacement = (std::max)(displacement, std::sqrt(CGAL::squared_distance(mesh.point(v), original.point(v))));
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(original);
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  if(!quiet)
    std::cerr << "NS variance " << input_variance << " -> " << output_variance << "; largest displacement "
              << displacement / diagonal << " of the diagonal\nwritten to " << output << "\n";
  if(args.flag("--json"))
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
        .integer("steps_per_level", (long long)steps_per_level)
        .number("sigma", options.sigma)
        .number("time", options.time)
        .integer("eigenpairs", (long long)options.eigenpairs)
        .number("anchor_weight", anchor_weight)
        .number("ns_variance_before", input_variance)
        .number("ns_variance_after", output_variance)
        .number("max_displacement_relative", displacement / diagonal)
        .object("timings_ms", timings_json(timer));
    std::cout << summary.str() << std::endl;
  }
  return success;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_ENHANCE_H
