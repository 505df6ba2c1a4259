// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The diffusion options every subcommand that diffuses shares (diffuse, features, hks,
// decompose, enhance, denoise): --sigma --time --kernel -m --coarse -k
// --scale-invariant --field -o --json --quiet, parsed, checked and documented in one
// place; and building the kernel and the diffusion from them, with a progress bar.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_OPTIONS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_OPTIONS_H

#include "cli_support.h"

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/heat_kernel_method.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

typedef HD::Edge_weighted_heat_kernel<Mesh> Heat_kernel;
typedef HD::Anisotropic_heat_diffusion<Mesh> Diffusion;

// The largest values the options take: far inside the range of std::size_t, and
// beyond anything that finishes (the eigen solve is O(n m^2)).
constexpr double maximum_eigenpairs = 1000000;
constexpr double maximum_coarse_vertex_count = 1000000000;
constexpr double maximum_steps = 1000000;

// One option of a --help text: the name in a column of 20 characters, the text
// wrapped at 92 columns ('\n' in the text starts a new line).
inline std::string help_option(const std::string& name, const std::string& text)
{
  const std::size_t indent = 22, width = 92;
  std::string result, line = "  " + name;
  if(line.size() + 1 > indent)
  {
    result += line + "\n";
    line.clear();
  }
  line.resize(indent, ' ');
  bool empty = true, first = true;
  std::istringstream paragraphs(text);
  std::string paragraph;
  while(std::getline(paragraphs, paragraph, '\n'))
  {
    if(!first)
    {
      result += line + "\n";
      line.assign(indent, ' ');
      empty = true;
    }
    first = false;
    std::istringstream words(paragraph);
    std::string word;
    while(words >> word)
    {
      if(!empty && line.size() + 1 + word.size() > width)
      {
        result += line + "\n";
        line.assign(indent, ' ');
        empty = true;
      }
      line += (empty ? "" : " ") + word;
      empty = false;
    }
  }
  return result + line + "\n";
}

// What a subcommand takes of the shared diffusion options, with its defaults.
struct Diffusion_spec
{
  enum Steps { no_steps, step_list, single_step };

  std::string sigma_default = "0.1";
  std::string sigma_note;            // appended to the help of --sigma
  std::string time_default = "1";
  std::string time_note;             // appended to the help of --time
  bool time_alias = false;           // -t is --time (hks)
  Steps steps = step_list;           // -k
  std::string steps_default = "0,10,40";
  std::string steps_help;            // the help of -k
  std::string local_refusal;         // why --kernel local is refused; empty if supported
  std::string coarse_refusal;        // why --coarse is refused; empty if supported
  bool scale_invariant = true;       // --scale-invariant
  bool normalization = true;         // --normalization (the commands that build A_t)
  bool field = false;                // --field ns|FILE
};

// The parsed options.
struct Diffusion_options
{
  double sigma = 0.1;
  double time = 1.;
  HD::Heat_kernel_method method = HD::Heat_kernel_method::local;  // never automatic: resolved by the parser
  bool automatic_method = true;                                   // --kernel not given
  HD::Operator_normalization normalization = HD::Operator_normalization::balanced;  // --normalization
  bool builds_operator = true;  // the subcommand builds A_t (and so has --normalization)
  std::size_t eigenpairs = 150;
  long long coarse = -1;  // -1: the package's automatic choice
  bool scale_invariant = false;
  std::vector<std::size_t> steps;  // -k (one entry for a single_step spec)
  std::string field = "ns";
  std::string time_option = "--time";
  bool json = false;
  bool quiet = false;

  bool local() const { return method == HD::Heat_kernel_method::local; }
  std::string kernel_name() const { return local() ? "local" : "spectral"; }
  std::string normalization_name() const
  {
    return normalization == HD::Operator_normalization::balanced ? "balanced" : "columns";
  }
};

