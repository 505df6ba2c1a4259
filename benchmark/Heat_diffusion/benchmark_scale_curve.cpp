// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The scale curve of the spectral path with its coarse level (paper, eq. 21): CGAL's
// armadillo Loop-subdivided at benchmark time to about 100k, 400k and 1.6M vertices
// (nothing is committed), then, for each size, the time from mesh to the features of
// the NS diffused by k = 10 steps, each stage's share, and the peak memory. Each size
// runs in a child process so that its peak memory is its own.
//
// Usage: benchmark_scale_curve [DATA_DIR] [--min-level L] [--max-level L] [--coarse N] [--time T] [--order]
//                              [--denoising]
//
// --order also times one diffusion step (a 3-ring operator times a vector) in the
// vertex order of the mesh and in that of the package (along a Hilbert curve).
// --denoising times, instead of the pipeline, two parts of denoise_mesh(): CHOLMOD's
// simplicial and supernodal factorisations of the implicit cotangent flow's system (for
// the size from which the package uses the supernodal one, least_supernodal_size), and
// PMP's search for intersecting faces, sequential and parallel (the untangling's).
//
// At the paper's t = 1 the truncated kernel's peak h_t(j, j) is about m / n, below the
// threshold tau(1) = 0.005 once n exceeds 30000 or so: every heat region collapses and
// nothing diffuses (the 'coll.' column). The timings are still those of the pipeline;
// --time 75 (4 ln 10 / lambda_m on armadillo) shows the valid regime.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Heat_diffusion/internal/Denoising/cotangent_flow.h>
#include <CGAL/Heat_diffusion/internal/parallel_for.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include "benchmark_command_line.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HD = CGAL::Heat_diffusion;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double cpu_seconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double peak_memory_gib()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / (1024. * 1024.);  // ru_maxrss is in KiB on Linux
}

// Seconds of one diffusion step next = A current (row-major, as the package does it),
// best of 5 runs of 10 steps, sequential or parallel.
double step_seconds(const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, bool parallel)
{
  Eigen::VectorXd current = Eigen::VectorXd::Ones(a.rows()), next(a.rows());
  double best = 1e300;
  for(int run = 0; run < 5; ++run)
  {
    const auto start = std::chrono::steady_clock::now();
    for(int k = 0; k < 10; ++k)
    {
      auto row = [&](std::size_t i) {
        double sum = 0;
        for(Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(a, Eigen::Index(i)); it; ++it)
          sum += it.value() * current[it.index()];
        next[Eigen::Index(i)] = sum;
      };
      if(parallel)
        HD::internal::parallel_for(std::size_t(a.rows()), row);
      else
        for(std::size_t i = 0; i < std::size_t(a.rows()); ++i)
          row(i);
      current.swap(next);
    }
    best = (std::min)(best, seconds_since(start) / 10.);
  }
  return best;
}

