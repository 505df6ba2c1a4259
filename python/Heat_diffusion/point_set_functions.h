// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The module's functions on point sets: P (n x 3 numbers, as V) and optional normals
// N (n x 3), made a CGAL::Point_set_3 (with a normal map only if N is given, as the
// tool reads a file with or without normals), given to the package's point-set
// classes. Results are per row of P. Part of cgal_heat_diffusion.cpp's one translation
// unit, whose argument helpers (vertex_array(), field_array(), step_list(), ...) it uses.

#ifndef CGAL_HEAT_DIFFUSION_PYTHON_POINT_SET_FUNCTIONS_H
#define CGAL_HEAT_DIFFUSION_PYTHON_POINT_SET_FUNCTIONS_H

#include <CGAL/Point_set_3.h>

#include <CGAL/Heat_diffusion/parameter_defaults.h>
#include <CGAL/Heat_diffusion/point_set_anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/point_set_decomposition.h>
#include <CGAL/Heat_diffusion/point_set_denoising.h>
#include <CGAL/Heat_diffusion/point_set_multiscale_features.h>
#include <CGAL/Heat_diffusion/point_set_normal_controlled_coordinates.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

// (in the anonymous namespace of the helpers it uses)
namespace {
namespace point_set_binding {

typedef CGAL::Point_set_3<Point, Kernel::Vector_3> Point_set;
typedef HD::Point_set_normal_controlled_coordinates<Point_set> Point_set_NCC;
typedef HD::Point_set_anisotropic_heat_diffusion<Point_set> Point_set_diffusion;

// P, and N if it is not None, as a point set; N is checked as P is (shape, numbers,
// finite values), with its own name. A null normal is the package's to refuse.
inline std::unique_ptr<Point_set> make_point_set(py::handle P_object, py::handle N_object, const std::string& function)
{
  const py::array_t<double, py::array::c_style> P = vertex_array(P_object, function, "P");
  const std::size_t n = std::size_t(P.shape(0));
  const double* p = P.data();
  auto points = std::make_unique<Point_set>();
  if(N_object.is_none())
  {
    for(std::size_t i = 0; i < n; ++i)
      points->insert(Point(p[3 * i], p[3 * i + 1], p[3 * i + 2]));
    return points;
  }
  const py::array N_array = numeric_array(N_object, function, "N", "fiu");
  if(N_array.ndim() != 2 || std::size_t(N_array.shape(0)) != n || N_array.shape(1) != 3)
    invalid(function, "N must have shape (" + std::to_string(n) + ", 3) (one normal per row of P), not " +
                          shape_text(N_array));
  const py::array_t<double, py::array::c_style> N = float64_array(N_array);
  const double* q = N.data();
  points->add_normal_map();
  for(std::size_t i = 0; i < n; ++i)
  {
    if(!std::isfinite(q[3 * i]) || !std::isfinite(q[3 * i + 1]) || !std::isfinite(q[3 * i + 2]))
    {
      std::ostringstream os;
      os << "N[" << i << "] is (" << q[3 * i] << ", " << q[3 * i + 1] << ", " << q[3 * i + 2]
         << "), not a finite normal";
      invalid(function, os.str());
    }
    points->insert(Point(p[3 * i], p[3 * i + 1], p[3 * i + 2]),
                   Kernel::Vector_3(q[3 * i], q[3 * i + 1], q[3 * i + 2]));
  }
  return points;
}

// The package's advice in its messages on point sets, in the module's terms.
// (in_front_end_terms() is the tool's, from cli_errors.h, which mesh_repair.h includes)
inline std::string in_module_terms(const std::string& message)
{
  return heat_diffusion_cli::in_front_end_terms(message, {{"with the normal_map named parameter", "as N (n x 3)"},
                                                          {"or a normal_map, may help", "or normals N, may help"},
                                                          {"or more neighbours", "or more neighbours (neighbors=)"}});
}

// neighbors (None: the package's defaults::number_of_neighbors) and neighbor_radius
// (None: the k nearest); their values are the package's to check.
struct Neighbourhood
{
  unsigned int k = HD::defaults::number_of_neighbors;
  std::optional<double> radius;
};

inline Neighbourhood neighbourhood(const py::object& neighbors, const py::object& radius, const std::string& function)
{
  Neighbourhood nb;
  if(!neighbors.is_none())
    nb.k = unsigned(bounded_whole_number(neighbors, function, "neighbors", 0, (std::numeric_limits<unsigned>::max)()));
  nb.radius = optional_number(radius, function, "neighbor_radius");
  return nb;
}

// Calls `f` with the named parameters of the neighbourhood added to `np`.
template <typename NamedParameters, typename Function>
auto with_neighbourhood(const Neighbourhood& nb, const NamedParameters& np, Function&& f)
{
  if(nb.radius)
    return f(HD::parameters::combine(np, CGAL::parameters::neighbor_radius(*nb.radius)));
  return f(np);
}

inline py::array_t<std::int64_t> index_array(const std::vector<std::size_t>& indices)
{
  py::array_t<std::int64_t> a(static_cast<py::ssize_t>(indices.size()));
  std::copy(indices.begin(), indices.end(), a.mutable_data());
  return a;
}

inline py::array_t<double> vector_array(const Eigen::VectorXd& v)
{
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.data(), v.data() + v.size(), a.mutable_data());
  return a;
}

// The positions (n, 3) of the points, or the normals of their normal map, in their order.
inline py::array_t<double> rows_array(const Point_set& points, bool normals)
{
  py::array_t<double> a({py::ssize_t(points.size()), py::ssize_t(3)});
  double* out = a.mutable_data();
  std::size_t i = 0;
  for(Point_set::Index index : points)
  {
    for(int c = 0; c < 3; ++c)
      out[3 * i + std::size_t(c)] = normals ? points.normal(index)[c] : points.point(index)[c];
    ++i;
  }
  return a;
}

// The NCC of a point set, without the GIL.
inline std::unique_ptr<Point_set_NCC> make_ncc(const Point_set& points, const Neighbourhood& nb)
{
  return without_gil([&] {
    return nb.radius ? std::make_unique<Point_set_NCC>(points, nb.k, CGAL::parameters::neighbor_radius(*nb.radius))
                     : std::make_unique<Point_set_NCC>(points, nb.k);
  });
}

inline py::array_t<double> normal_signature(py::object P, py::object N, py::object neighbors, py::object radius)
{
  const std::string function = "point_set_normal_signature";
  const Neighbourhood nb = neighbourhood(neighbors, radius, function);
  const auto points = make_point_set(P, N, function);
  const auto ncc = make_ncc(*points, nb);
  Eigen::VectorXd ns(static_cast<Eigen::Index>(ncc->number_of_points()));
  for(std::size_t i = 0; i < ncc->number_of_points(); ++i)
    ns[Eigen::Index(i)] = ncc->normal_signature(i);
  return vector_array(ns);
}

// The NCC (n, 3) and the normals they were measured against (n, 3).
inline py::tuple normal_controlled_coordinates(py::object P, py::object N, py::object neighbors, py::object radius)
{
  const std::string function = "point_set_normal_controlled_coordinates";
  const Neighbourhood nb = neighbourhood(neighbors, radius, function);
  const auto points = make_point_set(P, N, function);
  const auto ncc = make_ncc(*points, nb);
  const std::size_t n = ncc->number_of_points();
  py::array_t<double> coordinates({py::ssize_t(n), py::ssize_t(3)}), normals({py::ssize_t(n), py::ssize_t(3)});
  double* c = coordinates.mutable_data();
  double* m = normals.mutable_data();
  for(std::size_t i = 0; i < n; ++i)
    for(int a = 0; a < 3; ++a)
    {
      c[3 * i + std::size_t(a)] = ncc->ncc(i)[a];
      m[3 * i + std::size_t(a)] = ncc->normal(i)[a];
    }
  return py::make_tuple(coordinates, normals);
}

inline py::list features_list(const std::vector<HD::Features_at_scale<std::size_t> >& features)
{
  py::list result;
  for(const auto& f : features)
  {
    py::dict d;
    d["steps"] = f.number_of_steps;
    d["convex"] = index_array(f.convex);
    d["concave"] = index_array(f.concave);
    result.append(d);
  }
  return result;
}

// The Python class PointSetHeatDiffusion: the point set and its operator A_t.
class Heat_diffusion
{
public:
  Heat_diffusion(py::object P, py::object N, py::object neighbors, py::object radius, py::object sigma,
                 py::object time, py::object kernel, py::object kernel_tolerance, py::object m,
                 py::object scale_invariant, py::object normalization, py::object progress,
                 const std::string& function = "PointSetHeatDiffusion")
  {
    const Neighbourhood nb = neighbourhood(neighbors, radius, function);
    // (no coarse level: the spectral kernel of a point set has the points' own eigenpairs)
    Diffusion_options o =
        diffusion_options(function, sigma, time, kernel, m, py::none(), scale_invariant, kernel_tolerance);
    if(!normalization.is_none())
    {
      const std::string name = py::isinstance<py::str>(normalization) ? normalization.cast<std::string>() : "";
      if(name != "balanced" && name != "columns")
        invalid(function, "normalization must be 'balanced', 'columns' or None, not " +
                              (name.empty() ? type_name(normalization) : "'" + name + "'"));
      o.normalization = name == "balanced" ? HD::Operator_normalization::balanced : HD::Operator_normalization::columns;
    }
    points_ = make_point_set(P, N, function);
    Python_progress guard(std::move(progress));
    diffusion_ = guard.run([&] {
      return with_neighbourhood(nb, diffusion_parameters(o, guard.callback()), [&](const auto& np) {
        return std::make_unique<Point_set_diffusion>(*points_, nb.k, np);
      });
    });
  }

