// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The library as a user calls it, for the parity test of the front ends
// (python/test_parity.py): each subcommand of the tool as the one library call it stands
// for, with no named parameter, or with exactly one, given on the command line.
//
//   parity_reference COMMAND MESH OUTPUT [PARAMETER VALUE]
//
// reads MESH with CGAL::IO::read_polygon_mesh() and writes the result to OUTPUT as
// little-endian doubles, in the order of MESH's vertices:
//   ncc        the Normal Signature (n)
//   coordinates  the Normal-Controlled Coordinates (n x 3)
//   reconstruct  the vertices of reconstruct_from_normal_signature() from the mesh's own NS (n x 3)
//   diffuse    F^k of the NS for each k of the feature scales (or of PARAMETER steps,
//              "3,7"), one row of n per k
//   features   per scale: k, the number of convex features, their indices, the number of
//              concave ones, their indices
//   hks        the heat kernel signature (n), then 1 at its maxima, 0 elsewhere (n)
//   decompose  the detail bands, then the residual (levels + 1 rows of n)
//   enhance    the vertices of filter_shape() with the enhancement weights (n x 3)
//   denoise    the vertices of denoise_mesh() (n x 3)
// and on a point set (MESH is then a file of points, read with CGAL::IO::read_point_set(),
// normals included where it has them), with the neighbour count k of
// defaults::number_of_neighbors unless the parameter "k" is given:
//   points_ncc          the Normal Signature (n)
//   points_coordinates  the NCC (n x 3), then the normals they were measured against (n x 3)
//   points_diffuse      F^k of the NS for each k of the feature scales (or of "steps")
//   points_features     as features
//   points_decompose    as decompose (decompose_point_set_field())
//   points_enhance      the points of filter_point_set_shape() with the enhancement weights (n x 3)
//   points_denoise      the points of denoise_point_set() (n x 3), then, where the file has
//                       normals, the filtered normals (n x 3); k is
//                       defaults::point_set_denoising::number_of_neighbors unless given
// Each subcommand takes the parameters that its tool command passes on; the steps lists,
// the levels and the weights, which the library takes as arguments, are the front ends'
// defaults (defaults::feature_scales, detail_levels, enhancement_weights) unless given.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/decomposition.h>
#include <CGAL/Heat_diffusion/denoising.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/parameter_defaults.h>
#include <CGAL/Heat_diffusion/point_set_anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/point_set_decomposition.h>
#include <CGAL/Heat_diffusion/point_set_denoising.h>
#include <CGAL/Heat_diffusion/point_set_multiscale_features.h>
#include <CGAL/Heat_diffusion/point_set_normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/reconstruction.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace HD = CGAL::Heat_diffusion;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef CGAL::Point_set_3<Kernel::Point_3, Kernel::Vector_3> Point_set;

namespace {

struct Output
{
  std::vector<double> values;
  void add(double x) { values.push_back(x); }
  void write(const std::string& path) const
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(double)));
    if(!out)
      throw std::runtime_error("cannot write " + path);
  }
};

std::vector<std::size_t> numbers(const std::string& text)
{
  std::vector<std::size_t> list;
  std::stringstream ss(text);
  std::string item;
  while(std::getline(ss, item, ','))
    list.push_back(std::size_t(std::stoul(item)));
  return list;
}

std::vector<double> normal_signature(const Mesh& mesh)
{
  std::vector<double> ns(mesh.number_of_vertices());
  const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
  for(Vertex v : mesh.vertices())
    ns[v.idx()] = ncc.normal_signature(v);
  return ns;
}

// A field of `mesh` by vertex, from a vector in the order of its vertices.
Mesh::Property_map<Vertex, double> field_map(Mesh& mesh, const std::string& name, const std::vector<double>& values)
{
  auto map = mesh.add_property_map<Vertex, double>(name, 0.).first;
  for(Vertex v : mesh.vertices())
    map[v] = values[v.idx()];
  return map;
}