// A column-stochastic operator with the sparsity of a real A_t of about 3 rings (the
// regions of the local kernel at t = 1 have 55 vertices on average): column j spreads
// the heat of v_j evenly over its 3-ring. Vertex i gets row number[i]. Row-major.
Eigen::SparseMatrix<double, Eigen::RowMajor> three_ring_operator(const HD::internal::Indexed_mesh& mesh,
                                                                 const std::vector<int>& number)
{
  const std::size_t n = mesh.number_of_vertices();
  std::vector<std::vector<int> > rings(n);
  std::vector<std::size_t> mark(n, 0);
  std::vector<std::size_t> queue;
  for(std::size_t j = 0; j < n; ++j)
  {
    queue.assign(1, j);
    mark[j] = j + 1;
    std::size_t begin = 0;
    for(int depth = 0; depth < 3; ++depth)
    {
      const std::size_t end = queue.size();
      for(std::size_t q = begin; q < end; ++q)
        for(std::size_t k = mesh.fan_begin[queue[q]]; k < mesh.fan_begin[queue[q] + 1]; ++k)
          if(mark[mesh.fan[k]] != j + 1)
          {
            mark[mesh.fan[k]] = j + 1;
            queue.push_back(mesh.fan[k]);
          }
      begin = end;
    }
    for(std::size_t i : queue)
      rings[j].push_back(number[i]);
    std::sort(rings[j].begin(), rings[j].end());
  }
  // the rings are symmetric: row number[i] has the entries 1/|ring(j)| at number[j], j in ring(i)
  std::vector<int> vertex_of(n);
  for(std::size_t i = 0; i < n; ++i)
    vertex_of[std::size_t(number[i])] = int(i);
  std::size_t total = 0;
  for(const auto& r : rings)
    total += r.size();
  Eigen::SparseMatrix<double, Eigen::RowMajor> a(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  a.resizeNonZeros(Eigen::Index(total));
  std::size_t position = 0;
  for(std::size_t row = 0; row < n; ++row)
  {
    a.outerIndexPtr()[row] = int(position);
    for(int column : rings[std::size_t(vertex_of[row])])
    {
      a.innerIndexPtr()[position] = column;
      a.valuePtr()[position] = 1. / double(rings[std::size_t(vertex_of[std::size_t(column)])].size());
      ++position;
    }
  }
  a.outerIndexPtr()[n] = int(position);
  return a;
}

// --order: one diffusion step in the vertex order of the mesh (Surface_mesh's own
// indices) and in the order of the package (vertex_index(): along a Hilbert curve
// from 100000 vertices on). At t = 1 the spectral A_t of these meshes is the identity
// (every region collapses), so the step is timed on the 3-ring operator above.
void measure_order(const Mesh& mesh, const HD::Edge_weighted_heat_kernel<Mesh>& kernel)
{
  const HD::internal::Indexed_mesh& indexed = kernel.normal_controlled_coordinates().indexed_mesh();
  const std::size_t n = mesh.number_of_vertices();
  std::vector<int> mesh_order(n), package_order(n);
  for(auto v : mesh.vertices())
    mesh_order[kernel.vertex_index(v)] = int(v.idx());
  for(std::size_t i = 0; i < n; ++i)
    package_order[i] = int(i);
  // mean index distance between the ends of an edge
  double mesh_distance = 0, package_distance = 0;
  for(auto e : mesh.edges())
  {
    const std::size_t i = kernel.vertex_index(mesh.vertex(e, 0)), j = kernel.vertex_index(mesh.vertex(e, 1));
    mesh_distance += std::abs(double(mesh_order[i]) - double(mesh_order[j]));
    package_distance += std::abs(double(i) - double(j));
  }
  const double edges = double(mesh.number_of_edges());
  double mesh_1, package_1, mesh_p, package_p;
  long nonzeros;
  {
    const Eigen::SparseMatrix<double, Eigen::RowMajor> a = three_ring_operator(indexed, mesh_order);
    nonzeros = long(a.nonZeros());
    mesh_1 = step_seconds(a, false);
    mesh_p = step_seconds(a, true);
  }
  {
    const Eigen::SparseMatrix<double, Eigen::RowMajor> a = three_ring_operator(indexed, package_order);
    package_1 = step_seconds(a, false);
    package_p = step_seconds(a, true);
  }
  const double bytes = double(nonzeros) * 12. + double(n) * 8. * 2. + double(n + 1) * 4.;
  std::printf("    order: 3-ring operator, %ld nonzeros (%.1f a row); mean |i - j| over edges: mesh %.0f, package %.0f\n"
              "    one step, 1 thread: mesh order %.2f ms (%.1f GB/s), package order %.2f ms (%.1f GB/s): %.2fx\n"
              "    one step, parallel: mesh order %.2f ms, package order %.2f ms: %.2fx\n",
              nonzeros, double(nonzeros) / double(n), mesh_distance / edges, package_distance / edges, 1e3 * mesh_1,
              bytes / mesh_1 * 1e-9, 1e3 * package_1, bytes / package_1 * 1e-9, mesh_1 / package_1, 1e3 * mesh_p,
              1e3 * package_p, mesh_p / package_p);
}

// --denoising: the system M + t L of the cotangent flow (t a squared mean edge length)
// factorised and solved for the three coordinates, each factorisation after its own
// symbolic analysis; then the search for intersecting faces. Best of 3 runs (1 from a
// million vertices).
void measure_denoising_parts(const Mesh& mesh)
{
  const int runs = mesh.number_of_vertices() < 1000000 ? 3 : 1;
  auto search_seconds = [&](auto tag) {
    double best = 1e300;
    for(int run = 0; run < runs; ++run)
    {
      std::vector<std::pair<Mesh::Face_index, Mesh::Face_index> > pairs;
      const auto start = std::chrono::steady_clock::now();
      CGAL::Polygon_mesh_processing::self_intersections<decltype(tag)>(mesh, std::back_inserter(pairs));
      best = (std::min)(best, seconds_since(start));
    }
    return best;
  };
  const double sequential = search_seconds(CGAL::Sequential_tag()),
               parallel = search_seconds(CGAL::Parallel_if_available_tag());
#ifdef CGAL_HEAT_DIFFUSION_USE_CHOLMOD
  const HD::internal::Indexed_mesh indexed =
      HD::internal::make_indexed_mesh(mesh, get(CGAL::vertex_point, mesh), get(CGAL::vertex_index, mesh));
  Eigen::SparseMatrix<double> stiffness;
  std::vector<double> masses;
  HD::internal::cotangent_stiffness(indexed, indexed.points, stiffness, masses);
  double squared_length = 0;
  for(const auto& t : indexed.triangles)
    squared_length += (indexed.points[t[1]] - indexed.points[t[0]]).squaredNorm();
  squared_length /= double(indexed.triangles.size());
  Eigen::SparseMatrix<double> system = squared_length * stiffness;
  for(std::size_t i = 0; i < masses.size(); ++i)
    system.coeffRef(Eigen::Index(i), Eigen::Index(i)) += masses[i];
  Eigen::MatrixXd coordinates(system.rows(), 3);
  for(std::size_t i = 0; i < indexed.points.size(); ++i)
    coordinates.row(Eigen::Index(i)) = indexed.points[i].transpose();
  auto seconds = [&](Eigen::CholmodMode mode) {
    double best = 1e300;
    for(int run = 0; run < runs; ++run)
    {
      HD::internal::Sparse_cholesky cholesky;
      cholesky.setMode(mode);
      cholesky.analyzePattern(system);
      const auto start = std::chrono::steady_clock::now();
      cholesky.factorize(system);
      const Eigen::MatrixXd solution = cholesky.solve(coordinates);
      best = (std::min)(best, seconds_since(start));
      if(cholesky.info() != Eigen::Success || !solution.allFinite())
        std::printf("    the factorisation failed\n");
    }
    return best;
  };
  const double simplicial = seconds(Eigen::CholmodSimplicialLLt), supernodal = seconds(Eigen::CholmodSupernodalLLt);
  std::printf("%9zu | %10.3f %10.3f %6.2f %10s | %10.3f %8.3f %6.2f\n", mesh.number_of_vertices(), simplicial,
              supernodal, simplicial / supernodal,
              system.rows() >= HD::internal::least_supernodal_size ? "supernodal" : "simplicial", sequential, parallel,
              parallel / sequential);
#else
  std::printf("%9zu | %10s %10s %6s %10s | %10.3f %8.3f %6.2f\n", mesh.number_of_vertices(), "-", "-", "-",
              "no CHOLMOD", sequential, parallel, parallel / sequential);
#endif
}

// One row of the table: subdivide, then mesh -> kernel -> A_t -> F^10.
void run_level(const std::string& path, int level, long coarse, double time, bool order, bool denoising)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh))
  {
    std::fprintf(stderr, "cannot read %s\n", path.c_str());
    std::exit(1);
  }
  if(level > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(level));
  if(denoising)
  {
    measure_denoising_parts(mesh);
    std::fflush(stdout);  // the child ends with _Exit, which does not flush
    return;
  }

  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_seconds();
  const auto np = HD::parameters::combine(HD::parameters::sigma(1.), HD::parameters::number_of_eigenpairs(150));
  const HD::Edge_weighted_heat_kernel<Mesh> kernel =
      coarse < 0 ? HD::Edge_weighted_heat_kernel<Mesh>(mesh, np)
                 : HD::Edge_weighted_heat_kernel<Mesh>(
                       mesh, HD::parameters::combine(np, HD::parameters::coarse_vertex_count(std::size_t(coarse))));
  auto lap = std::chrono::steady_clock::now();
  const HD::Anisotropic_heat_diffusion<Mesh> diffusion(kernel, time);
  const double operator_seconds = seconds_since(lap);
  lap = std::chrono::steady_clock::now();
  auto ns = mesh.add_property_map<Mesh::Vertex_index, double>("v:ns", 0.).first;
  for(auto v : mesh.vertices())
    ns[v] = kernel.normal_controlled_coordinates().normal_signature(v);
  const auto features = HD::detect_multiscale_features(diffusion, ns, std::vector<std::size_t>{10});
  const double diffusion_seconds = seconds_since(lap);
  const double total = seconds_since(start);
  const double cpu = cpu_seconds() - cpu_start;

  // heat drift of F^10 (not timed)
  Eigen::VectorXd f0(Eigen::Index(mesh.number_of_vertices()));
  for(auto v : mesh.vertices())
    f0[Eigen::Index(kernel.vertex_index(v))] = ns[v];
  const Eigen::VectorXd f10 = diffusion.diffuse(f0, 10);
  const HD::Heat_kernel_timings& t = kernel.timings();
  auto share = [&](double s) { return 100. * s / total; };
  std::printf("%9zu %8zu %8.2f %7.1f | %5.1f%% %5.1f%% %5.1f%% %5.1f%% %5.1f%% %5.1f%% %5.1f%% | %6.2f | %8.2e | %7.1f %7zu | %.2e | %zu/%zu\n",
              mesh.number_of_vertices(), kernel.coarse_vertex_count(), total, cpu, share(t.normal_controlled_coordinates),
              share(t.simplification), share(t.operators), share(t.eigen_solve), share(t.rayleigh_ritz),
              share(operator_seconds), share(diffusion_seconds), peak_memory_gib(),
              total / double(mesh.number_of_vertices()),
              diffusion.region_statistics().mean_size, diffusion.region_statistics().collapsed_regions,
              std::abs(f10.sum() - f0.sum()) / f0.cwiseAbs().sum(), features[0].convex.size(),
              features[0].concave.size());
  std::fflush(stdout);
  if(order)
    measure_order(mesh, kernel);
  std::fflush(stdout);
}

} // namespace

