// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion denoise: mesh denoising (denoise_mesh), by anisotropic normal filtering or by
// the paper's diffusion of the Normal Signature (eq. 22-23).

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DENOISE_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DENOISE_H

#include "cli_arguments.h"
#include "cli_measures.h"
#include "cli_output.h"
#include "command.h"
#include "diffusion_options.h"
#include "diffusion_setup.h"
#include "point_set_applications.h"

#include <CGAL/Heat_diffusion/denoising.h>

#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

inline Diffusion_spec denoise_spec()
{
  namespace D = HD::defaults::denoising;
  Diffusion_spec spec;
  spec.sigma_default = D::sigma;
  spec.sigma_note = "signature diffusion only";
  spec.time_default = D::time;
  spec.time_note = "signature diffusion only";
  spec.steps = Diffusion_spec::single_step;
  spec.steps_default = std::to_string(D::number_of_steps);
  spec.steps_help = "steps per iteration, 0 to 1000000: normal diffusion steps (normal filtering) or diffusion "
                    "steps of the signature (signature diffusion); default " + spec.steps_default;
  spec.scale_invariant = false;
  return spec;
}

// The name of a stage of denoise_mesh(), for the JSON summary.
inline std::string stage_name(HD::Denoising_stage stage)
{
  switch(stage)
  {
  case HD::Denoising_stage::unchanged: return "unchanged";
  case HD::Denoising_stage::user_normal_sigma: return "user_normal_sigma";
  case HD::Denoising_stage::piecewise_flat: return "piecewise_flat";
  case HD::Denoising_stage::curved: return "curved";
  case HD::Denoising_stage::needle_copy: return "needle_copy";
  case HD::Denoising_stage::needle_fit: return "needle_fit";
  case HD::Denoising_stage::cotangent_flow: return "cotangent_flow";
  case HD::Denoising_stage::signature_diffusion: return "signature_diffusion";
  case HD::Denoising_stage::impulses: return "impulses";
  }
  return "unknown";
}

inline std::string denoise_help()
{
  namespace D = HD::defaults::denoising;
  return "Usage: heat_diffusion denoise NOISY [-o OUT] [--method normal_filtering|signature_diffusion]\n"
         "                              [--iterations N] [-k K] [--normal-sigma S] [--displacement-limit D]\n"
         "                              [--sigma S] [--time T] [--kernel K] [--normalization N] [-m M]\n"
         "                              [--coarse N] [--anchor-weight W] [--json] [--quiet]\n"
         "       heat_diffusion denoise POINTS [-o OUT.ply] [--iterations N] [-k K] [--normal-sigma S]\n"
         "                              [--displacement-limit D] [--neighbors K] [--neighbor-radius R]\n"
         "\n"
         "Denoises a triangle mesh, keeping its connectivity (CGAL::Heat_diffusion::denoise_mesh).\n"
         "normal_filtering (default): the face normals are diffused with the edge weights of the\n"
         "paper's eq. 10 (normals in place of the NCC, a width per face adapted to the noise) and\n"
         "the vertices moved to fit them, until the vertices have moved by the estimated noise\n"
         "level; curved surfaces are then filtered without the weights, up to their noise level.\n"
         "On curved meshes of needle triangles the result is the input smoothed by the cotangent\n"
         "mean curvature flow for a time set by the noise, rescaled to the input's volume; so is\n"
         "it where the filter would change the volume of a closed part by more than 1 %.\n"
         "It stops where its displacement turns one-way (the shape shrinking), and returns a mesh\n"
         "whose roughness is all shape (a clean mesh, mostly) unchanged.\n"
         "signature_diffusion: the paper's pipeline (eq. 22-23): each iteration diffuses the Normal\n"
         "Signature with the edge-weighted heat kernel, updates the normals and reconstructs the\n"
         "vertices from the diffused signature in the least-squares sense.\n"
         "On POINTS (a file of points without faces, see ncc --help): normal filtering on the\n"
         "points' neighbours (CGAL::Heat_diffusion::denoise_point_set, " +
         std::to_string(HD::defaults::point_set_denoising::number_of_neighbors) +
         " neighbours unless --neighbors),\n"
         "each point moved along its own normal only, until the points have moved by the\n"
         "estimated noise level; the output is a PLY of the points, with their filtered normals\n"
         "if the file has normals.\n"
         "\n"
         "Options:\n" +
         help_option("--method M", "normal_filtering (default) or signature_diffusion") +
         help_option("--iterations N", "at most N iterations, each on the previous result, 0 to 10000 (default " +
                                           std::to_string(D::normal_filtering_iterations) +
                                           " for normal filtering, where the displacement limit usually stops it "
                                           "earlier; " + std::to_string(D::signature_diffusion_iterations) +
                                           " for signature diffusion)") +
         help_option("--normal-sigma S", "normal filtering: one width of the normal weights exp(-|n_f-n_g|^2/2S^2) "
                                         "for every face and iteration, until the displacement limit (default: "
                                         "a width per face from 0.2 to 0.45, then none on curved surfaces)") +
         help_option("--displacement-limit D", "normal filtering: stop when the RMS vertex displacement reaches D "
                                               "times the estimated noise level (default " +
                                                   format_number(D::displacement_limit) + ")") +
         diffusion_options_help(denoise_spec()) +
         help_option("--anchor-weight W", "signature diffusion: weight that holds vertices at their current "
                                          "positions (default " + format_number(D::anchor_weight) + ")") +
         help_option("-o OUT", "the denoised mesh, .off, .obj, .ply or .stl (default: NOISY's name with "
                               "_denoised.off, in the current folder); for POINTS a .ply (default: "
                               "_denoised.ply); never the input") +
         help_option("--json", "print a JSON summary on stdout: the parameters given, what the denoiser chose "
                               "(the noise level it estimated, in mean edge lengths, its iterations, the stage "
                               "whose result it returned, the kernel of signature diffusion), the mean and "
                               "largest vertex displacement (in mean edge lengths) and the time of each stage in "
                               "milliseconds") +
         neighbourhood_options_help(HD::defaults::point_set_denoising::number_of_neighbors,
                                    "to whose planes it is fitted and whose normals filter its own") +
         common_options_help();
}