template <typename NP>
void diffuse(Mesh& mesh, const std::vector<std::size_t>& steps, const NP& np, Output& out)
{
  const HD::Anisotropic_heat_diffusion<Mesh> diffusion(mesh, np);
  const std::vector<double> ns = normal_signature(mesh);
  Eigen::VectorXd f0(Eigen::Index(ns.size()));
  for(Vertex v : mesh.vertices())
    f0[Eigen::Index(diffusion.vertex_index(v))] = ns[v.idx()];
  for(const Eigen::VectorXd& f : diffusion.diffuse(f0, steps))
    for(Vertex v : mesh.vertices())
      out.add(f[Eigen::Index(diffusion.vertex_index(v))]);
}

template <typename DiffusionNP, typename FeatureNP>
void features(Mesh& mesh, const std::vector<std::size_t>& steps, const DiffusionNP& np, const FeatureNP& feature_np,
              Output& out)
{
  const HD::Anisotropic_heat_diffusion<Mesh> diffusion(mesh, np);
  const auto ns = field_map(mesh, "v:reference_ns", normal_signature(mesh));
  for(const auto& scale : HD::detect_multiscale_features(diffusion, ns, steps, feature_np))
  {
    out.add(double(scale.number_of_steps));
    for(const auto* list : {&scale.convex, &scale.concave})
    {
      std::vector<std::size_t> indices;
      for(Vertex v : *list)
        indices.push_back(v.idx());
      std::sort(indices.begin(), indices.end());
      out.add(double(indices.size()));
      for(std::size_t i : indices)
        out.add(double(i));
    }
  }
}

template <typename KernelNP, typename FeatureNP>
void hks(Mesh& mesh, double t, const KernelNP& np, const FeatureNP& feature_np, Output& out)
{
  const HD::Edge_weighted_heat_kernel<Mesh> kernel(mesh, np);
  std::vector<double> values(mesh.number_of_vertices()), maximum(mesh.number_of_vertices(), 0.);
  for(Vertex v : mesh.vertices())
    values[v.idx()] = kernel.heat_kernel_signature(v, t);
  const auto map = field_map(mesh, "v:reference_hks", values);
  std::vector<Vertex> maxima, minima;
  HD::detect_multiscale_features(mesh, map, std::back_inserter(maxima), std::back_inserter(minima), feature_np);
  for(Vertex v : maxima)
    maximum[v.idx()] = 1.;
  out.values = values;
  out.values.insert(out.values.end(), maximum.begin(), maximum.end());
}

template <typename DiffusionNP, typename LevelNP>
void decompose_with(Mesh& mesh, std::size_t levels, const DiffusionNP& np, const LevelNP& level_np, Output& out)
{
  const HD::Anisotropic_heat_diffusion<Mesh> diffusion(mesh, np);
  const auto ns = field_map(mesh, "v:reference_ns", normal_signature(mesh));
  std::vector<Mesh::Property_map<Vertex, double> > bands;
  for(std::size_t j = 0; j < levels; ++j)
    bands.push_back(mesh.add_property_map<Vertex, double>("v:band" + std::to_string(j), 0.).first);
  auto residual = mesh.add_property_map<Vertex, double>("v:residual", 0.).first;
  HD::decompose_field(diffusion, ns, bands, residual, level_np);
  bands.push_back(residual);
  for(const auto& band : bands)
    for(Vertex v : mesh.vertices())
      out.add(band[v]);
}

void points(const Mesh& mesh, Output& out)
{
  for(Vertex v : mesh.vertices())
    for(int c = 0; c < 3; ++c)
      out.add(mesh.point(v)[c]);
}

template <typename NP>
void enhance(Mesh& mesh, const std::vector<double>& weights, const NP& np, Output& out)
{
  HD::filter_shape(mesh, weights, np);
  points(mesh, out);
}

template <typename NP>
void denoise(Mesh& mesh, const NP& np, Output& out)
{
  HD::denoise_mesh(mesh, np);
  points(mesh, out);
}

HD::Heat_kernel_method kernel_method(const std::string& name)
{
  if(name == "local")
    return HD::Heat_kernel_method::local;
  if(name == "spectral")
    return HD::Heat_kernel_method::spectral;
  if(name == "automatic")
    return HD::Heat_kernel_method::automatic;
  throw std::invalid_argument("unknown kernel " + name);
}

