// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Times the stages of the package on CGAL's meshes and prints them next to the
// paper's Table 1 (2.67 GHz CPU, MATLAB) and next to baselines measured in the same
// run on the same mesh, since the machine may be shared and noisy.
//
// Table 1: the NCC alone, on four meshes, against CGAL's vertex normals.
// Table 2: the whole pipeline of the paper's Table 1 (NCC, eigen solve, convolution)
//          on fandisk and armadillo, for sigma = 0.1 and 1, m = 150, t = 1, with the
//          construction of A_t, the isotropic global heat smoothing as a baseline, the
//          heat regions and the conservation of the total heat.
//
// Usage: benchmark_heat_diffusion [DATA_DIR] [--repeats R] [--eigen-repeats E]
//   R (default 21): runs of the NCC and of the construction of A_t; the diffusion
//                   steps and the global smoothing are timed 10 R + 1 times;
//   E (default 3):  runs of the eigen solve (seconds each on armadillo).
// All times are medians of wall-clock times; the program takes about a minute on
// 2 cores with the defaults.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/internal/generalized_eigensolver.h>
#include <CGAL/Heat_diffusion/internal/heat_operators.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Core>

#include "benchmark_command_line.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Heat_diffusion::Normal_controlled_coordinates<Mesh> NCC;
typedef CGAL::Heat_diffusion::Edge_weighted_heat_kernel<Mesh> Heat_kernel;
typedef CGAL::Heat_diffusion::Anisotropic_heat_diffusion<Mesh> Diffusion;
namespace HD = CGAL::Heat_diffusion;
namespace PMP = CGAL::Polygon_mesh_processing;

// Results of the timed computations are written here, so that the compiler cannot
// drop a computation whose result would otherwise be unused.
volatile double benchmark_sink = 0;

double milliseconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The median of `values` (the upper one for an even count).
double median(std::vector<double> values)
{
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// Median wall-clock time of `repeats` runs, in milliseconds.
double median_ms(int repeats, const std::function<void()>& run)
{
  std::vector<double> times;
  for(int r = 0; r < repeats; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    run();
    times.push_back(milliseconds_since(start));
  }
  return median(times);
}

bool read_mesh(const std::string& data, const std::string& file, Mesh& mesh)
{
  if(CGAL::IO::read_polygon_mesh(data + "/" + file, mesh))
    return true;
  std::fprintf(stderr, "cannot read %s/%s\n", data.c_str(), file.c_str());
  return false;
}

// One row of the paper's Table 1, and the CGAL mesh that is timed in its place.
struct Paper_table1_row
{
  const char* mesh_file;     // CGAL's mesh
  const char* paper_mesh;    // the mesh of the paper's figures
  double paper_vertices;
  double ncc_seconds;
  double eigen_seconds;
  double convolution_seconds;
};

// The paper's Table 1 (seconds). CGAL's data set has no Dinosaur: armadillo
// (26002 vertices) stands in for the paper's 28287-vertex Dinosaur.
const Paper_table1_row paper_table1[] = {{"fandisk.off", "Fandisk", 6475, 0.619, 3.944, 0.119},
                                         {"armadillo.off", "Dinosaur", 28287, 2.919, 16.554, 0.519}};

// The row timed on `mesh_file`, or null.
const Paper_table1_row* paper_row(const std::string& mesh_file)
{
  for(const Paper_table1_row& row : paper_table1)
    if(mesh_file == row.mesh_file)
      return &row;
  return nullptr;
}

// ---------------------------------------------------------------------------
// Table 1: NCC on four meshes.

int print_ncc_table(const std::string& data, int repeats)
{
  const std::vector<std::string> meshes = {"fandisk.off", "armadillo.off", "bunny00.off", "refined_elephant.off"};

  std::printf("TABLE 1. NCC (Normal_controlled_coordinates: indexing, MWAAT normals, mean value weights, Voronoi areas, NS)\n");
  std::printf("median of %d runs; baseline: CGAL::Polygon_mesh_processing::compute_vertex_normals on the same mesh\n\n",
              repeats);
  std::printf("%-22s %9s %10s %12s %14s %12s %16s\n", "mesh", "vertices", "NCC ms", "ns/vertex", "PMP normals ms",
              "NCC/normals", "paper NCC ms (x)");
  for(const std::string& file : meshes)
  {
    Mesh mesh;
    if(!read_mesh(data, file, mesh))
      return 1;
    const double n = double(mesh.number_of_vertices());
    const double ncc_ms = median_ms(repeats, [&] {
      const NCC ncc(mesh);
      benchmark_sink = ncc.normal_signature(*mesh.vertices().begin());
    });
    auto normals = mesh.add_property_map<Mesh::Vertex_index, K::Vector_3>("v:bench_normals").first;
    const double normals_ms = median_ms(repeats, [&] { PMP::compute_vertex_normals(mesh, normals); });
    char paper[64] = "-";
    if(const Paper_table1_row* row = paper_row(file))
    {
      // Scaled to this mesh's vertex count (the NCC is linear).
      const double paper_ms = row->ncc_seconds * 1e3 * n / row->paper_vertices;
      std::snprintf(paper, sizeof paper, "%.0f (%.0fx)", paper_ms, paper_ms / ncc_ms);
    }
    std::printf("%-22s %9.0f %10.2f %12.0f %14.2f %12.2f %16s\n", file.c_str(), n, ncc_ms, ncc_ms * 1e6 / n,
                normals_ms, ncc_ms / normals_ms, paper);
  }
  std::printf("\nThe paper's Dinosaur figure is scaled to armadillo's vertex count (linear cost).\n");
  return 0;
}

// ---------------------------------------------------------------------------
// Table 2: the pipeline of the paper's Table 1.

// The paper's figures are for its own mesh: they are scaled linearly to the number of
// vertices of the CGAL mesh before the speed-up is computed (the NCC and a diffusion
// step are linear in n; the eigen solve grows at least linearly, so for it the scaling
// flatters neither side); for fandisk, the same mesh, the factor is 1.
void print_stage_header()
{
  std::printf("  %-34s %10s %6s %10s %18s %11s\n", "stage", "ours ms", "runs", "paper ms", "paper ms, n-scaled",
              "paper/ours");
}

void print_stage(const char* stage, double ours_ms, int runs, double paper_seconds, double vertex_scale)
{
  char runs_text[16] = "-";
  if(runs > 0)
    std::snprintf(runs_text, sizeof runs_text, "%d", runs);
  if(paper_seconds > 0)
    std::printf("  %-34s %10.3f %6s %10.0f %18.0f %10.0fx\n", stage, ours_ms, runs_text, paper_seconds * 1e3,
                paper_seconds * 1e3 * vertex_scale, paper_seconds * 1e3 * vertex_scale / ours_ms);
  else
    std::printf("  %-34s %10.3f %6s %10s %18s %11s\n", stage, ours_ms, runs_text, "-", "-", "-");
}

// The Normal Signature of every vertex, in the kernel's vertex order: the field that
// the paper diffuses.
Eigen::VectorXd normal_signature_field(const Mesh& mesh, const Heat_kernel& kernel)
{
  Eigen::VectorXd field(Eigen::Index(kernel.number_of_vertices()));
  for(Mesh::Vertex_index v : mesh.vertices())
    field[Eigen::Index(kernel.vertex_index(v))] = kernel.normal_controlled_coordinates().normal_signature(v);
  return field;
}

// |sum F - sum F0| / sum |F0|: the drift of the total heat, relative to the heat that
// is moved (the NS is signed, its plain sum can be close to zero).
double vertex_sum_drift(const Eigen::VectorXd& initial, const Eigen::VectorXd& diffused)
{
  return std::abs(diffused.sum() - initial.sum()) / initial.cwiseAbs().sum();
}

// The same with the integral of the field over the surface, 1^T B F, as the total
// heat: the quantity that the global smoothing conserves (its constant mode is
// B-orthogonal to all others), whereas A_t conserves the plain vertex sum.
double area_weighted_drift(const Eigen::SparseMatrix<double>& mass, const Eigen::VectorXd& initial,
                           const Eigen::VectorXd& diffused)
{
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(initial.size());
  return std::abs(ones.dot(mass * (diffused - initial))) / ones.dot(mass * initial.cwiseAbs());
}

struct Table2_settings
{
  std::size_t number_of_eigenpairs = 150;
  double time = 1.;
  int short_repeats = 21;   // NCC, A_t
  int step_repeats = 211;   // one diffusion step, global smoothing
  int eigen_repeats = 3;    // L and B + eigen solve
  std::size_t drift_steps = 1000;
  double target_operator_to_eigen_ratio = 0.25;
};

// The timings and statistics of one mesh and one sigma.
void print_pipeline(const Mesh& mesh, const Paper_table1_row& paper, double sigma, double ncc_ms,
                   const Heat_kernel& isotropic_kernel, const Table2_settings& settings)
{
  const double n = double(mesh.number_of_vertices());
  const double vertex_scale = n / paper.paper_vertices;
  std::printf("\n-- %s, sigma = %g, m = %zu, t = %g --\n", paper.mesh_file, sigma, settings.number_of_eigenpairs,
              settings.time);

  // The eigen solve, stage by stage, with the package's own internal functions: the
  // same calls as the constructor of Edge_weighted_heat_kernel after its NCC.
  const NCC ncc(mesh);
  std::vector<double> assembly_ms, solve_ms, eigen_ms;
  HD::internal::Generalized_eigenpairs pairs;
  for(int r = 0; r < settings.eigen_repeats; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    const HD::internal::Heat_operators operators =
        HD::internal::assemble_heat_operators(ncc.indexed_mesh(), ncc.data(), sigma);
    assembly_ms.push_back(milliseconds_since(start));
    const auto solve_start = std::chrono::steady_clock::now();
    pairs = HD::internal::compute_smallest_generalized_eigenpairs(operators.stiffness, operators.mass,
                                                                  Eigen::Index(settings.number_of_eigenpairs));
    solve_ms.push_back(milliseconds_since(solve_start));
    eigen_ms.push_back(milliseconds_since(start));
  }
  const double eigen_median_ms = median(eigen_ms);

  // The public kernel, built once for the stages below; its construction minus the NCC
  // cross-checks the stage timing above (a single run, so noisier).
  const auto kernel_start = std::chrono::steady_clock::now();
  const Heat_kernel kernel(mesh, HD::parameters::combine(HD::parameters::sigma(sigma),
                                                         HD::parameters::number_of_eigenpairs(settings.number_of_eigenpairs)));
  const double kernel_ms = milliseconds_since(kernel_start);

  // A_t: the previous operator is freed before the clock starts, so that only the
  // construction is timed.
  std::unique_ptr<Diffusion> diffusion;
  std::vector<double> operator_times;
  for(int r = 0; r < settings.short_repeats; ++r)
  {
    diffusion.reset();
    const auto start = std::chrono::steady_clock::now();
    diffusion = std::make_unique<Diffusion>(kernel, settings.time);
    operator_times.push_back(milliseconds_since(start));
  }
  const double operator_ms = median(operator_times);

  const Eigen::VectorXd field = normal_signature_field(mesh, kernel);
  auto time_diffusion = [&](std::size_t steps) {
    return median_ms(settings.step_repeats, [&] { benchmark_sink = diffusion->diffuse(field, steps)[0]; });
  };
  auto time_global_smoothing = [&](double t) {
    return median_ms(settings.step_repeats,
                     [&] { benchmark_sink = isotropic_kernel.global_heat_smoothing(field, t)[0]; });
  };
  const double step_ms = time_diffusion(1);

  print_stage_header();
  print_stage("NCC", ncc_ms, settings.short_repeats, paper.ncc_seconds, vertex_scale);
  print_stage("eigen solve (L, B + eigenpairs)", eigen_median_ms, settings.eigen_repeats, paper.eigen_seconds,
              vertex_scale);
  print_stage("  assembly of L and B", median(assembly_ms), settings.eigen_repeats, -1, 1);
  print_stage("  Cholesky + Lanczos", median(solve_ms), settings.eigen_repeats, -1, 1);
  print_stage("  check: kernel construction - NCC", kernel_ms - ncc_ms, 1, -1, 1);
  print_stage("A_t construction", operator_ms, settings.short_repeats, -1, 1);
  print_stage("one diffusion step (convolution)", step_ms, settings.step_repeats, paper.convolution_seconds,
              vertex_scale);
  // The paper's convolution may include evaluating the kernel over the heat regions,
  // which A_t does once for all steps: this row bounds the comparison from below.
  print_stage("A_t construction + one step", operator_ms + step_ms, -1, paper.convolution_seconds, vertex_scale);
  std::printf("  Lanczos: %lld restarts, %lld operator applications, subspace %lld, shift %.3g%s\n",
              static_cast<long long>(pairs.iterations), static_cast<long long>(pairs.operator_applications),
              static_cast<long long>(pairs.subspace_dimension), pairs.shift,
              pairs.reorthonormalized ? ", re-orthonormalised" : "");

  const double ratio = operator_ms / eigen_median_ms;
  std::printf("\n  A_t construction / eigen solve = %.3f (target < %.2f: %s)\n", ratio,
              settings.target_operator_to_eigen_ratio,
              ratio < settings.target_operator_to_eigen_ratio ? "met" : "NOT met");

  std::printf("\n  local diffusion vs isotropic global heat smoothing (sigma = inf, same m), NS field, median of %d runs\n",
              settings.step_repeats);
  std::printf("  %6s %18s %36s %13s\n", "k", "diffuse(F, k) ms", "global_heat_smoothing(F, k t) ms", "global/local");
  for(std::size_t k : {std::size_t(1), std::size_t(10)})
  {
    const double local_ms = time_diffusion(k);
    const double global_ms = time_global_smoothing(double(k) * settings.time);
    std::printf("  %6zu %18.3f %36.3f %12.1fx\n", k, local_ms, global_ms, global_ms / local_ms);
  }

  // The truncated kernel is accurate only for t >~ 4 ln 10 / lambda_m (see
  // Edge_weighted_heat_kernel); below, it is too flat and regions collapse.
  const HD::Heat_region_statistics& regions = diffusion->region_statistics();
  const double lambda_m = kernel.eigenvalues()[kernel.eigenvalues().size() - 1];
  std::printf("\n  heat regions (t = %g, tau = %.4g): min %zu, mean %.1f, max %zu vertices; collapsed %zu (%.1f%%), "
              "capped %zu\n",
              settings.time, diffusion->threshold(), regions.min_size, regions.mean_size, regions.max_size,
              regions.collapsed_regions, 100. * double(regions.collapsed_regions) / n, regions.capped_regions);
  std::printf("  kernel: lambda_m = %.4g, accurate for t >= 4 ln 10 / lambda_m = %.0f; %zu connected component(s)\n",
              lambda_m, 4. * std::log(10.) / lambda_m, kernel.number_of_connected_components());

  const std::size_t k = settings.drift_steps;
  const double t_global = double(k) * settings.time;
  const Eigen::VectorXd local = diffusion->diffuse(field, k);
  const Eigen::VectorXd global = isotropic_kernel.global_heat_smoothing(field, t_global);
  const Eigen::SparseMatrix<double>& mass = isotropic_kernel.mass_matrix();
  std::printf("\n  total heat drift, NS field   %32s %30s\n", "|sum F - sum F0| / sum|F0|",
              "|1'B(F - F0)| / 1'B|F0|");
  std::printf("  local diffusion, k = %-7zu  %32.2e %30.2e\n", k, vertex_sum_drift(field, local),
              area_weighted_drift(mass, field, local));
  std::printf("  global (sigma = inf), t = %-4g %31.2e %30.2e\n", t_global, vertex_sum_drift(field, global),
              area_weighted_drift(mass, field, global));
}

int print_pipeline_table(const std::string& data, const Table2_settings& settings)
{
  const std::vector<double> sigmas = {0.1, 1.};

  std::printf("\n\nTABLE 2. The paper's Table 1: NCC, eigen solve, convolution (m = %zu, t = %g)\n",
              settings.number_of_eigenpairs, settings.time);
  std::printf("medians: NCC and A_t of %d runs, eigen solve of %d, diffusion steps of %d; %u hardware threads, %s, %s\n",
              settings.short_repeats, settings.eigen_repeats, settings.step_repeats,
              std::thread::hardware_concurrency(),
#ifdef CGAL_LINKED_WITH_TBB
              "TBB",
#else
              "no TBB",
#endif
#ifdef CGAL_HEAT_DIFFUSION_USE_CHOLMOD
              "CHOLMOD"
#else
              "Eigen's SimplicialLDLT"
#endif
  );
  std::printf("paper: 2.67 GHz CPU, MATLAB; its figures are scaled by (our vertices / its vertices) before the\n"
              "speed-up paper/ours is taken. The field diffused is the Normal Signature (NS).\n");

  for(const Paper_table1_row& paper : paper_table1)
  {
    Mesh mesh;
    if(!read_mesh(data, paper.mesh_file, mesh))
      return 1;
    std::printf("\n== %s: %zu vertices; paper figures for %s, %.0f vertices (NCC %.3f s, eigen %.3f s, "
                "convolution %.3f s) ==\n",
                paper.mesh_file, std::size_t(mesh.number_of_vertices()), paper.paper_mesh, paper.paper_vertices,
                paper.ncc_seconds, paper.eigen_seconds, paper.convolution_seconds);

    // The NCC does not depend on sigma: timed once per mesh.
    const double ncc_ms = median_ms(settings.short_repeats, [&] {
      const NCC ncc(mesh);
      benchmark_sink = ncc.normal_signature(*mesh.vertices().begin());
    });

    // The baseline of the paper's Fig. 5 and 8: global smoothing with the isotropic
    // kernel (plain graph Laplacian), one per mesh.
    const auto isotropic_start = std::chrono::steady_clock::now();
    const Heat_kernel isotropic_kernel(
        mesh, HD::parameters::combine(HD::parameters::sigma(std::numeric_limits<double>::infinity()),
                                      HD::parameters::number_of_eigenpairs(settings.number_of_eigenpairs)));
    std::printf("isotropic baseline kernel (sigma = inf, m = %zu) built in %.0f ms (single run)\n",
                settings.number_of_eigenpairs, milliseconds_since(isotropic_start));

    for(double sigma : sigmas)
      print_pipeline(mesh, paper, sigma, ncc_ms, isotropic_kernel, settings);
  }
  return 0;
}

int main(int argc, char* argv[])
{
  std::string data = CGAL_HEAT_DIFFUSION_DATA_DIR;
  int repeats = 21;
  int eigen_repeats = 3;
  namespace cli = heat_diffusion_cli;
  const std::string usage = "usage: benchmark_heat_diffusion [DATA_DIR] [--repeats R] [--eigen-repeats E]\n"
                            "  --repeats        runs of the NCC and of A_t's construction (of the steps and the global\n"
                            "                   smoothing: 10 R + 1), 1 to 1000 (default 21)\n"
                            "  --eigen-repeats  runs of each eigen solve, 1 to 100 (default 3)\n";
  if(const auto exit_code = heat_diffusion_benchmark::read_command_line(
         argc, argv, {}, {"--repeats", "--eigen-repeats"}, usage, [&](const cli::Arguments& a) {
           data = heat_diffusion_benchmark::optional_argument(a, "DATA_DIR", data);
           repeats = int(cli::parse_count("--repeats", a.value("--repeats", "21"), 1, 1000));
           eigen_repeats = int(cli::parse_count("--eigen-repeats", a.value("--eigen-repeats", "3"), 1, 100));
         }))
    return *exit_code;

  const auto start = std::chrono::steady_clock::now();
  Table2_settings settings;
  settings.short_repeats = repeats;
  settings.step_repeats = 10 * repeats + 1;
  settings.eigen_repeats = eigen_repeats;
  try
  {
    if(print_ncc_table(data, repeats) != 0 || print_pipeline_table(data, settings) != 0)
      return 1;
  }
  catch(const std::exception& error)   // e.g. an eigen solve that does not converge
  {
    std::fprintf(stderr, "benchmark_heat_diffusion: %s\n", error.what());
    return 1;
  }

  std::printf("\nRe-run: cmake --build build --target benchmark_heat_diffusion && build/bin/benchmark_heat_diffusion "
              "[DATA_DIR] [--repeats R] [--eigen-repeats E]\n");
  std::printf("(total %.0f s; the machine may be shared: compare ratios measured in the same run rather than "
              "absolute times across runs)\n",
              milliseconds_since(start) * 1e-3);
  return 0;
}
