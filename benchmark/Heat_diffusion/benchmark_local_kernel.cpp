// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The local heat kernel (Heat_kernel_method::local) against the spectral one.
//
// Table 1: on fandisk and armadillo, t = 1: the time to A_t from the mesh with each
//          kernel (NCC, L, B, then the eigen solve and A_t, or the local columns and
//          A_t), their ratio (wall clock, and CPU time of all threads), and the heat
//          regions.
// Table 2: scaling in n: armadillo Loop-subdivided (CGAL::Subdivision_method_3) at run
//          time to about 100k, 400k and 1.6M vertices; end to end from the mesh to the
//          features of the Normal Signature at k = 10 with the local kernel (NCC,
//          operators, A_t and its balancing, diffusion, features), then with the local
//          kernel at its earlier default tolerance 1e-4, then with the
//          spectral kernel and its automatic coarse level on the same mesh (the ratios of
//          their totals to the first), and the peak memory (getrusage's ru_maxrss). The balancing of
//          A_t is timed from the progress callback's report that the heat regions are
//          done to the end of the construction, with the products it took. Each run has
//          its own process, so that each peak is its own.
//
// Table 3: the balanced A_t (Operator_normalization::balanced, the default) against the
//          paper's column-normalised one on fandisk and armadillo, sigma 0.1 and 1,
//          t = 0.5 to 4, both from the local kernel: the products the balancing took,
//          its time against the construction of A_t, the distance between the columns
//          of the two operators (relative L2: median, 99th percentile, worst), and the
//          row sums of the column-normalised one, which the balancing brings to 1.
//
// Usage: benchmark_local_kernel [DATA_DIR] [--levels L] [--first-level F] [--no-table-1]
//                               [--no-table-3] [--no-spectral] [--time T] [--sigma S] [--repeat R]
//   L (default 3): Loop subdivision levels of table 2 (3 gives 1.6M vertices: minutes);
//   F (default 0): the first level of table 2 (L = -1 skips table 2);
//   R (default 1): the runs of each kernel per level of table 2, alternating local and
//                  spectral; with R > 1, a last row per level gives the medians, and
//                  the ratios of NCC + A_t, default / 1e-4, in wall and in CPU time;
//   --no-spectral: table 2 without the spectral runs.
// Wall-clock times: the eigen solve and the large meshes take seconds to minutes, and
// the machine may be shared, so compare within a run (and repeat the runs of table 2:
// their ratio moves by several percent from run to run).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include "benchmark_command_line.h"
#include "benchmark_mesh.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace HD = CGAL::Heat_diffusion;
typedef HD::Edge_weighted_heat_kernel<Mesh> Heat_kernel;
typedef HD::Anisotropic_heat_diffusion<Mesh> Diffusion;

volatile double benchmark_sink = 0;

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// CPU seconds of the process so far (all threads): less sensitive than the wall clock
// to the other jobs on a shared machine.
double cpu_seconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// The median of the values (the mean of the middle two for an even count).
double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

double peak_memory_gib()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / (1024. * 1024.);  // ru_maxrss is in KiB on Linux
}

Mesh load(const std::string& path) { return heat_diffusion_benchmark::load_mesh_or_exit<Mesh>(path); }

