// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The diffusion options every subcommand that diffuses shares (diffuse, features, hks,
// decompose, enhance, denoise): --sigma --time --kernel --kernel-tolerance --normalization
// -m --coarse -k --scale-invariant --field, parsed, checked and documented in one place.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_OPTIONS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_OPTIONS_H

#include "cli_arguments.h"
#include "mesh_input.h"

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/heat_kernel_method.h>
#include <CGAL/Heat_diffusion/parameter_defaults.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

namespace HD = CGAL::Heat_diffusion;

// The largest values the options take: far inside the range of std::size_t, and
// beyond anything that finishes (the eigen solve is O(n m^2)).
constexpr double maximum_eigenpairs = 1000000;
constexpr double maximum_coarse_vertex_count = 1000000000;
constexpr double maximum_steps = 1000000;

// The steps "0,10,40" of a list of them.
template <typename Steps>
std::string step_list_text(const Steps& steps)
{
  std::string text;
  for(std::size_t k : steps)
    text += (text.empty() ? "" : ",") + std::to_string(k);
  return text;
}

// What a subcommand takes of the shared diffusion options. The defaults are the
// library's, shown by --help; the options that are not given are not passed to the
// library (Diffusion_options), so that its defaults apply, adaptive ones included.
struct Diffusion_spec
{
  enum Steps { no_steps, step_list, single_step };

  double sigma_default = HD::defaults::sigma;
  std::string sigma_note;            // appended to the help of --sigma
  double time_default = HD::defaults::time;
  std::string time_note;             // appended to the help of --time
  bool time_alias = false;           // -t is --time (hks)
  Steps steps = step_list;           // -k
  // The default of -k: for a step list, the steps written (the tool's, from the
  // library's feature scales); for a single step, the library's default, for --help.
  std::string steps_default = step_list_text(HD::defaults::feature_scales);
  std::string steps_help;            // the help of -k
  std::string local_refusal;         // why --kernel local is refused; empty if supported
  std::string coarse_refusal;        // why --coarse is refused; empty if supported
  bool scale_invariant = true;       // --scale-invariant
  bool normalization = true;         // --normalization (the commands that build A_t)
  bool field = false;                // --field ns|FILE
};

// The parsed options: those given, as given; an empty optional is an option not given,
// whose default the library chooses (with_diffusion_parameters() passes it empty).
struct Diffusion_options
{
  std::optional<double> sigma;
  std::optional<double> time;
  std::optional<HD::Heat_kernel_method> kernel;  // --kernel as given (automatic included)
  // The kernel the library selects (never automatic): by the library's rule for
  // Heat_kernel_method::automatic, for the stages the tool times and reports.
  HD::Heat_kernel_method method = HD::Heat_kernel_method::local;
  std::optional<HD::Operator_normalization> normalization;
  std::optional<double> kernel_tolerance;  // the local kernel's accuracy
  bool builds_operator = true;  // the subcommand builds A_t (and so has --normalization)
  std::optional<std::size_t> eigenpairs;
  std::optional<long long> coarse;  // not given: the library's automatic coarse level
  bool scale_invariant = false;
  std::vector<std::size_t> steps;        // -k of a step list (the default list if not given)
  std::optional<std::size_t> step_count;  // -k of a single step, if given
  std::string field = "ns";
  std::string time_option = "--time";
  bool json = false;
  bool quiet = false;

  bool local() const { return method == HD::Heat_kernel_method::local; }
  // Whether the library chose the kernel: --kernel not given, or automatic.
  bool automatic_method() const { return !kernel || *kernel == HD::Heat_kernel_method::automatic; }
  // The time of one step, for the calls that take it as an argument (A_t from a spectral
  // kernel): the one given, or the library's default.
  double time_or_default() const { return time.value_or(HD::defaults::time); }
  // The names of the options given, as the library's named parameters, for the JSON summary.
  std::vector<std::string> given() const
  {
    std::vector<std::string> names;
    if(sigma) names.push_back("sigma");
    if(time) names.push_back("time");
    if(kernel) names.push_back("kernel_method");
    if(normalization) names.push_back("operator_normalization");
    if(kernel_tolerance) names.push_back("local_kernel_tolerance");
    if(eigenpairs) names.push_back("number_of_eigenpairs");
    if(coarse) names.push_back("coarse_vertex_count");
    if(scale_invariant) names.push_back("scale_invariant_kernel");
    return names;
  }
  std::string kernel_name() const { return local() ? "local" : "spectral"; }
};

