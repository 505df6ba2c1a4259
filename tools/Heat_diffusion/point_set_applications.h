// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The subcommands decompose, enhance and denoise on a point set: the library's
// decompose_point_set_field(), filter_point_set_shape() and denoise_point_set() on the
// points of the input file, and their PLY outputs (points without faces).

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_APPLICATIONS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_APPLICATIONS_H

#include "cli_measures.h"
#include "cli_output.h"
#include "command.h"
#include "diffusion_setup.h"
#include "point_set_commands.h"
#include "point_set_options.h"

#include <CGAL/Heat_diffusion/point_set_decomposition.h>
#include <CGAL/Heat_diffusion/point_set_denoising.h>
#include <CGAL/Point_set_3/IO.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace heat_diffusion_cli {

// The output of a point-set command that moves the points: it must be a PLY.
inline void check_point_output(const std::string& path)
{
  if(mesh_format(path) != ".ply")
    throw Usage_error("the output " + path + " of a point set must end in .ply (points without faces)");
}

// Writes the points, with their normal map where they have one, as a binary PLY of
// vertices without faces (x, y, z, then nx, ny, nz).
inline void write_points_ply(Output_files& files, const std::string& path, const Point_set& points)
{
  files.add(path, [&](std::ostream& os) {
    CGAL::IO::set_binary_mode(os);
    return CGAL::IO::write_PLY(os, points, "written by CGAL Heat_diffusion", CGAL::parameters::use_binary_mode(true));
  });
}

// The largest distance a point moved from `before` to `after`, relative to the diagonal
// of the bounding box of `before` (0 for a single point).
inline double largest_relative_displacement(const Point_set& before, const Point_set& after)
{
  double largest = 0;
  CGAL::Bbox_3 box;
  for(Point_set::Index i : before)
  {
    largest = (std::max)(largest, point_distance(before.point(i), after.point(i)));
    box += before.point(i).bbox();
  }
  const double diagonal = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin());
  return diagonal > 0 ? largest / diagonal : 0.;
}

// The tail of the commands that move the points: `after` written to `output`, then
// reported; returns the largest displacement from `before`, relative to the diagonal.
inline double write_moved_points(Run& r, const Point_set& before, const Point_set& after,
                                 const Neighbourhood_options& nb, const std::string& output)
{
  const double relative_displacement = largest_relative_displacement(before, after);
  Output_files files;
  write_points_ply(files, output, after);
  files.commit();
  r.timer.stop("write");
  report_point_set(r, after, nb);
  return relative_displacement;
}

// decompose on a point set: the bands and the residual of the NS or of a field, written
// to `outputs` (the bands, then the residual).
inline void decompose_on_points(Run& r, std::size_t levels, const std::optional<std::size_t>& steps_per_level,
                                const std::string& prefix, const std::vector<std::string>& outputs)
{
  const Point_set_setup setup = make_point_set_diffusion(r, outputs);
  const Point_set_diffusion& diffusion = *setup.diffusion;
  const Eigen::VectorXd f0 = initial_point_field(r.diffusion.field, diffusion);
  const std::vector<Eigen::VectorXd> bands = for_input(r.input, [&] {
    return HD::decompose_point_set_field(diffusion, f0, levels, HD::parameters::steps_per_level(steps_per_level));
  });
  r.timer.stop("decomposition");

  std::vector<std::vector<double> > values;
  for(const Eigen::VectorXd& band : bands)
    values.emplace_back(band.data(), band.data() + band.size());
  Output_files files;
  for(std::size_t j = 0; j < values.size(); ++j)
    write_point_fields_ply(files, outputs[j], setup.points, diffusion.normal_controlled_coordinates(),
                           {{"field", values[j]}});
  files.commit();
  r.timer.stop("write");

  const Band_summary summary = band_summary(std::vector<double>(f0.data(), f0.data() + f0.size()), values, outputs);
  const std::size_t steps_used = steps_per_level.value_or(HD::defaults::decomposition_steps_per_level);
  report_point_set(r, setup.points, setup.nb);
  if(!r.quiet)
    std::cerr << levels << " bands of " << steps_used << " steps; largest |band sum| / sum |S| = "
              << summary.worst_relative_sum << "\nwritten to " << prefix << "_band*.ply and " << outputs.back() << "\n";
  r.summary.string("field", r.diffusion.field).object("outputs", summary.names);
  add_point_set_diffusion_json(r, setup.points, setup.nb, diffusion,
                               steps_per_level ? std::vector<std::string>{"steps_per_level"} : std::vector<std::string>{});
  r.summary.integer("levels", (long long)levels).integer("steps_per_level", (long long)steps_used);
  summary.add_to(r.summary);
}

// The variance of the Normal Signature of a point set's fans.
inline double normal_signature_variance(const Point_set_NCC& ncc)
{
  double sum = 0, squares = 0;
  const double n = double(ncc.number_of_points());
  for(std::size_t i = 0; i < ncc.number_of_points(); ++i)
  {
    sum += ncc.normal_signature(i);
    squares += ncc.normal_signature(i) * ncc.normal_signature(i);
  }
  return n > 0 ? squares / n - (sum / n) * (sum / n) : 0.;
}

inline double normal_signature_variance(const Point_set& points, const Neighbourhood_options& nb)
{
  return with_neighbourhood(nb, [&](const auto& np) {
    return normal_signature_variance(Point_set_NCC(points, nb.k_or_default(), np));
  });
}