// The arguments of a subcommand: the shared options of `spec`, plus its own.
inline Arguments diffusion_arguments(const Diffusion_spec& spec, std::vector<std::string> flags,
                                     std::vector<std::string> valued)
{
  for(const char* f : {"--json", "--quiet", "-h", "--help"})
    flags.push_back(f);
  if(spec.scale_invariant)
    flags.push_back("--scale-invariant");
  for(const char* v : {"-o", "--sigma", "--time", "--kernel", "-m", "--coarse"})
    valued.push_back(v);
  if(spec.normalization)
    valued.push_back("--normalization");
  if(spec.time_alias)
    valued.push_back("-t");
  if(spec.steps != Diffusion_spec::no_steps)
    valued.push_back("-k");
  if(spec.field)
    valued.push_back("--field");
  return Arguments(std::move(flags), std::move(valued));
}

inline Diffusion_options parse_diffusion_options(const Arguments& args, const Diffusion_spec& spec)
{
  Diffusion_options o;
  o.json = args.flag("--json");
  o.quiet = args.flag("--quiet");

  const std::string sigma_text = args.value("--sigma", spec.sigma_default);
  if(sigma_text == "inf")
    o.sigma = std::numeric_limits<double>::infinity();
  else
  {
    char* end = nullptr;
    o.sigma = std::strtod(sigma_text.c_str(), &end);
    if(sigma_text.empty() || *end != '\0' || !std::isfinite(o.sigma) || !(o.sigma > 0))
      throw Usage_error("--sigma must be a number > 0 or 'inf', not '" + sigma_text + "'");
  }

  if(spec.time_alias && args.has("-t") && args.has("--time"))
    throw Usage_error("give the time once, with -t or --time");
  o.time_option = spec.time_alias && args.has("-t") ? "-t" : "--time";
  o.time = parse_number(o.time_option, args.value(o.time_option, spec.time_default), 0., true);

  // The package's Heat_kernel_method::automatic: spectral when the eigenpairs are
  // asked for (-m, --coarse, --scale-invariant), else local.
  const std::string kernel = args.value("--kernel", "automatic");
  if(kernel != "spectral" && kernel != "local" && kernel != "automatic")
    throw Usage_error("--kernel must be 'automatic', 'spectral' or 'local', not '" + kernel + "'");
  o.automatic_method = kernel == "automatic";
  const bool eigenpairs_requested =
      args.has("-m") || args.has("--coarse") || (spec.scale_invariant && args.flag("--scale-invariant"));
  if(kernel == "local" || (o.automatic_method && spec.local_refusal.empty() && !eigenpairs_requested))
    o.method = HD::Heat_kernel_method::local;
  else
    o.method = HD::Heat_kernel_method::spectral;
  if(o.local() && !spec.local_refusal.empty())
    throw Usage_error("--kernel local: " + spec.local_refusal);

  o.builds_operator = spec.normalization;
  const std::string normalization = args.value("--normalization", "balanced");
  if(normalization != "balanced" && normalization != "columns")
    throw Usage_error("--normalization must be 'balanced' or 'columns', not '" + normalization + "'");
  o.normalization = normalization == "balanced" ? HD::Operator_normalization::balanced
                                                : HD::Operator_normalization::columns;

  o.eigenpairs = parse_count("-m", args.value("-m", "150"), 1, maximum_eigenpairs);
  if(args.has("--coarse"))
  {
    if(!spec.coarse_refusal.empty())
      throw Usage_error("--coarse: " + spec.coarse_refusal);
    o.coarse = (long long)parse_count("--coarse", args.value("--coarse", ""), 0, maximum_coarse_vertex_count);
    if(o.coarse > 0 && o.coarse < 4)
      throw Usage_error("--coarse must be 0 (no coarse level) or at least 4, not '" + args.value("--coarse", "") + "'");
  }
  o.scale_invariant = spec.scale_invariant && args.flag("--scale-invariant");
  if(o.local())
  {
    // The local kernel has no eigenpairs: the options of the eigenpairs are refused
    // rather than silently ignored.
    if(args.has("-m"))
      throw Usage_error("-m is the number of eigenpairs of the spectral kernel: --kernel local computes none");
    if(args.has("--coarse"))
      throw Usage_error("--coarse is the coarse level of the eigen solve: --kernel local computes none");
    if(o.scale_invariant)
      throw Usage_error("--scale-invariant needs the eigenvalues: use --kernel spectral");
  }

  if(spec.steps == Diffusion_spec::step_list)
    o.steps = parse_steps(args.value("-k", spec.steps_default));
  else if(spec.steps == Diffusion_spec::single_step)
    o.steps = {parse_count("-k", args.value("-k", spec.steps_default), 0, maximum_steps)};
  if(spec.field)
    o.field = args.value("--field", "ns");
  return o;
}

