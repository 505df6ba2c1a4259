// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Denoising quality of denoise_mesh() against published filters, all run in the same
// process on the same noisy meshes:
//  - Guided Mesh Normal Filtering (GNF, Zhang et al. 2015), Bilateral Normal
//    Filtering (BNF, Zheng et al. 2011), L0 minimization (He and Schaefer 2013) and mesh
//    total generalized variation (MeshTGV, Liu et al. 2022), at their papers' default
//    parameters (MeshTGV: those that reproduce its paper's fandisk figure), and each as
//    the best of a small grid of its parameters (GNF-grid, ...; test/Heat_diffusion/baselines/);
//  - bilateral mesh denoising (Fleishman, Drori and Cohen-Or 2003), best of a grid of
//    its two widths and iteration counts (test/Heat_diffusion/mesh_measures.h);
//  - Taubin's lambda|mu smoothing, best of a range of iteration counts;
//  - CGAL's Polygon_mesh_processing::smooth_shape, best of a grid of time steps and
//    iteration counts;
//  - optionally (--signature) the paper's pipeline, Denoising_method::signature_diffusion.
// The benchmark set: CAD meshes with flat parts and creases, CAD meshes with needle
// triangles (minimum angle under 10 degrees on most faces), organic meshes, and CAD
// exports whose coarse tessellation puts most faces at a crease with all their
// neighbours (couplingdown, b9_mesh) or makes every face a needle across curved holes
// (cheese), organic meshes with fine detail (lion-head, head, mannequin-devil, open);
// three kinds of noise, with fixed seeds: Gaussian noise of 0.1, 0.2, 0.3 and 0.5 mean
// edge length on every vertex, along the vertex normals and in random directions;
// impulsive noise (a random 10 % or 20 % of the vertices moved along their normals by
// Gaussian noise of 0.5 or 1 mean edge length, the others left clean); the noise of a
// simulated depth camera at 0.1, 0.2 and 0.3 (depth_camera_noise.h: several views, noise
// along the rays growing with the square of the depth, low-frequency bumps, depth
// quantisation, flying points at silhouettes). The meshes are split into a half on which
// the defaults may be tuned and a half on which they are only checked (column "half").
//
// Metrics, for every method: MAD, the mean angle in degrees between corresponding face
// normals of the result and of the clean mesh (the grids are searched for the lowest
// MAD); RMS, the root mean square vertex distance to the clean mesh in mean edge
// lengths, and its tangential part (the error's component in the clean mesh's tangent
// plane at the vertex: vertices slid along the surface); the volume change in percent
// (closed meshes; the noisy input's row also gives the standard deviation of the change
// that the noise itself makes, set_volume_spread());
// the faces whose normal is flipped (more than 90 degrees from the clean one); the
// intersecting face pairs beyond those of the clean mesh; the time of the chosen setting.
// Per kind of noise and half of the set: the mean of every method, whether the mean of
// denoise_mesh is ahead of each published filter at its paper's parameters, and the rows
// where denoise_mesh is more than 10 % above the best grid of the published filters.
//
// Usage: benchmark_denoising [--quick] [--signature] [--normal-only] [--clean] [--gaussian] [--impulsive]
//                            [--depth] [--baselines list] [--half tune|check] [--noise x]... [mesh ...]
//   --quick       fandisk, anchor and elephant at noise 0.3 and 0.5 along the normals
//   --signature   also run the paper's pipeline (slow)
//   --normal-only only the noise along the normals (and the impulsive noise)
//   --clean       also each clean mesh (noise 0): how far each method moves a mesh that
//                 has no noise
//   --gaussian, --impulsive, --depth
//                 these kinds of noise only (default: all three)
//   --baselines l only these baselines, a comma-separated list of GNF, BNF, L0, MeshTGV,
//                 GNF-grid, BNF-grid, L0-grid, MeshTGV-grid, bilateral, Taubin, smooth_shape,
//                 or none (default: all; the grids take most of the time)
//   --half h      only the meshes of the tune or the check half of the set
//   --noise x     only this noise level, in mean edge lengths (repeatable; for the
//                 impulsive noise, the deviation of the impulses)
//   mesh          a file name in CGAL's data set, or a path (default: the whole set)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "benchmark_command_line.h"
#include "mesh_measures.h"
#include "depth_camera_noise.h"
#include "baselines/bilateral_normal_filtering.h"
#include "baselines/guided_normal_filtering.h"
#include "baselines/l0_minimization.h"
#include "baselines/mesh_tgv.h"
#include "baselines/taubin_smoothing.h"

