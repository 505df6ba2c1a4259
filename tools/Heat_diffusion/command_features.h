// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion features: multi-scale convex and concave features of a diffused field.
// Also the helpers the application subcommands (features, hks, decompose, enhance)
// share: the diffusion options, the kernel with its progress bar, the initial field.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_FEATURES_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_FEATURES_H

#include "cli_support.h"
#include "command_diffuse.h"  // read_field

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>

#include <unistd.h>

#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

// --sigma, --time, -m and --scale-invariant, as `diffuse` reads them.
struct Diffusion_options
{
  double sigma = 0.1;
  double time = 1.;
  std::size_t eigenpairs = 150;
  bool scale_invariant = false;
};

inline Diffusion_options parse_diffusion_options(const Arguments& args, const std::string& default_sigma = "0.1")
{
  Diffusion_options options;
  const std::string sigma_text = args.value("--sigma", default_sigma);
  options.sigma = sigma_text == "inf" ? std::numeric_limits<double>::infinity()
                                      : parse_number("--sigma", sigma_text, 0., true);
  options.time = parse_number("--time", args.value("--time", "1"), 0., true);
  options.eigenpairs = std::size_t(parse_number("-m", args.value("-m", "150"), 1., false));
  options.scale_invariant = args.flag("--scale-invariant");
  return options;
}

typedef HD::Edge_weighted_heat_kernel<Mesh> Heat_kernel;

// The kernel of `mesh`, with a progress bar on a terminal; the package's
// std::invalid_argument becomes an input error that names the file.
inline std::unique_ptr<Heat_kernel> make_heat_kernel(const Mesh& mesh, const Diffusion_options& options,
                                                     const std::string& input, bool quiet)
{
  Progress_bar progress("eigen solve", !quiet && isatty(STDERR_FILENO));
  try
  {
    return std::make_unique<Heat_kernel>(
        mesh, HD::parameters::combine(HD::parameters::sigma(options.sigma),
                                      HD::parameters::number_of_eigenpairs(options.eigenpairs),
                                      HD::parameters::scale_invariant_kernel(options.scale_invariant),
                                      HD::parameters::progress_callback(std::ref(progress))));
  }
  catch(const std::invalid_argument& e)
  {
    throw Input_error(input + ": " + e.what());
  }
}

// F^0 by the kernel's vertex index: the Normal Signature, or a field file with one
// number per vertex in the order of the mesh file.
inline Eigen::VectorXd initial_field(const std::string& source, const Mesh& mesh, const Heat_kernel& kernel)
{
  Eigen::VectorXd f0(static_cast<Eigen::Index>(mesh.number_of_vertices()));
  if(source == "ns")
    for(auto v : mesh.vertices())
      f0[Eigen::Index(kernel.vertex_index(v))] = kernel.normal_controlled_coordinates().normal_signature(v);
  else
  {
    const std::vector<double> values = read_field(source, mesh.number_of_vertices());
    for(auto v : mesh.vertices())
      f0[Eigen::Index(kernel.vertex_index(v))] = values[v.idx()];
  }
  return f0;
}

// A field by kernel index, back in the order of the mesh's vertices.
inline std::vector<double> in_mesh_order(const Eigen::VectorXd& field, const Mesh& mesh, const Heat_kernel& kernel)
{
  std::vector<double> values(mesh.number_of_vertices());
  for(auto v : mesh.vertices())
    values[v.idx()] = field[Eigen::Index(kernel.vertex_index(v))];
  return values;
}

inline Json_object heat_region_json(const HD::Heat_region_statistics& regions)
{
  Json_object o;
  o.integer("min", (long long)regions.min_size)
      .number("mean", regions.mean_size)
      .integer("max", (long long)regions.max_size)
      .integer("collapsed", (long long)regions.collapsed_regions)
      .integer("capped", (long long)regions.capped_regions);
  return o;
}

inline void warn_about_collapsed_regions(const HD::Heat_region_statistics& regions, bool quiet)
{
  if(!quiet && regions.collapsed_regions > 0)
    std::cerr << "warning: " << regions.collapsed_regions
              << " heat regions collapsed to their vertex (the truncated kernel is too flat at this t):"
                 " those vertices keep their heat; larger --sigma, --time or -m avoid it\n";
}

inline std::string json_index_list(const std::vector<Mesh::Vertex_index>& vertices)
{
  std::string s = "[";
  for(std::size_t i = 0; i < vertices.size(); ++i)
    s += (i ? ", " : "") + std::to_string(vertices[i].idx());
  return s + "]";
}

// +1 at convex features, -1 at concave ones, 0 elsewhere: with write_fields_ply's
// colour map saturated at 1, red, blue and light grey.
inline std::vector<double> feature_labels(const HD::Features_at_scale<Mesh::Vertex_index>& features, std::size_t n)
{
  std::vector<double> labels(n, 0.);
  for(auto v : features.convex)
    labels[v.idx()] = 1.;
  for(auto v : features.concave)
    labels[v.idx()] = -1.;
  return labels;
}

