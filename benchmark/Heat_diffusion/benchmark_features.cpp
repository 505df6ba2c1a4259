// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Multi-scale features (the paper's section 7) with each way of obtaining the heat
// kernel, on CGAL's meshes, so that the kernels are compared by what a user sees:
//
// Table 1: per mesh, sigma and kernel (the truncated spectral kernel of m = 150
//          eigenpairs, and the local kernel without truncation), t = 1, c = 0.8: the
//          time to build A_t, the collapsed heat regions, the number of convex /
//          concave features at k = 0, 10, 40, and the share of the local kernel's
//          features that the spectral kernel also finds (same type, within the 2-ring).
// Table 2: robustness to noise: Gaussian noise of 0.1 mean edge length along the
//          vertex normals (seeds 1..S), features at k = 10: the share of the clean
//          mesh's features re-detected with their type within their 2-ring.
// Table 3: the coarse-level spectral kernel (coarse sizes 1000, 2000, 5000) against
//          the full spectral computation, at t = 1 and at t = 4 ln 10 / lambda_m (where
//          the truncated kernel is accurate): the share of the full features at k = 10
//          and 40 the coarse path finds with their type within the 2-ring, and the reverse.
// Table 4 (--shape-filter, alone): the shape filters of filter_shape() (the paper's
//          Fig. 10, built on the same diffusion) by sigma, steps per level and anchor
//          weight: for the enhancement (1, 3, 3), the NS variance of its target
//          (the re-synthesised NS) and of the result, relative to the input's, the share
//          of the asked change reached, the largest vertex displacement (% of the
//          bounding-box diagonal) and whether the result self-intersects; for the
//          smoothing (0, 0, 1), the NS variance ratio and self-intersections. The
//          defaults of filter_shape() were chosen from this table.
//
// Usage: benchmark_features [DATA_DIR] [--seeds S] [--meshes a.off,b.off]
//                           [--shape-filter [--sigmas S1,S2,...] [--steps K1,K2,...]]
//   S (default 3); meshes (default fandisk.off,armadillo.off; with --shape-filter,
//   armadillo.off,bunny00.off,elephant.off,fandisk.off); the sigmas (default 0.1) and
//   steps per level (default 2,5) of table 4. A few minutes on 2 cores.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/decomposition.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/bounding_box.h>
#include <CGAL/Surface_mesh.h>

#include "benchmark_command_line.h"
#include "mesh_measures.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
namespace HD = CGAL::Heat_diffusion;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef HD::Anisotropic_heat_diffusion<Mesh> Diffusion;
typedef HD::Features_at_scale<Vertex> Features;

const std::vector<std::size_t> scales = {0, 10, 40};

struct Kernel_setting
{
  const char* name;
  HD::Heat_kernel_method method;
  std::size_t coarse;  // coarse vertex count of the spectral kernel, 0 for none
};

struct Run
{
  std::vector<Features> features;
  double build_seconds = 0;
  std::size_t collapsed = 0;
};

Run run_features(const Mesh& input, double sigma, const Kernel_setting& kernel)
{
  Mesh mesh = input;
  auto ns = mesh.add_property_map<Vertex, double>("v:ns", 0.).first;
  HD::compute_normal_signature(mesh, ns);
  const auto start = std::chrono::steady_clock::now();
  const Diffusion diffusion(mesh, HD::parameters::combine(
                                      HD::parameters::sigma(sigma), HD::parameters::time(1.),
                                      HD::parameters::number_of_eigenpairs(150), HD::parameters::kernel_method(kernel.method),
                                      HD::parameters::coarse_vertex_count(kernel.coarse)));
  Run run;
  run.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.collapsed = diffusion.region_statistics().collapsed_regions;
  run.features = HD::detect_multiscale_features(diffusion, ns, scales);
  return run;
}

// The share of the features of `wanted` (both types) that `found` has with the same
// type within their 2-ring; NaN if `wanted` has none.
double share_found(const Features& wanted, const Features& found, const std::vector<std::set<std::size_t> >& rings)
{
  const std::size_t total = wanted.convex.size() + wanted.concave.size();
  if(total == 0)
    return std::nan("");
  return double(test_support::count_found_nearby(wanted.convex, found.convex, rings) +
                test_support::count_found_nearby(wanted.concave, found.concave, rings)) /
         double(total);
}

std::string percent(double share)
{
  if(std::isnan(share))
    return "-";
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f %%", 100 * share);
  return text;
}

std::string counts(const Features& f)
{
  return std::to_string(f.convex.size()) + "/" + std::to_string(f.concave.size());
}

