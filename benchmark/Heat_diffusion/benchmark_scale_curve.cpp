// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The scale curve of the spectral path with its coarse level (paper, eq. 21): CGAL's
// armadillo Loop-subdivided at benchmark time to about 100k, 400k and 1.6M vertices
// (nothing is committed), then, for each size, the time from mesh to the NS diffused
// by k = 10 steps, each stage's share, and the peak memory. Each size runs in a child
// process so that its peak memory is its own.
//
// Usage: benchmark_scale_curve [DATA_DIR] [--max-level L] [--coarse N] [--time T]
//
// At the paper's t = 1 the truncated kernel's peak h_t(j, j) is about m / n, below the
// threshold tau(1) = 0.005 once n exceeds 30000 or so: every heat region collapses and
// nothing diffuses (the 'coll.' column). The timings are still those of the pipeline;
// --time 75 (4 ln 10 / lambda_m on armadillo) shows the valid regime.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HD = CGAL::Heat_diffusion;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double peak_memory_gib()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / (1024. * 1024.);  // ru_maxrss is in KiB on Linux
}

// One row of the table: subdivide, then mesh -> kernel -> A_t -> F^10.
void run_level(const std::string& path, int level, long coarse, double time)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh))
  {
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
    std::exit(1);
  }
  if(level > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(level));

  const auto start = std::chrono::steady_clock::now();
  const auto np = HD::parameters::combine(HD::parameters::sigma(1.), HD::parameters::number_of_eigenpairs(150));
  const HD::Edge_weighted_heat_kernel<Mesh> kernel =
      coarse < 0 ? HD::Edge_weighted_heat_kernel<Mesh>(mesh, np)
                 : HD::Edge_weighted_heat_kernel<Mesh>(
                       mesh, HD::parameters::combine(np, HD::parameters::coarse_vertex_count(std::size_t(coarse))));
  auto lap = std::chrono::steady_clock::now();
  const HD::Anisotropic_heat_diffusion<Mesh> diffusion(kernel, time);
  const double operator_seconds = seconds_since(lap);
  lap = std::chrono::steady_clock::now();
  Eigen::VectorXd f0(Eigen::Index(mesh.number_of_vertices()));
  for(auto v : mesh.vertices())
    f0[Eigen::Index(kernel.vertex_index(v))] = kernel.normal_controlled_coordinates().normal_signature(v);
  const Eigen::VectorXd f10 = diffusion.diffuse(f0, 10);
  const double diffusion_seconds = seconds_since(lap);
  const double total = seconds_since(start);

  const HD::Heat_kernel_timings& t = kernel.timings();
  auto share = [&](double s) { return 100. * s / total; };
  std::printf("%9zu %8zu %8.2f | %5.1f%% %5.1f%% %5.1f%% %5.1f%% %5.1f%% %5.1f%% %5.1f%% | %6.2f | %7.1f %6zu | %.2e\n",
              mesh.number_of_vertices(), kernel.coarse_vertex_count(), total, share(t.normal_controlled_coordinates),
              share(t.simplification), share(t.operators), share(t.eigen_solve), share(t.rayleigh_ritz),
              share(operator_seconds), share(diffusion_seconds), peak_memory_gib(),
              diffusion.region_statistics().mean_size, diffusion.region_statistics().collapsed_regions,
              std::abs(f10.sum() - f0.sum()) / f0.cwiseAbs().sum());
  std::fflush(stdout);
}

} // namespace

int main(int argc, char* argv[])
{
  std::string data = CGAL_HEAT_DIFFUSION_DATA_DIR;
  int max_level = 3;
  long coarse = -1;  // automatic
  double time = 1.;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--max-level" && i + 1 < argc)
      max_level = std::atoi(argv[++i]);
    else if(a == "--coarse" && i + 1 < argc)
      coarse = std::atol(argv[++i]);
    else if(a == "--time" && i + 1 < argc)
      time = std::atof(argv[++i]);
    else
      data = a;
  }
  const std::string path = data + "/armadillo.off";
  std::printf("Scale curve: armadillo Loop-subdivided; sigma = 1, m = 150, t = %g, NS diffused by k = 10 steps\n", time);
  std::printf("coarse level: %s; stages as shares of the total (mesh in memory -> F^10)\n\n",
              coarse < 0 ? "automatic (above 100000 vertices: 20000)" : std::to_string(coarse).c_str());
  std::printf("%9s %8s %8s | %6s %6s %6s %6s %6s %6s %6s | %6s | %7s %6s | %s\n", "vertices", "coarse", "total s",
              "NCC", "simpl", "L,B", "eigen", "ritz", "A_t", "F^10", "GiB", "region", "coll.", "heat drift");
  for(int level = 0; level <= max_level; ++level)
  {
    std::fflush(stdout);  // or the child would print the parent's buffer again
    const pid_t child = fork();
    if(child == 0)
    {
      run_level(path, level, coarse, time);
      std::_Exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if(!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      std::printf("level %d failed (status %d)\n", level, status);
  }
  std::printf("\nGiB: peak resident memory of the process for that size (ru_maxrss), subdivision included.\n"
              "Re-run: build/bin/benchmark_scale_curve [DATA_DIR] [--max-level L] [--coarse N] [--time T]\n");
  return 0;
}
