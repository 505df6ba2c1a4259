// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Point-set denoising: denoise_point_set() against Point_set_processing_3's smoothers,
// all run in the same process on the same noisy points:
//  - bilateral_smooth_point_set() (Huang et al. 2013), best of a grid of its neighbour
//    count (12, 24, 48), sharpness angle (10, 20, 40, 60 degrees) and iteration count
//    (1 to 3), on normals by jet_estimate_normals() and mst_orient_normals() over the
//    same neighbours;
//  - jet_smooth_point_set(), best of a grid of its neighbour count (12 to 192);
//  - wlop_simplify_and_regularize_point_set() (Huang et al. 2009), at its defaults but
//    for the share of points it keeps;
//  - the package's other way to denoise points, the paper's signature diffusion (eq.
//    22-23, as denoise_mesh()'s signature_diffusion): iterations of
//    filter_point_set_shape() with the single weight 0 (the NS replaced by its diffused
//    F^s, the points moved along their normals to match it), at the mesh denoiser's sigma,
//    time and anchor weight, best of s (1, 3, 10, 30, 100) and iterations (1 to 12),
//    each searched until the error rises, on normals re-estimated before each
//    iteration as for the peers.
// The points are sampled uniformly on the surfaces of clean CGAL meshes (fixed seeds),
// then Gaussian noise is added to every coordinate (standard deviation: a percentage of
// the bounding-box diagonal, fixed seeds). Every method is measured against the clean
// surface (an AABB tree): the mean and root mean square distance of its points to it,
// in per mille of the diagonal; the mean angle in degrees between its normals (those it
// gives, else jet_estimate_normals() over 24 neighbours of its points) and the normal of
// the clean face closest to each point, unoriented (an orientation is no part of the
// error); the time, which includes the normals that a method needs as input. The grids
// are searched for the lowest mean distance, against the clean surface: the best setting
// that a user with the clean surface could pick. denoise_point_set() runs at one setting
// on every row (k = defaults::point_set_denoising::number_of_neighbors, 24, and the
// library's defaults), on normals estimated as for the peers.
//
// Usage: benchmark_point_set_denoising [DATA_DIR] [--meshes a.off,b.off] [--points N]
//          [--noise p1,p2] [--k K] [--normal-sigma S] [--steps S] [--limit L] [--no-wlop] [--no-peers]
//          [--no-signature]

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/bilateral_smooth_point_set.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/jet_smooth_point_set.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>
#include <CGAL/wlop_simplify_and_regularize_point_set.h>

#include <CGAL/Heat_diffusion/point_set_decomposition.h>
#include <CGAL/Heat_diffusion/point_set_denoising.h>

#include "benchmark_command_line.h"
#include "benchmark_mesh.h"
#include "mesh_measures.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace HD = CGAL::Heat_diffusion;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;
typedef std::pair<Point, Vector> Point_with_normal;
typedef std::vector<Point_with_normal> Points;
const auto point_map = CGAL::First_of_pair_property_map<Point_with_normal>();
const auto normal_map = CGAL::Second_of_pair_property_map<Point_with_normal>();

struct Clean_surface
{
  Mesh mesh;
  Tree tree;
  Mesh::Property_map<Mesh::Face_index, Vector> face_normals;
  double diagonal = 0;
};

struct Measure
{
  double mean = 0, rms = 0, angle = 0, seconds = 0;
  std::string setting;
};

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string format(double x, int precision = 3)
{
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(precision);
  os << x;
  return os.str();
}

// n points uniformly on the surface (faces chosen by area, then uniform barycentric
// coordinates), from a fixed seed.
Points sample_surface(const Mesh& mesh, std::size_t n, unsigned seed)
{
  const test_support::Uniform_surface_sampler<Mesh> sample(mesh);
  std::mt19937_64 random(seed);
  Points points;
  for(std::size_t i = 0; i < n; ++i)
    points.emplace_back(sample(random), Vector(0, 0, 0));
  return points;
}