  std::size_t number_of_points() const { return diffusion_->number_of_points(); }
  double time() const { return diffusion_->time(); }
  std::string kernel() const
  {
    return diffusion_->kernel_method() == HD::Heat_kernel_method::local ? "local" : "spectral";
  }
  std::string normalization() const
  {
    return diffusion_->operator_normalization() == HD::Operator_normalization::balanced ? "balanced" : "columns";
  }

  py::array_t<double> normal_signature() const { return vector_array(ns_vector()); }

  py::array_t<double> normals() const
  {
    const Point_set_NCC& ncc = diffusion_->normal_controlled_coordinates();
    py::array_t<double> result({py::ssize_t(number_of_points()), py::ssize_t(3)});
    double* out = result.mutable_data();
    for(std::size_t i = 0; i < number_of_points(); ++i)
      for(int a = 0; a < 3; ++a)
        out[3 * i + std::size_t(a)] = ncc.normal(i)[a];
    return result;
  }

  py::object diffuse(py::object field, py::object steps) const
  {
    const std::string function = "PointSetHeatDiffusion.diffuse";
    bool single = false;
    const std::vector<std::size_t> ks = steps.is_none() ? std::vector<std::size_t>(1, HD::defaults::number_of_steps)
                                                        : step_list(steps, function, single, {});
    single = single || steps.is_none();
    const Eigen::VectorXd f0 = field_vector(field, function);
    const std::vector<Eigen::VectorXd> fields =
        interruptible([&](const auto& progress) { return diffusion_->diffuse(f0, ks, progress); });
    if(single)
      return vector_array(fields.front());
    const std::size_t n = number_of_points();
    py::array_t<double> result({py::ssize_t(ks.size()), py::ssize_t(n)});
    for(std::size_t s = 0; s < ks.size(); ++s)
      std::copy(fields[s].data(), fields[s].data() + n, result.mutable_data() + s * n);
    return result;
  }