HD::Operator_normalization normalization(const std::string& name)
{
  return name == "columns" ? HD::Operator_normalization::columns : HD::Operator_normalization::balanced;
}

// Calls `f` with no named parameter, or with the one named `parameter`, among those of
// the diffusion (Anisotropic_heat_diffusion, Edge_weighted_heat_kernel).
template <typename Function>
bool with_diffusion_parameter(const std::string& parameter, const std::string& value, Function&& f)
{
  namespace P = HD::parameters;
  if(parameter.empty())
    f(P::default_values());
  else if(parameter == "sigma")
    f(P::sigma(value == "inf" ? std::numeric_limits<double>::infinity() : std::stod(value)));
  else if(parameter == "time")
    f(P::time(std::stod(value)));
  else if(parameter == "kernel_method")
    f(P::kernel_method(kernel_method(value)));
  else if(parameter == "operator_normalization")
    f(P::operator_normalization(normalization(value)));
  else if(parameter == "number_of_eigenpairs")
    f(P::number_of_eigenpairs(std::size_t(std::stoul(value))));
  else if(parameter == "coarse_vertex_count")
    f(P::coarse_vertex_count(std::size_t(std::stoul(value))));
  else if(parameter == "scale_invariant_kernel")
    f(P::scale_invariant_kernel(value == "true"));
  else if(parameter == "local_kernel_tolerance")
    f(P::local_kernel_tolerance(std::stod(value)));
  else
    return false;
  return true;
}

