// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// heat_diffusion diffuse: anisotropic, heat-conserving multi-scale diffusion.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DIFFUSE_H
#define CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DIFFUSE_H

#include "cli_output.h"
#include "command.h"
#include "diffusion_fields.h"
#include "diffusion_options.h"
#include "diffusion_setup.h"
#include "point_set_commands.h"
#include "point_set_options.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

inline Diffusion_spec diffuse_spec()
{
  Diffusion_spec spec;
  spec.steps_help = "the steps k to write, 0 to 1000000 (default " + spec.steps_default + ")";
  spec.field = true;
  return spec;
}

inline std::string diffuse_help()
{
  return "Usage: heat_diffusion diffuse MESH [--sigma S] [--time T] [--kernel K] [-m M]\n"
         "                              [--coarse N] [-k K1,K2,...] [--field ns|FILE] [--scale-invariant]\n"
         "                              [-o PREFIX] [--json] [--no-baseline] [--quiet]\n"
         "       heat_diffusion diffuse POINTS [--neighbors K] [--neighbor-radius R] [OPTIONS]\n"
         "\n"
         "Diffuses a scalar field over the mesh with the edge-weighted heat kernel of the paper:\n"
         "F^k = A_t^k F^0, where A_t convolves each vertex's heat with the kernel over its heat\n"
         "region. The total heat sum_i F^k(i) is conserved exactly.\n"
         "\n"
         "On POINTS (a file of points without faces, see ncc --help) the diffusion runs on the\n"
         "surface of the points' fans, with either kernel (the spectral one without --coarse: its\n"
         "eigenpairs are the points' own); the outputs are PLYs of the points with 'field' and the\n"
         "normals, and there is no global baseline.\n"
         "\n"
         "Options:\n" +
         diffusion_options_help(diffuse_spec()) +
         help_option("-o PREFIX",
                     "outputs PREFIX_k<K>.ply (default: MESH's name with _diffused, in the current folder): binary "
                     "PLYs with the per-vertex property 'field' and a diverging colour map saturated at the 98th "
                     "percentile of |F^0|, so that the pictures of different k compare. All are written, or none") +
         help_option("--json",
                     "print a JSON summary on stdout: the total heat at each k ('total_heat'), the same for the "
                     "global isotropic baseline of the paper's Fig. 5 ('global_total_heat': the spectral smoothing "
                     "sum_j exp(-lambda_j k T) phi_j phi_j^T B F^0 with sigma = inf, one more eigen solve unless "
                     "--sigma inf), the heat regions (min/mean/max size, collapsed), the eigenvalue range and "
                     "coarse level (spectral kernel), and the time of each stage in milliseconds") +
         help_option("--no-baseline", "leave 'global_total_heat' out of the JSON summary (no second eigen solve)") +
         neighbourhood_options_help() + common_options_help();
}

// The total heat of the global isotropic smoothing (sigma = inf) of F^0 after the time
// k t, for each k: the baseline of the paper's Fig. 5. `f0` is by the index of
// `diffusion`; `kernel` is the spectral kernel already built (used if isotropic).
inline std::vector<double> global_total_heat(const Mesh& mesh, const Diffusion& diffusion, const Eigen::VectorXd& f0,
                                             const Heat_kernel* kernel, const Diffusion_options& o,
                                             const std::string& input, Json_object& baseline)
{
  std::unique_ptr<Heat_kernel> isotropic_kernel;
  const Heat_kernel* isotropic = kernel;
  if(isotropic == nullptr || !std::isinf(isotropic->sigma()) || isotropic->is_scale_invariant())
  {
    Diffusion_options iso = o;
    iso.sigma = std::numeric_limits<double>::infinity();
    iso.scale_invariant = false;
    iso.method = HD::Heat_kernel_method::spectral;
    isotropic_kernel = make_heat_kernel(mesh, iso, input, "isotropic eigen solve");
    isotropic = isotropic_kernel.get();
  }
  Eigen::VectorXd g0(f0.size());
  for(auto v : mesh.vertices())
    g0[Eigen::Index(isotropic->vertex_index(v))] = f0[Eigen::Index(diffusion.vertex_index(v))];
  std::vector<double> heat;
  for(std::size_t k : o.steps)
    heat.push_back(for_input(input, [&] { return isotropic->global_heat_smoothing(g0, double(k) * diffusion.time()).sum(); }));
  Json_object coarse;
  coarse.integer("vertex_count", (long long)isotropic->coarse_vertex_count()).boolean("automatic", !o.coarse);
  baseline.string("method", "global spectral heat smoothing, isotropic")
      .number("sigma", isotropic->sigma())
      .integer("eigenpairs", (long long)isotropic->number_of_eigenpairs())
      .object("coarse", coarse);
  return heat;
}