  // A_t as scipy.sparse.csc_matrix, rows and columns in the order of the points.
  py::object operator_matrix() const
  {
    const Eigen::SparseMatrix<double>& A = without_gil([&]() -> const Eigen::SparseMatrix<double>& {
      return diffusion_->operator_matrix();
    });
    const std::size_t n = number_of_points(), nnz = std::size_t(A.nonZeros());
    py::array_t<double> data(static_cast<py::ssize_t>(nnz));
    py::array_t<std::int64_t> indices(static_cast<py::ssize_t>(nnz)), indptr(py::ssize_t(n + 1));
    double* d = data.mutable_data();
    std::int64_t* r = indices.mutable_data();
    std::int64_t* p = indptr.mutable_data();
    std::size_t k = 0;
    p[0] = 0;
    for(Eigen::Index j = 0; j < A.outerSize(); ++j)
    {
      for(Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it, ++k)
      {
        r[k] = std::int64_t(it.row());
        d[k] = it.value();
      }
      p[j + 1] = std::int64_t(k);
    }
    py::object csc = py::module_::import("scipy.sparse").attr("csc_matrix");
    py::object matrix = csc(py::make_tuple(data, indices, indptr), py::arg("shape") = py::make_tuple(n, n));
    matrix.attr("sort_indices")();
    return matrix;
  }