void run(const std::string& command, Mesh& mesh, const std::string& parameter, const std::string& value,
         Output& out)
{
  namespace P = HD::parameters;
  namespace D = HD::defaults;
  const std::vector<std::size_t> scales(D::feature_scales.begin(), D::feature_scales.end());
  bool known = true;
  if(command == "ncc")
  {
    if(parameter.empty())
      out.values = normal_signature(mesh);
    else if(parameter == "vertex_normal_rule" && value == "pmp")
    {
      const HD::Normal_controlled_coordinates<Mesh> ncc(
          mesh, P::vertex_normal_rule(HD::Polygon_mesh_processing_vertex_normals()));
      for(Vertex v : mesh.vertices())
        out.add(ncc.normal_signature(v));
    }
    else
      known = false;
  }
  else if(command == "coordinates" && parameter.empty())
  {
    const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
    for(Vertex v : mesh.vertices())
      for(int c = 0; c < 3; ++c)
        out.add(ncc.ncc(v)[c]);
  }
  else if(command == "reconstruct")
  {
    const auto ns = field_map(mesh, "v:reference_ns", normal_signature(mesh));
    if(parameter.empty())
      HD::reconstruct_from_normal_signature(mesh, ns);
    else if(parameter == "anchor_weight")
      HD::reconstruct_from_normal_signature(mesh, ns, P::anchor_weight(std::stod(value)));
    else
      known = false;
    points(mesh, out);
  }
  else if(command == "diffuse")
  {
    if(parameter == "steps")
      diffuse(mesh, numbers(value), P::default_values(), out);
    else
      known = with_diffusion_parameter(parameter, value, [&](const auto& np) { diffuse(mesh, scales, np, out); });
  }
  else if(command == "features")
  {
    if(parameter == "feature_threshold")
      features(mesh, scales, P::default_values(), P::feature_threshold(std::stod(value)), out);
    else
      known = with_diffusion_parameter(parameter, value,
                                       [&](const auto& np) { features(mesh, scales, np, P::default_values(), out); });
  }
  else if(command == "hks")
  {
    // The classical signature: the plain Laplacian, at the time t of defaults::heat_kernel_signature.
    const double sigma = D::heat_kernel_signature::sigma;
    const double t = parameter == "time" ? std::stod(value) : D::heat_kernel_signature::time;
    if(parameter.empty() || parameter == "time")
      hks(mesh, t, P::sigma(sigma), P::default_values(), out);
    else if(parameter == "feature_threshold")
      hks(mesh, t, P::sigma(sigma), P::feature_threshold(std::stod(value)), out);
    else if(parameter == "sigma")
      hks(mesh, t, P::sigma(std::stod(value)), P::default_values(), out);
    else if(parameter == "number_of_eigenpairs")
      hks(mesh, t, P::sigma(sigma).number_of_eigenpairs(std::size_t(std::stoul(value))), P::default_values(), out);
    else if(parameter == "coarse_vertex_count")
      hks(mesh, t, P::sigma(sigma).coarse_vertex_count(std::size_t(std::stoul(value))), P::default_values(), out);
    else if(parameter == "scale_invariant_kernel")
      hks(mesh, t, P::sigma(sigma).scale_invariant_kernel(true), P::default_values(), out);
    else
      known = false;
  }
  else if(command == "decompose")
  {
    if(parameter == "levels")
      decompose_with(mesh, std::stoul(value), P::default_values(), P::default_values(), out);
    else if(parameter == "steps_per_level")
      decompose_with(mesh, D::detail_levels, P::default_values(), P::steps_per_level(std::size_t(std::stoul(value))),
                     out);
    else
      known = with_diffusion_parameter(parameter, value, [&](const auto& np) {
        decompose_with(mesh, D::detail_levels, np, P::default_values(), out);
      });
  }
  else if(command == "enhance")
  {
    std::vector<double> weights(D::enhancement_weights.begin(), D::enhancement_weights.end());
    if(parameter == "weights")
    {
      weights.clear();
      for(std::size_t w : numbers(value))
        weights.push_back(double(w));
      enhance(mesh, weights, P::default_values(), out);
    }
    else if(parameter == "steps_per_level")
      enhance(mesh, weights, P::steps_per_level(std::size_t(std::stoul(value))), out);
    else if(parameter == "anchor_weight")
      enhance(mesh, weights, P::anchor_weight(std::stod(value)), out);
    else
      known = with_diffusion_parameter(parameter, value, [&](const auto& np) { enhance(mesh, weights, np, out); });
  }
  else if(command == "denoise")
  {
    const HD::Denoising_method signature = HD::Denoising_method::signature_diffusion;
    // The parameters of signature diffusion come with --method signature_diffusion, as in
    // the tool (which refuses them otherwise): "signature:" before their name.
    const bool with_signature = parameter.rfind("signature:", 0) == 0;
    const std::string name = with_signature ? parameter.substr(10) : parameter;
    if(name == "denoising_method")
      denoise(mesh, P::denoising_method(signature), out);
    else if(name == "number_of_iterations")
      denoise(mesh, CGAL::parameters::number_of_iterations(unsigned(std::stoul(value))), out);
    else if(name == "number_of_steps")
      denoise(mesh, P::number_of_steps(std::size_t(std::stoul(value))), out);
    else if(name == "normal_sigma")
      denoise(mesh, P::normal_sigma(std::stod(value)), out);
    else if(name == "displacement_limit")
      denoise(mesh, P::displacement_limit(std::stod(value)), out);
    else if(with_signature && name == "anchor_weight")
      denoise(mesh, P::denoising_method(signature).anchor_weight(std::stod(value)), out);
    else if(with_signature)
      known = with_diffusion_parameter(name, value, [&](const auto& np) {
        denoise(mesh, P::combine(P::denoising_method(signature), np), out);
      });
    else if(parameter.empty())
      denoise(mesh, P::default_values(), out);
    else
      known = false;
  }
  else
    throw std::invalid_argument("unknown command " + command);
  if(!known)
    throw std::invalid_argument(command + ": unknown parameter " + parameter + " " + value);
}

