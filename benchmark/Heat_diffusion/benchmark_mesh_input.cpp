// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The heat_diffusion tool end to end on a large mesh on disk, and its mesh input.
//
// Writes armadillo Loop-subdivided L times (L = 3: 1,664,002 vertices) as ASCII OFF
// (17 significant digits: the file holds the mesh exactly) and as binary PLY, unless
// the files exist. Then, for each file:
//  - the tool's fast reader against what the tool did before it (its pre-check, then
//    CGAL::IO::read_polygon_mesh), in this process, alternating, R runs each: the
//    median seconds, their ratio, and whether the two meshes are identical;
//  - R runs of `heat_diffusion features FILE -k 10 --kernel local --json` under
//    /usr/bin/time -v, alternating with R runs of the same command with
//    `--kernel-tolerance 1e-4`, the local kernel's earlier default accuracy: the
//    tool's stages (its --json timings), the wall time, the CPU time (user + system)
//    and the peak memory of the whole command, each run and the medians, and the
//    ratios of the medians (default / 1e-4).
// With --points, then the tool on the same vertices as points (issue of scans without a
// mesh): the mesh's binary PLY against binary PLYs of its vertices without faces, with
// the mesh's vertex normals (CGAL::Polygon_mesh_processing::compute_vertex_normals()) and
// without normals (estimated by the tool), R runs each, alternating, with the tool's
// defaults (8 neighbours): the same figures, and the ratios of the medians to the mesh's.
// The machine may be shared: compare within a run (the CPU times move less with the
// other jobs than the wall times).
//
// Usage: benchmark_mesh_input [TOOL] [--dir DIR] [--levels L] [--repeat R] [--data DATA_DIR] [--points]
//   TOOL: the heat_diffusion executable (default: the one next to this program); DIR
//   (default /tmp): where the meshes and the tool's output go; L (default 3); R
//   (default 3). The medians are those of the tool's runs that succeeded; if none did,
//   the benchmark says so and exits with 1.

#include "benchmark_command_line.h"
#include "mesh_input.h"

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace cli = heat_diffusion_cli;
typedef cli::Mesh Mesh;

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// (of a non-empty sample)
double median(std::vector<double> x)
{
  std::sort(x.begin(), x.end());
  return x.size() % 2 ? x[x.size() / 2] : 0.5 * (x[x.size() / 2 - 1] + x[x.size() / 2]);
}

// What the tool did before its fast reader: the pre-check, then CGAL's reader.
bool read_with_cgal(const std::string& path, Mesh& mesh)
{
  std::error_code ec;
  const std::string extension = std::filesystem::path(path).extension().string();
  std::ifstream is(path, std::ios::binary);
  if(extension == ".off")
    cli::check_off_stream(is, std::filesystem::file_size(path, ec));
  else if(extension == ".ply")
    cli::check_ply_stream(is, std::filesystem::file_size(path, ec));
  return CGAL::IO::read_polygon_mesh(path, mesh);
}

// The figures of one run of the tool.
struct Tool_run
{
  std::array<double, 5> stages{};  // read, ncc_and_local_operator, diffusion, features, write (s)
  double wall = 0, cpu = 0, peak_gib = 0;  // cpu: user + system seconds of all threads
  bool ok = false;
};

const char* const stage_names[5] = {"read", "ncc_and_local_operator", "diffusion", "features", "write"};

// A number of the object "timings_ms" (the summary has a "features" member too).
double json_timing(const std::string& text, const std::string& key)
{
  const std::size_t timings = text.find("\"timings_ms\":");
  const std::size_t at = timings == std::string::npos ? timings : text.find("\"" + key + "\":", timings);
  return at == std::string::npos ? -1 : std::atof(text.c_str() + at + key.size() + 3);
}

// The settings the tool runs with: its defaults, and the local kernel's accuracy before
// version 1.1.
const char* const setting_names[2] = {"default", "1e-4"};
const char* const setting_options[2] = {" --kernel local", " --kernel local --kernel-tolerance 1e-4"};