void add_noise(Points& points, double deviation, unsigned seed)
{
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gaussian(0., deviation);
  for(Point_with_normal& p : points)
  {
    const double x = gaussian(random), y = gaussian(random), z = gaussian(random);
    p.first = p.first + Vector(x, y, z);
  }
}

// The normals of `points` by jet fitting over k neighbours, oriented where
// mst_orient_normals() can (the smoothers only need them consistent locally).
void estimate_normals(Points& points, unsigned k, bool orient)
{
  CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(
      points, k, CGAL::parameters::point_map(point_map).normal_map(normal_map));
  if(orient)
    CGAL::mst_orient_normals(points, k, CGAL::parameters::point_map(point_map).normal_map(normal_map));
}

Measure measure(const Clean_surface& clean, const Points& points, double seconds)
{
  Measure m;
  m.seconds = seconds;
  double sum = 0, squares = 0, angles = 0;
  for(const Point_with_normal& p : points)
  {
    const auto closest = clean.tree.closest_point_and_primitive(p.first);
    const double d = std::sqrt(CGAL::squared_distance(p.first, closest.first));
    sum += d;
    squares += d * d;
    const Vector& n = clean.face_normals[closest.second];
    const double length = std::sqrt(p.second.squared_length());
    const double c = length > 0 ? std::abs(n * p.second) / length : 0.;
    angles += std::acos(std::clamp(c, 0., 1.)) * 180. / CGAL_PI;
  }
  const double n = double(points.size()), per_mille = 1000. / clean.diagonal;
  m.mean = sum / n * per_mille;
  m.rms = std::sqrt(squares / n) * per_mille;
  m.angle = angles / n;
  return m;
}

// Measure of the points of a method that gives no normals: jet normals for the angle.
Measure measure_without_normals(const Clean_surface& clean, Points points, double seconds)
{
  estimate_normals(points, 24, false);
  return measure(clean, points, seconds);
}

struct Settings
{
  unsigned k = HD::defaults::point_set_denoising::number_of_neighbors;
  double normal_sigma = 0;  // automatic
  std::size_t steps = HD::defaults::point_set_denoising::number_of_steps;
  double limit = HD::defaults::point_set_denoising::displacement_limit;
  bool wlop = true, peers = true, signature = true;
};

Measure run_denoise_point_set(const Clean_surface& clean, Points points, const Settings& s, double noise)
{
  const auto start = std::chrono::steady_clock::now();
  estimate_normals(points, s.k + 1, true);
  const auto np = HD::parameters::combine(CGAL::parameters::point_map(point_map).normal_map(normal_map),
                                          HD::parameters::number_of_steps(s.steps),
                                          HD::parameters::displacement_limit(s.limit));
  const HD::Point_set_denoising_report report =
      s.normal_sigma > 0
          ? HD::denoise_point_set(points, s.k, HD::parameters::combine(np, HD::parameters::normal_sigma(s.normal_sigma)))
          : HD::denoise_point_set(points, s.k, np);
  Measure m = measure(clean, points, seconds_since(start));
  m.setting = "k " + std::to_string(s.k) + ", " + std::to_string(report.iterations) + " it, sigma_n " +
              format(report.normal_sigma, 2) + ", noise level " + format(report.noise_level / noise, 2) + " of the true";
  return m;
}

Measure best_jet_smooth(const Clean_surface& clean, const Points& noisy)
{
  Measure best;
  best.mean = -1;
  for(unsigned k : {12u, 24u, 48u, 96u, 192u})
  {
    Points points = noisy;
    const auto start = std::chrono::steady_clock::now();
    CGAL::jet_smooth_point_set<CGAL::Parallel_if_available_tag>(points, k,
                                                                CGAL::parameters::point_map(point_map));
    const double seconds = seconds_since(start);
    Measure m = measure_without_normals(clean, points, seconds);
    m.setting = "k " + std::to_string(k);
    if(best.mean < 0 || m.mean < best.mean)
      best = m;
  }
  return best;
}