// The help of the shared diffusion options of `spec`.
inline std::string diffusion_options_help(const Diffusion_spec& spec)
{
  std::string h;
  h += help_option("--sigma S", "edge-weight width of the kernel (default " + spec.sigma_default +
                                    "): small preserves features (0.1), large smooths (1), 'inf' is "
                                    "isotropic" + (spec.sigma_note.empty() ? "" : "; " + spec.sigma_note));
  h += help_option(spec.time_alias ? "-t, --time T" : "--time T",
                   (spec.time_note.empty() ? "time of one diffusion step" : spec.time_note) +
                       ", on the mesh rescaled to area = vertex count (default " + spec.time_default + ")");
  if(spec.local_refusal.empty())
    h += help_option("--kernel K",
                     "'local': each kernel column computed around its vertex, without eigenpairs and without "
                     "truncation (relative error below 1e-4 measured for T from 0.5 to 4, where it is 1.1 to 9.5 "
                     "times faster than 'spectral'; its cost per vertex grows with T); 'spectral': the paper's "
                     "truncated kernel from M eigenpairs, accurate for large T only (T > 4 ln 10 / lambda_M); "
                     "'automatic' (default): 'spectral' if -m, --coarse or --scale-invariant is given, else "
                     "'local'. -m, --coarse and --scale-invariant concern the eigenpairs: with 'local' they are "
                     "usage errors");
  else
    h += help_option("--kernel K", "'spectral' only (the default): " + spec.local_refusal);
  if(spec.normalization)
    h += help_option("--normalization N",
                   "'balanced' (default): A_t is the kernel balanced to be doubly stochastic: heat is conserved, "
                   "a constant field stays constant, values stay within the input's range; 'columns': the "
                   "paper's A_t, whose columns alone sum to 1: heat is conserved, but a constant field is not "
                   "kept (vertices whose region collapsed gather heat)");
  h += help_option("-m M", "number of eigenpairs of the spectral kernel, 1 to 1000000, clamped to the vertex count "
                           "(default 150)");
  if(spec.coarse_refusal.empty())
    h += help_option("--coarse N",
                     "compute the eigenpairs on a copy simplified to about N vertices and prolongate them to the "
                     "mesh (the paper's eq. 21); 0 computes them on the mesh itself. Default: automatic, " +
                         std::to_string(Heat_kernel::automatic_coarse_vertex_count) + " vertices for meshes of more "
                         "than " + std::to_string(Heat_kernel::automatic_coarse_threshold) +
                         " vertices, else none; --json reports the size used and whether it was automatic");
  else
    h += help_option("--coarse N", "not supported yet: " + spec.coarse_refusal);
  if(spec.steps != Diffusion_spec::no_steps)
    h += help_option(spec.steps == Diffusion_spec::step_list ? "-k K1,K2,..." : "-k K", spec.steps_help);
  if(spec.scale_invariant)
    h += help_option("--scale-invariant", "the scale-invariant kernel of the paper's eq. 14 (spectral kernel only)");
  if(spec.field)
    h += help_option("--field F", "'ns' (default): the Normal Signature; or a text file with one number per vertex, "
                                  "in the order of the mesh file's vertices");
  return h;
}