// `options`: the tool's options after `features FILE -k 10`.
Tool_run run_tool(const std::string& tool, const std::string& input, const std::string& prefix,
                  const std::string& options)
{
  const std::string json = prefix + ".json", time_log = prefix + ".time";
  const std::string command = "/usr/bin/time -v " + tool + " features '" + input + "' -k 10" + options +
                              " --json --quiet -o '" + prefix + "' > '" + json + "' 2> '" + time_log + "'";
  Tool_run run;
  if(std::system(command.c_str()) != 0)
    return run;
  std::ifstream js(json), ts(time_log);
  std::stringstream jbuf, tbuf;
  jbuf << js.rdbuf();
  tbuf << ts.rdbuf();
  const std::string j = jbuf.str(), t = tbuf.str();
  for(int s = 0; s < 5; ++s)
    run.stages[s] = json_timing(j, stage_names[s]) / 1000;
  // "Elapsed (wall clock) time (h:mm:ss or m:ss): 0:31.42"
  const std::size_t w = t.find("Elapsed (wall clock) time");
  if(w != std::string::npos)
  {
    std::string clock = t.substr(t.find("): ", w) + 3);
    clock = clock.substr(0, clock.find('\n'));
    double total = 0;
    std::stringstream parts(clock);
    std::string part;
    while(std::getline(parts, part, ':'))
      total = 60 * total + std::atof(part.c_str());
    run.wall = total;
  }
  // the CPU time of all its threads, less sensitive than the wall time to other jobs
  const std::size_t user = t.find("User time (seconds): "), system = t.find("System time (seconds): ");
  if(user != std::string::npos && system != std::string::npos)
    run.cpu = std::atof(t.c_str() + user + 21) + std::atof(t.c_str() + system + 23);
  const std::size_t m = t.find("Maximum resident set size (kbytes): ");
  if(m != std::string::npos)
    run.peak_gib = std::atof(t.c_str() + m + 36) / (1024.0 * 1024.0);
  run.ok = w != std::string::npos && m != std::string::npos && user != std::string::npos && system != std::string::npos &&
           std::all_of(run.stages.begin(), run.stages.end(), [](double s) { return s >= 0; });
  return run;
}

// One way of running the tool in a comparison: a name, the input, the options.
struct Tool_case
{
  std::string name, input, options;
};

void print_row(const std::string& run, const std::string& name, const std::array<double, 8>& v)
{
  std::printf("  %-6s %-13s %8.2f %12.2f %10.2f %9.2f %7.2f %8.2f %8.2f %8.2f\n", run.c_str(), name.c_str(), v[0], v[1],
              v[2], v[3], v[4], v[5], v[6], v[7]);
}

// R runs of each case, alternating: each run's figures (the tool's stages, wall and CPU
// time, peak memory), their medians, and the ratios of each case's medians to those of
// case `reference`. False if a case had no successful run.
bool compare_tool_runs(const std::string& tool, const std::string& dir, int repeat, const std::vector<Tool_case>& cases,
                       std::size_t reference)
{
  std::printf("  %-6s %-13s %8s %12s %10s %9s %7s %8s %8s %8s\n", "run", "case", "read", "ncc+A_t", "steps",
              "features", "write", "wall", "cpu", "peak");
  std::vector<std::vector<std::array<double, 8> > > runs(cases.size());
  for(int r = 0; r < repeat; ++r)
    for(std::size_t i = 0; i < cases.size(); ++i)
    {
      const Tool_run run = run_tool(tool, cases[i].input, dir + "/benchmark_mesh_input_out", cases[i].options);
      if(!run.ok)
      {
        std::printf("  %-6d %-13s (the tool failed: see %s/benchmark_mesh_input_out.json and .time)\n", r + 1,
                    cases[i].name.c_str(), dir.c_str());
        continue;
      }
      const std::array<double, 8> v = {run.stages[0], run.stages[1], run.stages[2], run.stages[3],
                                       run.stages[4], run.wall,      run.cpu,       run.peak_gib};
      print_row(std::to_string(r + 1), cases[i].name, v);
      runs[i].push_back(v);
    }
  if(std::any_of(runs.begin(), runs.end(), [](const auto& r) { return r.empty(); }))
  {
    std::printf("  no run of the tool succeeded in one of the cases: no medians\n");
    return false;
  }
  std::vector<std::array<double, 8> > medians(cases.size());
  for(std::size_t i = 0; i < cases.size(); ++i)
  {
    for(std::size_t c = 0; c < 8; ++c)
    {
      std::vector<double> column;
      for(const auto& v : runs[i])
        column.push_back(v[c]);
      medians[i][c] = median(column);
    }
    print_row("median", cases[i].name, medians[i]);
  }
  for(std::size_t i = 0; i < cases.size(); ++i)
    if(i != reference)
    {
      std::array<double, 8> q;
      for(std::size_t c = 0; c < 8; ++c)
        q[c] = medians[i][c] / medians[reference][c];
      print_row("ratio", cases[i].name + "/" + cases[reference].name, q);
    }
  return true;
}