const char* const features_help =
    "Usage: heat_diffusion features MESH [--sigma S] [--time T] [-m M] [-k K1,K2,...] [--c C]\n"
    "                               [--field ns|FILE] [--scale-invariant] [-o PREFIX] [--json] [--quiet]\n"
    "\n"
    "Multi-scale feature detection (the paper's section 7). The field F^0 (the Normal\n"
    "Signature by default) is diffused to F^k = A_t^k F^0; at scale k, a vertex is a convex\n"
    "feature if F^k there is above F^k at every other vertex of its 2-ring and above\n"
    "C max F^k, a concave feature if it is below them all and below C min F^k.\n"
    "\n"
    "Options:\n"
    "  --sigma S         edge-weight width: 0.1 (default) preserves features, 1 smooths (the\n"
    "                    paper's Fig. 6), 'inf' is isotropic\n"
    "  --time T          time of one step, on the mesh rescaled to area = vertex count (default 1)\n"
    "  -m M              number of eigenpairs of the truncated kernel (default 150)\n"
    "  -k K1,K2,...      the scales k (default 0,10,40)\n"
    "  --c C             the threshold c in [0, 1] (default 0.8)\n"
    "  --field F         'ns' (default): the Normal Signature; or a text file with one number\n"
    "                    per vertex, in the order of the mesh file's vertices\n"
    "  --scale-invariant the scale-invariant kernel of the paper's eq. 14\n"
    "  -o PREFIX         outputs PREFIX_k<K>.ply (default: MESH's name with _features, in the\n"
    "                    current folder): binary PLYs with the vertex properties 'feature'\n"
    "                    (+1 convex, -1 concave, 0 else) and 'field' (F^k), coloured red\n"
    "                    (convex), blue (concave) and light grey\n"
    "  --json            print a JSON summary on stdout: the vertex indices of the convex and\n"
    "                    concave features per k (0-based, in the order of the mesh file), the\n"
    "                    heat regions and the time of each stage in milliseconds\n"
    "  --quiet           print nothing but errors (and the JSON summary if asked for)\n"
    "  -h, --help        this text\n"
    "\n"
    "Heat regions that collapse to their vertex (the truncated kernel at small sigma and\n"
    "t) keep their heat and can make spurious features: the tool warns about them.\n";

inline int run_features(int argc, char** argv)
{
  Arguments args({"--json", "--quiet", "--scale-invariant", "-h", "--help"},
                 {"-o", "--sigma", "--time", "-m", "-k", "--c", "--field"});
  args.parse(argc, argv, 2);
  if(args.flag("-h") || args.flag("--help"))
  {
    std::cout << features_help;
    return success;
  }
  if(args.positional().size() != 1)
    throw Usage_error("features takes exactly one MESH argument");
  const std::string input = args.positional()[0];
  const Diffusion_options options = parse_diffusion_options(args);
  const std::vector<std::size_t> steps = parse_steps(args.value("-k", "0,10,40"));
  const double c = parse_number("--c", args.value("--c", "0.8"), 0., false);
  if(c > 1)
    throw Usage_error("--c must be in [0, 1], not '" + args.value("--c", "") + "'");
  const std::string field_source = args.value("--field", "ns");
  const std::string prefix = args.value("-o", fs::path(input).stem().string() + "_features");
  std::vector<std::string> outputs;
  for(std::size_t k : steps)
    outputs.push_back(prefix + "_k" + std::to_string(k) + ".ply");
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

  const Eigen::VectorXd f0 = initial_field(field_source, mesh, *kernel);
  auto field = mesh.add_property_map<Mesh::Vertex_index, double>("v:initial_field", 0.).first;
  for(auto v : mesh.vertices())
    field[v] = f0[Eigen::Index(kernel->vertex_index(v))];
  const auto features =
      HD::detect_multiscale_features(diffusion, field, steps, HD::parameters::feature_threshold(c));
  const std::vector<Eigen::VectorXd> fields = diffusion.diffuse(f0, steps);  // for the PLYs
  mesh.remove_property_map(field);
  timer.stop("features");

  Json_object per_scale, files;
  for(std::size_t s = 0; s < steps.size(); ++s)
  {
    write_fields_ply(outputs[s], mesh,
                     {{"feature", feature_labels(features[s], mesh.number_of_vertices())},
                      {"field", in_mesh_order(fields[s], mesh, *kernel)}},
                     1.);
    Json_object scale;
    scale.raw("convex", json_index_list(features[s].convex)).raw("concave", json_index_list(features[s].concave));
    per_scale.object(std::to_string(steps[s]), scale);
    files.string(std::to_string(steps[s]), outputs[s]);
  }
  timer.stop("write");

  const HD::Heat_region_statistics& regions = diffusion.region_statistics();
  warn_about_collapsed_regions(regions, quiet);
  if(!quiet)
  {
    for(const auto& f : features)
      std::cerr << "k = " << f.number_of_steps << ": " << f.convex.size() << " convex, " << f.concave.size()
                << " concave features\n";
    std::cerr << "written to " << prefix << "_k*.ply\n";
  }
  if(args.flag("--json"))
  {
    Json_object summary;
    summary.string("command", "features")
        .string("input", input)
        .string("field", field_source)
        .object("outputs", files)
        .integer("vertices", (long long)mesh.number_of_vertices())
        .number("sigma", options.sigma)
        .number("time", options.time)
        .integer("eigenpairs", (long long)kernel->number_of_eigenpairs())
        .boolean("scale_invariant", kernel->is_scale_invariant())
        .number("c", c)
        .object("heat_regions", heat_region_json(regions))
        .object("features", per_scale)
        .object("timings_ms", timings_json(timer));
    std::cout << summary.str() << std::endl;
  }
  return success;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_FEATURES_H