// --method, checked; the options of the other method would be silently ignored: they
// are refused instead.
inline void adapt_denoise_spec(const Arguments& args, Diffusion_spec&)
{
  const std::string method_name = args.value("--method", "normal_filtering");
  if(method_name != "normal_filtering" && method_name != "signature_diffusion")
    throw Usage_error("--method must be normal_filtering or signature_diffusion, not '" + method_name + "'");
  const bool filtering = method_name == "normal_filtering";
  for(const char* option : filtering ? std::vector<const char*>{"--sigma", "--time", "--kernel", "-m", "--coarse",
                                                                "--normalization", "--kernel-tolerance",
                                                                "--anchor-weight"}
                                     : std::vector<const char*>{"--normal-sigma", "--displacement-limit"})
    if(args.has(option))
      throw Usage_error(std::string(option) + " applies to --method " +
                        (filtering ? "signature_diffusion" : "normal_filtering") + " only");
}

inline Command denoise_command()
{
  Command command;
  command.name = "denoise";
  command.overview = "denoise NOISY  Mesh denoising by diffusion of the NS (eq. 22-23), writes OFF, OBJ, PLY or STL";
  command.argument = "NOISY mesh";
  command.valued = {"--iterations", "--anchor-weight", "--method", "--normal-sigma", "--displacement-limit"};
  command.diffusion = denoise_spec();
  command.adapt_diffusion = adapt_denoise_spec;
  command.point_sets = true;
  command.help = denoise_help;
  command.run = [](Run& r) {
    const Diffusion_options& o = r.diffusion;
    // Every option as given, or empty: denoise_mesh() chooses the rest itself. `given`:
    // the named parameters given, beyond the diffusion's.
    std::vector<std::string> given;
    auto optional_number = [&](const char* option, const char* parameter) {
      if(!r.args.has(option))
        return std::optional<double>();
      given.push_back(parameter);
      return std::optional<double>(parse_number(option, r.args.value(option, ""), 0., true));
    };
    std::optional<HD::Denoising_method> method;
    if(r.args.has("--method"))
    {
      given.push_back("denoising_method");
      method = r.args.value("--method", "") == "normal_filtering" ? HD::Denoising_method::normal_filtering
                                                                  : HD::Denoising_method::signature_diffusion;
    }
    std::optional<unsigned> iterations;
    if(r.args.has("--iterations"))
    {
      given.push_back("number_of_iterations");
      iterations = unsigned(parse_count("--iterations", r.args.value("--iterations", ""), 0, 10000));
    }
    if(o.step_count)
      given.push_back("number_of_steps");
    const std::optional<double> anchor_weight = optional_number("--anchor-weight", "anchor_weight");
    const std::optional<double> displacement_limit = optional_number("--displacement-limit", "displacement_limit");
    const std::optional<double> normal_sigma = optional_number("--normal-sigma", "normal_sigma");
    const std::string output =
        r.args.value("-o", default_output(r.input, r.points ? "_denoised.ply" : "_denoised.off"));
    if(r.points)
      return denoise_on_points(r, {iterations, o.step_count, normal_sigma, displacement_limit, given}, output);
    mesh_format(output);
    r.check_outputs({output});

    Mesh mesh;
    const std::size_t triangulated = r.read_mesh(mesh);
    const Mesh noisy = mesh;

    // One call: denoise_mesh()'s iterations are not independent calls on the previous
    // result (its normal filtering bounds the total displacement by the noise level of
    // the input). The progress bar follows its progress_callback, where it reports one.
    Progress_bar progress("denoising", !r.quiet);
    const HD::Denoising_report report = for_input(r.input, [&] {
      return HD::denoise_mesh(
          mesh, HD::parameters::combine(
                    HD::parameters::denoising_method(method), CGAL::parameters::number_of_iterations(iterations),
                    HD::parameters::number_of_steps(o.step_count), HD::parameters::displacement_limit(displacement_limit),
                    HD::parameters::normal_sigma(normal_sigma), HD::parameters::sigma(o.sigma),
                    HD::parameters::time(o.time), HD::parameters::kernel_method(o.kernel),
                    HD::parameters::operator_normalization(o.normalization),
                    HD::parameters::local_kernel_tolerance(o.kernel_tolerance),
                    HD::parameters::number_of_eigenpairs(o.eigenpairs), HD::parameters::coarse_vertex_count(o.coarse),
                    HD::parameters::anchor_weight(anchor_weight),
                    HD::parameters::progress_callback(std::function<bool(double)>(std::ref(progress)))));
    });
    namespace D = HD::defaults::denoising;
    const bool filtering = report.method == HD::Denoising_method::normal_filtering;
    const std::string method_name = filtering ? "normal_filtering" : "signature_diffusion";
    progress.finish();
    r.timer.stop("denoise");

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
    r.timer.stop("write");

    if(!r.quiet)
      std::cerr << r.input << ": " << mesh.number_of_vertices() << " vertices, " << method_name
                << ", vertices moved by " << displacement_mean << " mean edge lengths on average (at most "
                << displacement_max << ")\nwritten to " << output << "\n";
    Json_object displacement;
    displacement.number("mean", displacement_mean).number("max", displacement_max);
    r.summary.string("output", output)
        .integer("vertices", (long long)mesh.number_of_vertices())
        .integer("faces", (long long)mesh.number_of_faces())
        .integer("triangulated_faces", (long long)triangulated)
        .string("method", method_name)
        .integer("max_iterations",
                 (long long)iterations.value_or(filtering ? D::normal_filtering_iterations
                                                          : D::signature_diffusion_iterations))
        .integer("steps", (long long)o.step_count.value_or(D::number_of_steps));
    if(filtering)
    {
      std::vector<std::string> all_given = o.given();
      all_given.insert(all_given.end(), given.begin(), given.end());
      r.summary.raw("given", json_string_list(all_given))
          .number("displacement_limit", displacement_limit.value_or(D::displacement_limit));
      if(normal_sigma)
        r.summary.number("normal_sigma", *normal_sigma);
    }
    else
    {
      add_diffusion_json(r.summary, o, mesh.number_of_vertices(), nullptr, nullptr, given, D::sigma, D::time);
      r.summary.number("anchor_weight", anchor_weight.value_or(D::anchor_weight));
    }
    // What denoise_mesh() chose and did.
    Json_object chosen;
    chosen.number("noise_level_in_mean_edge_lengths", report.noise_level)
        .integer("iterations", (long long)report.iterations)
        .string("stage", stage_name(report.stage));
    if(!filtering)
      chosen.string("kernel", report.kernel_method == HD::Heat_kernel_method::local ? "local" : "spectral");
    r.summary.object("denoiser", chosen).object("displacement_in_mean_edge_lengths", displacement);
  };
  return command;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DENOISE_H