// The tool on the mesh's binary PLY and on its vertices as points (with the mesh's
// vertex normals, and without), alternating; false if an input had no successful run.
bool run_on_points(const std::string& tool, const std::string& mesh_file, const std::string& base,
                   const std::string& dir, int repeat)
{
  const std::vector<std::string> inputs = {mesh_file, base + "_points_normals.ply", base + "_points.ply"};
  const char* const input_names[3] = {"mesh", "points+N", "points"};
  if(!std::filesystem::exists(inputs[1]) || !std::filesystem::exists(inputs[2]))
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(mesh_file, mesh))
    {
      std::fprintf(stderr, "cannot read %s\n", mesh_file.c_str());
      return false;
    }
    auto normals = mesh.add_property_map<Mesh::Vertex_index, cli::Kernel::Vector_3>("v:benchmark_normal").first;
    CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
    CGAL::Point_set_3<cli::Kernel::Point_3> with_normals, without_normals;
    with_normals.add_normal_map();
    for(Mesh::Vertex_index v : mesh.vertices())
    {
      with_normals.insert(mesh.point(v), normals[v]);
      without_normals.insert(mesh.point(v));
    }
    std::ofstream a(inputs[1], std::ios::binary), b(inputs[2], std::ios::binary);
    CGAL::IO::set_binary_mode(a);
    CGAL::IO::set_binary_mode(b);
    if(!CGAL::IO::write_PLY(a, with_normals) || !CGAL::IO::write_PLY(b, without_normals))
    {
      std::fprintf(stderr, "cannot write the point files under %s\n", dir.c_str());
      return false;
    }
  }
  std::printf("\nthe same vertices as points: %s features FILE -k 10 --json, the tool's defaults (8 neighbours;"
              " seconds, peak GiB)\n  %s, %s (the mesh's vertex normals), %s (normals estimated)\n",
              tool.c_str(), inputs[0].c_str(), inputs[1].c_str(), inputs[2].c_str());
  return compare_tool_runs(tool, dir, repeat,
                           {{input_names[0], inputs[0], ""}, {input_names[1], inputs[1], ""}, {input_names[2], inputs[2], ""}},
                           0);
}