inline Command diffuse_command()
{
  Command command;
  command.name = "diffuse";
  command.overview = "diffuse MESH Anisotropic, heat-conserving multi-scale diffusion of the NS or of a field";
  command.flags = {"--no-baseline"};
  command.diffusion = diffuse_spec();
  command.point_sets = true;
  command.help = diffuse_help;
  command.run = [](Run& r) {
    const Diffusion_options& o = r.diffusion;
    const std::string prefix = r.args.value("-o", default_output(r.input, "_diffused"));
    const std::vector<std::string> outputs = step_outputs(prefix, o.steps);
    if(r.points)
      return diffuse_on_points(r, prefix, outputs);
    r.check_outputs(outputs, {o.field});

    Mesh mesh;
    const std::size_t triangulated = r.read_mesh(mesh);
    const Diffusion_setup setup = make_diffusion(mesh, o, r.input, r.timer);
    const Diffusion& diffusion = *setup.diffusion;
    const Eigen::VectorXd f0 = initial_field(o.field, mesh, diffusion);
    const std::vector<Eigen::VectorXd> fields = diffuse_fields(diffusion, f0, o.steps, o, r.input);
    r.timer.stop("diffusion");

    Json_object baseline;
    std::vector<double> baseline_heat;
    if(r.json && !r.args.flag("--no-baseline"))
    {
      baseline_heat = global_total_heat(mesh, diffusion, f0, setup.kernel.get(), o, r.input, baseline);
      r.timer.stop("global_baseline");
    }

    // All outputs, or none: they are renamed into place together at the end.
    const double half_range = robust_half_range(in_mesh_order(f0, mesh, diffusion));
    Output_files files;
    Json_object heat, global_heat, names, minimum, maximum;
    for(std::size_t s = 0; s < o.steps.size(); ++s)
    {
      write_fields_ply(files, outputs[s], mesh, r.with_origin({{"field", in_mesh_order(fields[s], mesh, diffusion)}}),
                       half_range);
      heat.number(std::to_string(o.steps[s]), fields[s].sum());
      minimum.number(std::to_string(o.steps[s]), fields[s].minCoeff());
      maximum.number(std::to_string(o.steps[s]), fields[s].maxCoeff());
      if(!baseline_heat.empty())
        global_heat.number(std::to_string(o.steps[s]), baseline_heat[s]);
      names.string(std::to_string(o.steps[s]), outputs[s]);
    }
    files.commit();
    r.timer.stop("write");

    const HD::Heat_region_statistics& regions = diffusion.region_statistics();
    const std::size_t coarse = setup.kernel ? setup.kernel->coarse_vertex_count() : 0;
    note_automatic_coarse(o, mesh.number_of_vertices(), coarse);
    if(!r.quiet)
    {
      std::cerr << r.input << ": " << mesh.number_of_vertices() << " vertices, heat regions of " << regions.min_size
                << ".." << regions.max_size << " vertices (mean " << regions.mean_size << ")\n";
      warn_about_collapsed_regions(diffusion, o);
      std::cerr << "written to " << prefix << "_k*.ply\n";
    }
    r.summary.string("field", o.field)
        .object("outputs", names)
        .integer("vertices", (long long)mesh.number_of_vertices())
        .integer("faces", (long long)mesh.number_of_faces())
        .integer("triangulated_faces", (long long)triangulated);
    add_diffusion_json(r.summary, o, mesh.number_of_vertices(), setup.kernel.get(), &diffusion);
    if(setup.kernel)
    {
      const Eigen::VectorXd& lambda = setup.kernel->eigenvalues();
      r.summary.number("lambda_min", lambda[0]).number("lambda_max", lambda[lambda.size() - 1]);
    }
    r.summary.object("heat_regions", heat_region_json(regions)).object("total_heat", heat);
    // (the balanced operator keeps every F^k within the range of F^0)
    r.summary.object("minimum", minimum).object("maximum", maximum);
    if(!baseline_heat.empty())
      r.summary.object("global_total_heat", global_heat).object("global_baseline", baseline);
  };
  return command;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_COMMAND_DIFFUSE_H
