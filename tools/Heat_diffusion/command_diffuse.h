// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion diffuse: anisotropic, heat-conserving multi-scale diffusion.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DIFFUSE_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DIFFUSE_H

#include "cli_support.h"

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>

#include <unistd.h>

#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

const char* const diffuse_help =
    "Usage: heat_diffusion diffuse MESH [--sigma S] [--time T] [--kernel spectral|local] [-m M]\n"
    "                              [-k K1,K2,...] [--field ns|FILE] [--scale-invariant] [-o PREFIX]\n"
    "                              [--json] [--quiet]\n"
    "\n"
    "Diffuses a scalar field over the mesh with the edge-weighted heat kernel of the paper:\n"
    "F^k = A_t^k F^0, where A_t convolves each vertex's heat with the kernel over its heat\n"
    "region. The total heat sum_i F^k(i) is conserved exactly.\n"
    "\n"
    "Options:\n"
    "  --sigma S         edge-weight width: small preserves features (0.1, default), large\n"
    "                    smooths (1); 'inf' gives isotropic diffusion\n"
    "  --time T          time of one step, on the mesh rescaled to area = vertex count (default 1)\n"
    "  --kernel K        'spectral' (default): the paper's kernel from M eigenpairs, accurate\n"
    "                    for large T only; 'local': each kernel column computed around its\n"
    "                    vertex without eigenpairs and without truncation (relative error\n"
    "                    below 1e-3 at any T; cost per vertex grows like T^1.5)\n"
    "  -m M              number of eigenpairs of the spectral kernel (default 150)\n"
    "  -k K1,K2,...      the steps k to write (default 0,10,40)\n"
    "  --field F         'ns' (default): the Normal Signature; or a text file with one number\n"
    "                    per vertex, in the order of the mesh file's vertices\n"
    "  --scale-invariant the scale-invariant kernel of the paper's eq. 14 (spectral kernel only)\n"
    "  -o PREFIX         outputs PREFIX_k<K>.ply (default: MESH's name with _diffused, in the\n"
    "                    current folder): binary PLYs with the per-vertex property 'field' and\n"
    "                    a diverging colour map saturated at the 98th percentile of |F^0|, so\n"
    "                    that the pictures of different k compare\n"
    "  --json            print a JSON summary on stdout: the total heat at each k, the heat\n"
    "                    regions (min/mean/max size, collapsed), the eigenvalue range\n"
    "                    (spectral kernel), and the time of each stage in milliseconds\n"
    "  --quiet           print nothing but errors (and the JSON summary if asked for)\n"
    "  -h, --help        this text\n"
    "\n"
    "A progress bar is shown on stderr during the eigen solve when stderr is a terminal.\n";

inline std::vector<double> read_field(const std::string& path, std::size_t n)
{
  std::ifstream is(path);
  if(!is)
    throw Input_error(path + ": cannot open the field file");
  std::vector<double> field;
  std::string token;
  while(is >> token)
  {
    char* end = nullptr;
    const double x = std::strtod(token.c_str(), &end);
    if(*end != '\0' || !std::isfinite(x))
      throw Input_error(path + ": value " + std::to_string(field.size()) + " ('" + token + "') is not a finite number");
    field.push_back(x);
  }
  if(field.size() != n)
    throw Input_error(path + ": has " + std::to_string(field.size()) + " values, the mesh has " + std::to_string(n) +
                      " vertices");
  return field;
}