int main(int argc, char** argv)
{
  const std::string usage =
      "usage: benchmark_mesh_input [TOOL] [--dir DIR] [--levels L] [--repeat R] [--data DATA_DIR]\n"
      "  TOOL      the heat_diffusion executable (default: the one next to this program)\n"
      "  --dir     where the meshes and the tool's output go (default /tmp)\n"
      "  --levels  Loop subdivisions of armadillo, 0 to 4 (default 3: 1,664,002 vertices)\n"
      "  --repeat  runs of each reader and of the tool, 1 to 100 (default 3)\n"
      "  --data    the directory of CGAL's meshes\n"
      "  --points  then the tool on the vertices as points, with and without normals\n";
  std::string tool = (std::filesystem::path(argv[0]).parent_path() / "heat_diffusion").string();
  std::string dir = "/tmp", data = CGAL_HEAT_DIFFUSION_DATA_DIR;
  int levels = 3, repeat = 3;
  bool points = false;
  if(const auto exit_code = heat_diffusion_benchmark::read_command_line(
         argc, argv, {"--points"}, {"--dir", "--levels", "--repeat", "--data"}, usage, [&](const cli::Arguments& a) {
           points = a.flag("--points");
           tool = heat_diffusion_benchmark::optional_argument(a, "TOOL", tool);
           // checked now: the meshes take minutes to write and read before the tool runs
           if(!std::filesystem::is_regular_file(tool) || access(tool.c_str(), X_OK) != 0)
             throw cli::Usage_error("TOOL '" + tool + "' is not an executable file");
           dir = a.value("--dir", dir);
           if(!std::filesystem::is_directory(dir))
             throw cli::Usage_error("--dir '" + dir + "' is not a directory");
           data = a.value("--data", data);
           levels = int(cli::parse_count("--levels", a.value("--levels", "3"), 0, 4));
           repeat = int(cli::parse_count("--repeat", a.value("--repeat", "3"), 1, 100));
         }))
    return *exit_code;
  const std::string base = dir + "/armadillo_loop" + std::to_string(levels);
  const std::vector<std::string> files = {base + ".off", base + ".ply"};
  if(!std::filesystem::exists(files[0]) || !std::filesystem::exists(files[1]))
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(data + "/armadillo.off", mesh))
    {
      std::fprintf(stderr, "cannot read %s/armadillo.off\n", data.c_str());
      return 1;
    }
    if(levels > 0)
      CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
    std::ofstream off(files[0]), ply(files[1], std::ios::binary);
    CGAL::IO::set_binary_mode(ply);  // the stream's mode decides, not a named parameter
    if(!CGAL::IO::write_OFF(off, mesh, CGAL::parameters::stream_precision(17)) || !CGAL::IO::write_PLY(ply, mesh))
    {
      std::fprintf(stderr, "cannot write the meshes under %s\n", dir.c_str());
      return 1;
    }
    std::printf("wrote %s and %s (%zu vertices)\n", files[0].c_str(), files[1].c_str(), mesh.number_of_vertices());
  }

  bool failed = false;
  for(const std::string& file : files)
  {
    std::error_code ec;
    std::printf("\n%s (%.0f MB)\n", file.c_str(), double(std::filesystem::file_size(file, ec)) / 1e6);
    std::vector<double> fast, cgal;
    bool same = true;
    std::size_t n = 0;
    for(int r = 0; r < repeat; ++r)
    {
      Mesh a, b;
      auto start = std::chrono::steady_clock::now();
      const bool fast_read = cli::fast_input::read_mesh_fast(file, a);
      fast.push_back(seconds_since(start));
      start = std::chrono::steady_clock::now();
      const bool cgal_read = read_with_cgal(file, b);
      cgal.push_back(seconds_since(start));
      same = same && fast_read && cgal_read && cli::fast_input::identical_meshes(a, b);
      n = b.number_of_vertices();
    }
    std::printf("  reading %zu vertices (median of %d):  fast %.2f s,  CGAL's reader (with the pre-check) %.2f s,"
                "  ratio %.1f;  meshes identical: %s\n",
                n, repeat, median(fast), median(cgal), median(cgal) / median(fast), same ? "yes" : "NO");

    std::printf("  %s features FILE -k 10 --kernel local [--kernel-tolerance 1e-4] --json (seconds; peak GiB):\n",
                tool.c_str());
    if(!compare_tool_runs(tool, dir, repeat,
                          {{setting_names[0], file, setting_options[0]}, {setting_names[1], file, setting_options[1]}}, 1))
      failed = true;
    std::printf("  (CGAL's reader on this file in this run: %.2f s)\n", median(cgal));
  }
  if(points && !run_on_points(tool, files[1], base, dir, repeat))
    failed = true;
  return failed ? 1 : 0;
}