// A point-set command: the library's point-set classes with k neighbours and the named
// parameters `np`, and the feature threshold of `feature_np`.
template <typename NP, typename FeatureNP>
void run_on_points(const std::string& command, const Point_set& points, unsigned int k,
                   const std::vector<std::size_t>& steps, const NP& np, const FeatureNP& feature_np, Output& out)
{
  if(command == "points_ncc" || command == "points_coordinates")
  {
    const HD::Point_set_normal_controlled_coordinates<Point_set> ncc(points, k, np);
    for(std::size_t i = 0; i < ncc.number_of_points(); ++i)
      if(command == "points_ncc")
        out.add(ncc.normal_signature(i));
      else
        for(int c = 0; c < 3; ++c)
          out.add(ncc.ncc(i)[c]);
    if(command == "points_coordinates")
      for(std::size_t i = 0; i < ncc.number_of_points(); ++i)
        for(int c = 0; c < 3; ++c)
          out.add(ncc.normal(i)[c]);
    return;
  }
  const HD::Point_set_anisotropic_heat_diffusion<Point_set> diffusion(points, k, np);
  Eigen::VectorXd ns(static_cast<Eigen::Index>(points.size()));
  for(std::size_t i = 0; i < points.size(); ++i)
    ns[Eigen::Index(i)] = diffusion.normal_controlled_coordinates().normal_signature(i);
  if(command == "points_diffuse")
    for(const Eigen::VectorXd& f : diffusion.diffuse(ns, steps))
      out.values.insert(out.values.end(), f.data(), f.data() + f.size());
  else if(command == "points_features")
    for(const auto& scale : HD::detect_point_set_multiscale_features(diffusion, ns, steps, feature_np))
    {
      out.add(double(scale.number_of_steps));
      for(const auto* list : {&scale.convex, &scale.concave})
      {
        out.add(double(list->size()));
        for(std::size_t i : *list)
          out.add(double(i));
      }
    }
  else
    throw std::invalid_argument("unknown command " + command);
}

// The positions of the points, then their normals if `with_normals` and they have some.
void add_points(const Point_set& points, bool with_normals, Output& out)
{
  for(Point_set::Index i : points)
    for(int c = 0; c < 3; ++c)
      out.add(points.point(i)[c]);
  if(with_normals && points.has_normal_map())
    for(Point_set::Index i : points)
      for(int c = 0; c < 3; ++c)
        out.add(points.normal(i)[c]);
}

template <typename NP>
void decompose_points(const Point_set& points, unsigned int k, std::size_t levels, const NP& np, Output& out)
{
  const HD::Point_set_anisotropic_heat_diffusion<Point_set> diffusion(points, k, np);
  Eigen::VectorXd ns(static_cast<Eigen::Index>(points.size()));
  for(std::size_t i = 0; i < points.size(); ++i)
    ns[Eigen::Index(i)] = diffusion.normal_controlled_coordinates().normal_signature(i);
  for(const Eigen::VectorXd& band : HD::decompose_point_set_field(diffusion, ns, levels, np))
    out.values.insert(out.values.end(), band.data(), band.data() + band.size());
}

template <typename NP>
void enhance_points(Point_set points, unsigned int k, const std::vector<double>& weights, const NP& np, Output& out)
{
  HD::filter_point_set_shape(points, k, weights, np);
  add_points(points, false, out);
}

template <typename NP>
void denoise_points(Point_set points, unsigned int k, const NP& np, Output& out)
{
  HD::denoise_point_set(points, k, np);
  add_points(points, true, out);
}

