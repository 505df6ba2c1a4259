// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Building the heat kernel and the diffusion operator A_t from the diffusion options,
// with a progress bar, and reporting them (messages, JSON).

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_SETUP_H
#define CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_SETUP_H

#include "cli_errors.h"
#include "cli_json.h"
#include "cli_progress.h"
#include "diffusion_options.h"
#include "mesh_input.h"

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>

#include <algorithm>
#include <functional>
#include <iostream>
#include <memory>
#include <string>

namespace heat_diffusion_cli {

namespace HD = CGAL::Heat_diffusion;

typedef HD::Edge_weighted_heat_kernel<Mesh> Heat_kernel;
typedef HD::Anisotropic_heat_diffusion<Mesh> Diffusion;

// Calls `f` with the named parameters of the kernel and the diffusion (the package's
// automatic coarse level unless --coarse was given).
template <typename Function>
auto with_diffusion_parameters(const Diffusion_options& o, Progress_bar& progress, Function&& f)
{
  const auto np = HD::parameters::combine(
      HD::parameters::sigma(o.sigma), HD::parameters::time(o.time), HD::parameters::kernel_method(o.method),
      HD::parameters::number_of_eigenpairs(o.eigenpairs), HD::parameters::scale_invariant_kernel(o.scale_invariant),
      HD::parameters::operator_normalization(o.normalization),
      HD::parameters::progress_callback(std::function<bool(double)>(std::ref(progress))));
  if(o.coarse < 0)
    return f(np);
  return f(HD::parameters::combine(np, HD::parameters::coarse_vertex_count(std::size_t(o.coarse))));
}

// The spectral kernel of `mesh`, with a progress bar; errors name the input file.
inline std::unique_ptr<Heat_kernel> make_heat_kernel(const Mesh& mesh, const Diffusion_options& o,
                                                     const std::string& input,
                                                     const std::string& label = "eigen solve")
{
  Progress_bar progress(label, !o.quiet);
  return for_input(input, [&] {
    return with_diffusion_parameters(o, progress, [&](const auto& np) { return std::make_unique<Heat_kernel>(mesh, np); });
  });
}

// The kernel (spectral only) and the diffusion operator A_t.
struct Diffusion_setup
{
  std::unique_ptr<Heat_kernel> kernel;
  std::unique_ptr<Diffusion> diffusion;
};

// Builds A_t by the method of --kernel, timing the stages "ncc_and_eigen_solve" and
// "operator" (spectral) or "ncc_and_local_operator" (local).
inline Diffusion_setup make_diffusion(const Mesh& mesh, const Diffusion_options& o, const std::string& input,
                                      Stage_timer& timer)
{
  Diffusion_setup s;
  if(o.local())
  {
    // No eigen solve: the NCC, L and B, then A_t block by block of columns.
    Progress_bar progress("local kernel", !o.quiet);
    s.diffusion = for_input(input, [&] {
      return with_diffusion_parameters(o, progress, [&](const auto& np) { return std::make_unique<Diffusion>(mesh, np); });
    });
    timer.stop("ncc_and_local_operator");
  }
  else
  {
    s.kernel = make_heat_kernel(mesh, o, input);
    timer.stop("ncc_and_eigen_solve");
    Progress_bar progress("heat regions", !o.quiet);
    s.diffusion = for_input(input, [&] {
      return std::make_unique<Diffusion>(
          *s.kernel, o.time,
          HD::parameters::combine(HD::parameters::operator_normalization(o.normalization),
                                  HD::parameters::progress_callback(std::function<bool(double)>(std::ref(progress)))));
    });
    progress.finish();
    timer.stop("operator");
  }
  return s;
}

// The coarse vertex count the package aims at for a mesh of n vertices (before the
// simplification rounds it), by its own rule: for the JSON summary when the package
// builds the kernel itself (filter_shape, denoise_mesh).
inline std::size_t expected_coarse_vertex_count(const Diffusion_options& o, std::size_t n)
{
  return HD::internal::coarse_vertex_count_for(double(o.coarse), n);
}

// Says on stderr when the package chose a coarse level by itself.
inline void note_automatic_coarse(const Diffusion_options& o, std::size_t n, std::size_t used)
{
  if(!o.quiet && !o.local() && o.coarse < 0 && used > 0)
    std::cerr << "note: " << n << " vertices (more than " << Heat_kernel::automatic_coarse_threshold
              << "): the eigenpairs are computed on a coarse level of " << used
              << " vertices (--coarse N to choose, --coarse 0 for the full computation)\n";
}

// The diffusion parameters of a JSON summary: sigma, time, kernel and, for the
// spectral kernel, the eigenpairs and the coarse level ({"vertex_count": the size
// used, 0 for none; "automatic": whether the package chose it}). Without a kernel
// object (the package built it internally), the documented choice is reported.
inline void add_diffusion_json(Json_object& summary, const Diffusion_options& o, std::size_t n,
                               const Heat_kernel* kernel)
{
  summary.number("sigma", o.sigma).number("time", o.time).string("kernel", o.kernel_name());
  summary.boolean("kernel_automatic", o.automatic_method);
  if(o.builds_operator)
    summary.string("normalization", o.normalization_name());
  if(o.local())
    return;
  Json_object coarse;
  coarse.integer("vertex_count", (long long)(kernel ? kernel->coarse_vertex_count() : expected_coarse_vertex_count(o, n)))
      .boolean("automatic", o.coarse < 0);
  summary.integer("eigenpairs", (long long)(kernel ? kernel->number_of_eigenpairs() : (std::min)(o.eigenpairs, n)))
      .boolean("scale_invariant", o.scale_invariant)
      .object("coarse", coarse);
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

inline void warn_about_collapsed_regions(const Diffusion& diffusion, const Diffusion_options& o)
{
  const HD::Heat_region_statistics& regions = diffusion.region_statistics();
  if(o.quiet || regions.collapsed_regions == 0)
    return;
  if(o.local())
    std::cerr << "warning: " << regions.collapsed_regions
              << " heat regions collapsed to their vertex (its edge weights isolate it): those vertices keep "
                 "their heat; a larger --sigma joins them to their neighbours\n";
  else
    std::cerr << "warning: " << regions.collapsed_regions
              << " heat regions collapsed to their vertex (the truncated kernel is too flat at this t): those "
                 "vertices keep their heat; larger --sigma, --time or -m, or --kernel local, avoid it\n";
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_SETUP_H