Measure best_bilateral(const Clean_surface& clean, const Points& noisy)
{
  Measure best;
  best.mean = -1;
  for(unsigned k : {12u, 24u, 48u})
    for(double angle : {10., 20., 40., 60.})
    {
      Points points = noisy;
      const auto start = std::chrono::steady_clock::now();
      estimate_normals(points, k, true);
      for(int iteration = 1; iteration <= 3; ++iteration)
      {
        CGAL::bilateral_smooth_point_set<CGAL::Parallel_if_available_tag>(
            points, k, CGAL::parameters::point_map(point_map).normal_map(normal_map).sharpness_angle(angle));
        Measure m = measure(clean, points, seconds_since(start));
        m.setting = "k " + std::to_string(k) + ", " + format(angle, 0) + " deg, " + std::to_string(iteration) + " it";
        if(best.mean < 0 || m.mean < best.mean)
          best = m;
      }
    }
  return best;
}

Measure best_signature_diffusion(const Clean_surface& clean, const Points& noisy)
{
  namespace D = HD::defaults;
  Measure best;
  best.mean = -1;
  // Each s runs until its error rises (or 12 iterations), and s grows until the best
  // of an s is no better than that of the s before: the best setting is then inside
  // the grid, not on its edge.
  for(std::size_t steps : {1u, 3u, 10u, 30u, 100u})
  {
    Points points = noisy;
    Measure best_of_steps;
    best_of_steps.mean = -1;
    const auto start = std::chrono::steady_clock::now();
    for(int iteration = 1; iteration <= 12; ++iteration)
    {
      estimate_normals(points, 24, true);
      HD::filter_point_set_shape(
          points, D::number_of_neighbors, std::vector<double>{0.},
          HD::parameters::combine(CGAL::parameters::point_map(point_map).normal_map(normal_map),
                                  HD::parameters::steps_per_level(steps),
                                  HD::parameters::anchor_weight(D::denoising::anchor_weight),
                                  HD::parameters::sigma(D::denoising::sigma), HD::parameters::time(D::denoising::time)));
      Measure m = measure_without_normals(clean, points, seconds_since(start));
      m.setting = "s " + std::to_string(steps) + ", " + std::to_string(iteration) + " it";
      if(best_of_steps.mean >= 0 && m.mean >= best_of_steps.mean)
        break;
      best_of_steps = m;
    }
    if(best.mean >= 0 && best_of_steps.mean >= best.mean)
      break;
    best = best_of_steps;
  }
  return best;
}

Measure run_wlop(const Clean_surface& clean, const Points& noisy)
{
  std::vector<Point> input, output;
  for(const Point_with_normal& p : noisy)
    input.push_back(p.first);
  // (WLOP shuffles its input with std::rand)
  std::srand(1);
  const auto start = std::chrono::steady_clock::now();
  CGAL::wlop_simplify_and_regularize_point_set<CGAL::Parallel_if_available_tag>(
      input, std::back_inserter(output), CGAL::parameters::select_percentage(20.));
  const double seconds = seconds_since(start);
  Points points;
  for(const Point& p : output)
    points.emplace_back(p, Vector(0, 0, 0));
  Measure m = measure_without_normals(clean, points, seconds);
  m.setting = "20 % kept";
  return m;
}

} // namespace