void compare_kernels(const std::string& data, double t, double sigma)
{
  std::printf("\nTable 1: time to A_t from the mesh, t = %g, sigma = %g, m = 150 (%u threads)\n", t, sigma,
              std::thread::hardware_concurrency());
  std::printf("| mesh | n | spectral: NCC + L, B + eigen solve | + A_t | total s | local: NCC + L, B + A_t s |"
              " spectral / local | CPU s spectral / local (ratio) | regions spectral min/mean/max (collapsed) | local |\n"
              "|---|---|---|---|---|---|---|---|---|---|\n");
  for(const char* name : {"fandisk.off", "armadillo.off"})
  {
    const Mesh mesh = load(data + "/" + name);
    const auto sigma_parameter = HD::parameters::sigma(sigma);
    double cpu = cpu_seconds();
    auto start = std::chrono::steady_clock::now();
    const Heat_kernel kernel(mesh, HD::parameters::combine(sigma_parameter, HD::parameters::number_of_eigenpairs(150)));
    const double eigen_seconds = seconds_since(start);
    start = std::chrono::steady_clock::now();
    const Diffusion spectral(kernel, t);
    const double operator_seconds = seconds_since(start);
    const double spectral_cpu = cpu_seconds() - cpu;
    cpu = cpu_seconds();
    start = std::chrono::steady_clock::now();
    const Diffusion local(mesh, HD::parameters::combine(sigma_parameter, HD::parameters::time(t),
                                                        HD::parameters::kernel_method(HD::Heat_kernel_method::local)));
    const double local_seconds = seconds_since(start);
    const double local_cpu = cpu_seconds() - cpu;
    benchmark_sink = spectral.operator_matrix().sum() + local.operator_matrix().sum();
    const auto& a = spectral.region_statistics();
    const auto& b = local.region_statistics();
    std::printf("| %s | %zu | %.2f | %.3f | %.2f | %.2f | %.2f | %.2f / %.2f (%.2f) | %zu / %.1f / %zu (%zu) | %zu / %.1f / %zu (%zu) |\n",
                name, std::size_t(mesh.number_of_vertices()), eigen_seconds, operator_seconds,
                eigen_seconds + operator_seconds, local_seconds, (eigen_seconds + operator_seconds) / local_seconds,
                spectral_cpu, local_cpu, spectral_cpu / local_cpu, a.min_size, a.mean_size, a.max_size, a.collapsed_regions, b.min_size, b.mean_size, b.max_size,
                b.collapsed_regions);
    std::fflush(stdout);
  }
}

