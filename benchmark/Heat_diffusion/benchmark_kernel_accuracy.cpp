// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The local kernel's accuracy budget: how far A_t (balanced, the default) built from
// the local kernel at a tolerance lies from A_t built from a much more accurate kernel
// (tolerance 2e-6, three poles: the reference; the heat balance of single-precision
// substitutions cannot check a tighter one), next to the error that the heat regions
// already make by truncating each column of the kernel. Per mesh and time t, with
// sigma = 0.1:
// - truncation: the heat of a reference kernel column that its heat region leaves out,
//   sum_{i not in R_j} m_i |h_ij| / sum_i m_i |h_ij| (m: the lumped mass), over every 8th
//   source: mean and largest;
// - per tolerance (the poles it chooses): the distance of A_t's columns to the reference
//   A_t's, ||a_j - a*_j||_1 / ||a*_j||_1 (mean, 99th percentile, largest), the mean's
//   fraction of the truncation's mean; F^10 of the Normal Signature against the
//   reference's, relative to what the 10 steps change (||F - F*|| / ||F* - F^0||); the
//   features at k = 10 that differ from the reference's (convex and concave, the
//   symmetric difference, against the reference's count); the time to A_t, and its
//   ratio to the time at 1e-4 (the package's earlier default),
//   measured in the same run.
//
// Usage: benchmark_kernel_accuracy [DATA_DIR] [--meshes a.off,b.off] [--times 0.5,1]
//   defaults: fandisk, armadillo, elephant and mech-holes-shark; t = 0.5, 1, 2, 4.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/internal/local_heat_kernel.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include "benchmark_command_line.h"
#include "benchmark_mesh.h"
#include "kernel_accuracy.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace HD = CGAL::Heat_diffusion;
typedef HD::Anisotropic_heat_diffusion<Mesh> Diffusion;

namespace {

using kernel_accuracy::previous_tolerance;
using kernel_accuracy::reference_tolerance;
const std::vector<double> tolerances = {1e-4, 1e-3, 1e-2, 3e-2};

Mesh load(const std::string& path) { return heat_diffusion_benchmark::load_mesh_or_exit<Mesh>(path); }

Diffusion build(const Mesh& mesh, double t, double tolerance, double* seconds = nullptr)
{
  const auto start = std::chrono::steady_clock::now();
  Diffusion diffusion(mesh, HD::parameters::time(t)
                                .kernel_method(HD::Heat_kernel_method::local)
                                .local_kernel_tolerance(tolerance));
  if(seconds)
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return diffusion;
}

std::set<Vertex> features(const Diffusion& diffusion, const Mesh::Property_map<Vertex, double>& ns)
{
  const auto found = HD::detect_multiscale_features(diffusion, ns, std::vector<std::size_t>(1, 10));
  std::set<Vertex> all(found[0].convex.begin(), found[0].convex.end());
  all.insert(found[0].concave.begin(), found[0].concave.end());
  return all;
}

void run(const std::string& path, const std::string& name, const std::vector<double>& times)
{
  Mesh mesh = load(path);
  for(double t : times)
  {
    const Diffusion reference = build(mesh, t, reference_tolerance);
    const Diffusion reference_columns(mesh, HD::parameters::time(t)
                                                .kernel_method(HD::Heat_kernel_method::local)
                                                .local_kernel_tolerance(reference_tolerance)
                                                .operator_normalization(HD::Operator_normalization::columns));
    const kernel_accuracy::Summary truncation = kernel_accuracy::heat_outside_regions(reference_columns);
    auto ns = mesh.add_property_map<Vertex, double>("v:accuracy_ns", 0.).first;
    Eigen::VectorXd f0(Eigen::Index(reference.number_of_vertices()));
    for(Vertex v : mesh.vertices())
    {
      ns[v] = reference.normal_controlled_coordinates().normal_signature(v);
      f0[Eigen::Index(reference.vertex_index(v))] = ns[v];
    }
    const Eigen::VectorXd f10_reference = reference.diffuse(f0, 10);
    const std::set<Vertex> reference_features = features(reference, ns);
    const Eigen::SparseMatrix<double>& A_reference = reference.operator_matrix();
    double previous_seconds = 0;
    for(double tolerance : tolerances)
    {
      double seconds = 0;
      const Diffusion diffusion = build(mesh, t, tolerance, &seconds);
      if(tolerance == previous_tolerance)
        previous_seconds = seconds;
      const kernel_accuracy::Summary distance =
          kernel_accuracy::column_distances(diffusion.operator_matrix(), A_reference);
      const Eigen::VectorXd f10 = diffusion.diffuse(f0, 10);
      const double field_error = (f10 - f10_reference).norm() / (f10_reference - f0).norm();
      const std::set<Vertex> found = features(diffusion, ns);
      std::vector<Vertex> differ;
      std::set_symmetric_difference(found.begin(), found.end(), reference_features.begin(), reference_features.end(),
                                    std::back_inserter(differ));
      const int poles = int(HD::internal::Local_heat_kernel::exponential_for(tolerance).number_of_poles);
      std::printf("| %s | %g | %.4f / %.4f | %g (%d) | %.2e | %.2e | %.2e | %.2f %% | %.2e | %zu / %zu | %.3f |"
                  " %.2f |\n",
                  name.c_str(), t, truncation.mean, truncation.largest, tolerance, poles, distance.mean,
                  distance.percentile_99, distance.largest, 100. * distance.mean / truncation.mean, field_error,
                  differ.size(), reference_features.size(), seconds,
                  previous_seconds > 0 ? seconds / previous_seconds : 0.);
      std::fflush(stdout);
    }
    mesh.remove_property_map(ns);
  }
}

std::vector<std::string> split(const std::string& list)
{
  std::vector<std::string> items;
  std::stringstream stream(list);
  for(std::string item; std::getline(stream, item, ',');)
    if(!item.empty())
      items.push_back(item);
  return items;
}

} // namespace

