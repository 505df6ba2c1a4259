// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion denoise: mesh denoising by diffusion of the Normal Signature (eq. 22-23).

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DENOISE_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DENOISE_H

#include "cli_support.h"

#include <CGAL/Heat_diffusion/denoising.h>

#include <iostream>
#include <string>

namespace heat_diffusion_cli {

const char* const denoise_help =
    "Usage: heat_diffusion denoise NOISY [-o OUT] [--iterations N] [--sigma S] [--time T] [-m M]\n"
    "                              [-k K] [--anchor-weight W] [--json] [--quiet]\n"
    "\n"
    "Denoises a triangle mesh: each iteration diffuses the Normal Signature with the\n"
    "edge-weighted heat kernel of the current mesh, averages the normals of each one-ring\n"
    "weighted by |NS| (the paper's eq. 22, made robust), and moves the vertices to match the\n"
    "diffused signature along those normals in the least-squares sense (eq. 23). The\n"
    "connectivity is kept.\n"
    "\n"
    "Options:\n"
    "  -o OUT            the denoised mesh, OFF or PLY by extension (default: NOISY's name\n"
    "                    with _denoised.off, in the current folder); never the input\n"
    "  --iterations N    outer iterations, each on the previous result (default 2)\n"
    "  --sigma S         edge-weight width of the heat kernel (default 1; much smaller values\n"
    "                    make the eigen solve fail on noisy meshes)\n"
    "  --time T          time of one diffusion step (default 1)\n"
    "  -m M              number of eigenpairs of the truncated kernel (default 150)\n"
    "  -k K              diffusion steps of the signature per iteration (default 1)\n"
    "  --anchor-weight W weight that holds vertices at their current positions (default 0.7)\n"
    "  --json            print a JSON summary on stdout: the parameters, the mean and largest\n"
    "                    vertex displacement (in mean edge lengths) and the time of each stage\n"
    "                    in milliseconds\n"
    "  --quiet           print nothing but errors (and the JSON summary if asked for)\n"
    "  -h, --help        this text\n";

inline int run_denoise(int argc, char** argv)
{
  Arguments args({"--json", "--quiet", "-h", "--help"},
                 {"-o", "--iterations", "--sigma", "--time", "-m", "-k", "--anchor-weight"});
  args.parse(argc, argv, 2);
  if(args.flag("-h") || args.flag("--help"))
  {
    std::cout << denoise_help;
    return success;
  }
  if(args.positional().size() != 1)
    throw Usage_error("denoise takes exactly one NOISY mesh argument");
  const std::string input = args.positional()[0];
  const double iterations = parse_number("--iterations", args.value("--iterations", "2"), 0., false);
  const double sigma = parse_number("--sigma", args.value("--sigma", "1"), 0., true);
  const double time = parse_number("--time", args.value("--time", "1"), 0., true);
  const double m = parse_number("-m", args.value("-m", "150"), 1., false);
  const double k = parse_number("-k", args.value("-k", "1"), 0., false);
  const double anchor_weight = parse_number("--anchor-weight", args.value("--anchor-weight", "0.7"), 0., true);
  if(iterations != std::floor(iterations) || m != std::floor(m) || k != std::floor(k))
    throw Usage_error("--iterations, -m and -k take whole numbers");
  const std::string output = args.value("-o", default_output(input, "_denoised.off"));
  const std::string extension = fs::path(output).extension().string();
  if(extension != ".off" && extension != ".ply")
    throw Usage_error("-o must name an .off or .ply file, not '" + output + "'");
  check_output_path(output, {input});
  const bool quiet = args.flag("--quiet");

  Stage_timer timer;
  Mesh mesh;
  const std::size_t triangulated = read_triangle_mesh(input, mesh);
  const Mesh noisy = mesh;
  timer.stop("read");

  try
  {
    HD::denoise_mesh(mesh, HD::parameters::combine(CGAL::parameters::number_of_iterations(unsigned(iterations)),
                                                   HD::parameters::sigma(sigma), HD::parameters::time(time),
                                                   HD::parameters::number_of_eigenpairs(std::size_t(m)),
                                                   HD::parameters::number_of_steps(std::size_t(k)),
                                                   HD::parameters::anchor_weight(anchor_weight)));
  }
  catch(const std::invalid_argument& e)
  {
    throw Input_error(input + ": " + e.what());
  }
  timer.stop("denoise");

  write_atomically(output, [&](std::ostream& os) {
    return extension == ".ply" ? CGAL::IO::write_PLY(os, mesh, CGAL::parameters::stream_precision(17))
                               : CGAL::IO::write_OFF(os, mesh, CGAL::parameters::stream_precision(17));
  });
  timer.stop("write");

  // How far the vertices moved, in mean edge lengths of the input: a scale-free figure.
  // std::hypot, not the squared distance, which overflows for coordinates near 1e300
  // and underflows near 1e-300.
  const auto distance = [](const Kernel::Point_3& p, const Kernel::Point_3& q) {
    return std::hypot(p.x() - q.x(), p.y() - q.y(), p.z() - q.z());
  };
  double edge_sum = 0, displacement_sum = 0, displacement_max = 0;
  for(auto e : noisy.edges())
    edge_sum += distance(noisy.point(noisy.vertex(e, 0)), noisy.point(noisy.vertex(e, 1)));
  const double mean_edge = noisy.number_of_edges() > 0 ? edge_sum / double(noisy.number_of_edges()) : 1.;
  for(auto v : mesh.vertices())
  {
    const double d = distance(mesh.point(v), noisy.point(v)) / mean_edge;
    displacement_sum += d;
    displacement_max = (std::max)(displacement_max, d);
  }
  const double displacement_mean = mesh.number_of_vertices() > 0 ? displacement_sum / double(mesh.number_of_vertices()) : 0.;

  if(!quiet)
    std::cerr << input << ": " << mesh.number_of_vertices() << " vertices, " << std::size_t(iterations)
              << " iterations, vertices moved by " << displacement_mean << " mean edge lengths on average (at most "
              << displacement_max << ")\nwritten to " << output << "\n";
  if(args.flag("--json"))
  {
    Json_object displacement;
    displacement.number("mean", displacement_mean).number("max", displacement_max);
    Json_object summary;
    summary.string("command", "denoise")
        .string("input", input)
        .string("output", output)
        .integer("vertices", (long long)mesh.number_of_vertices())
        .integer("faces", (long long)mesh.number_of_faces())
        .integer("triangulated_faces", (long long)triangulated)
        .integer("iterations", (long long)iterations)
        .number("sigma", sigma)
        .number("time", time)
        .integer("eigenpairs", (long long)m)
        .integer("steps", (long long)k)
        .number("anchor_weight", anchor_weight)
        .object("displacement_in_mean_edge_lengths", displacement)
        .object("timings_ms", timings_json(timer));
    std::cout << summary.str() << std::endl;
  }
  return success;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DENOISE_H
