// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion hks: the heat kernel signature and its maxima, the baseline the
// paper's Fig. 7 compares its features with.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_HKS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_HKS_H

#include "cli_measures.h"
#include "cli_output.h"
#include "command.h"
#include "command_features.h"  // json_index_list, parse_feature_threshold
#include "diffusion_options.h"
#include "diffusion_setup.h"

#include <cmath>
#include <iostream>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

inline Diffusion_spec hks_spec()
{
  Diffusion_spec spec;
  spec.sigma_default = HD::defaults::heat_kernel_signature::sigma;
  spec.sigma_note = "'inf' (the default) is the plain Laplacian of the classical HKS";
  spec.time_default = HD::defaults::heat_kernel_signature::time;
  spec.time_note = "the time t of the signature";
  spec.time_alias = true;
  spec.steps = Diffusion_spec::no_steps;
  spec.normalization = false;  // no A_t
  spec.local_refusal = "the heat kernel signature is a sum over the eigenpairs";
  return spec;
}

inline std::string hks_help()
{
  return "Usage: heat_diffusion hks MESH [-t T] [--sigma S] [--kernel spectral] [-m M] [--coarse N] [--c C]\n"
         "                          [--scale-invariant] [-o OUT.ply] [--json] [--quiet]\n"
         "\n"
         "The heat kernel signature HKS(x, t) = sum_k exp(-lambda_k t) phi_k(x)^2 (Sun, Ovsjanikov\n"
         "and Guibas 2009) and its maxima: the vertices whose HKS is above that of every other\n"
         "vertex of their 2-ring and above C max HKS. The HKS is positive, so it has no concave\n"
         "features: it cannot tell convex from concave (compare with 'features'). The truncated\n"
         "kernel is accurate for t >= 4 ln 10 / lambda_m only (17.8 on fandisk with m = 150): the\n"
         "tool warns below that bound. No diffusion steps: hks takes no -k.\n"
         "\n"
         "Options:\n" +
         diffusion_options_help(hks_spec()) + feature_threshold_help() +
         help_option("-o OUT.ply", "output (default: MESH's name with _hks.ply, in the current folder): a binary PLY "
                                   "with the vertex properties 'maximum' (1 at the maxima, red; 0 elsewhere, light "
                                   "grey) and 'hks'") +
         help_option("--json", "print a JSON summary on stdout: the maxima (0-based vertex indices in the order of "
                               "the mesh file), the HKS range, t and its bound, the kernel and its coarse level") +
         common_options_help();
}

inline Command hks_command()
{
  Command command;
  command.name = "hks";
  command.overview = "hks MESH       The heat kernel signature and its maxima (the paper's baseline)";
  command.valued = {"--c"};
  command.diffusion = hks_spec();
  command.help = hks_help;
  command.run = [](Run& r) {
    // The classical signature's sigma and t unless given (the kernel's own sigma is not
    // that of the classical signature).
    Diffusion_options o = r.diffusion;
    if(!o.sigma)
      o.sigma = HD::defaults::heat_kernel_signature::sigma;
    const double t = o.time.value_or(HD::defaults::heat_kernel_signature::time);
    const std::optional<double> c = parse_feature_threshold(r.args);
    const std::string output = r.args.value("-o", default_output(r.input, "_hks.ply"));
    r.check_outputs({output});

    Mesh mesh;
    r.read_mesh(mesh);
    const std::unique_ptr<Heat_kernel> kernel = make_heat_kernel(mesh, o, r.input);
    r.timer.stop("ncc_and_eigen_solve");

    auto hks = mesh.add_property_map<Mesh::Vertex_index, double>("v:hks_values", 0.).first;
    for(auto v : mesh.vertices())
      hks[v] = kernel->heat_kernel_signature(v, t);
    std::vector<Mesh::Vertex_index> maxima, minima;
    for_input(r.input, [&] {
      HD::detect_multiscale_features(mesh, hks, std::back_inserter(maxima), std::back_inserter(minima),
                                     HD::parameters::feature_threshold(c));
    });
    std::vector<double> values(mesh.number_of_vertices()), is_maximum(mesh.number_of_vertices(), 0.);
    for(auto v : mesh.vertices())
      values[v.idx()] = hks[v];
    for(auto v : maxima)
      is_maximum[v.idx()] = 1.;
    mesh.remove_property_map(hks);
    r.timer.stop("hks_and_maxima");
    write_fields_ply(output, mesh, r.with_origin({{"maximum", is_maximum}, {"hks", values}}), 1.);
    r.timer.stop("write");

    // The truncated kernel needs e^(-lambda_m t) <= 1e-4 to be accurate.
    const double lambda_m = kernel->decay_rate(kernel->number_of_eigenpairs() - 1);
    const double t_min = lambda_m > 0 ? 4 * std::log(10.) / lambda_m : std::numeric_limits<double>::infinity();
    note_automatic_coarse(o, mesh.number_of_vertices(), kernel->coarse_vertex_count());
    if(!r.quiet)
    {
      if(t < t_min)
        std::cerr << "warning: t = " << t << " is below 4 ln 10 / lambda_m = " << t_min
                  << ": the truncated kernel is inaccurate there (larger -m or -t)\n";
      std::cerr << maxima.size() << " HKS maxima; written to " << output << "\n";
    }
    r.summary.string("output", output).integer("vertices", (long long)mesh.number_of_vertices());
    add_diffusion_json(r.summary, r.diffusion, mesh.number_of_vertices(), kernel.get(), nullptr,
                       c ? std::vector<std::string>{"feature_threshold"} : std::vector<std::string>{},
                       HD::defaults::heat_kernel_signature::sigma, HD::defaults::heat_kernel_signature::time);
    r.summary.number("t", t)
        .number("t_min", t_min)
        .number("c", c.value_or(HD::defaults::feature_threshold))
        .object("hks", statistics(values).json())
        .raw("maxima", json_index_list(maxima));
  };
  return command;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_HKS_H