  py::dict region_statistics() const { return region_statistics_dict(diffusion_->region_statistics()); }

  py::list features(py::object field, py::object steps, py::object feature_threshold) const
  {
    return features_as("PointSetHeatDiffusion.features", field, steps, feature_threshold);
  }

  py::list features_as(const std::string& function, py::object field, py::object steps,
                       py::object feature_threshold_object) const
  {
    bool single = false;
    const std::vector<std::size_t> ks = step_list(steps, function, single, feature_scales());
    const std::optional<double> c = optional_number(feature_threshold_object, function, "feature_threshold");
    const Eigen::VectorXd f0 = field.is_none() ? ns_vector() : field_vector(field, function);
    return features_list(interruptible([&](const auto& progress) {
      return HD::detect_point_set_multiscale_features(
          *diffusion_, f0, ks, HD::parameters::combine(progress, HD::parameters::feature_threshold(c)));
    }));
  }

  py::tuple decompose(py::object field, py::object levels, py::object steps_per_level) const
  {
    return decompose_as("PointSetHeatDiffusion.decompose", field, levels, steps_per_level);
  }

  // The bands (levels, n) and the residual (n,) of decompose_point_set_field().
  py::tuple decompose_as(const std::string& function, py::object field, py::object levels_object,
                         py::object steps_object) const
  {
    const std::size_t levels = checked_levels(levels_object, function);
    const std::optional<long long> steps_per_level = optional_whole_number(steps_object, function, "steps_per_level");
    const Eigen::VectorXd f0 = field.is_none() ? ns_vector() : field_vector(field, function);
    const std::vector<Eigen::VectorXd> bands = interruptible([&](const auto& progress) {
      // None: decompose_point_set_field()'s own default.
      return HD::decompose_point_set_field(
          *diffusion_, f0, levels, HD::parameters::combine(progress, HD::parameters::steps_per_level(steps_per_level)));
    });
    const std::size_t n = number_of_points();
    py::array_t<double> band_array({py::ssize_t(levels), py::ssize_t(n)});
    for(std::size_t j = 0; j < levels; ++j)
      std::copy(bands[j].data(), bands[j].data() + n, band_array.mutable_data() + j * n);
    return py::make_tuple(band_array, vector_array(bands.back()));
  }

private:
  Eigen::VectorXd ns_vector() const
  {
    const Point_set_NCC& ncc = diffusion_->normal_controlled_coordinates();
    Eigen::VectorXd s(static_cast<Eigen::Index>(number_of_points()));
    for(std::size_t i = 0; i < number_of_points(); ++i)
      s[Eigen::Index(i)] = ncc.normal_signature(i);
    return s;
  }

  Eigen::VectorXd field_vector(py::handle field, const std::string& function) const
  {
    const std::vector<double> values = field_array(field, number_of_points(), function, "field", "point");
    return Eigen::Map<const Eigen::VectorXd>(values.data(), Eigen::Index(values.size()));
  }

