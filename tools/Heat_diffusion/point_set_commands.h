// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The subcommands ncc, diffuse and features on a point set: the library's point-set
// classes on the points of the input file, and their PLY outputs (the points, their
// normals and the fields, without faces).

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_COMMANDS_H
#define CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_COMMANDS_H

#include "cli_measures.h"
#include "cli_output.h"
#include "command.h"
#include "diffusion_fields.h"
#include "diffusion_setup.h"
#include "point_set_input.h"
#include "point_set_options.h"

#include <CGAL/Heat_diffusion/point_set_anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/point_set_multiscale_features.h>
#include <CGAL/Heat_diffusion/point_set_normal_controlled_coordinates.h>

#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace heat_diffusion_cli {

typedef HD::Point_set_normal_controlled_coordinates<Point_set> Point_set_NCC;
typedef HD::Point_set_anisotropic_heat_diffusion<Point_set> Point_set_diffusion;
typedef std::vector<std::pair<std::string, std::vector<double> > > Fields;

// The library's advice in its messages on point sets, in the tool's terms.
inline std::string in_tool_terms(const std::string& message)
{
  return in_front_end_terms(
      message,
      {{"with the normal_map named parameter", "in the file (PWN, XYZ with 6 numbers a line, or PLY with nx, ny, nz)"},
       {"or a normal_map, may help", "or normals in the file, may help"},
       {"or more neighbours", "or more neighbours (--neighbors)"},
       {"within the neighbor_radius", "within --neighbor-radius"}});
}

// for_input() for the library's point-set calls, with in_tool_terms().
template <typename Function>
auto for_points(const std::string& input, Function&& function) -> decltype(function())
{
  try
  {
    return for_input(input, function);
  }
  catch(const Input_error& e)
  {
    throw Input_error(in_tool_terms(e.what()));
  }
}

// The points of the run's input (stage "read").
inline Point_set read_points(Run& r)
{
  r.timer.start();
  Point_set points;
  read_point_file(r.input, points);
  r.timer.stop("read");
  return points;
}

// Writes the points with `fields` (the first one also as colours, saturated at
// `half_range`, 0: its robust_half_range()) and the normals the NCC were measured
// against (nx, ny, nz), as a binary PLY of vertices without faces.
inline void write_point_fields_ply(Output_files& files, const std::string& path, const Point_set& points,
                                   const Point_set_NCC& ncc, Fields fields, double half_range = 0.)
{
  Mesh vertices;  // the points as the vertices of a mesh without faces, for write_fields_ply()
  vertices.reserve(Mesh::size_type(points.size()), 0, 0);
  for(Point_set::Index i : points)
    vertices.add_vertex(points.point(i));
  const std::size_t n = points.size();
  std::vector<double> normal[3];
  for(int c = 0; c < 3; ++c)
    normal[c].resize(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const Kernel::Vector_3 v = ncc.normal(i);
    for(int c = 0; c < 3; ++c)
      normal[c][i] = v[c];
  }
  fields.emplace_back("nx", std::move(normal[0]));
  fields.emplace_back("ny", std::move(normal[1]));
  fields.emplace_back("nz", std::move(normal[2]));
  write_fields_ply(files, path, vertices, fields, half_range);
}

// The JSON account of the point set: its size, the neighbourhoods (the radius if
// given), where the normals come from, its border points and the orientation conflicts
// of estimated normals.
inline Json_object point_set_json(const Point_set& points, const Neighbourhood_options& nb, const Point_set_NCC& ncc)
{
  std::size_t border = 0;
  for(std::size_t i = 0; i < ncc.number_of_points(); ++i)
    border += ncc.is_border_point(i) ? 1 : 0;
  Json_object o;
  o.integer("points", (long long)points.size()).integer("neighbors", (long long)nb.k_or_default());
  if(nb.radius)
    o.number("neighbor_radius", *nb.radius);
  o.string("normals", points.has_normal_map() ? "file" : "estimated")
      .integer("border_points", (long long)border)
      .integer("orientation_conflicts", (long long)ncc.surface().orientation_conflicts);
  return o;
}

// Says on stderr what the point set is.
inline void report_point_set(const Run& r, const Point_set& points, const Neighbourhood_options& nb)
{
  if(!r.quiet)
    std::cerr << r.input << ": " << points.size() << " points, " << nb.k_or_default() << " neighbours"
              << (nb.radius ? " at most, within " + format_number(*nb.radius) : std::string()) << ", normals "
              << (points.has_normal_map() ? "from the file" : "estimated") << "\n";
}