// The arguments of a subcommand: the shared options of `spec`, plus its own.
inline Arguments diffusion_arguments(const Diffusion_spec& spec, std::vector<std::string> flags,
                                     std::vector<std::string> valued)
{
  for(const char* f : {"--json", "--quiet", "--no-repair", "-h", "--help"})
    flags.push_back(f);
  if(spec.scale_invariant)
    flags.push_back("--scale-invariant");
  for(const char* v : {"-o", "--sigma", "--time", "--kernel", "-m", "--coarse"})
    valued.push_back(v);
  if(spec.normalization)
    valued.push_back("--normalization");
  if(spec.local_refusal.empty())
    valued.push_back("--kernel-tolerance");
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

  if(args.has("--sigma"))
  {
    const std::string sigma_text = args.value("--sigma", "");
    if(sigma_text == "inf")
      o.sigma = std::numeric_limits<double>::infinity();
    else
    {
      char* end = nullptr;
      const double sigma = std::strtod(sigma_text.c_str(), &end);
      if(sigma_text.empty() || *end != '\0' || !std::isfinite(sigma) || !(sigma > 0))
        throw Usage_error("--sigma must be a number > 0 or 'inf', not '" + sigma_text + "'");
      o.sigma = sigma;
    }
  }

  if(spec.time_alias && args.has("-t") && args.has("--time"))
    throw Usage_error("give the time once, with -t or --time");
  o.time_option = spec.time_alias && args.has("-t") ? "-t" : "--time";
  if(args.has(o.time_option))
    o.time = parse_number(o.time_option, args.value(o.time_option, ""), 0., true);

  // --kernel automatic is the package's Heat_kernel_method::automatic, by the package's
  // rule: spectral when the eigenpairs are asked for (-m, --coarse, --scale-invariant,
  // or a subcommand that has no local kernel), else local.
  const std::string kernel = args.value("--kernel", "automatic");
  if(kernel != "spectral" && kernel != "local" && kernel != "automatic")
    throw Usage_error("--kernel must be 'automatic', 'spectral' or 'local', not '" + kernel + "'");
  const HD::Heat_kernel_method requested = kernel == "local"      ? HD::Heat_kernel_method::local
                                           : kernel == "spectral" ? HD::Heat_kernel_method::spectral
                                                                  : HD::Heat_kernel_method::automatic;
  if(args.has("--kernel"))
    o.kernel = requested;
  // A subcommand without a local kernel (hks) builds the spectral kernel itself.
  const bool eigenpairs_requested = args.has("-m") || args.has("--coarse") ||
                                    (spec.scale_invariant && args.flag("--scale-invariant")) ||
                                    !spec.local_refusal.empty();
  o.method = HD::internal::choose_kernel_method(requested, eigenpairs_requested);
  if(o.local() && !spec.local_refusal.empty())
    throw Usage_error("--kernel local: " + spec.local_refusal);

  o.builds_operator = spec.normalization;
  if(args.has("--normalization"))
  {
    const std::string normalization = args.value("--normalization", "");
    if(normalization != "balanced" && normalization != "columns")
      throw Usage_error("--normalization must be 'balanced' or 'columns', not '" + normalization + "'");
    o.normalization = normalization == "balanced" ? HD::Operator_normalization::balanced
                                                  : HD::Operator_normalization::columns;
  }

  if(args.has("-m"))
    o.eigenpairs = parse_count("-m", args.value("-m", ""), 1, maximum_eigenpairs);
  if(args.has("--coarse"))
  {
    if(!spec.coarse_refusal.empty())
      throw Usage_error("--coarse: " + spec.coarse_refusal);
    o.coarse = (long long)parse_count("--coarse", args.value("--coarse", ""), 0, maximum_coarse_vertex_count);
    if(*o.coarse > 0 && *o.coarse < 4)
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
  if(args.has("--kernel-tolerance"))
  {
    if(!o.local())
      throw Usage_error("--kernel-tolerance is the accuracy of the local kernel: the spectral kernel has none");
    const std::string text = args.value("--kernel-tolerance", "");
    o.kernel_tolerance = parse_number("--kernel-tolerance", text, 0., true);
    if(!(*o.kernel_tolerance < 1))
      throw Usage_error("--kernel-tolerance must be below 1, not '" + text + "'");
  }

  if(spec.steps == Diffusion_spec::step_list)
    o.steps = parse_steps(args.value("-k", spec.steps_default));
  else if(spec.steps == Diffusion_spec::single_step && args.has("-k"))
    o.step_count = parse_count("-k", args.value("-k", ""), 0, maximum_steps);
  if(spec.field)
    o.field = args.value("--field", "ns");
  return o;
}

// The help of the shared diffusion options of `spec`.
inline std::string diffusion_options_help(const Diffusion_spec& spec)
{
  std::string h;
  h += help_option("--sigma S", "edge-weight width of the kernel (default " + format_number(spec.sigma_default) +
                                    "): small preserves features (0.1), large smooths (1), 'inf' is "
                                    "isotropic" + (spec.sigma_note.empty() ? "" : "; " + spec.sigma_note));
  h += help_option(spec.time_alias ? "-t, --time T" : "--time T",
                   (spec.time_note.empty() ? "time of one diffusion step" : spec.time_note) +
                       ", on the mesh rescaled to area = vertex count (default " + format_number(spec.time_default) +
                       ")");
  if(spec.local_refusal.empty())
    h += help_option("--kernel K",
                     "'local': each kernel column computed around its vertex, without eigenpairs and without "
                     "truncation (to --kernel-tolerance; its cost per vertex grows with T); 'spectral': the paper's truncated kernel from M eigenpairs, accurate for large T "
                     "only (T > 4 ln 10 / lambda_M); "
                     "'automatic' (default): 'spectral' if -m, --coarse or --scale-invariant is given, else "
                     "'local'. -m, --coarse and --scale-invariant concern the eigenpairs: with 'local' they are "
                     "usage errors");
  else
    h += help_option("--kernel K", "'spectral' only (the default): " + spec.local_refusal);
  if(spec.local_refusal.empty())
    h += help_option("--kernel-tolerance E",
                     "accuracy of the local kernel: the heat a kernel column may lose through the border of the "
                     "patch it is computed on, relative to its heat; from about 5e-4 on, the exponential is "
                     "approximated with two poles instead of three (default " +
                         format_number(HD::defaults::local_kernel_tolerance) +
                         ", chosen from the heat regions' own truncation of the columns; 1e-4, three poles, was the "
                         "earlier default). Local kernel only");
  if(spec.normalization)
    h += help_option("--normalization N",
                   "'balanced' (default): A_t is the kernel balanced to be doubly stochastic: heat is conserved, "
                   "a constant field stays constant, values stay within the input's range; 'columns': the "
                   "paper's A_t, whose columns alone sum to 1: heat is conserved, but a constant field is not "
                   "kept (vertices whose region collapsed gather heat)");
  h += help_option("-m M", "number of eigenpairs of the spectral kernel, 1 to 1000000, clamped to the vertex count "
                           "(default " + std::to_string(HD::defaults::number_of_eigenpairs) + ")");
  if(spec.coarse_refusal.empty())
    h += help_option("--coarse N",
                     "compute the eigenpairs on a copy simplified to about N vertices and prolongate them to the "
                     "mesh (the paper's eq. 21); 0 computes them on the mesh itself. Default: automatic, " +
                         std::to_string(HD::Edge_weighted_heat_kernel<Mesh>::automatic_coarse_vertex_count) + " vertices for meshes of more "
                         "than " + std::to_string(HD::Edge_weighted_heat_kernel<Mesh>::automatic_coarse_threshold) +
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
inline std::string repair_option_help()
{
  return help_option("--no-repair", "refuse an input that is no mesh the package can process, instead of "
                                    "repairing it with CGAL's repair functions (duplicate points merged, "
                                    "degenerate and duplicate polygons removed, faces reoriented, non-manifold "
                                    "vertices split, isolated vertices and faces of zero area removed: the "
                                    "default, said on stderr and in --json's \"repair\"; PLY outputs then give "
                                    "each vertex's vertex in the file as the property 'origin')");
}

inline std::string common_options_help()
{
  return repair_option_help() +
         help_option("--quiet", "print nothing but errors (and the JSON summary if asked for); no progress bar") +
         help_option("-h, --help", "this text") +
         "\nA progress bar is shown on stderr for every stage that lasts more than a second (the eigen solve\n"
         "with the coarse level's simplification, the heat regions, the local kernel, the diffusion steps,\n"
         "denoising), when stderr is a terminal (HEAT_DIFFUSION_PROGRESS=always|never overrides).\n";
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_DIFFUSION_OPTIONS_H