#include <CGAL/Heat_diffusion/denoising.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace HD = CGAL::Heat_diffusion;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace B = test_support::baselines;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Face_index Face;

namespace {

struct Reference
{
  Mesh clean;
  std::vector<Vector_3> normals;
  std::vector<Vector_3> vertex_normals;  // of the clean mesh, for the tangential error
  double edge = 0;
  bool closed = false;
  double volume = 0;
  std::size_t intersections = 0;
  // The standard deviation of the noisy input's volume change, in percent of the clean
  // volume per mean edge length of noise, along the normals and in random directions.
  double volume_spread_normal = 0, volume_spread_random = 0;
};

// The spread of the volume that the noise itself adds (closed meshes). The signed volume
// (1/6) sum_f p_a . (p_b x p_c) is linear in each vertex, and the noise is independent
// from vertex to vertex with mean zero: the noisy input's volume is the clean volume on
// average, and off by sum_i d_i . g_i, g_i = (1/6) sum over the faces abc of i of
// p_b x p_c (its gradient in p_i), to first order in the displacements d_i. Its standard
// deviation is sigma (sum_i (g_i . n_i)^2)^(1/2) for noise of deviation sigma along the
// vertex normals n_i, sigma (sum_i |g_i|^2 / 3)^(1/2) in random directions. No smoothing
// can tell this change (the noise's area-weighted mean along the normals) from an offset
// of the clean surface, and a denoiser that keeps the input's volume keeps its error.
void set_volume_spread(Reference& ref)
{
  auto normals = ref.clean.add_property_map<Vertex, Vector_3>("v:volume_spread_normal").first;
  PMP::compute_vertex_normals(ref.clean, normals);
  std::vector<Vector_3> gradient(ref.clean.number_of_vertices(), CGAL::NULL_VECTOR);
  for(auto h : ref.clean.halfedges())
    if(!ref.clean.is_border(h))
    {
      const Point_3& b = ref.clean.point(ref.clean.target(ref.clean.next(h)));
      const Point_3& c = ref.clean.point(ref.clean.source(h));
      gradient[ref.clean.target(h)] += CGAL::cross_product(b - CGAL::ORIGIN, c - CGAL::ORIGIN) / 6.;
    }
  double along = 0, random = 0;
  for(Vertex v : ref.clean.vertices())
  {
    along += CGAL::square(gradient[v] * normals[v]);
    random += gradient[v].squared_length() / 3.;
  }
  ref.clean.remove_property_map(normals);
  ref.volume_spread_normal = 100. * ref.edge * std::sqrt(along) / std::abs(ref.volume);
  ref.volume_spread_random = 100. * ref.edge * std::sqrt(random) / std::abs(ref.volume);
}

std::size_t count_self_intersections(const Mesh& mesh)
{
  std::vector<std::pair<Face, Face> > pairs;
  PMP::self_intersections(mesh, std::back_inserter(pairs));
  return pairs.size();
}

struct Score
{
  double mad = std::numeric_limits<double>::infinity();
  double rms = 0, tangential_rms = 0, volume_change = 0, seconds = 0;
  std::size_t flipped = 0;
  long new_intersections = 0;
  std::string setting;
};

double mad_of(const Reference& ref, const Mesh& result, std::size_t* flipped = nullptr)
{
  double angles = 0;
  std::size_t k = 0, flips = 0;
  for(Face f : result.faces())
  {
    const Vector_3 b = PMP::compute_face_normal(f, result);
    const double c = (std::max)(-1., (std::min)(1., ref.normals[k++] * b));
    angles += std::acos(c);
    flips += c < 0 ? 1 : 0;
  }
  if(flipped != nullptr)
    *flipped = flips;
  return angles / double(result.number_of_faces()) * 180. / CGAL_PI;
}

Score full_score(const Reference& ref, const Mesh& result, double seconds, const std::string& setting)
{
  Score s;
  s.mad = mad_of(ref, result, &s.flipped);
  double squares = 0, tangential_squares = 0;
  for(Vertex v : ref.clean.vertices())
  {
    const Vector_3 error = result.point(v) - ref.clean.point(v);
    const Vector_3& normal = ref.vertex_normals[v.idx()];
    squares += error.squared_length();
    tangential_squares += (error - (error * normal) * normal).squared_length();
  }
  s.rms = std::sqrt(squares / double(ref.clean.number_of_vertices())) / ref.edge;
  s.tangential_rms = std::sqrt(tangential_squares / double(ref.clean.number_of_vertices())) / ref.edge;
  s.volume_change = ref.closed ? 100. * (PMP::volume(result) - ref.volume) / ref.volume : 0.;
  s.new_intersections = long(count_self_intersections(result)) - long(ref.intersections);
  s.seconds = seconds;
  s.setting = setting;
  return s;
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

// A method run once with fixed parameters.
Score run_once(const Reference& ref, const Mesh& noisy, const std::function<void(Mesh&)>& method,
               const std::string& setting)
{
  Mesh mesh = noisy;
  const auto start = std::chrono::steady_clock::now();
  method(mesh);
  const double seconds = seconds_since(start);
  return full_score(ref, mesh, seconds, setting);
}

// An iterated method over a grid: `make(setting)` returns one iteration's step; the
// lowest MAD over the settings and the iteration counts in `counts` is kept.
struct Grid_best
{
  double mad = std::numeric_limits<double>::infinity();
  Mesh mesh;
  double seconds = 0;
  std::string setting;
  void consider(const Reference& ref, const Mesh& candidate, double seconds_, const std::string& setting_)
  {
    const double m = mad_of(ref, candidate);
    if(m < mad)
    {
      mad = m;
      mesh = candidate;
      seconds = seconds_;
      setting = setting_;
    }
  }
  Score score(const Reference& ref) const { return full_score(ref, mesh, seconds, setting); }
};

const std::vector<unsigned> bilateral_counts = {1, 2, 3, 5, 10};

Score best_bilateral(const Reference& ref, const Mesh& noisy)
{
  Grid_best best;
  for(double c : {1., 1.5, 2.})
    for(double s : {0.3, 0.6, 1.})
    {
      Mesh mesh = noisy;
      const auto start = std::chrono::steady_clock::now();
      for(unsigned it = 1; it <= bilateral_counts.back(); ++it)
      {
        test_support::bilateral_denoising_iteration(mesh, c * ref.edge, s * ref.edge);
        if(std::find(bilateral_counts.begin(), bilateral_counts.end(), it) != bilateral_counts.end())
          best.consider(ref, mesh, seconds_since(start),
                        "sc " + format(c) + "e, ss " + format(s) + "e, " + std::to_string(it) + " it");
      }
    }
  return best.score(ref);
}

Score best_taubin(const Reference& ref, const Mesh& noisy)
{
  Grid_best best;
  const std::vector<unsigned> counts = {1, 2, 3, 5, 10, 20, 50};
  B::Face_mesh fm = B::make_face_mesh(noisy);
  Mesh mesh = noisy;
  const auto start = std::chrono::steady_clock::now();
  for(unsigned it = 1; it <= counts.back(); ++it)
  {
    B::taubin_iteration(fm);
    if(std::find(counts.begin(), counts.end(), it) != counts.end())
    {
      B::write_points(fm, mesh);
      best.consider(ref, mesh, seconds_since(start), std::to_string(it) + " it");
    }
  }
  return best.score(ref);
}

// smooth_shape's time step is a squared length: the grid is in squared mean edge
// lengths, so that it means the same on every mesh. Its iterations are run one call
// at a time (each call is one implicit step of the same flow).
Score best_smooth_shape(const Reference& ref, const Mesh& noisy)
{
  Grid_best best;
  for(double c : {0.03, 0.1, 0.3, 1., 3.})
  {
    Mesh mesh = noisy;
    const auto start = std::chrono::steady_clock::now();
    for(unsigned it = 1; it <= bilateral_counts.back(); ++it)
    {
      PMP::smooth_shape(mesh, c * ref.edge * ref.edge, CGAL::parameters::number_of_iterations(1));
      if(std::find(bilateral_counts.begin(), bilateral_counts.end(), it) != bilateral_counts.end())
        best.consider(ref, mesh, seconds_since(start), "time " + format(c) + "e^2, " + std::to_string(it) + " it");
    }
  }
  return best.score(ref);
}

// A grid of settings of a method: the lowest MAD against the clean mesh is kept (an
// oracle no user has: the baseline at its best).
Score best_of(const Reference& ref, const Mesh& noisy,
              const std::vector<std::pair<std::string, std::function<void(Mesh&)> > >& settings)
{
  Score best;
  for(const auto& setting : settings)
  {
    Score s = run_once(ref, noisy, setting.second, setting.first);
    if(s.mad < best.mad)
      best = s;
  }
  return best;
}

void run_l0(Mesh& mesh, double lambda_factor)
{
  B::Face_mesh fm = B::make_face_mesh(mesh);
  B::L0_parameters p;
  p.lambda_factor *= lambda_factor;
  B::l0_minimization(fm, p);
  B::write_points(fm, mesh);
}

// The grids of the four published filters: their papers' widths and strengths, and a
// step either side.
Score best_gnf(const Reference& ref, const Mesh& noisy)
{
  std::vector<std::pair<std::string, std::function<void(Mesh&)> > > settings;
  for(double sigma_r : {0.25, 0.35, 0.5})
    for(std::size_t iterations : {10, 20, 40})
      settings.emplace_back("sigma_r " + format(sigma_r) + ", " + std::to_string(iterations) + " it", [=](Mesh& m) {
        B::Guided_normal_filtering_parameters p;
        p.sigma_r = sigma_r;
        p.normal_iterations = iterations;
        B::guided_normal_filtering(m, p);
      });
  return best_of(ref, noisy, settings);
}

Score best_bnf(const Reference& ref, const Mesh& noisy)
{
  std::vector<std::pair<std::string, std::function<void(Mesh&)> > > settings;
  for(double sigma_s : {0.25, 0.35, 0.5})
    for(std::size_t iterations : {10, 20, 40})
      settings.emplace_back("sigma_s " + format(sigma_s) + ", " + std::to_string(iterations) + " it", [=](Mesh& m) {
        B::Bilateral_normal_filtering_parameters p;
        p.sigma_s = sigma_s;
        p.normal_iterations = iterations;
        B::bilateral_normal_filtering(m, p);
      });
  return best_of(ref, noisy, settings);
}

Score best_l0(const Reference& ref, const Mesh& noisy)
{
  std::vector<std::pair<std::string, std::function<void(Mesh&)> > > settings;
  for(double factor : {0.5, 1., 2.})
    settings.emplace_back("lambda x " + format(factor), [=](Mesh& m) { run_l0(m, factor); });
  return best_of(ref, noisy, settings);
}

Score best_mesh_tgv(const Reference& ref, const Mesh& noisy)
{
  std::vector<std::pair<std::string, std::function<void(Mesh&)> > > settings;
  for(double alpha : {0.5, 1., 2.})
    settings.emplace_back("alpha_1 = alpha_0 = " + format(alpha), [=](Mesh& m) {
      B::Mesh_tgv_parameters p;
      p.alpha_1 = p.alpha_0 = alpha;
      p.penalty = 4 * alpha;
      B::mesh_tgv(m, p);
    });
  return best_of(ref, noisy, settings);
}

bool is_grid_of_published(const std::string& method)
{
  return method == "GNF-grid" || method == "BNF-grid" || method == "L0-grid" || method == "MeshTGV-grid";
}

struct Set_entry
{
  std::string file, kind, half;
};

// Every kind has meshes in both halves. A rule of the defaults is kept only if it pays
// on the check half, which it was not tuned on.
const std::vector<Set_entry> full_set = {
    {"fandisk.off", "CAD, creases", "tune"},        {"anchor_dense.off", "CAD, creases", "check"},
    {"turbine.off", "CAD, creases", "tune"},        {"blade.off", "CAD, needles", "check"},
    {"anchor.off", "CAD, needles", "tune"},         {"rotor_small.off", "CAD, needles", "check"},
    {"elephant.off", "organic", "tune"},            {"armadillo.off", "organic", "check"},
    {"bunny00.off", "organic", "tune"},             {"lion-head.off", "organic, fine detail", "check"},
    {"head.off", "organic, fine detail", "tune"},   {"mannequin-devil.off", "organic, fine detail", "check"},
    {"couplingdown.off", "CAD export", "tune"},     {"b9_mesh.off", "CAD export", "check"},
    {"cheese.off", "CAD export", "check"}};

const std::vector<Set_entry> quick_set = {{"fandisk.off", "CAD, creases", "tune"},
                                          {"anchor.off", "CAD, needles", "tune"},
                                          {"elephant.off", "organic", "tune"}};

// One noisy input: Gaussian noise of `level` mean edge lengths on every vertex along the
// normals (seed 5) or in random directions (seed 6), or impulsive noise on `fraction` of
// the vertices (seed 7).
struct Noise
{
  enum Kind { none, normal, random, impulsive, depth } kind;
  double level, fraction;
  std::string direction() const
  {
    return kind == none        ? "none"
           : kind == normal    ? "normal"
           : kind == random    ? "random"
           : kind == impulsive ? "impulsive"
                               : "depth camera";
  }
  std::string family() const
  {
    return kind == none ? "no" : kind == impulsive ? "impulsive" : kind == depth ? "depth camera" : "Gaussian";
  }
  std::string label() const
  {
    return kind == impulsive ? format(level) + " on " + format(100. * fraction) + " %" : format(level);
  }
  void apply(Mesh& mesh) const
  {
    if(kind == normal)
      test_support::add_normal_noise(mesh, level, 5);
    else if(kind == random)
      test_support::add_random_direction_noise(mesh, level, 6);
    else if(kind == impulsive)
      test_support::add_impulsive_noise(mesh, fraction, level, 7);
    else if(kind == depth)
      test_support::add_depth_camera_noise(mesh, level, 8);
  }
};

} // namespace

int main(int argc, char** argv)
{
  bool quick = false, signature = false, normal_only = false, clean = false, gaussian = false, impulsive = false,
       depth = false;
  // The baselines, in the order of their columns; the tuned grids are the slow ones.
  const std::vector<std::string> baseline_names = {"GNF",      "BNF",      "L0",        "MeshTGV",
                                                   "GNF-grid", "BNF-grid", "L0-grid",   "MeshTGV-grid",
                                                   "bilateral", "Taubin",  "smooth_shape"};
  std::vector<std::string> baselines = baseline_names;
  std::string half;
  std::vector<double> noises;
  std::vector<Set_entry> set;
  namespace cli = heat_diffusion_cli;
  const std::string usage =
      "usage: benchmark_denoising [--quick] [--signature] [--normal-only] [--clean] [--gaussian] [--impulsive] [--depth]\n"
      "                           [--baselines list] [--half tune|check] [--noise x]... [mesh ...]\n"
      "  --quick        fandisk, anchor and elephant at noise 0.3 and 0.5 along the normals\n"
      "  --signature    also run the paper's pipeline (slow)\n"
      "  --normal-only  only the noise along the normals (and the impulsive noise)\n"
      "  --clean        also each clean mesh (noise 0)\n"
      "  --gaussian     the Gaussian noise on every vertex\n"
      "  --impulsive    the impulsive noise (10 % and 20 % of the vertices)\n"
      "  --depth        the noise of a simulated depth camera (default: all three kinds of noise)\n"
      "  --baselines l  only these baselines, comma-separated: GNF, BNF, L0, MeshTGV (the\n"
      "                 papers' parameters), GNF-grid, BNF-grid, L0-grid, MeshTGV-grid (the best of\n"
      "                 a grid), bilateral, Taubin, smooth_shape, or none (default: all)\n"
      "  --half h       only the meshes of the half h of the set: tune or check\n"
      "  --noise x      only this noise level, in mean edge lengths, > 0 and <= 10 (repeatable;\n"
      "                 impulsive noise: the deviation of the impulses)\n"
      "  mesh           a file name in CGAL's data set, or a path (default: the whole set)\n";
  if(const auto exit_code = heat_diffusion_benchmark::read_command_line(
         argc, argv, {"--quick", "--signature", "--normal-only", "--clean", "--gaussian", "--impulsive", "--depth"},
         {"--noise", "--half", "--baselines"}, usage,
         [&](const cli::Arguments& a) {
           quick = a.flag("--quick");
           signature = a.flag("--signature");
           normal_only = a.flag("--normal-only");
           clean = a.flag("--clean");
           gaussian = a.flag("--gaussian");
           impulsive = a.flag("--impulsive");
           depth = a.flag("--depth");
           for(const std::string& list : a.values("--baselines"))
           {
             baselines.clear();
             std::istringstream items(list);
             for(std::string item; std::getline(items, item, ',');)
               if(item == "none")
                 continue;
               else if(std::find(baseline_names.begin(), baseline_names.end(), item) != baseline_names.end())
                 baselines.push_back(item);
               else
                 throw cli::Usage_error("--baselines: unknown baseline '" + item + "'");
           }
           for(const std::string& h : a.values("--half"))
           {
             if(h != "tune" && h != "check")
               throw cli::Usage_error("--half takes tune or check, not '" + h + "'");
             half = h;
           }
           for(const std::string& noise : a.values("--noise"))
             noises.push_back(cli::parse_number("--noise", noise, 0., true, 10.));
           for(const std::string& mesh : a.positional())
           {
             // A mesh of the set keeps its kind and half.
             const auto known = std::find_if(full_set.begin(), full_set.end(),
                                             [&](const Set_entry& e) { return e.file == mesh; });
             set.push_back(known != full_set.end() ? *known : Set_entry{mesh, "given", "given"});
           }
         }))
    return *exit_code;
  if(set.empty())
    set = quick ? quick_set : full_set;
  if(!half.empty())
    set.erase(std::remove_if(set.begin(), set.end(), [&](const Set_entry& e) { return e.half != half; }), set.end());
  if(quick)
  {
    normal_only = gaussian = true;
    impulsive = depth = false;
  }
  else if(!gaussian && !impulsive && !depth)
    gaussian = impulsive = depth = true;
  std::vector<Noise> inputs;
  if(clean)
    inputs.push_back({Noise::none, 0., 0.});
  const std::vector<double> gaussian_levels =
      !noises.empty() ? noises : quick ? std::vector<double>{0.3, 0.5} : std::vector<double>{0.1, 0.2, 0.3, 0.5};
  if(gaussian)
    for(double level : gaussian_levels)
    {
      inputs.push_back({Noise::normal, level, 1.});
      if(!normal_only)
        inputs.push_back({Noise::random, level, 1.});
    }
  if(impulsive)
    for(double level : noises.empty() ? std::vector<double>{0.5, 1.} : noises)
      for(double fraction : {0.1, 0.2})
        inputs.push_back({Noise::impulsive, level, fraction});
  if(depth)
    for(double level : noises.empty() ? std::vector<double>{0.1, 0.2, 0.3} : noises)
      inputs.push_back({Noise::depth, level, 1.});

  // The methods' names in the table: the noisy input, denoise_mesh, the baselines run, and
  // the paper's pipeline if asked.
  std::vector<std::string> methods = {"noisy input", "denoise_mesh"};
  for(const std::string& b : baselines)
    methods.push_back(b == "bilateral" || b == "Taubin" || b == "smooth_shape" ? b + " (tuned)" : b);
  if(signature)
    methods.push_back("signature diffusion");
  const std::size_t last_baseline = 1 + baselines.size();  // methods[2 .. last_baseline]
  // Mean MAD, RMS and tangential RMS per method, by noise family and half of the set.
  std::map<std::string, std::vector<double> > mads, rmss, tangential_rmss;
  std::vector<std::string> families;
  std::vector<std::string> losing_rows, volume_rows, rms_rows;
  std::size_t closed_noisy_rows = 0;
  double largest_input_volume_deviation = 0;  // in standard deviations (set_volume_spread())

  std::cout << "| mesh | kind | half | noise | direction | method | MAD | RMS | tangential RMS | volume % | flipped "
               "| new SI | time s | setting |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for(const Set_entry& entry : set)
  {
    const std::string path =
        entry.file.find('/') == std::string::npos ? std::string(CGAL_HEAT_DIFFUSION_DATA_DIR) + "/" + entry.file : entry.file;
    Reference ref;
    if(!CGAL::IO::read_polygon_mesh(path, ref.clean) || !CGAL::is_triangle_mesh(ref.clean) ||
       ref.clean.number_of_faces() == 0)
    {
      std::cerr << "cannot read the triangle mesh " << path << std::endl;
      return EXIT_FAILURE;
    }
    ref.edge = test_support::mean_edge_length(ref.clean);
    for(Face f : ref.clean.faces())
      ref.normals.push_back(PMP::compute_face_normal(f, ref.clean));
    for(Vertex v : ref.clean.vertices())
      ref.vertex_normals.push_back(PMP::compute_vertex_normal(v, ref.clean));
    ref.closed = CGAL::is_closed(ref.clean);
    if(ref.closed)
    {
      ref.volume = PMP::volume(ref.clean);
      set_volume_spread(ref);
    }
    ref.intersections = count_self_intersections(ref.clean);
    const std::string name = path.substr(path.find_last_of('/') + 1) + " (" +
                             std::to_string(ref.clean.number_of_vertices()) + ")";
    for(const Noise& noise : inputs)
    {
      Mesh noisy = ref.clean;
      noise.apply(noisy);
      const std::string row = "| " + name + " | " + entry.kind + " | " + entry.half + " | " + noise.label() + " | " +
                              noise.direction() + " | ";
      std::vector<Score> scores;
      // The first-order spread of the volume (set_volume_spread()): impulses are noise
      // along the normals on a fraction of the vertices.
      const double volume_spread =
          noise.kind == Noise::impulsive ? noise.level * std::sqrt(noise.fraction) * ref.volume_spread_normal
          : noise.kind == Noise::random  ? noise.level * ref.volume_spread_random
                                         : noise.level * ref.volume_spread_normal;
      scores.push_back(full_score(ref, noisy, 0,
                                  ref.closed && noise.kind != Noise::none
                                      ? "input, volume std " + format(volume_spread, 2) + " %"
                                      : std::string("input")));
      scores.push_back(run_once(ref, noisy, [](Mesh& m) { HD::denoise_mesh(m); }, "defaults"));
      for(const std::string& b : baselines)
        if(b == "GNF")
          scores.push_back(run_once(ref, noisy, [](Mesh& m) { B::guided_normal_filtering(m); }, "paper's defaults"));
        else if(b == "BNF")
          scores.push_back(run_once(ref, noisy, [](Mesh& m) { B::bilateral_normal_filtering(m); }, "paper's defaults"));
        else if(b == "L0")
          scores.push_back(run_once(ref, noisy, [](Mesh& m) { run_l0(m, 1.); }, "paper's defaults"));
        else if(b == "MeshTGV")
          scores.push_back(run_once(ref, noisy, [](Mesh& m) { B::mesh_tgv(m); }, "paper's figure"));
        else if(b == "GNF-grid")
          scores.push_back(best_gnf(ref, noisy));
        else if(b == "BNF-grid")
          scores.push_back(best_bnf(ref, noisy));
        else if(b == "L0-grid")
          scores.push_back(best_l0(ref, noisy));
        else if(b == "MeshTGV-grid")
          scores.push_back(best_mesh_tgv(ref, noisy));
        else if(b == "bilateral")
          scores.push_back(best_bilateral(ref, noisy));
        else if(b == "Taubin")
          scores.push_back(best_taubin(ref, noisy));
        else
          scores.push_back(best_smooth_shape(ref, noisy));
      if(signature)
        scores.push_back(run_once(ref, noisy, [](Mesh& m) {
          HD::denoise_mesh(m, HD::parameters::denoising_method(HD::Denoising_method::signature_diffusion));
        }, "defaults"));
      const std::string group = noise.family() + " noise, " + entry.half + " half";
      if(std::find(families.begin(), families.end(), group) == families.end())
        families.push_back(group);
      // The best baseline: of the published filters at the best of their grids where they
      // ran, else of all the baselines run.
      double best_baseline = std::numeric_limits<double>::infinity(), best_grid = best_baseline;
      for(std::size_t k = 0; k < scores.size(); ++k)
      {
        const Score& s = scores[k];
        const std::string& method = methods[k];
        if(k >= 2 && k <= last_baseline)
        {
          best_baseline = (std::min)(best_baseline, s.mad);
          if(is_grid_of_published(method))
            best_grid = (std::min)(best_grid, s.mad);
        }
        mads[group + "|" + method].push_back(s.mad);
        rmss[group + "|" + method].push_back(s.rms);
        tangential_rmss[group + "|" + method].push_back(s.tangential_rms);
        std::cout << row << method << " | " << format(s.mad) << " | " << format(s.rms, 2) << " | "
                  << format(s.tangential_rms, 2) << " | "
                  << (ref.closed ? format(s.volume_change, 2) : std::string("open")) << " | " << s.flipped << " | "
                  << s.new_intersections << " | " << format(s.seconds, 2) << " | " << s.setting << " |\n";
      }
      const std::string row_name = name + ", noise " + noise.label() + " " + noise.direction();
      if(std::isfinite(best_grid))
        best_baseline = best_grid;
      if(!baselines.empty() && scores[1].mad > 1.1 * best_baseline)
        losing_rows.push_back(row_name + ": " + format(scores[1].mad) + " against " + format(best_baseline));
      if(noise.kind != Noise::none && scores[1].rms > scores[0].rms)
        rms_rows.push_back(row_name + ": RMS " + format(scores[1].rms, 3) + " (tangential " +
                           format(scores[1].tangential_rms, 3) + "), the noisy input " + format(scores[0].rms, 3));
      if(ref.closed && noise.kind != Noise::none)
      {
        ++closed_noisy_rows;
        largest_input_volume_deviation =
            (std::max)(largest_input_volume_deviation, std::abs(scores[0].volume_change) / volume_spread);
        if(std::abs(scores[1].volume_change) > 1.)
          volume_rows.push_back(row_name + ": " + format(scores[1].volume_change, 3) + " %, the noisy input " +
                                format(scores[0].volume_change, 3) + " % (std " + format(volume_spread, 2) + " %)");
      }
      std::cout << std::flush;
    }
  }
  std::cout << "\nMAD in degrees; RMS vertex error and its tangential part in mean edge lengths; volume change in "
               "percent of the clean mesh's (closed meshes); flipped: faces more than 90 degrees from the clean "
               "normal; new SI: intersecting face pairs beyond those of the clean mesh. Gaussian noise in mean edge "
               "lengths on every vertex, along the normals (seed 5) or in random directions (seed 6); impulsive "
               "noise: 10 % or 20 % of the vertices moved along their normals (seed 7); depth camera: the level is the "
               "deviation of the noise along the rays at the distance of the mesh's centre (seed 8).\n";
  for(const std::string& group : families)
  {
    std::cout << "\nMean MAD, RMS and tangential RMS, " << group << " (" << mads[group + "|denoise_mesh"].size() << " rows):\n";
    for(const std::string& method : methods)
    {
      const std::vector<double>& m = mads[group + "|" + method];
      const std::vector<double>& r = rmss[group + "|" + method];
      const std::vector<double>& t = tangential_rmss[group + "|" + method];
      if(m.empty())
        continue;
      double mad_sum = 0, rms_sum = 0, tangential_sum = 0;
      for(std::size_t i = 0; i < m.size(); ++i)
      {
        mad_sum += m[i];
        rms_sum += r[i];
        tangential_sum += t[i];
      }
      std::cout << "  " << method << ": MAD " << format(mad_sum / double(m.size()), 4) << ", RMS "
                << format(rms_sum / double(r.size()), 3) << ", tangential RMS "
                << format(tangential_sum / double(t.size()), 3) << "\n";
    }
  }
  // The mean of denoise_mesh against the published filters at their papers' parameters.
  for(const std::string& group : families)
  {
    const auto mean_of = [&](const std::string& method) {
      const std::vector<double>& m = mads[group + "|" + method];
      double sum = 0;
      for(double x : m)
        sum += x;
      return m.empty() ? std::numeric_limits<double>::quiet_NaN() : sum / double(m.size());
    };
    std::vector<std::string> ahead_of, behind;
    for(const std::string& published : {"GNF", "BNF", "L0", "MeshTGV"})
      if(!mads[group + "|" + published].empty())
        (mean_of("denoise_mesh") < mean_of(published) ? ahead_of : behind).push_back(published);
    if(ahead_of.size() + behind.size() == 0)
      continue;
    std::cout << group << ": the mean MAD of denoise_mesh is ahead of";
    for(const std::string& b : ahead_of)
      std::cout << " " << b;
    if(!behind.empty())
    {
      std::cout << ", behind";
      for(const std::string& b : behind)
        std::cout << " " << b;
    }
    std::cout << " (at their papers' parameters)\n";
  }
  if(!baselines.empty())
    std::cout << "Rows where denoise_mesh is more than 10 % above the best baseline (the best grid of GNF, BNF, L0 "
                 "and MeshTGV where they ran): "
              << losing_rows.size() << "\n";
  for(const std::string& row : losing_rows)
    std::cout << "  " << row << "\n";
  std::cout << "Noisy rows where denoise_mesh's RMS exceeds the noisy input's: " << rms_rows.size() << "\n";
  for(const std::string& row : rms_rows)
    std::cout << "  " << row << "\n";
  if(closed_noisy_rows == 0)
    return EXIT_SUCCESS;
  std::cout << "Noisy rows of closed meshes where denoise_mesh changes the clean volume by more than 1 %: "
            << volume_rows.size() << " of " << closed_noisy_rows << "\n";
  for(const std::string& row : volume_rows)
    std::cout << "  " << row << "\n";
  std::cout << "The noisy inputs' volume changes are within " << format(largest_input_volume_deviation, 2)
            << " standard deviations of the noise's own (the volume std in the noisy input's setting column, to "
               "first order: a change that no smoothing can tell from an offset of the surface)\n";
  return EXIT_SUCCESS;
}