// ncc on a point set: the NS of each point, written to `output`.
inline void ncc_on_points(Run& r, const std::string& output)
{
  if(r.args.has("--normals"))
    throw Usage_error("--normals is the vertex normal rule of a mesh: a point set's normals are the file's, or "
                      "else estimated");
  const Neighbourhood_options nb = parse_neighbourhood(r.args);
  r.check_outputs({output});
  const Point_set points = read_points(r);
  const std::unique_ptr<Point_set_NCC> ncc = for_points(r.input, [&] {
    return with_neighbourhood(nb, [&](const auto& np) {
      return std::make_unique<Point_set_NCC>(points, nb.k_or_default(), np);
    });
  });
  r.timer.stop("ncc");
  std::vector<double> ns(points.size());
  for(std::size_t i = 0; i < ns.size(); ++i)
    ns[i] = ncc->normal_signature(i);
  Output_files files;
  write_point_fields_ply(files, output, points, *ncc, {{"ns", ns}});
  files.commit();
  r.timer.stop("write");

  const Field_statistics s = statistics(ns);
  report_point_set(r, points, nb);
  if(!r.quiet)
    std::cerr << r.input << ": NS in [" << s.min << ", " << s.max << "], written to " << output << "\n";
  r.summary.string("output", output)
      .string("input_kind", "points")
      .raw("given", json_string_list(nb.given()))
      .object("point_set", point_set_json(points, nb, *ncc))
      .object("ns", s.json());
}

// What diffuse and features run on a point set: its options, its points and their
// diffusion (the diffusion keeps no reference to the points).
struct Point_set_setup
{
  Neighbourhood_options nb;
  Point_set points;
  std::unique_ptr<Point_set_diffusion> diffusion;
};

// The options checked, the outputs checked, the points read (stage "read") and their
// diffusion built (stage "ncc_and_local_operator", with a progress bar).
inline Point_set_setup make_point_set_diffusion(Run& r, const std::vector<std::string>& outputs)
{
  refuse_mesh_only_diffusion_options(r.diffusion);
  Point_set_setup s;
  s.nb = parse_neighbourhood(r.args);
  r.check_outputs(outputs, {r.diffusion.field});
  s.points = read_points(r);
  Progress_bar progress("local kernel", !r.diffusion.quiet);
  s.diffusion = for_points(r.input, [&] {
    return with_neighbourhood(s.nb, [&](const auto& neighbourhood) {
      return with_diffusion_parameters(r.diffusion, progress, [&](const auto& np) {
        return std::make_unique<Point_set_diffusion>(s.points, s.nb.k_or_default(),
                                                     HD::parameters::combine(np, neighbourhood));
      });
    });
  });
  r.timer.stop("ncc_and_local_operator");
  return s;
}

// F^0 of a point set: the NS, or a field file with one number per point.
inline Eigen::VectorXd initial_point_field(const std::string& source, const Point_set_diffusion& diffusion)
{
  const Point_set_NCC& ncc = diffusion.normal_controlled_coordinates();
  const std::size_t n = ncc.number_of_points();
  Eigen::VectorXd f0(static_cast<Eigen::Index>(n));
  const std::vector<double> values = source == "ns" ? std::vector<double>() : read_field(source, n, "points");
  for(std::size_t i = 0; i < n; ++i)
    f0[Eigen::Index(i)] = values.empty() ? ncc.normal_signature(i) : values[i];
  return f0;
}

// F^k for every k of the run's steps, with a progress bar.
inline std::vector<Eigen::VectorXd> diffuse_point_field(const Run& r, const Point_set_diffusion& diffusion,
                                                        const Eigen::VectorXd& f0)
{
  Progress_bar progress("diffusion", !r.diffusion.quiet);
  return for_input(r.input, [&] {
    return diffusion.diffuse(f0, r.diffusion.steps,
                             HD::parameters::progress_callback(std::function<bool(double)>(std::ref(progress))));
  });
}

// The diffusion parameters and the point set of a JSON summary: those of the diffusion
// that ran, and for the spectral kernel its eigenpairs (no coarse level on points).
inline void add_point_set_diffusion_json(Run& r, const Point_set& points, const Neighbourhood_options& nb,
                                         const Point_set_diffusion& diffusion, std::vector<std::string> own_given)
{
  std::vector<std::string> given = nb.given();
  given.insert(given.end(), own_given.begin(), own_given.end());
  r.summary.string("input_kind", "points").integer("points", (long long)points.size());
  add_diffusion_choice_json(r.summary, r.diffusion, given, diffusion.sigma(), diffusion.time(),
                            diffusion.kernel_method(), diffusion.operator_normalization());
  if(diffusion.kernel_method() == HD::Heat_kernel_method::spectral)
    r.summary.integer("eigenpairs", (long long)diffusion.eigenvalues().size())
        .boolean("scale_invariant", r.diffusion.scale_invariant);
  r.summary.object("point_set", point_set_json(points, nb, diffusion.normal_controlled_coordinates()))
      .object("heat_regions", heat_region_json(diffusion.region_statistics()));
}