// enhance on a point set: filter_point_set_shape() with `weights`, the points written to
// `output` (with the file's normals, which the filter reads and keeps).
inline void enhance_on_points(Run& r, const std::vector<double>& weights,
                              const std::optional<std::size_t>& steps_per_level,
                              const std::optional<double>& anchor_weight, const std::string& output)
{
  refuse_mesh_only_diffusion_options(r.diffusion);
  const Neighbourhood_options nb = parse_neighbourhood(r.args);
  check_point_output(output);
  r.check_outputs({output});
  Point_set points = read_points(r);
  const Point_set original = points;
  const double input_variance = for_points(r.input, [&] { return normal_signature_variance(points, nb); });
  r.timer.stop("ncc");
  Progress_bar progress("local kernel", !r.quiet);
  for_points(r.input, [&] {
    with_neighbourhood(nb, [&](const auto& neighbourhood) {
      with_diffusion_parameters(r.diffusion, progress, [&](const auto& np) {
        HD::filter_point_set_shape(points, nb.k_or_default(), weights,
                                   HD::parameters::combine(np, neighbourhood,
                                                           HD::parameters::steps_per_level(steps_per_level),
                                                           HD::parameters::anchor_weight(anchor_weight)));
      });
    });
  });
  progress.finish();
  r.timer.stop("filter_shape");
  // Measured before writing: a failure leaves no output.
  const double output_variance = for_points(r.input, [&] { return normal_signature_variance(points, nb); });
  const double relative_displacement = write_moved_points(r, original, points, nb, output);
  if(!r.quiet)
    std::cerr << "NS variance " << input_variance << " -> " << output_variance << "; largest displacement "
              << relative_displacement << " of the diagonal\nwritten to " << output << "\n";
  std::vector<std::string> given = nb.given();
  if(steps_per_level)
    given.push_back("steps_per_level");
  if(anchor_weight)
    given.push_back("anchor_weight");
  r.summary.string("output", output)
      .string("input_kind", "points")
      .integer("points", (long long)points.size())
      .raw("weights", number_list_json(weights))
      .integer("steps_per_level",
               (long long)steps_per_level.value_or(HD::defaults::shape_filter_steps_per_level));
  add_diffusion_choice_json(r.summary, r.diffusion, given, r.diffusion.sigma.value_or(HD::defaults::sigma),
                            r.diffusion.time.value_or(HD::defaults::time), r.diffusion.method,
                            r.diffusion.normalization.value_or(HD::Operator_normalization::balanced));
  r.summary.number("anchor_weight", anchor_weight.value_or(HD::defaults::shape_filter_anchor_weight))
      .number("ns_variance_before", input_variance)
      .number("ns_variance_after", output_variance)
      .number("max_displacement_relative", relative_displacement);
}

// The options of denoise on a point set, as given (empty: denoise_point_set()'s default).
struct Point_set_denoising_options
{
  std::optional<unsigned> iterations;
  std::optional<std::size_t> steps;
  std::optional<double> normal_sigma;
  std::optional<double> displacement_limit;
  std::vector<std::string> given;  // the library's names of those given
};

// denoise on a point set: denoise_point_set(), the points written to `output` (with
// their filtered normals where the file has normals).
inline void denoise_on_points(Run& r, const Point_set_denoising_options& options, const std::string& output)
{
  if(r.args.has("--method") && r.args.value("--method", "") != "normal_filtering")
    throw Usage_error("on a point set the denoiser is normal filtering (denoise_point_set): --method "
                      "signature_diffusion needs a mesh");
  Neighbourhood_options nb = parse_neighbourhood(r.args);
  nb.default_k = HD::defaults::point_set_denoising::number_of_neighbors;
  check_point_output(output);
  r.check_outputs({output});
  Point_set points = read_points(r);
  const Point_set noisy = points;
  Progress_bar progress("denoising", !r.quiet);
  const HD::Point_set_denoising_report report = for_points(r.input, [&] {
    return with_neighbourhood(nb, [&](const auto& neighbourhood) {
      return HD::denoise_point_set(
          points, nb.k_or_default(),
          HD::parameters::combine(
              neighbourhood, CGAL::parameters::number_of_iterations(options.iterations),
              HD::parameters::number_of_steps(options.steps), HD::parameters::normal_sigma(options.normal_sigma),
              HD::parameters::displacement_limit(options.displacement_limit),
              HD::parameters::progress_callback(std::function<bool(double)>(std::ref(progress)))));
    });
  });
  progress.finish();
  r.timer.stop("denoise");
  const double relative_displacement = write_moved_points(r, noisy, points, nb, output);
  if(!r.quiet)
    std::cerr << r.input << ": noise level " << report.noise_level << ", " << report.iterations
              << " iterations, points moved by " << report.mean_displacement << " on average along their normals\n"
              << "written to " << output << "\n";
  std::vector<std::string> given = nb.given();
  given.insert(given.end(), options.given.begin(), options.given.end());
  namespace D = HD::defaults::point_set_denoising;
  Json_object chosen, displacement;
  chosen.number("noise_level", report.noise_level)
      .number("normal_sigma", report.normal_sigma)
      .integer("iterations", (long long)report.iterations);
  displacement.number("mean", report.mean_displacement).number("max_relative_to_diagonal", relative_displacement);
  r.summary.string("output", output)
      .string("input_kind", "points")
      .integer("points", (long long)points.size())
      .integer("neighbors", (long long)nb.k_or_default())
      .string("normals", points.has_normal_map() ? "file" : "estimated")
      .raw("given", json_string_list(given))
      .integer("max_iterations", (long long)options.iterations.value_or(D::iterations))
      .integer("steps", (long long)options.steps.value_or(D::number_of_steps))
      .number("displacement_limit", options.displacement_limit.value_or(D::displacement_limit))
      .object("denoiser", chosen)
      .object("displacement", displacement);
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_APPLICATIONS_H