inline int run_diffuse(int argc, char** argv)
{
  Arguments args({"--json", "--quiet", "--scale-invariant", "-h", "--help"},
                 {"-o", "--sigma", "--time", "-m", "-k", "--field", "--kernel"});
  args.parse(argc, argv, 2);
  if(args.flag("-h") || args.flag("--help"))
  {
    std::cout << diffuse_help;
    return success;
  }
  if(args.positional().size() != 1)
    throw Usage_error("diffuse takes exactly one MESH argument");
  const std::string input = args.positional()[0];
  const std::string sigma_text = args.value("--sigma", "0.1");
  const double sigma = sigma_text == "inf" ? std::numeric_limits<double>::infinity()
                                           : parse_number("--sigma", sigma_text, 0., true);
  const double time = parse_number("--time", args.value("--time", "1"), 0., true);
  const double m = parse_number("-m", args.value("-m", "150"), 1., false);
  const std::string kernel_name = args.value("--kernel", "spectral");
  if(kernel_name != "spectral" && kernel_name != "local")
    throw Usage_error("--kernel must be 'spectral' or 'local'");
  const bool local = kernel_name == "local";
  if(local && args.flag("--scale-invariant"))
    throw Usage_error("--scale-invariant needs the eigenvalues: use --kernel spectral");
  const std::vector<std::size_t> steps = parse_steps(args.value("-k", "0,10,40"));
  const std::string field_source = args.value("--field", "ns");
  const std::string prefix = args.value("-o", fs::path(input).stem().string() + "_diffused");
  std::vector<std::string> outputs;
  for(std::size_t k : steps)
    outputs.push_back(prefix + "_k" + std::to_string(k) + ".ply");
  for(const std::string& output : outputs)
    check_output_path(output, {input, field_source});
  const bool quiet = args.flag("--quiet");

  Stage_timer timer;
  Mesh mesh;
  const std::size_t triangulated = read_triangle_mesh(input, mesh);
  timer.stop("read");

  typedef HD::Edge_weighted_heat_kernel<Mesh> Kernel;
  typedef HD::Anisotropic_heat_diffusion<Mesh> Diffusion;
  std::unique_ptr<Kernel> kernel;
  std::unique_ptr<Diffusion> diffusion_pointer;
  try
  {
    if(local)
    {
      // no eigen solve: the NCC, L and B, then A_t column by column
      diffusion_pointer = std::make_unique<Diffusion>(
          mesh, HD::parameters::combine(HD::parameters::sigma(sigma), HD::parameters::time(time),
                                        HD::parameters::kernel_method(HD::Heat_kernel_method::local)));
      timer.stop("ncc_and_local_operator");
    }
    else
    {
      Progress_bar progress("eigen solve", !quiet && isatty(STDERR_FILENO));
      kernel = std::make_unique<Kernel>(
          mesh, HD::parameters::combine(HD::parameters::sigma(sigma),
                                        HD::parameters::number_of_eigenpairs(std::size_t(m)),
                                        HD::parameters::scale_invariant_kernel(args.flag("--scale-invariant")),
                                        HD::parameters::progress_callback(std::ref(progress))));
      timer.stop("ncc_and_eigen_solve");
      diffusion_pointer = std::make_unique<Diffusion>(*kernel, time);
      timer.stop("operator");
    }
  }
  catch(const std::invalid_argument& e)
  {
    throw Input_error(input + ": " + e.what());
  }
  const Diffusion& diffusion = *diffusion_pointer;

  Eigen::VectorXd f0(static_cast<Eigen::Index>(mesh.number_of_vertices()));
  if(field_source == "ns")
    for(auto v : mesh.vertices())
      f0[Eigen::Index(diffusion.vertex_index(v))] = diffusion.normal_controlled_coordinates().normal_signature(v);
  else
  {
    const std::vector<double> values = read_field(field_source, mesh.number_of_vertices());
    for(auto v : mesh.vertices())
      f0[Eigen::Index(diffusion.vertex_index(v))] = values[v.idx()];
  }
  const std::vector<Eigen::VectorXd> fields = diffusion.diffuse(f0, steps);
  timer.stop("diffusion");

  std::vector<double> initial(mesh.number_of_vertices());
  for(auto v : mesh.vertices())
    initial[v.idx()] = f0[Eigen::Index(diffusion.vertex_index(v))];
  const double half_range = robust_half_range(initial);
  Json_object heat;
  for(std::size_t s = 0; s < steps.size(); ++s)
  {
    std::vector<double> values(mesh.number_of_vertices());
    for(auto v : mesh.vertices())
      values[v.idx()] = fields[s][Eigen::Index(diffusion.vertex_index(v))];
    write_fields_ply(outputs[s], mesh, {{"field", values}}, half_range);
    heat.number(std::to_string(steps[s]), fields[s].sum());
  }
  timer.stop("write");

  const HD::Heat_region_statistics& regions = diffusion.region_statistics();
  if(!quiet)
  {
    std::cerr << input << ": " << mesh.number_of_vertices() << " vertices, heat regions of " << regions.min_size
              << ".." << regions.max_size << " vertices (mean " << regions.mean_size << ")";
    if(regions.collapsed_regions > 0)
      std::cerr << "; " << regions.collapsed_regions
                << (local ? " regions collapsed to their vertex (its edge weights isolate it)"
                          : " regions collapsed to their vertex (the truncated kernel is too flat at this t)");
    std::cerr << "\nwritten to " << prefix << "_k*.ply\n";
  }
  if(args.flag("--json"))
  {
    Json_object region_json, files;
    region_json.integer("min", (long long)regions.min_size)
        .number("mean", regions.mean_size)
        .integer("max", (long long)regions.max_size)
        .integer("collapsed", (long long)regions.collapsed_regions)
        .integer("capped", (long long)regions.capped_regions);
    for(std::size_t s = 0; s < steps.size(); ++s)
      files.string(std::to_string(steps[s]), outputs[s]);
    Json_object summary;
    summary.string("command", "diffuse")
        .string("input", input)
        .string("field", field_source)
        .object("outputs", files)
        .integer("vertices", (long long)mesh.number_of_vertices())
        .integer("faces", (long long)mesh.number_of_faces())
        .integer("triangulated_faces", (long long)triangulated)
        .number("sigma", sigma)
        .number("time", time)
        .string("kernel", kernel_name);
    if(kernel)
    {
      const Eigen::VectorXd& lambda = kernel->eigenvalues();
      summary.integer("eigenpairs", (long long)kernel->number_of_eigenpairs())
          .boolean("scale_invariant", kernel->is_scale_invariant())
          .number("lambda_min", lambda[0])
          .number("lambda_max", lambda[lambda.size() - 1]);
    }
    summary        .object("heat_regions", region_json)
        .object("total_heat", heat)
        .object("timings_ms", timings_json(timer));
    std::cout << summary.str() << std::endl;
  }
  return success;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DIFFUSE_H
