// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Denoising quality of denoise_mesh() against two baselines, on CGAL's meshes with
// Gaussian noise along the normals of 0.1, 0.2, 0.3 and 0.5 mean edge length:
//  - CGAL's Polygon_mesh_processing::smooth_shape (mean curvature flow), best of a
//    grid of time steps and iteration counts;
//  - bilateral mesh denoising (Fleishman, Drori and Cohen-Or 2003), in
//    test/Heat_diffusion/mesh_measures.h (test_denoising uses the same), best of a grid
//    of its two widths and iteration counts.
// denoise_mesh() is run with its defaults (normal filtering) and as the best of a
// small grid too; the paper's pipeline (Denoising_method::signature_diffusion) with
// its defaults, with the spectral kernel and with the local one (the default kernel), and its
// reconstruction with the clean mesh's own Normal Signature and
// normals as targets ("NS oracle"): the same reconstruction fed with perfect targets,
// which separates what the diffusion of the signature costs from what the
// reconstruction costs.
//
// Metrics: MAD, the mean angle in degrees between corresponding face normals of the
// result and of the clean mesh; RMS, the root mean square vertex distance to the
// clean mesh in mean edge lengths. The grids are searched for the lowest MAD.
//
// Usage: benchmark_denoising [mesh.off ...]   (default: fandisk, elephant, armadillo)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "mesh_measures.h"

#include <CGAL/Heat_diffusion/denoising.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace HD = CGAL::Heat_diffusion;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;