// The help of --quiet and -h, the same for every subcommand, and the progress note.
inline std::string common_options_help()
{
  return help_option("--quiet", "print nothing but errors (and the JSON summary if asked for); no progress bar") +
         help_option("-h, --help", "this text") +
         "\nA progress bar is shown on stderr for every stage that lasts more than a second (the eigen solve\n"
         "with the coarse level's simplification, the heat regions, the local kernel, the diffusion steps,\n"
         "denoising), when stderr is a terminal (HEAT_DIFFUSION_PROGRESS=always|never overrides).\n";
}

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

// The coarse vertex count the package chooses for a mesh of n vertices (before the
// simplification rounds it), as Edge_weighted_heat_kernel documents it.
inline std::size_t expected_coarse_vertex_count(const Diffusion_options& o, std::size_t n)
{
  if(o.coarse < 0)
    return n > Heat_kernel::automatic_coarse_threshold ? Heat_kernel::automatic_coarse_vertex_count : 0;
  return std::size_t(o.coarse) < n ? std::size_t(o.coarse) : 0;
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

// A field file: one finite number per vertex.
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

// F^0 by the diffusion's vertex index: the Normal Signature, or a field file with one
// number per vertex in the order of the mesh file.
inline Eigen::VectorXd initial_field(const std::string& source, const Mesh& mesh, const Diffusion& diffusion)
{
  Eigen::VectorXd f0(static_cast<Eigen::Index>(mesh.number_of_vertices()));
  if(source == "ns")
    for(auto v : mesh.vertices())
      f0[Eigen::Index(diffusion.vertex_index(v))] = diffusion.normal_controlled_coordinates().normal_signature(v);
  else
  {
    const std::vector<double> values = read_field(source, mesh.number_of_vertices());
    for(auto v : mesh.vertices())
      f0[Eigen::Index(diffusion.vertex_index(v))] = values[v.idx()];
  }
  return f0;
}

// A field by the diffusion's vertex index, back in the order of the mesh's vertices.
inline std::vector<double> in_mesh_order(const Eigen::VectorXd& field, const Mesh& mesh, const Diffusion& diffusion)
{
  std::vector<double> values(mesh.number_of_vertices());
  for(auto v : mesh.vertices())
    values[v.idx()] = field[Eigen::Index(diffusion.vertex_index(v))];
  return values;
}

// F^k = A_t^k F^0 for every k of `steps`, with a progress bar over the steps.
inline std::vector<Eigen::VectorXd> diffuse_fields(const Diffusion& diffusion, const Eigen::VectorXd& f0,
                                                   const std::vector<std::size_t>& steps, const Diffusion_options& o,
                                                   const std::string& input)
{
  return for_input(input, [&] {
    std::vector<std::size_t> stops(steps);
    std::sort(stops.begin(), stops.end());
    const std::size_t last = stops.empty() ? 0 : stops.back();
    const std::size_t chunk = (std::max)(std::size_t(1), last / 100);
    Progress_bar progress("diffusion", !o.quiet);
    std::vector<Eigen::VectorXd> result(steps.size());
    Eigen::VectorXd current = f0;
    std::size_t k = 0;
    for(std::size_t stop : stops)
    {
      while(k < stop)
      {
        const std::size_t n = (std::min)(chunk, stop - k);
        current = diffusion.diffuse(current, n);
        k += n;
        progress(double(k) / double(last));
      }
      for(std::size_t s = 0; s < steps.size(); ++s)
        if(steps[s] == stop)
          result[s] = current;
    }
    return result;
  });
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
                 "their heat; a larger --sigma or --time avoids it\n";
  else
    std::cerr << "warning: " << regions.collapsed_regions
              << " heat regions collapsed to their vertex (the truncated kernel is too flat at this t): those "
                 "vertices keep their heat; larger --sigma, --time or -m, or --kernel local, avoid it\n";
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_OPTIONS_H
