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

// The named parameters of the kernel and the diffusion: the options given, the others
// as empty optionals, which the library reads as not given (its defaults apply; the
// kernel it then selects is o.method, which the tool resolved by the library's own rule
// to time the stages that run).
inline auto diffusion_parameters(const Diffusion_options& o, Progress_bar& progress)
{
  return HD::parameters::combine(
      HD::parameters::sigma(o.sigma), HD::parameters::time(o.time), HD::parameters::kernel_method(o.kernel),
      HD::parameters::number_of_eigenpairs(o.eigenpairs),
      HD::parameters::scale_invariant_kernel(o.scale_invariant ? std::optional<bool>(true) : std::nullopt),
      HD::parameters::operator_normalization(o.normalization), HD::parameters::coarse_vertex_count(o.coarse),
      HD::parameters::local_kernel_tolerance(o.kernel_tolerance),
      HD::parameters::progress_callback(std::function<bool(double)>(std::ref(progress))));
}

// Calls `f` with diffusion_parameters().
template <typename Function>
auto with_diffusion_parameters(const Diffusion_options& o, Progress_bar& progress, Function&& f)
{
  return f(diffusion_parameters(o, progress));
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
          *s.kernel, o.time_or_default(),
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
  return HD::internal::coarse_vertex_count_for(o.coarse ? double(*o.coarse) : -1., n);
}

// Says on stderr when the package chose a coarse level by itself.
inline void note_automatic_coarse(const Diffusion_options& o, std::size_t n, std::size_t used)
{
  if(!o.quiet && !o.local() && !o.coarse && used > 0)
    std::cerr << "note: " << n << " vertices (more than " << Heat_kernel::automatic_coarse_threshold
              << "): the eigenpairs are computed on a coarse level of " << used
              << " vertices (--coarse N to choose, --coarse 0 for the full computation)\n";
}

// The names of a list, as a JSON array of strings.
inline std::string json_string_list(const std::vector<std::string>& names)
{
  std::string list = "[";
  for(std::size_t i = 0; i < names.size(); ++i)
    list += (i ? ", \"" : "\"") + names[i] + "\"";
  return list + "]";
}

// The diffusion parameters of a JSON summary that meshes and point sets share: "given",
// the named parameters the user set (those of the diffusion, then the subcommand's own,
// `own_given`), then sigma, time, the kernel and (where the subcommand builds A_t) the
// normalization, as used.
inline void add_diffusion_choice_json(Json_object& summary, const Diffusion_options& o,
                                      const std::vector<std::string>& own_given, double sigma, double time,
                                      HD::Heat_kernel_method method, HD::Operator_normalization normalization)
{
  std::vector<std::string> given = o.given();
  given.insert(given.end(), own_given.begin(), own_given.end());
  summary.raw("given", json_string_list(given));
  summary.number("sigma", sigma).number("time", time);
  summary.string("kernel", method == HD::Heat_kernel_method::local ? "local" : "spectral");
  summary.boolean("kernel_automatic", o.automatic_method());
  if(o.builds_operator)
    summary.string("normalization", normalization == HD::Operator_normalization::balanced ? "balanced" : "columns");
}

// The diffusion parameters of a JSON summary, as used (add_diffusion_choice_json()):
// sigma, time, the kernel and the normalization read from the diffusion that ran, when
// there is one (else the values given or the library's defaults, which are then what the
// library used); for the spectral kernel, the eigenpairs and the coarse level
// ({"vertex_count": the size used, 0 for none; "automatic": whether the package chose
// it}), from the kernel, else by the package's own rule.
inline void add_diffusion_json(Json_object& summary, const Diffusion_options& o, std::size_t n,
                               const Heat_kernel* kernel, const Diffusion* diffusion = nullptr,
                               std::vector<std::string> own_given = {}, double sigma_default = HD::defaults::sigma,
                               double time_default = HD::defaults::time)
{
  add_diffusion_choice_json(
      summary, o, own_given,
      diffusion ? diffusion->sigma() : kernel ? kernel->sigma() : o.sigma.value_or(sigma_default),
      diffusion ? diffusion->time() : o.time.value_or(time_default), diffusion ? diffusion->kernel_method() : o.method,
      diffusion ? diffusion->operator_normalization() : o.normalization.value_or(HD::Operator_normalization::balanced));
  if(o.local())
    return;
  Json_object coarse;
  coarse.integer("vertex_count", (long long)(kernel ? kernel->coarse_vertex_count() : expected_coarse_vertex_count(o, n)))
      .boolean("automatic", !o.coarse);
  summary.integer("eigenpairs", (long long)(kernel ? kernel->number_of_eigenpairs()
                                                   : (std::min)(o.eigenpairs.value_or(HD::defaults::number_of_eigenpairs), n)))
      .boolean("scale_invariant", kernel ? kernel->is_scale_invariant() : o.scale_invariant)
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