// diffuse on a point set: F^k of the NS or of a field, written to `outputs` (one per k).
inline void diffuse_on_points(Run& r, const std::string& prefix, const std::vector<std::string>& outputs)
{
  const Diffusion_options& o = r.diffusion;
  const Point_set_setup setup = make_point_set_diffusion(r, outputs);
  const Point_set& points = setup.points;
  const Neighbourhood_options& nb = setup.nb;
  const std::unique_ptr<Point_set_diffusion>& diffusion = setup.diffusion;
  const Eigen::VectorXd f0 = initial_point_field(o.field, *diffusion);
  const std::vector<Eigen::VectorXd> fields = diffuse_point_field(r, *diffusion, f0);
  r.timer.stop("diffusion");

  const double half_range = robust_half_range(std::vector<double>(f0.data(), f0.data() + f0.size()));
  Output_files files;
  Json_object heat, names, minimum, maximum;
  for(std::size_t s = 0; s < o.steps.size(); ++s)
  {
    const std::string k = std::to_string(o.steps[s]);
    write_point_fields_ply(files, outputs[s], points, diffusion->normal_controlled_coordinates(),
                           {{"field", std::vector<double>(fields[s].data(), fields[s].data() + fields[s].size())}},
                           half_range);
    heat.number(k, fields[s].sum());
    minimum.number(k, fields[s].minCoeff());
    maximum.number(k, fields[s].maxCoeff());
    names.string(k, outputs[s]);
  }
  files.commit();
  r.timer.stop("write");

  report_point_set(r, points, nb);
  if(!r.quiet)
  {
    const HD::Heat_region_statistics& regions = diffusion->region_statistics();
    std::cerr << r.input << ": heat regions of " << regions.min_size << ".." << regions.max_size << " points (mean "
              << regions.mean_size << ")\nwritten to " << prefix << "_k*.ply\n";
  }
  r.summary.string("field", o.field).object("outputs", names);
  add_point_set_diffusion_json(r, points, nb, *diffusion, {});
  r.summary.object("total_heat", heat).object("minimum", minimum).object("maximum", maximum);
}

// features on a point set: the features of F^k at each k, written to `outputs`.
inline void features_on_points(Run& r, const std::optional<double>& c, const std::string& prefix,
                               const std::vector<std::string>& outputs)
{
  const Diffusion_options& o = r.diffusion;
  const Point_set_setup setup = make_point_set_diffusion(r, outputs);
  const Point_set& points = setup.points;
  const Neighbourhood_options& nb = setup.nb;
  const std::unique_ptr<Point_set_diffusion>& diffusion = setup.diffusion;
  // The fields F^k once, then the features of each: what detect_point_set_multiscale_features()
  // does, keeping the fields for the outputs.
  const std::vector<Eigen::VectorXd> fields =
      diffuse_point_field(r, *diffusion, initial_point_field(o.field, *diffusion));
  r.timer.stop("diffusion");
  std::vector<HD::Features_at_scale<std::size_t> > features;
  for(const Eigen::VectorXd& field : fields)
    features.push_back(for_input(r.input, [&] {
      return HD::detect_point_set_features(diffusion->normal_controlled_coordinates(), field,
                                           HD::parameters::feature_threshold(c));
    }));
  r.timer.stop("features");

  Output_files files;
  Json_object per_scale, names;
  const auto list = [](const std::vector<std::size_t>& indices) {
    std::string s = "[";
    for(std::size_t i = 0; i < indices.size(); ++i)
      s += (i ? ", " : "") + std::to_string(indices[i]);
    return s + "]";
  };
  for(std::size_t s = 0; s < o.steps.size(); ++s)
  {
    std::vector<double> labels(points.size(), 0.);
    for(std::size_t i : features[s].convex)
      labels[i] = 1.;
    for(std::size_t i : features[s].concave)
      labels[i] = -1.;
    write_point_fields_ply(files, outputs[s], points, diffusion->normal_controlled_coordinates(),
                           {{"feature", labels},
                            {"field", std::vector<double>(fields[s].data(), fields[s].data() + fields[s].size())}},
                           1.);
    Json_object scale;
    scale.raw("convex", list(features[s].convex)).raw("concave", list(features[s].concave));
    per_scale.object(std::to_string(o.steps[s]), scale);
    names.string(std::to_string(o.steps[s]), outputs[s]);
  }
  files.commit();
  r.timer.stop("write");

  report_point_set(r, points, nb);
  if(!r.quiet)
  {
    for(std::size_t s = 0; s < o.steps.size(); ++s)
      std::cerr << "k = " << o.steps[s] << ": " << features[s].convex.size() << " convex, "
                << features[s].concave.size() << " concave features\n";
    std::cerr << "written to " << prefix << "_k*.ply\n";
  }
  r.summary.string("field", o.field).object("outputs", names);
  add_point_set_diffusion_json(r, points, nb, *diffusion,
                               c ? std::vector<std::string>{"feature_threshold"} : std::vector<std::string>{});
  r.summary.number("c", c.value_or(HD::defaults::feature_threshold)).object("features", per_scale);
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_POINT_SET_COMMANDS_H
