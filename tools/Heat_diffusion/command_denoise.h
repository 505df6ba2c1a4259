// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion denoise: mesh denoising by diffusion of the Normal Signature (eq. 22-23).

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DENOISE_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DENOISE_H

#include "cli_support.h"
#include "diffusion_options.h"

#include <CGAL/Heat_diffusion/denoising.h>

#include <functional>
#include <iostream>
#include <string>

namespace heat_diffusion_cli {

inline Diffusion_spec denoise_spec()
{
  Diffusion_spec spec;
  spec.sigma_default = "1";
  spec.sigma_note = "much smaller values make the eigen solve fail on noisy meshes";
  spec.steps = Diffusion_spec::single_step;
  spec.steps_default = "1";
  spec.steps_help = "diffusion steps of the signature per iteration, 0 to 1000000 (default 1)";
  // CGAL::Heat_diffusion::denoise_mesh() builds its diffusion from sigma, time and
  // number_of_eigenpairs only: the other options would be silently ignored.
  spec.local_refusal = "denoise_mesh() uses the spectral kernel only";
  spec.coarse_refusal = "denoise_mesh() does not take the coarse level (it applies the automatic choice)";
  spec.scale_invariant = false;
  return spec;
}

inline std::string denoise_help()
{
  return "Usage: heat_diffusion denoise NOISY [-o OUT] [--iterations N] [--sigma S] [--time T]\n"
         "                              [--kernel spectral] [-m M] [-k K] [--anchor-weight W] [--json] [--quiet]\n"
         "\n"
         "Denoises a triangle mesh: each iteration diffuses the Normal Signature with the\n"
         "edge-weighted heat kernel of the current mesh, averages the normals of each one-ring\n"
         "weighted by |NS| (the paper's eq. 22, made robust), and moves the vertices to match the\n"
         "diffused signature along those normals in the least-squares sense (eq. 23). The\n"
         "connectivity is kept.\n"
         "\n"
         "Options:\n" +
         help_option("--iterations N", "outer iterations, each on the previous result, 0 to 10000 (default 2)") +
         diffusion_options_help(denoise_spec()) +
         help_option("--anchor-weight W", "weight that holds vertices at their current positions (default 0.7)") +
         help_option("-o OUT", "the denoised mesh, .off, .obj, .ply or .stl (default: NOISY's name with "
                               "_denoised.off, in the current folder); never the input") +
         help_option("--json", "print a JSON summary on stdout: the parameters, the mean and largest vertex "
                               "displacement (in mean edge lengths) and the time of each stage in milliseconds") +
         common_options_help();
}

inline int run_denoise(int argc, char** argv)
{
  const Diffusion_spec spec = denoise_spec();
  Arguments args = diffusion_arguments(spec, {}, {"--iterations", "--anchor-weight"});
  args.parse(argc, argv, 2);
  if(args.flag("-h") || args.flag("--help"))
  {
    std::cout << denoise_help();
    return success;
  }
  if(args.positional().size() != 1)
    throw Usage_error("denoise takes exactly one NOISY mesh argument");
  const std::string input = args.positional()[0];
  const Diffusion_options o = parse_diffusion_options(args, spec);
  const std::size_t iterations = parse_count("--iterations", args.value("--iterations", "2"), 0, 10000);
  const std::size_t k = o.steps.front();
  const double anchor_weight = parse_number("--anchor-weight", args.value("--anchor-weight", "0.7"), 0., true);
  const std::string output = args.value("-o", default_output(input, "_denoised.off"));
  mesh_format(output);
  check_output_path(output, {input});

  Stage_timer timer;
  Mesh mesh;
  const std::size_t triangulated = read_triangle_mesh(input, mesh);
  const Mesh noisy = mesh;
  timer.stop("read");

  // One call: denoise_mesh()'s iterations are not independent calls on the previous
  // result (its normal filtering bounds the total displacement by the noise level of
  // the input). The progress bar follows its progress_callback, where it reports one.
  Progress_bar progress("denoising", !o.quiet);
  for_input(input, [&] {
    HD::denoise_mesh(mesh, HD::parameters::combine(CGAL::parameters::number_of_iterations(unsigned(iterations)),
                                                   HD::parameters::sigma(o.sigma), HD::parameters::time(o.time),
                                                   HD::parameters::number_of_eigenpairs(o.eigenpairs),
                                                   HD::parameters::number_of_steps(k),
                                                   HD::parameters::anchor_weight(anchor_weight),
                                                   HD::parameters::progress_callback(
                                                       std::function<bool(double)>(std::ref(progress)))));
  });
  progress.finish();
  timer.stop("denoise");

  // How far the vertices moved, in mean edge lengths of the input: a scale-free
  // figure, measured before writing (a failure leaves no output). Distances by
  // std::hypot and running means: no overflow for coordinates near 1e300, no
  // underflow near 1e-300.
  double mean_edge = 0, displacement_mean = 0, displacement_max = 0, count = 0;
  for(auto e : noisy.edges())
  {
    count += 1;
    mean_edge += (point_distance(noisy.point(noisy.vertex(e, 0)), noisy.point(noisy.vertex(e, 1))) - mean_edge) / count;
  }
  if(!(mean_edge > 0))
    mean_edge = 1.;
  count = 0;
  for(auto v : mesh.vertices())
  {
    const double d = point_distance(mesh.point(v), noisy.point(v)) / mean_edge;
    count += 1;
    displacement_mean += (d - displacement_mean) / count;
    displacement_max = (std::max)(displacement_max, d);
  }
  write_mesh(output, mesh);
  timer.stop("write");

  if(!o.quiet)
    std::cerr << input << ": " << mesh.number_of_vertices() << " vertices, " << iterations
              << " iterations, vertices moved by " << displacement_mean << " mean edge lengths on average (at most "
              << displacement_max << ")\nwritten to " << output << "\n";
  if(o.json)
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
        .integer("iterations", (long long)iterations);
    add_diffusion_json(summary, o, mesh.number_of_vertices(), nullptr);
    summary.integer("steps", (long long)k)
        .number("anchor_weight", anchor_weight)
        .object("displacement_in_mean_edge_lengths", displacement)
        .object("timings_ms", timings_json(timer));
    std::cout << summary.str() << std::endl;
  }
  return success;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DENOISE_H