  std::unique_ptr<Point_set> points_;  // must outlive diffusion_, which refers to it
  std::unique_ptr<Point_set_diffusion> diffusion_;
};

inline py::list multiscale_features(py::object P, py::object N, py::object field, py::object steps,
                                    py::object feature_threshold, py::object neighbors, py::object radius,
                                    py::object sigma, py::object time, py::object kernel, py::object kernel_tolerance,
                                    py::object m, py::object scale_invariant, py::object progress)
{
  const std::string function = "point_set_multiscale_features";
  bool single = false;
  step_list(steps, function, single, feature_scales());  // before the diffusion is built
  const Heat_diffusion diffusion(P, N, neighbors, radius, sigma, time, kernel, kernel_tolerance, m, scale_invariant,
                                 py::none(), progress, function);
  return diffusion.features_as(function, field, steps, feature_threshold);
}

inline py::tuple decompose(py::object P, py::object N, py::object field, py::object levels,
                           py::object steps_per_level, py::object neighbors, py::object radius, py::object sigma,
                           py::object time, py::object kernel, py::object kernel_tolerance, py::object m,
                           py::object scale_invariant, py::object progress)
{
  const std::string function = "point_set_decompose";
  checked_levels(levels, function);  // before the diffusion is built
  const Heat_diffusion diffusion(P, N, neighbors, radius, sigma, time, kernel, kernel_tolerance, m, scale_invariant,
                                 py::none(), progress, function);
  return diffusion.decompose_as(function, field, levels, steps_per_level);
}

// The new positions (n, 3) of filter_point_set_shape().
inline py::array_t<double> filter_shape(py::object P, py::object N, py::object weights_object,
                                        py::object steps_object, py::object anchor_object, py::object neighbors,
                                        py::object radius, py::object sigma, py::object time, py::object kernel,
                                        py::object kernel_tolerance, py::object m, py::object scale_invariant,
                                        py::object progress)
{
  const std::string function = "point_set_filter_shape";
  const Neighbourhood nb = neighbourhood(neighbors, radius, function);
  const Diffusion_options o =
      diffusion_options(function, sigma, time, kernel, m, py::none(), scale_invariant, kernel_tolerance);
  const std::vector<double> weights = checked_shape_weights(weights_object, function);
  const std::optional<long long> steps_per_level = optional_whole_number(steps_object, function, "steps_per_level");
  const std::optional<double> anchor_weight = optional_number(anchor_object, function, "anchor_weight");
  const auto points = make_point_set(P, N, function);
  Python_progress guard(std::move(progress));
  // None: filter_point_set_shape()'s own defaults.
  const auto np = HD::parameters::combine(diffusion_parameters(o, guard.callback()),
                                          HD::parameters::steps_per_level(steps_per_level),
                                          HD::parameters::anchor_weight(anchor_weight));
  guard.run([&] {
    with_neighbourhood(nb, np, [&](const auto& all) { HD::filter_point_set_shape(*points, nb.k, weights, all); });
  });
  return rows_array(*points, false);
}

// (positions (n, 3), normals (n, 3) or None) of denoise_point_set(): the filtered normals
// where N is given, None where the package estimated them.
inline py::tuple denoise(py::object P, py::object N, py::object neighbors, py::object radius,
                         py::object iterations_object, py::object steps_object, py::object normal_sigma,
                         py::object displacement_object, py::object progress)
{
  const std::string function = "point_set_denoise";
  Neighbourhood nb = neighbourhood(neighbors, radius, function);
  if(neighbors.is_none())
    nb.k = HD::defaults::point_set_denoising::number_of_neighbors;
  const Denoising_options options = denoising_options(function, iterations_object, steps_object, normal_sigma,
                                                      displacement_object);
  const auto points = make_point_set(P, N, function);
  Python_progress guard(std::move(progress));
  // None: denoise_point_set()'s own defaults.
  const auto np = HD::parameters::combine(
      CGAL::parameters::number_of_iterations(options.iterations), HD::parameters::number_of_steps(options.steps),
      HD::parameters::normal_sigma(options.normal_sigma),
      HD::parameters::displacement_limit(options.displacement_limit),
      HD::parameters::progress_callback(guard.callback()));
  guard.run([&] {
    with_neighbourhood(nb, np, [&](const auto& all) { HD::denoise_point_set(*points, nb.k, all); });
  });
  return py::make_tuple(rows_array(*points, false),
                        points->has_normal_map() ? py::object(rows_array(*points, true)) : py::object(py::none()));
}

// The point-set functions and PointSetHeatDiffusion in `module`.
inline void add_point_set_functions(py::module_& module)
{
  namespace D = HD::defaults;
  const std::string diffusion_doc =
      "Every keyword left out or None takes the package's default: sigma: edge-weight width of eq. 10\n"
      "(default " + number_text(D::sigma) + "); time: t of one step, on the surface rescaled to area = number of "
      "points (default " + number_text(D::time) + ");\nkernel: 'local', 'spectral' or None (the package's choice: spectral if m or scale_invariant is\n"
      "given); kernel_tolerance: the local kernel's accuracy; m, scale_invariant: the spectral kernel's\n"
      "eigenpairs, as for HeatDiffusion (no coarse level on points); "
      "normalization (PointSetHeatDiffusion): 'balanced' (the\ndefault: A_t doubly stochastic) or 'columns' (the "
      "paper's); progress: None or a callable f(fraction), as\nfor HeatDiffusion; Ctrl-C cancels the construction "
      "(KeyboardInterrupt).\n";
  const std::string neighbourhood_doc =
      "P: (n, 3) points (any array-like of numbers, as V); N: None (normals estimated by CGAL's\n"
      "jet_estimate_normals() and oriented by mst_orient_normals()) or (n, 3) oriented normals.\n"
      "neighbors: the neighbour count k of each point's fan, the Delaunay triangulation of its neighbours\n"
      "on its tangent plane (default " + std::to_string(HD::defaults::number_of_neighbors) +
      "; with neighbor_radius, at most k of those within it, 0: all); neighbor_radius: None\n"
      "(the k nearest) or a distance in the units of P. Results are per row of P. Duplicate points, fewer\n"
      "than k + 1 points, degenerate neighbourhoods, null normals and normals that cannot be oriented raise\n"
      "ValueError naming the point.\n";
  py::class_<Heat_diffusion>(module, "PointSetHeatDiffusion",
                             ("The operator A_t of the point set P (normals N), built once, applied many times,\n"
                              "with the local or the spectral kernel.\n" + neighbourhood_doc + diffusion_doc)
                                 .c_str())
      .def(py::init<py::object, py::object, py::object, py::object, py::object, py::object, py::object, py::object,
                    py::object, py::object, py::object, py::object>(),
           py::arg("P"), py::arg("N") = py::none(), py::kw_only(), py::arg("neighbors") = py::none(),
           py::arg("neighbor_radius") = py::none(), py::arg("sigma") = py::none(), py::arg("time") = py::none(),
           py::arg("kernel") = py::none(), py::arg("kernel_tolerance") = py::none(), py::arg("m") = py::none(),
           py::arg("scale_invariant") = py::none(), py::arg("normalization") = py::none(),
           py::arg("progress") = py::none())
      .def("diffuse", &Heat_diffusion::diffuse, py::arg("field"), py::arg("steps") = py::none(),
           "F^k = A_t^k F^0, as HeatDiffusion.diffuse, per point.")
      .def("operator_matrix", &Heat_diffusion::operator_matrix,
           "A_t as a scipy.sparse.csc_matrix, rows and columns in the order of the points.")
      .def("region_statistics", &Heat_diffusion::region_statistics,
           "Sizes of the heat regions: min_size, mean_size, max_size, collapsed_regions, capped_regions.")
      .def("normal_signature", &Heat_diffusion::normal_signature, "The Normal Signature of the points, (n,).")
      .def("normals", &Heat_diffusion::normals, "The unit normals the NCC were measured against, (n, 3).")
      .def("features", &Heat_diffusion::features, py::arg("field") = py::none(), py::arg("steps") = py::none(),
           py::kw_only(), py::arg("feature_threshold") = py::none(),
           "Features of the diffused field (default: the NS), as HeatDiffusion.features, with point indices.")
      .def("decompose", &Heat_diffusion::decompose, py::arg("field") = py::none(), py::arg("levels") = py::none(),
           py::kw_only(), py::arg("steps_per_level") = py::none(),
           "(bands (levels, n), residual (n,)) of the field (default: the NS), as HeatDiffusion.decompose.")
      .def_property_readonly("number_of_points", &Heat_diffusion::number_of_points)
      .def_property_readonly("time", &Heat_diffusion::time)
      .def_property_readonly("kernel", &Heat_diffusion::kernel, "'local' or 'spectral'")
      .def_property_readonly("normalization", &Heat_diffusion::normalization, "'balanced' or 'columns'");
  module.def("point_set_normal_signature", &normal_signature, py::arg("P"), py::arg("N") = py::none(), py::kw_only(),
             py::arg("neighbors") = py::none(), py::arg("neighbor_radius") = py::none(),
             ("The Normal Signature (n,) of the point set P: > 0 convex, < 0 concave, 0 flat.\n" + neighbourhood_doc)
                 .c_str());
  module.def("point_set_normal_controlled_coordinates", &normal_controlled_coordinates, py::arg("P"),
             py::arg("N") = py::none(), py::kw_only(), py::arg("neighbors") = py::none(),
             py::arg("neighbor_radius") = py::none(),
             ("(NCC, normals): the Normal-Controlled Coordinates (n, 3) of the point set P and the unit normals\n"
              "(n, 3) they are parallel to (N normalised, or estimated).\n" + neighbourhood_doc)
                 .c_str());
  module.def("point_set_multiscale_features", &multiscale_features, py::arg("P"), py::arg("N") = py::none(),
             py::arg("field") = py::none(), py::arg("steps") = py::none(), py::kw_only(),
             py::arg("feature_threshold") = py::none(), py::arg("neighbors") = py::none(),
             py::arg("neighbor_radius") = py::none(), py::arg("sigma") = py::none(), py::arg("time") = py::none(),
             py::arg("kernel") = py::none(), py::arg("kernel_tolerance") = py::none(), py::arg("m") = py::none(),
             py::arg("scale_invariant") = py::none(), py::arg("progress") = py::none(),
             ("Features of the diffused field (default: the NS) of the point set P, as\n"
              "PointSetHeatDiffusion.features.\n" + neighbourhood_doc + diffusion_doc)
                 .c_str());
  module.def("point_set_decompose", &decompose, py::arg("P"), py::arg("N") = py::none(),
             py::arg("field") = py::none(), py::arg("levels") = py::none(), py::kw_only(),
             py::arg("steps_per_level") = py::none(), py::arg("neighbors") = py::none(),
             py::arg("neighbor_radius") = py::none(), py::arg("sigma") = py::none(), py::arg("time") = py::none(),
             py::arg("kernel") = py::none(), py::arg("kernel_tolerance") = py::none(), py::arg("m") = py::none(),
             py::arg("scale_invariant") = py::none(), py::arg("progress") = py::none(),
             ("(bands (levels, n), residual (n,)) of the field (default: the NS) of the point set P, as\n"
              "decompose (decompose_point_set_field()); synthesize() re-weights them.\n" + neighbourhood_doc +
              diffusion_doc)
                 .c_str());
  module.def("point_set_filter_shape", &filter_shape, py::arg("P"), py::arg("N") = py::none(), py::kw_only(),
             py::arg("weights"), py::arg("steps_per_level") = py::none(), py::arg("anchor_weight") = py::none(),
             py::arg("neighbors") = py::none(), py::arg("neighbor_radius") = py::none(),
             py::arg("sigma") = py::none(), py::arg("time") = py::none(), py::arg("kernel") = py::none(),
             py::arg("kernel_tolerance") = py::none(), py::arg("m") = py::none(),
             py::arg("scale_invariant") = py::none(), py::arg("progress") = py::none(),
             ("New positions (n, 3) of the point set P, moved along their normals (filter_point_set_shape()):\n"
              "the NS bands reweighted by weights (one per band, finest first; the paper's smoothing filter\n"
              "is [0, 0, 1], its enhancement filter [1, 3, 3]), as filter_shape; steps_per_level (default " +
              std::to_string(D::shape_filter_steps_per_level) + ") and anchor_weight (default " +
              number_text(D::shape_filter_anchor_weight) + ").\n" + neighbourhood_doc + diffusion_doc)
                 .c_str());
  module.def("point_set_denoise", &denoise, py::arg("P"), py::arg("N") = py::none(), py::kw_only(),
             py::arg("neighbors") = py::none(), py::arg("neighbor_radius") = py::none(),
             py::arg("number_of_iterations") = py::none(), py::arg("number_of_steps") = py::none(),
             py::arg("normal_sigma") = py::none(), py::arg("displacement_limit") = py::none(),
             py::arg("progress") = py::none(),
             ("(positions (n, 3), normals (n, 3) or None) of the point set P denoised by denoise_point_set():\n"
              "the normals filtered on the neighbours, each point moved along its own normal only, until\n"
              "the points have moved by the estimated noise level. normals: the filtered unit normals where N\n"
              "is given, None where they were estimated. neighbors: default " +
              std::to_string(D::point_set_denoising::number_of_neighbors) +
              " (the planes fitted to the neighbours\naverage over a few noise deviations); every other keyword "
              "None is denoise_point_set()'s default:\nat most " + std::to_string(D::point_set_denoising::iterations) +
              " iterations, " + std::to_string(D::point_set_denoising::number_of_steps) +
              " filtering step each, the width of the normal weights from the noise,\ndisplacement_limit " +
              number_text(D::point_set_denoising::displacement_limit) + ". P, N, neighbor_radius, progress and the "
              "errors as for\npoint_set_normal_signature.\n")
                 .c_str());
}

} // namespace point_set_binding
} // namespace

#endif // CGAL_HEAT_DIFFUSION_PYTHON_POINT_SET_FUNCTIONS_H