int main(int argc, char** argv)
{
  namespace cli = heat_diffusion_benchmark::cli;
  const std::string usage =
      "usage: benchmark_kernel_accuracy [DATA_DIR] [--meshes a.off,b.off] [--times 0.5,1]\n"
      "  the local kernel's A_t at several tolerances against a reference (tolerance 2e-6),\n"
      "  next to the heat regions' truncation of the kernel (sigma 0.1)\n";
  std::string data = CGAL_HEAT_DIFFUSION_DATA_DIR;
  std::vector<std::string> meshes = {"fandisk.off", "armadillo.off", "elephant.off", "mech-holes-shark.off"};
  std::vector<double> times = {0.5, 1., 2., 4.};
  if(const auto exit_code = heat_diffusion_benchmark::read_command_line(
         argc, argv, {}, {"--meshes", "--times"}, usage, [&](const cli::Arguments& arguments) {
           data = heat_diffusion_benchmark::optional_argument(arguments, "DATA_DIR", data);
           if(arguments.has("--meshes"))
             meshes = heat_diffusion_benchmark::mesh_names(arguments);
           if(arguments.has("--times"))
           {
             times.clear();
             for(const std::string& item : split(arguments.value("--times", "")))
               times.push_back(cli::parse_number("--times", item, 0., true, 1e3));
             if(times.empty())
               throw cli::Usage_error("--times needs at least one time");
           }
         }))
    return *exit_code;

  std::printf("The local kernel's A_t against the reference (tolerance %g), sigma %g (the default)\n",
              reference_tolerance, HD::defaults::sigma);
  std::printf("| mesh | t | truncation: heat outside the regions, mean / largest | tolerance (poles) |"
              " A_t column distance: mean | 99th percentile | largest | mean / truncation's | F^10 of the NS |"
              " features at k = 10 that differ | A_t s | / 1e-4's |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const std::string& name : meshes)
    run(data + "/" + name, name, times);
  return EXIT_SUCCESS;
}