namespace {

// The noise of the tests: Gaussian, along the vertex normals, of standard deviation
// `relative_sigma` mean edge lengths, seeded.
Mesh noisy_copy(const Mesh& clean, double relative_sigma, unsigned seed)
{
  Mesh mesh = clean;
  test_support::add_normal_noise(mesh, relative_sigma, seed);
  return mesh;
}

struct Score
{
  double mad = std::numeric_limits<double>::infinity();
  double rms = std::numeric_limits<double>::infinity();
  double seconds = 0;
  std::string setting;
};

Score score(const Mesh& clean, const Mesh& result, double edge)
{
  Score s;
  double angles = 0, squares = 0;
  for(auto f : clean.faces())
  {
    const Vector_3 a = PMP::compute_face_normal(f, clean), b = PMP::compute_face_normal(f, result);
    angles += std::acos((std::max)(-1., (std::min)(1., a * b)));
  }
  for(auto v : clean.vertices())
    squares += CGAL::squared_distance(clean.point(v), result.point(v));
  s.mad = angles / double(clean.number_of_faces()) * 180. / CGAL_PI;
  s.rms = std::sqrt(squares / double(clean.number_of_vertices())) / edge;
  return s;
}

void keep_best(Score& best, Score candidate, const std::string& setting, double seconds)
{
  if(candidate.mad < best.mad)
  {
    candidate.setting = setting;
    candidate.seconds = seconds;
    best = candidate;
  }
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format(double x, int precision = 3)
{
  std::ostringstream os;
  os.precision(precision);
  os << x;
  return os.str();
}

const std::vector<unsigned> iteration_counts = {1, 2, 3, 5, 10};

Score best_bilateral(const Mesh& clean, const Mesh& noisy, double edge)
{
  Score best;
  for(double c : {1., 1.5, 2.})
    for(double s : {0.3, 0.6, 1.})
    {
      Mesh mesh = noisy;
      const auto start = std::chrono::steady_clock::now();
      for(unsigned it = 1; it <= iteration_counts.back(); ++it)
      {
        test_support::bilateral_denoising_iteration(mesh, c * edge, s * edge);
        if(std::find(iteration_counts.begin(), iteration_counts.end(), it) != iteration_counts.end())
          keep_best(best, score(clean, mesh, edge),
                    "sc " + format(c) + "e, ss " + format(s) + "e, " + std::to_string(it) + " it",
                    seconds_since(start));
      }
    }
  return best;
}

// smooth_shape's time step is a squared length: the grid is in squared mean edge
// lengths, so that it means the same on every mesh. Its iterations are run one call
// at a time (each call is one implicit step of the same flow).
Score best_smooth_shape(const Mesh& clean, const Mesh& noisy, double edge)
{
  Score best;
  for(double c : {0.03, 0.1, 0.3, 1., 3.})
  {
    Mesh mesh = noisy;
    const auto start = std::chrono::steady_clock::now();
    for(unsigned it = 1; it <= iteration_counts.back(); ++it)
    {
      PMP::smooth_shape(mesh, c * edge * edge, CGAL::parameters::number_of_iterations(1));
      if(std::find(iteration_counts.begin(), iteration_counts.end(), it) != iteration_counts.end())
        keep_best(best, score(clean, mesh, edge), "time " + format(c) + "e^2, " + std::to_string(it) + " it",
                  seconds_since(start));
    }
  }
  return best;
}

Score heat_diffusion_defaults(const Mesh& clean, const Mesh& noisy, double edge)
{
  Mesh mesh = noisy;
  const auto start = std::chrono::steady_clock::now();
  HD::denoise_mesh(mesh);
  Score s = score(clean, mesh, edge);
  s.seconds = seconds_since(start);
  s.setting = "defaults";
  return s;
}

// denoise_mesh() over a small grid of its two main parameters: the displacement
// limit (in multiples of the estimated noise) and the width of the normal weights
// (0 = automatic).
Score best_heat_diffusion(const Mesh& clean, const Mesh& noisy, double edge)
{
  Score best;
  for(double limit : {0.8, 1.1, 1.5})
    for(double normal_sigma : {0., 0.3, 0.5})
    {
      Mesh mesh = noisy;
      const auto start = std::chrono::steady_clock::now();
      if(normal_sigma > 0)
        HD::denoise_mesh(mesh, HD::parameters::combine(HD::parameters::displacement_limit(limit),
                                                       HD::parameters::normal_sigma(normal_sigma)));
      else
        HD::denoise_mesh(mesh, HD::parameters::displacement_limit(limit));
      keep_best(best, score(clean, mesh, edge),
                "limit " + format(limit) + ", normal_sigma " + (normal_sigma > 0 ? format(normal_sigma) : "auto"),
                seconds_since(start));
    }
  return best;
}

// The paper's pipeline (Denoising_method::signature_diffusion) with its defaults, with
// the spectral kernel (the paper's) or with the local kernel (the default).
Score heat_diffusion_signature(const Mesh& clean, const Mesh& noisy, double edge, HD::Heat_kernel_method kernel)
{
  Mesh mesh = noisy;
  const auto start = std::chrono::steady_clock::now();
  HD::denoise_mesh(mesh, HD::parameters::combine(
                             HD::parameters::denoising_method(HD::Denoising_method::signature_diffusion),
                             HD::parameters::kernel_method(kernel)));
  Score s = score(clean, mesh, edge);
  s.seconds = seconds_since(start);
  s.setting = "defaults";
  return s;
}

// The reconstruction of the signature diffusion (default iterations and anchors) with the
// clean mesh's Normal Signature and normals as targets: an upper bound of what a
// better diffusion of the signature could reach.
Score heat_diffusion_oracle(const Mesh& clean, const Mesh& noisy, double edge)
{
  Mesh mesh = noisy;
  auto signature = mesh.add_property_map<Vertex, double>("v:clean_ns").first;
  auto normals = mesh.add_property_map<Vertex, Vector_3>("v:clean_normal").first;
  const HD::Normal_controlled_coordinates<Mesh> ncc(clean);
  for(auto v : clean.vertices())
  {
    signature[v] = ncc.normal_signature(v);
    normals[v] = ncc.normal(v);
  }
  for(int it = 0; it < 2; ++it)
    HD::reconstruct_from_normal_signature(
        mesh, signature,
        HD::parameters::combine(CGAL::parameters::vertex_normal_map(normals), HD::parameters::anchor_weight(0.7)));
  Score s = score(clean, mesh, edge);
  s.setting = "clean NS";
  return s;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
    files.push_back(argv[i]);
  if(files.empty())
    for(const char* name : {"fandisk.off", "elephant.off", "armadillo.off"})
      files.push_back(std::string(CGAL_HEAT_DIFFUSION_DATA_DIR) + "/" + name);

  std::cout << "| mesh | noise | noisy MAD / RMS | denoise_mesh (defaults) | denoise_mesh (best of grid) "
               "| smooth_shape (best of grid) | bilateral (best of grid) | signature diffusion, spectral kernel "
               "| signature diffusion, local kernel (its default) | NS oracle |\n"
            << "|---|---|---|---|---|---|---|---|---|---|\n";
  for(const std::string& file : files)
  {
    Mesh clean;
    if(!CGAL::IO::read_polygon_mesh(file, clean) || !CGAL::is_triangle_mesh(clean))
    {
      std::cerr << "cannot read the triangle mesh " << file << std::endl;
      return EXIT_FAILURE;
    }
    const double edge = test_support::mean_edge_length(clean);
    const std::string name = file.substr(file.find_last_of('/') + 1) + " (" +
                             std::to_string(clean.number_of_vertices()) + ")";
    for(double noise : {0.1, 0.2, 0.3, 0.5})
    {
      const Mesh noisy = noisy_copy(clean, noise, 5);
      const Score input = score(clean, noisy, edge);
      auto cell = [](const Score& s, bool with_setting) {
        std::string text = format(s.mad) + " / " + format(s.rms, 2);
        if(with_setting)
          text += " (" + s.setting + ", " + format(s.seconds, 2) + " s)";
        return text;
      };
      std::cout << "| " << name << " | " << noise << " | " << cell(input, false) << " | "
                << cell(heat_diffusion_defaults(clean, noisy, edge), true) << " | "
                << cell(best_heat_diffusion(clean, noisy, edge), true) << " | "
                << cell(best_smooth_shape(clean, noisy, edge), true) << " | "
                << cell(best_bilateral(clean, noisy, edge), true) << " | "
                << cell(heat_diffusion_signature(clean, noisy, edge, HD::Heat_kernel_method::spectral), true) << " | "
                << cell(heat_diffusion_signature(clean, noisy, edge, HD::Heat_kernel_method::local), true) << " | "
                << cell(heat_diffusion_oracle(clean, noisy, edge), false) << " |" << std::endl;
    }
  }
  std::cout << "\nMAD in degrees / RMS vertex error in mean edge lengths; noise in mean edge lengths "
               "(Gaussian, along the normals, seed 5). Times are those of the chosen setting.\n";
  return EXIT_SUCCESS;
}