// points_decompose, points_enhance and points_denoise, with no named parameter or with the
// one given.
bool run_point_application(const std::string& command, const Point_set& points, const std::string& parameter,
                           const std::string& value, Output& out)
{
  namespace P = HD::parameters;
  namespace D = HD::defaults;
  const unsigned int k = parameter == "k" ? unsigned(std::stoul(value))
                         : command == "points_denoise" ? D::point_set_denoising::number_of_neighbors
                                                      : D::number_of_neighbors;
  const bool plain = parameter.empty() || parameter == "k";
  if(command == "points_decompose")
  {
    const std::size_t levels = parameter == "levels" ? std::size_t(std::stoul(value)) : D::detail_levels;
    if(plain || parameter == "levels")
      decompose_points(points, k, levels, P::default_values(), out);
    else if(parameter == "steps_per_level")
      decompose_points(points, k, levels, P::steps_per_level(std::size_t(std::stoul(value))), out);
    else if(parameter == "neighbor_radius")
      decompose_points(points, k, levels, CGAL::parameters::neighbor_radius(std::stod(value)), out);
    else
      return with_diffusion_parameter(parameter, value,
                                      [&](const auto& np) { decompose_points(points, k, levels, np, out); });
  }
  else if(command == "points_enhance")
  {
    std::vector<double> weights(D::enhancement_weights.begin(), D::enhancement_weights.end());
    if(parameter == "weights")
    {
      weights.clear();
      for(std::size_t w : numbers(value))
        weights.push_back(double(w));
    }
    if(plain || parameter == "weights")
      enhance_points(points, k, weights, P::default_values(), out);
    else if(parameter == "steps_per_level")
      enhance_points(points, k, weights, P::steps_per_level(std::size_t(std::stoul(value))), out);
    else if(parameter == "anchor_weight")
      enhance_points(points, k, weights, P::anchor_weight(std::stod(value)), out);
    else
      return with_diffusion_parameter(parameter, value,
                                      [&](const auto& np) { enhance_points(points, k, weights, np, out); });
  }
  else if(command == "points_denoise")
  {
    if(plain)
      denoise_points(points, k, P::default_values(), out);
    else if(parameter == "neighbor_radius")
      denoise_points(points, k, CGAL::parameters::neighbor_radius(std::stod(value)), out);
    else if(parameter == "number_of_iterations")
      denoise_points(points, k, CGAL::parameters::number_of_iterations(unsigned(std::stoul(value))), out);
    else if(parameter == "number_of_steps")
      denoise_points(points, k, P::number_of_steps(std::size_t(std::stoul(value))), out);
    else if(parameter == "normal_sigma")
      denoise_points(points, k, P::normal_sigma(std::stod(value)), out);
    else if(parameter == "displacement_limit")
      denoise_points(points, k, P::displacement_limit(std::stod(value)), out);
    else
      return false;
  }
  else
    throw std::invalid_argument("unknown command " + command);
  return true;
}

void run_on_points(const std::string& command, const Point_set& points, const std::string& parameter,
                   const std::string& value, Output& out)
{
  if(command == "points_decompose" || command == "points_enhance" || command == "points_denoise")
  {
    if(!run_point_application(command, points, parameter, value, out))
      throw std::invalid_argument(command + ": unknown parameter " + parameter + " " + value);
    return;
  }
  namespace P = HD::parameters;
  namespace D = HD::defaults;
  std::vector<std::size_t> steps(D::feature_scales.begin(), D::feature_scales.end());
  const unsigned int k = parameter == "k" ? unsigned(std::stoul(value)) : D::number_of_neighbors;
  if(parameter.empty() || parameter == "k")
    run_on_points(command, points, k, steps, P::default_values(), P::default_values(), out);
  else if(parameter == "steps")
    run_on_points(command, points, k, numbers(value), P::default_values(), P::default_values(), out);
  else if(parameter == "neighbor_radius")
    run_on_points(command, points, k, steps, CGAL::parameters::neighbor_radius(std::stod(value)),
                  P::default_values(), out);
  else if(parameter == "feature_threshold")
    run_on_points(command, points, k, steps, P::default_values(), P::feature_threshold(std::stod(value)), out);
  else if(!with_diffusion_parameter(parameter, value, [&](const auto& np) {
            run_on_points(command, points, k, steps, np, P::default_values(), out);
          }))
    throw std::invalid_argument(command + ": unknown parameter " + parameter + " " + value);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 4 && argc != 6)
  {
    std::cerr << "usage: parity_reference COMMAND MESH OUTPUT [PARAMETER VALUE]\n";
    return 2;
  }
  try
  {
    const std::string command = argv[1];
    Output out;
    if(command.rfind("points_", 0) == 0)
    {
      Point_set points;
      if(!CGAL::IO::read_point_set(argv[2], points))
        throw std::runtime_error(std::string("cannot read ") + argv[2]);
      run_on_points(command, points, argc == 6 ? argv[4] : "", argc == 6 ? argv[5] : "", out);
    }
    else
    {
      Mesh mesh;
      if(!CGAL::IO::read_polygon_mesh(argv[2], mesh))
        throw std::runtime_error(std::string("cannot read ") + argv[2]);
      run(command, mesh, argc == 6 ? argv[4] : "", argc == 6 ? argv[5] : "", out);
    }
    out.write(argv[3]);
  }
  catch(const std::exception& e)
  {
    std::cerr << "parity_reference: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