int main(int argc, char* argv[])
{
  std::string data = CGAL_HEAT_DIFFUSION_DATA_DIR;
  int min_level = 0, max_level = 3;
  long coarse = -1;  // automatic
  double time = 1.;
  bool order = false, denoising = false;
  namespace cli = heat_diffusion_cli;
  const std::string usage =
      "usage: benchmark_scale_curve [DATA_DIR] [--min-level L] [--max-level L] [--coarse N] [--time T] [--order]\n"
      "                             [--denoising]\n"
      "  --min-level, --max-level  Loop subdivisions of armadillo, 0 to 4 (default 0 and 3)\n"
      "  --coarse     the coarse level's vertices, 0 (none) or at least 4 (default: automatic)\n"
      "  --time       t (default 1)\n"
      "  --order      also one diffusion step in the mesh's order and in the package's\n"
      "  --denoising  two parts of denoise_mesh() instead of the pipeline\n";
  if(const auto exit_code = heat_diffusion_benchmark::read_command_line(
         argc, argv, {"--order", "--denoising"}, {"--min-level", "--max-level", "--coarse", "--time"}, usage,
         [&](const cli::Arguments& a) {
           data = heat_diffusion_benchmark::optional_argument(a, "DATA_DIR", data);
           min_level = int(cli::parse_count("--min-level", a.value("--min-level", "0"), 0, 4));
           max_level = int(cli::parse_count("--max-level", a.value("--max-level", "3"), 0, 4));
           if(min_level > max_level)
             throw cli::Usage_error("--min-level " + std::to_string(min_level) + " is above --max-level " +
                                    std::to_string(max_level));
           if(a.has("--coarse"))
           {
             coarse = long(cli::parse_count("--coarse", a.value("--coarse", ""), 0, 1e9));
             if(coarse > 0 && coarse < 4)
               throw cli::Usage_error("--coarse must be 0 (no coarse level) or at least 4, not '" +
                                      a.value("--coarse", "") + "'");
           }
           time = cli::parse_number("--time", a.value("--time", "1"), 0., true);
           order = a.flag("--order");
           denoising = a.flag("--denoising");
         }))
    return *exit_code;
  const std::string path = data + "/armadillo.off";
  if(denoising)
    std::printf("Two parts of denoise_mesh(), in seconds (best of 3; 1 from a million vertices); armadillo Loop-subdivided.\n"
                "The cotangent flow's system M + t L: CHOLMOD's numerical factorisation and solve for three right-hand\n"
                "sides; the search for intersecting faces (PMP::self_intersections)\n\n"
                "%9s | %10s %10s %6s %10s | %10s %8s %6s\n",
                "vertices", "simplicial", "supernodal", "ratio", "package", "sequential", "parallel", "ratio");
  else
  {
    std::printf("Scale curve: armadillo Loop-subdivided; sigma = 1, m = 150, t = %g, NS diffused by k = 10 steps\n", time);
    std::printf("coarse level: %s; stages as shares of the total (mesh in memory -> features of F^10)\n\n",
                coarse < 0 ? "automatic (above 100000 vertices: 20000)" : std::to_string(coarse).c_str());
    std::printf("%9s %8s %8s %7s | %6s %6s %6s %6s %6s %6s %6s | %6s | %8s | %7s %7s | %8s | %s\n", "vertices", "coarse",
                "total s", "CPU s", "NCC", "simpl", "L,B", "eigen", "ritz", "A_t", "feat.", "GiB", "s/vertex", "region", "coll.",
                "drift", "features");
  }
  bool failed = false;
  for(int level = min_level; level <= max_level; ++level)
  {
    std::fflush(stdout);  // or the child would print the parent's buffer again
    const pid_t child = fork();
    if(child == 0)
    {
      run_level(path, level, coarse, time, order, denoising);
      std::_Exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if(!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    {
      std::printf("level %d failed (status %d)\n", level, status);
      failed = true;
    }
  }
  if(denoising)
  {
    std::printf("\nratios: simplicial / supernodal, parallel / sequential; package: the factorisation that the package\n"
                "uses at that size. Re-run: build/bin/benchmark_scale_curve --denoising\n");
    return failed ? 1 : 0;
  }
  std::printf("\nGiB: peak resident memory of the process for that size (ru_maxrss), subdivision included.\n"
              "feat.: F^10 and its features (detect_multiscale_features, c = 0.8); features: convex/concave.\n"
              "total s: wall clock, mesh in memory -> features; CPU s: user + system time of the process over the same span;\n"
              "s/vertex: total s / vertices.\n"
              "Re-run: build/bin/benchmark_scale_curve [DATA_DIR] [--min-level L] [--max-level L] [--coarse N] [--time T] [--order]\n");
  return failed ? 1 : 0;
}