int main(int argc, char* argv[])
{
  std::string data = CGAL_HEAT_DIFFUSION_DATA_DIR;
  std::vector<std::string> meshes = {"fandisk.off", "armadillo.off", "mech-holes-shark.off"};
  std::vector<double> noise_levels = {0.25, 0.5, 1.};
  std::size_t point_count = 20000;
  Settings settings;
  namespace cli = heat_diffusion_cli;
  const std::string usage =
      "usage: benchmark_point_set_denoising [DATA_DIR] [--meshes a.off,b.off] [--points N] [--noise p1,p2]\n"
      "                                     [--k K] [--normal-sigma S] [--steps S] [--limit L] [--no-wlop] [--no-peers]\n"
      "                                     [--no-signature]\n"
      "  DATA_DIR        CGAL's meshes (default: the build's data/meshes)\n"
      "  --meshes        meshes sampled (default fandisk.off,armadillo.off,mech-holes-shark.off)\n"
      "  --points        points sampled on each mesh, 100 to 1000000 (default 20000)\n"
      "  --noise         noise levels, in percent of the bounding-box diagonal, > 0 and <= 10\n"
      "                  (default 0.25,0.5,1)\n"
      "  --k             denoise_point_set's neighbour count, 2 to 200 (default\n"
      "                  defaults::point_set_denoising::number_of_neighbors, 24)\n"
      "  --normal-sigma  denoise_point_set's normal_sigma (default: automatic, the library's)\n"
      "  --steps         denoise_point_set's number_of_steps, 0 to 100 (default the library's)\n"
      "  --limit         denoise_point_set's displacement_limit (default the library's)\n"
      "  --no-signature  without the signature diffusion rows\n"
      "  --no-wlop       leave WLOP out\n"
      "  --no-peers      only the noisy input and denoise_point_set (to try its settings)\n";
  if(const auto exit_code = heat_diffusion_benchmark::read_command_line(
         argc, argv, {"--no-wlop", "--no-peers", "--no-signature"}, {"--meshes", "--points", "--noise", "--k", "--normal-sigma", "--steps", "--limit"},
         usage, [&](const cli::Arguments& a) {
           data = heat_diffusion_benchmark::optional_argument(a, "DATA_DIR", data);
           settings.peers = !a.flag("--no-peers");
           settings.wlop = settings.peers && !a.flag("--no-wlop");
           settings.signature = settings.peers && !a.flag("--no-signature");
           if(a.has("--meshes"))
             meshes = heat_diffusion_benchmark::mesh_names(a);
           if(a.has("--noise"))
           {
             noise_levels.clear();
             std::stringstream list(a.value("--noise", ""));
             for(std::string value; std::getline(list, value, ',');)
             {
               const double x = cli::parse_number("--noise", value, 0., true);
               if(x > 10)
                 throw cli::Usage_error("--noise must be a number > 0 and <= 10, not '" + value + "'");
               noise_levels.push_back(x);
             }
             if(noise_levels.empty())
               throw cli::Usage_error("--noise needs at least one level");
           }
           point_count = cli::parse_count("--points", a.value("--points", "20000"), 100, 1000000);
           settings.k = unsigned(cli::parse_count(
               "--k", a.value("--k", std::to_string(HD::defaults::point_set_denoising::number_of_neighbors)), 2, 200));
           if(a.has("--normal-sigma"))
             settings.normal_sigma = cli::parse_number("--normal-sigma", a.value("--normal-sigma", ""), 0., true);
           if(a.has("--steps"))
             settings.steps = cli::parse_count("--steps", a.value("--steps", ""), 0, 100);
           if(a.has("--limit"))
             settings.limit = cli::parse_number("--limit", a.value("--limit", ""), 0., true);
         }))
    return *exit_code;

  std::vector<std::string> methods = {"noisy input", "denoise_point_set"};
  if(settings.peers)
  {
    methods.push_back("bilateral_smooth_point_set");
    methods.push_back("jet_smooth_point_set");
  }
  if(settings.wlop)
    methods.push_back("wlop_simplify_and_regularize_point_set");
  if(settings.signature)
    methods.push_back("signature diffusion (filter_point_set_shape)");
  std::map<std::string, std::vector<Measure> > results;
  std::vector<std::string> losing_rows;
  std::cout << "| mesh | points | noise % | method | best setting | mean | RMS | angle | time s |\n"
            << "|---|---|---|---|---|---|---|---|---|\n";
  unsigned mesh_seed = 0;
  try
  {
    for(const std::string& name : meshes)
    {
      ++mesh_seed;
      Clean_surface clean;
      clean.mesh = heat_diffusion_benchmark::load_mesh_or_exit<Mesh>(data + "/" + name);
      if(!CGAL::is_triangle_mesh(clean.mesh))
      {
        std::fprintf(stderr, "%s is not a triangle mesh\n", name.c_str());
        return EXIT_FAILURE;
      }
      clean.face_normals = clean.mesh.add_property_map<Mesh::Face_index, Vector>("f:normal").first;
      CGAL::Polygon_mesh_processing::compute_face_normals(clean.mesh, clean.face_normals);
      clean.tree.insert(faces(clean.mesh).first, faces(clean.mesh).second, clean.mesh);
      clean.tree.accelerate_distance_queries();
      const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(clean.mesh);
      clean.diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                 CGAL::square(box.zmax() - box.zmin()));
      const Points sampled = sample_surface(clean.mesh, point_count, mesh_seed);
      unsigned noise_seed = 0;
      for(double level : noise_levels)
      {
        Points noisy = sampled;
        add_noise(noisy, level / 100. * clean.diagonal, 1000 * mesh_seed + ++noise_seed);
        std::map<std::string, Measure> row;
        row["noisy input"] = measure_without_normals(clean, noisy, 0.);
        row["noisy input"].setting = "-";
        row["denoise_point_set"] = run_denoise_point_set(clean, noisy, settings, level / 100. * clean.diagonal);
        if(settings.peers)
        {
          row["bilateral_smooth_point_set"] = best_bilateral(clean, noisy);
          row["jet_smooth_point_set"] = best_jet_smooth(clean, noisy);
        }
        if(settings.wlop)
          row["wlop_simplify_and_regularize_point_set"] = run_wlop(clean, noisy);
        if(settings.signature)
          row["signature diffusion (filter_point_set_shape)"] = best_signature_diffusion(clean, noisy);
        double best_peer = -1;
        for(const std::string& method : methods)
        {
          const Measure& m = row[method];
          results[method].push_back(m);
          // (the peers are the other libraries' methods; signature diffusion is the package's own)
          if(method != "noisy input" && method != "denoise_point_set" && method.rfind("signature", 0) != 0 &&
             (best_peer < 0 || m.mean < best_peer))
            best_peer = m.mean;
          std::cout << "| " << name << " | " << point_count << " | " << format(level, 2) << " | " << method << " | "
                    << m.setting << " | " << format(m.mean) << " | " << format(m.rms) << " | " << format(m.angle, 2)
                    << " | " << format(m.seconds, 2) << " |\n";
        }
        if(settings.peers && row["denoise_point_set"].mean > 1.1 * best_peer)
          losing_rows.push_back(name + " at " + format(level, 2) + " %");
        std::cout << std::flush;
      }
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "\nmean and RMS distance to the clean surface in per mille of the bounding-box diagonal; angle: "
               "mean unoriented angle in degrees to the clean normal; noise: standard deviation of each "
               "coordinate in percent of the diagonal.\n";
  std::cout << "Rows where denoise_point_set's mean is more than 10 % above the best peer's: " << losing_rows.size()
            << "\n";
  for(const std::string& row : losing_rows)
    std::cout << "  " << row << "\n";
  std::cout << "Means over " << results["noisy input"].size() << " rows (mean / RMS / angle / time):";
  for(const std::string& method : methods)
  {
    const std::vector<Measure>& m = results[method];
    double mean = 0, rms = 0, angle = 0, seconds = 0;
    for(const Measure& x : m)
    {
      mean += x.mean;
      rms += x.rms;
      angle += x.angle;
      seconds += x.seconds;
    }
    const double count = double(m.size());
    std::cout << " " << method << " " << format(mean / count) << " / " << format(rms / count) << " / "
              << format(angle / count, 2) << " / " << format(seconds / count, 2) << ";";
  }
  std::cout << std::endl;
  return EXIT_SUCCESS;
}