double ns_variance(const Mesh& mesh)
{
  const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
  double sum = 0, squares = 0;
  for(Vertex v : mesh.vertices())
  {
    sum += ncc.normal_signature(v);
    squares += ncc.normal_signature(v) * ncc.normal_signature(v);
  }
  const double n = double(mesh.number_of_vertices());
  return squares / n - (sum / n) * (sum / n);
}

void shape_filter_table(const std::string& data, const std::vector<std::string>& meshes,
                        const std::vector<double>& sigmas, const std::vector<double>& step_counts)
{
  std::printf("Table 4: filter_shape(), t = 1, local kernel: enhancement (1, 3, 3) and smoothing (0, 0, 1)\n");
  std::printf("| mesh | sigma | steps per level | anchor weight | target NS variance | enhanced | reached | largest displacement"
              " | enhanced self-intersects | smoothed NS variance | smoothed self-intersects | s per filter |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const std::string& name : meshes)
  {
    Mesh mesh;
    if(!PMP::IO::read_polygon_mesh(data + "/" + name, mesh) || mesh.is_empty())
      throw std::runtime_error("cannot read " + data + "/" + name);
    const double v0 = ns_variance(mesh);
    const auto box = CGAL::bounding_box(mesh.points().begin(), mesh.points().end());
    const double diagonal = std::sqrt(CGAL::to_double(CGAL::squared_distance(box.min(), box.max())));
    const bool input_intersects = PMP::does_self_intersect(mesh);
    for(double sigma : sigmas)
      for(double step_count : step_counts)
      {
        const std::size_t steps = std::size_t(step_count);
        // the target: the NS re-synthesised as filter_shape() does
        Mesh copy = mesh;
        auto ns = copy.add_property_map<Vertex, double>("v:ns", 0.).first;
        HD::compute_normal_signature(copy, ns);
        std::vector<Mesh::Property_map<Vertex, double> > bands;
        for(int j = 1; j <= 3; ++j)
          bands.push_back(copy.add_property_map<Vertex, double>("v:d" + std::to_string(j), 0.).first);
        auto target = copy.add_property_map<Vertex, double>("v:target", 0.).first;
        HD::decompose_field(copy, ns, bands, target,
                            HD::parameters::combine(HD::parameters::sigma(sigma), HD::parameters::steps_per_level(steps)));
        HD::synthesize_field(copy, bands, target, std::vector<double>{1., 3., 3.}, target);
        double sum = 0, squares = 0;
        for(Vertex v : copy.vertices())
        {
          sum += target[v];
          squares += target[v] * target[v];
        }
        const double n = double(copy.number_of_vertices());
        const double target_variance = squares / n - (sum / n) * (sum / n);
        for(double anchor : {1., 0.1, 0.05, 0.03, 0.02, 0.01})
        {
          const auto np = HD::parameters::combine(HD::parameters::sigma(sigma), HD::parameters::steps_per_level(steps),
                                                  HD::parameters::anchor_weight(anchor));
          Mesh enhanced = mesh, smoothed = mesh;
          const auto start = std::chrono::steady_clock::now();
          HD::filter_shape(enhanced, std::vector<double>{1., 3., 3.}, np);
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          HD::filter_shape(smoothed, std::vector<double>{0., 0., 1.}, np);
          double moved = 0;
          for(Vertex v : mesh.vertices())
            moved = (std::max)(moved, std::sqrt(CGAL::to_double(CGAL::squared_distance(mesh.point(v), enhanced.point(v)))));
          const double enhanced_variance = ns_variance(enhanced);
          std::printf("| %s | %g | %zu | %g | %.3f | %.3f | %.2f | %.2f %% | %s | %.2f | %s | %.2f |\n", name.c_str(), sigma,
                      steps, anchor,
                      target_variance / v0, enhanced_variance / v0, (enhanced_variance - v0) / (target_variance - v0),
                      100 * moved / diagonal,
                      input_intersects ? "(input does)" : PMP::does_self_intersect(enhanced) ? "yes" : "no",
                      ns_variance(smoothed) / v0,
                      input_intersects ? "(input does)" : PMP::does_self_intersect(smoothed) ? "yes" : "no", seconds);
          std::fflush(stdout);
        }
      }
  }
}

int main(int argc, char* argv[])
{
  std::string data = CGAL_HEAT_DIFFUSION_DATA_DIR;
  unsigned seeds = 3;
  std::vector<std::string> meshes = {"fandisk.off", "armadillo.off"};
  bool shape_filter = false, meshes_given = false;
  std::vector<double> sigmas = {0.1}, step_counts = {2, 5};
  namespace cli = heat_diffusion_cli;
  // A comma-separated list of numbers of `option`, each > 0 (whole with `whole`).
  auto numbers = [](const std::string& option, const std::string& text, bool whole) {
    std::vector<double> values;
    std::stringstream list(text);
    for(std::string value; std::getline(list, value, ',');)
      values.push_back(whole ? double(cli::parse_count(option, value, 1, 1000000))
                             : cli::parse_number(option, value, 0., true));
    if(values.empty())
      throw cli::Usage_error(option + " needs at least one number");
    return values;
  };
  const std::string usage =
      "usage: benchmark_features [DATA_DIR] [--seeds S] [--meshes a.off,b.off]\n"
      "                          [--shape-filter [--sigmas S1,S2,...] [--steps K1,K2,...]]\n"
      "  --seeds         noise draws per mesh, 1 to 1000 (default 3)\n"
      "  --meshes        meshes of DATA_DIR (default fandisk.off,armadillo.off; with --shape-filter,\n"
      "                  armadillo.off,bunny00.off,elephant.off,fandisk.off)\n"
      "  --shape-filter  table 4 alone: the shape filters, with the sigmas (default 0.1) and steps\n"
      "                  per level (default 2,5) of --sigmas and --steps\n";
  if(const auto exit_code = heat_diffusion_benchmark::read_command_line(
         argc, argv, {"--shape-filter"}, {"--sigmas", "--steps", "--seeds", "--meshes"}, usage,
         [&](const cli::Arguments& a) {
           data = heat_diffusion_benchmark::optional_argument(a, "DATA_DIR", data);
           shape_filter = a.flag("--shape-filter");
           if((a.has("--sigmas") || a.has("--steps")) && !shape_filter)
             throw cli::Usage_error("--sigmas and --steps are settings of --shape-filter");
           if(a.has("--sigmas"))
             sigmas = numbers("--sigmas", a.value("--sigmas", ""), false);
           if(a.has("--steps"))
             step_counts = numbers("--steps", a.value("--steps", ""), true);
           seeds = unsigned(cli::parse_count("--seeds", a.value("--seeds", "3"), 1, 1000));
           if(a.has("--meshes"))
           {
             meshes = heat_diffusion_benchmark::mesh_names(a);
             meshes_given = true;
           }
         }))
    return *exit_code;
  try
  {
    if(shape_filter)
    {
      shape_filter_table(data, meshes_given ? meshes : std::vector<std::string>{"armadillo.off", "bunny00.off",
                                                                                 "elephant.off", "fandisk.off"},
                         sigmas, step_counts);
      return 0;
    }
    const Kernel_setting spectral{"spectral m=150", HD::Heat_kernel_method::spectral, 0};
    const Kernel_setting local{"local", HD::Heat_kernel_method::local, 0};
    std::printf("Table 1: features (convex/concave) with each kernel, t = 1, c = 0.8\n");
    std::printf("%-14s %5s %-15s %8s %9s %9s %9s %9s %18s\n", "mesh", "sigma", "kernel", "A_t s", "collapsed", "k=0",
                "k=10", "k=40", "local in spectral");
    for(const std::string& name : meshes)
    {
      Mesh mesh;
      if(!PMP::IO::read_polygon_mesh(data + "/" + name, mesh) || mesh.is_empty())
        throw std::runtime_error("cannot read " + data + "/" + name);
      const auto rings = test_support::two_rings(mesh);
      for(double sigma : {0.1, 1.})
      {
        const Run a = run_features(mesh, sigma, spectral);
        const Run b = run_features(mesh, sigma, local);
        for(const Run* r : {&a, &b})
        {
          std::string agreement;
          if(r == &b)
            for(std::size_t s = 0; s < scales.size(); ++s)
              agreement += (s ? " " : "") + percent(share_found(b.features[s], a.features[s], rings));
          std::printf("%-14s %5g %-15s %8.2f %9zu %9s %9s %9s %18s\n", name.c_str(), sigma,
                      r == &a ? spectral.name : local.name, r->build_seconds, r->collapsed,
                      counts(r->features[0]).c_str(), counts(r->features[1]).c_str(), counts(r->features[2]).c_str(),
                      agreement.c_str());
        }
      }
    }

    std::printf("\nTable 2: clean features re-detected under noise of 0.1 mean edge length (seeds 1..%u), "
                "k = 10, sigma = 1, t = 1, c = 0.8\n",
                seeds);
    std::printf("%-14s %-15s %9s %12s %12s\n", "mesh", "kernel", "clean", "noisy (mean)", "re-detected");
    for(const std::string& name : meshes)
    {
      Mesh mesh;
      PMP::IO::read_polygon_mesh(data + "/" + name, mesh);
      const auto rings = test_support::two_rings(mesh);
      for(const Kernel_setting& kernel : {spectral, local})
      {
        const Features clean = run_features(mesh, 1., kernel).features[1];
        std::size_t hits = 0, noisy_total = 0;
        for(unsigned seed = 1; seed <= seeds; ++seed)
        {
          Mesh noisy = mesh;
          test_support::add_normal_noise(noisy, 0.1, seed);
          const Features found = run_features(noisy, 1., kernel).features[1];
          noisy_total += found.convex.size() + found.concave.size();
          hits += test_support::count_found_nearby(clean.convex, found.convex, rings) +
                  test_support::count_found_nearby(clean.concave, found.concave, rings);
        }
        const std::size_t clean_total = clean.convex.size() + clean.concave.size();
        std::printf("%-14s %-15s %9zu %12.1f %12s\n", name.c_str(), kernel.name, clean_total,
                    double(noisy_total) / seeds,
                    percent(clean_total ? double(hits) / double(seeds * clean_total) : std::nan("")).c_str());
      }
    }

    // At t = 1 the full spectral kernel is itself far from the heat kernel (Table 1 of
    // the manual's local-kernel section), so the coarse path is also compared at
    // t = 4 ln 10 / lambda_m of the full kernel, where the truncation is accurate.
    std::printf("\nTable 3: coarse-level spectral kernel against the full one (sigma = 1, m = 150): full features "
                "found by the coarse path / coarse features found by the full path\n");
    std::printf("%-14s %7s %7s %8s %21s %21s\n", "mesh", "t", "coarse", "eigen s", "k=10", "k=40");
    typedef HD::Edge_weighted_heat_kernel<Mesh> Heat_kernel;
    for(const std::string& name : meshes)
    {
      Mesh mesh;
      PMP::IO::read_polygon_mesh(data + "/" + name, mesh);
      const auto rings = test_support::two_rings(mesh);
      auto ns = mesh.add_property_map<Vertex, double>("v:ns", 0.).first;
      HD::compute_normal_signature(mesh, ns);
      auto kernel_of = [&](std::size_t coarse, double& seconds) {
        const auto start = std::chrono::steady_clock::now();
        auto kernel = std::make_unique<Heat_kernel>(
            mesh, HD::parameters::combine(HD::parameters::sigma(1.), HD::parameters::number_of_eigenpairs(150),
                                          HD::parameters::coarse_vertex_count(coarse)));
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return kernel;
      };
      double full_seconds = 0;
      const auto full = kernel_of(0, full_seconds);
      const double accurate_t = 4 * std::log(10.) / full->eigenvalues().maxCoeff();
      std::vector<std::unique_ptr<Heat_kernel> > coarse_kernels;
      std::vector<std::pair<std::size_t, double> > coarse_sizes;
      for(std::size_t coarse : {1000, 2000, 5000})
        if(coarse < mesh.number_of_vertices())
        {
          double seconds = 0;
          coarse_kernels.push_back(kernel_of(coarse, seconds));
          coarse_sizes.emplace_back(coarse, seconds);
        }
      for(double t : {1., accurate_t})
      {
        const auto full_features = HD::detect_multiscale_features(Diffusion(*full, t), ns, scales);
        std::printf("%-14s %7.1f %7s %8.2f %21s %21s\n", name.c_str(), t, "full", full_seconds,
                    counts(full_features[1]).c_str(), counts(full_features[2]).c_str());
        for(std::size_t c = 0; c < coarse_kernels.size(); ++c)
        {
          const auto features = HD::detect_multiscale_features(Diffusion(*coarse_kernels[c], t), ns, scales);
          std::string cells[2];
          for(std::size_t s = 1; s < 3; ++s)
            cells[s - 1] = percent(share_found(full_features[s], features[s], rings)) + " / " +
                           percent(share_found(features[s], full_features[s], rings));
          std::printf("%-14s %7.1f %7zu %8.2f %21s %21s\n", name.c_str(), t, coarse_sizes[c].first,
                      coarse_sizes[c].second, cells[0].c_str(), cells[1].c_str());
        }
      }
    }
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "benchmark_features: %s\n", e.what());
    return 1;
  }
  return 0;
}
