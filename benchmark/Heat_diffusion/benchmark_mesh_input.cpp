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
//    /usr/bin/time -v: the tool's stages (its --json timings), the wall time and the
//    peak memory of the whole command, each run and the medians.
// The machine may be shared: compare within a run.
//
// Usage: benchmark_mesh_input TOOL [--dir DIR] [--levels L] [--repeat R] [--data DATA_DIR]
//   TOOL: the heat_diffusion executable; DIR (default /tmp): where the meshes and the
//   tool's output go; L (default 3); R (default 3).

#include "mesh_input.h"

#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cli = heat_diffusion_cli;
typedef cli::Mesh Mesh;

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> x)
{
  if(x.empty())
    return 0;
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
  double wall = 0, peak_gib = 0;
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

Tool_run run_tool(const std::string& tool, const std::string& input, const std::string& prefix)
{
  const std::string json = prefix + ".json", time_log = prefix + ".time";
  const std::string command = "/usr/bin/time -v " + tool + " features '" + input + "' -k 10 --kernel local --json --quiet -o '" +
                              prefix + "' > '" + json + "' 2> '" + time_log + "'";
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
  const std::size_t m = t.find("Maximum resident set size (kbytes): ");
  if(m != std::string::npos)
    run.peak_gib = std::atof(t.c_str() + m + 36) / (1024.0 * 1024.0);
  run.ok = w != std::string::npos && m != std::string::npos;
  return run;
}

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::fprintf(stderr, "usage: benchmark_mesh_input TOOL [--dir DIR] [--levels L] [--repeat R] [--data DATA_DIR]\n");
    return 2;
  }
  const std::string tool = argv[1];
  std::string dir = "/tmp", data = CGAL_HEAT_DIFFUSION_DATA_DIR;
  int levels = 3, repeat = 3;
  for(int i = 2; i + 1 < argc; i += 2)
  {
    const std::string arg = argv[i];
    if(arg == "--dir")
      dir = argv[i + 1];
    else if(arg == "--levels")
      levels = std::atoi(argv[i + 1]);
    else if(arg == "--repeat")
      repeat = std::max(1, std::atoi(argv[i + 1]));
    else if(arg == "--data")
      data = argv[i + 1];
  }
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

    std::printf("  %s features FILE -k 10 --kernel local --json (seconds; peak GiB):\n", tool.c_str());
    std::printf("  %-6s %8s %12s %10s %9s %7s %8s %8s\n", "run", "read", "ncc+A_t", "steps", "features", "write",
                "wall", "peak");
    std::vector<std::vector<double>> columns(7);
    for(int r = 0; r < repeat; ++r)
    {
      const Tool_run run = run_tool(tool, file, dir + "/benchmark_mesh_input_out");
      if(!run.ok)
      {
        std::printf("  %-6d (the tool failed)\n", r + 1);
        continue;
      }
      std::printf("  %-6d %8.2f %12.2f %10.2f %9.2f %7.2f %8.2f %8.2f\n", r + 1, run.stages[0], run.stages[1],
                  run.stages[2], run.stages[3], run.stages[4], run.wall, run.peak_gib);
      for(int s = 0; s < 5; ++s)
        columns[s].push_back(run.stages[s]);
      columns[5].push_back(run.wall);
      columns[6].push_back(run.peak_gib);
    }
    std::printf("  %-6s %8.2f %12.2f %10.2f %9.2f %7.2f %8.2f %8.2f\n", "median", median(columns[0]),
                median(columns[1]), median(columns[2]), median(columns[3]), median(columns[4]), median(columns[5]),
                median(columns[6]));
    std::printf("  (CGAL's reader on this file in this run: %.2f s)\n", median(cgal));
  }
  return 0;
}