void compare_normalizations(const std::string& data)
{
  std::printf("\nTable 3: the balanced A_t against the column-normalised one (local kernel, %u threads)\n",
              std::thread::hardware_concurrency());
  std::printf("| mesh | sigma | t | products | balancing s | A_t s | share | column distance: median | 99th percentile |"
              " worst | row sums of the column-normalised A_t |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const char* name : {"fandisk.off", "armadillo.off"})
  {
    const Mesh mesh = load(data + "/" + name);
    for(double sigma : {0.1, 1.})
      for(double t : {0.5, 1., 2., 4.})
      {
        const auto np = HD::parameters::combine(HD::parameters::sigma(sigma), HD::parameters::time(t),
                                                HD::parameters::kernel_method(HD::Heat_kernel_method::local));
        std::chrono::steady_clock::time_point regions_done{};
        const std::function<bool(double)> progress = [&](double fraction) {
          if(fraction >= 0.95 && regions_done == std::chrono::steady_clock::time_point{})
            regions_done = std::chrono::steady_clock::now();
          return true;
        };
        const auto start = std::chrono::steady_clock::now();
        const Diffusion balanced(mesh, HD::parameters::combine(np, HD::parameters::progress_callback(progress)));
        const double total = seconds_since(start);
        const double balancing = std::chrono::duration<double>(std::chrono::steady_clock::now() - regions_done).count();
        const Diffusion columns(
            mesh, HD::parameters::combine(np, HD::parameters::operator_normalization(HD::Operator_normalization::columns)));
        const Eigen::SparseMatrix<double>& A = balanced.operator_matrix();
        const Eigen::SparseMatrix<double>& C = columns.operator_matrix();
        std::vector<double> distance;
        for(Eigen::Index j = 0; j < A.cols(); ++j)
        {
          const Eigen::VectorXd a = A.col(j), c = C.col(j);
          distance.push_back((a - c).norm() / c.norm());
        }
        std::sort(distance.begin(), distance.end());
        const Eigen::VectorXd row_sums = C * Eigen::VectorXd::Ones(C.cols());
        std::printf("| %s | %g | %g | %zu | %.3f | %.3f | %.1f %% | %.3f | %.3f | %.3f | %.2f to %.2f |\n", name, sigma, t,
                    balanced.balancing_iterations(), balancing, total - balancing, 100. * balancing / total,
                    distance[distance.size() / 2], distance[distance.size() * 99 / 100], distance.back(),
                    row_sums.minCoeff(), row_sums.maxCoeff());
        std::fflush(stdout);
      }
  }
}

// Runs `f` in a child process: a process forked after TBB has started its workers gets
// none of them, and the runs of table 2 would then use one thread.
template <typename Function>
void run_in_child(const char* what, const Function& f)
{
  const pid_t child = fork();
  if(child == 0)
  {
    f();
    std::_Exit(EXIT_SUCCESS);
  }
  int status = 0;
  waitpid(child, &status, 0);
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    std::printf("(%s failed, status %d)\n", what, status);
}

// One row of table 2, in the calling process (run it in a child for its own peak):
// the local kernel (at its default tolerance, or at `tolerance` if given), or the
// spectral one of m = 150 eigenpairs with the package's automatic coarse level (above
// 100k vertices).
struct Run_seconds
{
  double total = 0;      // to the features, wall
  double build = 0;      // NCC + L, B (+ eigenpairs) + A_t, wall
  double build_cpu = 0;  // the same, CPU seconds of all threads
};

Run_seconds end_to_end(const Mesh& base, int levels, double t, double sigma, HD::Heat_kernel_method method,
                       double local_seconds, std::optional<double> tolerance = std::nullopt)
{
  Mesh mesh = base;
  if(levels > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
  const double before = peak_memory_gib();
  const double cpu_start = cpu_seconds();
  const auto start = std::chrono::steady_clock::now();
  // The construction reports 0.95 when the heat regions are done and the balancing starts.
  std::chrono::steady_clock::time_point regions_done{};
  const std::function<bool(double)> progress = [&](double fraction) {
    if(fraction >= 0.95 && regions_done == std::chrono::steady_clock::time_point{})
      regions_done = std::chrono::steady_clock::now();
    return true;
  };
  const Diffusion diffusion(mesh, HD::parameters::combine(HD::parameters::sigma(sigma), HD::parameters::time(t),
                                                          HD::parameters::kernel_method(method),
                                                          HD::parameters::local_kernel_tolerance(tolerance),
                                                          HD::parameters::progress_callback(progress)));
  const double build_seconds = seconds_since(start);
  const double build_cpu_seconds = cpu_seconds() - cpu_start;
  const double balancing_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - regions_done).count();
  auto ns = mesh.add_property_map<Mesh::Vertex_index, double>("v:ns").first;
  for(auto v : mesh.vertices())
    ns[v] = diffusion.normal_controlled_coordinates().normal_signature(v);
  const auto features = HD::detect_multiscale_features(diffusion, ns, {10});
  const double total_seconds = seconds_since(start);
  benchmark_sink = double(features[0].convex.size() + features[0].concave.size());
  const auto& r = diffusion.region_statistics();
  const double n = double(mesh.number_of_vertices());
  const bool local = method == HD::Heat_kernel_method::local;
  std::string kernel =
      tolerance ? "local, tolerance " + heat_diffusion_cli::format_number(*tolerance) : std::string("local");
  if(!local)
  {
    const std::size_t coarse = diffusion.heat_kernel().coarse_vertex_count();
    kernel = coarse > 0 ? "spectral, coarse " + std::to_string(coarse) : std::string("spectral");
  }
  char ratio[32] = "";
  if(local_seconds > 0)
    std::snprintf(ratio, sizeof(ratio), "%.2f", total_seconds / local_seconds);
  std::printf("| %d | %zu | %s | %.1f | %.1f | %.2f (%zu, %.1f %%) | %.1f | %s | %.2f | %.2f | %.2f | %zu / %.1f / %zu (%zu) |\n",
              levels, std::size_t(mesh.number_of_vertices()), kernel.c_str(), build_seconds, build_cpu_seconds,
              balancing_seconds,
              diffusion.balancing_iterations(), 100. * balancing_seconds / build_seconds, total_seconds, ratio,
              1e6 * total_seconds / n, before, peak_memory_gib(), r.min_size, r.mean_size, r.max_size,
              r.collapsed_regions);
  std::fflush(stdout);
  return {total_seconds, build_seconds, build_cpu_seconds};
}

// Runs end_to_end() in a child process, so that its peak memory is its own; returns its
// seconds (all 0 if it failed).
Run_seconds end_to_end_in_child(const Mesh& base, int levels, double t, double sigma, HD::Heat_kernel_method method,
                                double local_seconds, std::optional<double> tolerance = std::nullopt)
{
  int channel[2];
  if(pipe(channel) != 0)
    return {};
  const pid_t child = fork();
  if(child == 0)
  {
    close(channel[0]);
    const Run_seconds seconds = end_to_end(base, levels, t, sigma, method, local_seconds, tolerance);
    benchmark_sink = double(write(channel[1], &seconds, sizeof(seconds)));
    std::_Exit(EXIT_SUCCESS);
  }
  close(channel[1]);
  Run_seconds seconds;
  if(read(channel[0], &seconds, sizeof(seconds)) != ssize_t(sizeof(seconds)))
    seconds = Run_seconds();
  close(channel[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    std::printf("| %d | (the run failed, status %d) |\n", levels, status);
  return seconds;
}

int main(int argc, char** argv)
{
  std::string data = CGAL_HEAT_DIFFUSION_DATA_DIR;
  int levels = 3, first_level = 0, repeat = 1;
  bool table_1 = true, table_3 = true, spectral = true;
  double t = 1., sigma = 0.1;
  namespace cli = heat_diffusion_cli;
  const std::string usage =
      "usage: benchmark_local_kernel [DATA_DIR] [--levels L] [--first-level F] [--no-table-1] [--no-table-3]\n"
      "                              [--no-spectral] [--time T] [--sigma S] [--repeat R]\n"
      "  --levels       Loop subdivisions of table 2, -1 (no table 2) to 4 (default 3: 1.6M vertices)\n"
      "  --first-level  the first level of table 2, 0 to 4 (default 0)\n"
      "  --time, --sigma  t (default 1) and sigma (default 0.1) of tables 1 and 2\n"
      "  --repeat       runs of each kernel per level of table 2, 1 to 100 (default 1)\n"
      "  --no-spectral  table 2 without the spectral kernel\n";
  if(const auto exit_code = heat_diffusion_benchmark::read_command_line(
         argc, argv, {"--no-table-1", "--no-table-3", "--no-spectral"}, {"--levels", "--first-level", "--time", "--sigma", "--repeat"},
         usage, [&](const cli::Arguments& a) {
           data = heat_diffusion_benchmark::optional_argument(a, "DATA_DIR", data);
           const std::string levels_text = a.value("--levels", "3");
           try
           {
             levels = levels_text == "-1" ? -1 : int(cli::parse_count("--levels", levels_text, 0, 4));
           }
           catch(const cli::Usage_error&)  // its message would say "from 0 to 4"
           {
             throw cli::Usage_error("--levels must be a whole number from -1 (no table 2) to 4, not '" + levels_text + "'");
           }
           first_level = int(cli::parse_count("--first-level", a.value("--first-level", "0"), 0, 4));
           if(levels >= 0 && first_level > levels)
             throw cli::Usage_error("--first-level " + std::to_string(first_level) + " is above --levels " +
                                    std::to_string(levels));
           table_1 = !a.flag("--no-table-1");
           table_3 = !a.flag("--no-table-3");
           spectral = !a.flag("--no-spectral");
           t = cli::parse_number("--time", a.value("--time", "1"), 0., true);
           sigma = cli::parse_number("--sigma", a.value("--sigma", "0.1"), 0., true);
           repeat = int(cli::parse_count("--repeat", a.value("--repeat", "1"), 1, 100));
         }))
    return *exit_code;
  try
  {
    if(table_1)
      run_in_child("table 1", [&] { compare_kernels(data, t, sigma); });
    const Mesh armadillo = load(data + "/armadillo.off");
    std::printf("\nTable 2: armadillo, Loop-subdivided, end to end to the features at k = 10 (t = %g, sigma = %g):"
                " the local kernel, then at its earlier default tolerance 1e-4, then the spectral one"
                " (m = 150, automatic coarse level) on the same mesh; total / local is against the first\n", t, sigma);
    std::printf("| levels | n | kernel | NCC + L, B (+ eigenpairs) + A_t s | its CPU s (all threads) | of which the"
                " balancing s (products, share) | + F^10 and features (total) s | total / local | total us / vertex |"
                " memory before GiB | peak GiB | regions min/mean/max (collapsed) |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::fflush(stdout);
    for(int level = first_level; level <= levels; ++level)
    {
      std::vector<double> local_runs, previous_runs, spectral_runs, ratios, previous_ratios, build_ratios,
          build_cpu_ratios;
      for(int run = 0; run < repeat; ++run)
      {
        const Run_seconds local = end_to_end_in_child(armadillo, level, t, sigma, HD::Heat_kernel_method::local, 0.);
        const Run_seconds previous =
            end_to_end_in_child(armadillo, level, t, sigma, HD::Heat_kernel_method::local, local.total, 1e-4);
        const Run_seconds spectral_run =
            spectral ? end_to_end_in_child(armadillo, level, t, sigma, HD::Heat_kernel_method::spectral, local.total)
                     : Run_seconds();
        if(local.total > 0 && previous.total > 0 && (!spectral || spectral_run.total > 0))
        {
          local_runs.push_back(local.total);
          previous_runs.push_back(previous.total);
          previous_ratios.push_back(previous.total / local.total);
          build_ratios.push_back(local.build / previous.build);
          build_cpu_ratios.push_back(local.build_cpu / previous.build_cpu);
          if(spectral)
          {
            spectral_runs.push_back(spectral_run.total);
            ratios.push_back(spectral_run.total / local.total);
          }
        }
      }
      if(repeat > 1 && !local_runs.empty())
      {
        auto summary = [](const std::vector<double>& x) {
          const auto [least, most] = std::minmax_element(x.begin(), x.end());
          char text[64];
          std::snprintf(text, sizeof(text), "%.2f (%.2f to %.2f)", median(x), *least, *most);
          return std::string(text);
        };
        std::string spectral_text = "no spectral runs";
        if(spectral)
          spectral_text = "spectral " + summary(ratios);
        std::printf("| %d | median of %zu runs each | local %.1f s, at 1e-4 %.1f s%s | NCC + A_t, local / 1e-4: %s,"
                    " CPU %s | | | total / local: 1e-4 %s; %s | | | | |\n",
                    level, local_runs.size(), median(local_runs), median(previous_runs),
                    spectral ? (", spectral " + heat_diffusion_cli::format_number(median(spectral_runs)) + " s").c_str()
                             : "",
                    summary(build_ratios).c_str(), summary(build_cpu_ratios).c_str(), summary(previous_ratios).c_str(),
                    spectral_text.c_str());
        std::fflush(stdout);
      }
    }
    if(table_3)
      run_in_child("table 3", [&] { compare_normalizations(data); });
  }
  catch(const std::exception& e)
  {
    std::fprintf(stderr, "benchmark_local_kernel: %s\n", e.what());
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
