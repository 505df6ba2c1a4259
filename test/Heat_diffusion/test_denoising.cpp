// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tests of denoise_mesh(): quality against Guided Mesh Normal Filtering (Zhang et al.
// 2015), Bilateral Normal Filtering (Zheng et al. 2011) and tuned bilateral mesh
// denoising (Fleishman et al. 2003), run on the same noisy meshes -- CAD with creases
// (fandisk at 0.1, 0.3 and 0.5 mean edge length of noise, anchor_dense at 0.1),
// CAD with needle triangles, an organic mesh -- with absolute MAD bounds; impulsive noise
// on fandisk, elephant and head; validity of
// the result (no self-intersection, same vertices, finite, volume kept); the
// displacement limit; clean meshes left unchanged, no collapse of thin parts; the
// untangling of intersecting faces; the volume rescaling per closed component (three
// closed components); agreement
// across kernels and mesh types, scale and rigid-motion invariance, for both denoising
// methods; parameter checking.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#include <CGAL/Heat_diffusion/denoising.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include "test_support.h"
#include "baselines/bilateral_normal_filtering.h"
#include "baselines/guided_normal_filtering.h"
#include "baselines/l0_minimization.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace test_denoising {

namespace HD = CGAL::Heat_diffusion;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef CGAL::Simple_cartesian<double> Cartesian;
typedef CGAL::Surface_mesh<Epick::Point_3> Mesh;

namespace {

// Mean angle, in degrees, between the normals of corresponding faces (MAD).
double mean_angle_deviation(const Mesh& a, const Mesh& b)
{
  double sum = 0;
  for(auto f : a.faces())
  {
    const Epick::Vector_3 na = PMP::compute_face_normal(f, a), nb = PMP::compute_face_normal(f, b);
    sum += std::acos((std::max)(-1., (std::min)(1., na * nb)));
  }
  return sum / double(a.number_of_faces()) * 180. / CGAL_PI;
}

// The root mean square distance between corresponding vertices, in mean edge lengths of `a`.
double rms_distance(const Mesh& a, const Mesh& b)
{
  double squares = 0;
  for(auto v : a.vertices())
    squares += CGAL::squared_distance(a.point(v), b.point(v));
  return std::sqrt(squares / double(a.number_of_vertices())) / test_support::mean_edge_length(a);
}

bool all_finite(const Mesh& mesh)
{
  for(auto v : mesh.vertices())
  {
    const auto& p = mesh.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return false;
  }
  return true;
}

// The best MAD of bilateral mesh denoising over the benchmark's grid: widths sigma_c
// of 1, 1.5, 2 and sigma_s of 0.3, 0.6, 1 mean edge lengths, 1 to 10 iterations.
double best_bilateral(const Mesh& clean, const Mesh& noisy, std::string& best)
{
  const double edge = test_support::mean_edge_length(clean);
  double best_mad = std::numeric_limits<double>::infinity();
  for(double c : {1., 1.5, 2.})
    for(double s : {0.3, 0.6, 1.})
    {
      Mesh mesh = noisy;
      for(unsigned int iterations = 1; iterations <= 10; ++iterations)
      {
        test_support::bilateral_denoising_iteration(mesh, c * edge, s * edge);
        const double mad = mean_angle_deviation(clean, mesh);
        if(mad < best_mad)
        {
          best_mad = mad;
          std::ostringstream os;
          os << "sigma_c " << c << ", sigma_s " << s << " mean edge lengths, " << iterations << " iterations";
          best = os.str();
        }
      }
    }
  return best_mad;
}

// MAD bounds (the measured values, seed 5, plus about 15 %, so that a regression
// fails; elephant: 7.00 plus 7 %, below the 9.02 of the coarse isotropic iterations
// that stopped on the whole displacement and the 7.21 of the best bilateral setting),
// and comparisons with the same-run figures of GNF
// (the paper's defaults) and of the best of the bilateral grid where denoise_mesh() is
// ahead of them: everywhere
// but against the bilateral filter on elephant at 0.1, which checks the bound only.
// The needle-triangle CAD meshes: blade (median face aspect 0.08, every face a needle;
// open) and rotor_small (a third of the faces with a smallest angle under 10 degrees;
// closed, but the noise alone changes its volume by 3 %, which the result keeps, so the
// volume is not checked); a CAD export of needles and creases, couplingdown at 0.1, where
// the filter once made the noisy mesh worse (33.9 degrees against the input's 25.3) and
// shrank it by 3 %.
struct Quality_case
{
  const char* file;
  double noise;
  double bound;
  bool beats_guided, beats_bilateral, keeps_volume;
};

std::size_t count_self_intersections(const Mesh& mesh)
{
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index> > pairs;
  PMP::self_intersections(mesh, std::back_inserter(pairs));
  return pairs.size();
}

void test_quality()
{
  const Quality_case cases[] = {{"fandisk.off", 0.3, 3.2, true, true, true},
                                {"fandisk.off", 0.5, 5.2, true, true, true},
                                {"blade.off", 0.3, 5.0, true, true, false},
                                {"rotor_small.off", 0.3, 18.2, true, true, false},
                                {"couplingdown.off", 0.1, 21.7, true, true, true},
                                {"elephant.off", 0.1, 7.5, true, false, true}};
  for(const Quality_case& c : cases)
  {
    const Mesh clean = test_support::load<Mesh>(c.file);
    Mesh noisy = clean;
    test_support::add_normal_noise(noisy, c.noise, 5);
    Mesh denoised = noisy;
    HD::denoise_mesh(denoised);
    const double noisy_mad = mean_angle_deviation(clean, noisy);
    const double denoised_mad = mean_angle_deviation(clean, denoised);
    std::cout << c.file << ", noise " << c.noise << " mean edge length: MAD noisy " << noisy_mad << ", denoise_mesh "
              << denoised_mad;
    // The baselines are test code: under the sanitizers, where they take most of the
    // time, the package's result is checked against its bounds alone.
    const bool compare = !test_support::under_sanitizers;
    Mesh guided = noisy;
    std::string best_bilateral_setting;
    double guided_mad = 0, bilateral_mad = 0;
    if(compare)
    {
      test_support::baselines::guided_normal_filtering(guided);
      guided_mad = mean_angle_deviation(clean, guided);
      bilateral_mad = best_bilateral(clean, noisy, best_bilateral_setting);
      std::cout << ", GNF " << guided_mad << ", best bilateral " << bilateral_mad << " (" << best_bilateral_setting
                << ")";
    }
    std::cout << std::endl;

    CHECK(denoised.number_of_vertices() == clean.number_of_vertices());
    CHECK(denoised.number_of_faces() == clean.number_of_faces());
    CHECK(all_finite(denoised));
    CHECK_MESSAGE(denoised_mad < c.bound, c.file << ": " << denoised_mad << " vs the bound " << c.bound);
    CHECK_MESSAGE(denoised_mad < noisy_mad, c.file << ": " << denoised_mad << " vs noisy " << noisy_mad);
    if(compare && c.beats_guided)
      CHECK_MESSAGE(denoised_mad < guided_mad, c.file << ": " << denoised_mad << " vs GNF " << guided_mad);
    if(compare && c.beats_bilateral)
      CHECK_MESSAGE(denoised_mad < bilateral_mad, c.file << ": " << denoised_mad << " vs bilateral " << bilateral_mad);
    if(c.keeps_volume)
    {
      CHECK(CGAL::is_closed(clean));
      const double change = PMP::volume(denoised) / PMP::volume(clean) - 1;
      CHECK_MESSAGE(std::abs(change) < 0.01, c.file << ": volume change " << change);
      // EPICK: self-intersections are decided with exact predicates.
      if(compare)
        CHECK_MESSAGE(count_self_intersections(denoised) <= count_self_intersections(guided),
                      c.file << ": more intersecting faces than GNF's result");
    }
  }
}

// Noise in random directions also moves the vertices within the surface: at 0.5 mean
// edge length on elephant (seed 6, as the benchmark) the final tangential relaxations
// take the MAD from 14.1 to 10.3 degrees and the new self-intersections from 131 to 6
// (bound: 10.3 plus about 10 %; Taubin smoothing, the best baseline there, gives 9.66).
void test_random_direction_noise()
{
  const Mesh clean = test_support::load<Mesh>("elephant.off");
  Mesh noisy = clean;
  test_support::add_random_direction_noise(noisy, 0.5, 6);
  Mesh denoised = noisy;
  HD::denoise_mesh(denoised);
  const double mad = mean_angle_deviation(clean, denoised);
  const std::size_t new_intersections = count_self_intersections(denoised) - count_self_intersections(clean);
  const double change = PMP::volume(denoised) / PMP::volume(clean) - 1;
  std::cout << "elephant, noise 0.5 in random directions: MAD " << mad << ", new self-intersections "
            << new_intersections << ", volume change " << change << std::endl;
  CHECK_MESSAGE(mad < 11.4, "elephant, random directions: MAD " << mad);
  CHECK_MESSAGE(new_intersections <= 10, "elephant, random directions: " << new_intersections
                                                                         << " new self-intersections");
  CHECK_MESSAGE(std::abs(change) < 0.01, "elephant, random directions: volume change " << change);
}

// No sliding: the filter's fit to the normals and its tangential relaxations move the
// vertices within the surface of a curved mesh, which lowered the MAD but raised the RMS
// vertex error above the noisy input's where the noise was along the normals: elephant at
// 0.2 mean edge length (seed 5, as the benchmark) 0.22 against the input's 0.20, lion-head
// at 0.2 0.23 against 0.20 (0.089 and 0.092 at 0.1, below). With half the drift undone
// (undo_tangential_drift()) 0.146 and 0.139, 0.077 and 0.072 at 0.1; the MAD falls too
// (elephant 6.41 and 8.47 to 6.26 and 8.19 degrees; lion-head 4.90 and 6.63 to 4.79 and
// 6.30). Bounds: the RMS below 0.9 times the noisy input's, and the MAD at most what it
// was before the drift was undone.
void test_no_sliding()
{
  struct Case
  {
    const char* file;
    double noise, mad_bound;
  };
  for(const Case c : {Case{"elephant.off", 0.1, 6.41}, Case{"elephant.off", 0.2, 8.47},
                      Case{"lion-head.off", 0.1, 4.90}, Case{"lion-head.off", 0.2, 6.63}})
  {
    const Mesh clean = test_support::load<Mesh>(c.file);
    Mesh noisy = clean;
    test_support::add_normal_noise(noisy, c.noise, 5);
    Mesh denoised = noisy;
    HD::denoise_mesh(denoised);
    const double noisy_rms = rms_distance(clean, noisy), rms = rms_distance(clean, denoised);
    const double mad = mean_angle_deviation(clean, denoised);
    std::cout << c.file << ", noise " << c.noise << " along the normals: RMS " << noisy_rms << " -> " << rms
              << " mean edge lengths, MAD " << mad << std::endl;
    CHECK_MESSAGE(rms < 0.9 * noisy_rms, c.file << ", noise " << c.noise << ": RMS " << rms << " vs noisy " << noisy_rms);
    CHECK_MESSAGE(mad <= c.mad_bound, c.file << ", noise " << c.noise << ": MAD " << mad << " vs " << c.mad_bound);
  }
}

// The L0 minimization baseline of benchmark_denoising (He and Schaefer 2013): its
// edge-based operator sums to 0 and vanishes on four coplanar points, whatever their
// positions in the plane, but not on a folded edge; a regular triangulated grid (flat,
// every edge's two triangles a parallelogram, so that the regularisation vanishes too) is
// the optimisation's fixed point.
void test_l0_baseline()
{
  namespace TB = test_support::baselines;
  CGAL::Random random(3);
  for(int trial = 0; trial < 20; ++trial)
  {
    const Eigen::Vector3d u = Eigen::Vector3d::Random().normalized();
    const Eigen::Vector3d v = u.cross(Eigen::Vector3d::Random()).normalized();
    auto in_plane = [&](double a, double b) { return Eigen::Vector3d(a * u + b * v); };
    std::array<Eigen::Vector3d, 4> p = {in_plane(0, 0), in_plane(random.get_double(-0.5, 1.5), random.get_double(0.2, 1)),
                                        in_plane(1, 0), in_plane(random.get_double(-0.5, 1.5), -random.get_double(0.2, 1))};
    std::array<double, 4> c = TB::l0_edge_coefficients(p);
    const Eigen::Vector3d flat = c[0] * p[0] + c[1] * p[1] + c[2] * p[2] + c[3] * p[3];
    CHECK(std::abs(c[0] + c[1] + c[2] + c[3]) < 1e-12);
    CHECK_MESSAGE(flat.norm() < 1e-12, "L0 operator on coplanar points: " << flat.norm());
    p[1] += 0.3 * u.cross(v);
    c = TB::l0_edge_coefficients(p);
    const Eigen::Vector3d folded = c[0] * p[0] + c[1] * p[1] + c[2] * p[2] + c[3] * p[3];
    CHECK_MESSAGE(folded.norm() > 0.05, "L0 operator on a folded edge: " << folded.norm());
  }
  Mesh grid;
  CGAL::make_grid(8, 8, grid, true);
  TB::Face_mesh fm = TB::make_face_mesh(grid);
  const std::vector<Eigen::Vector3d> before = fm.points;
  CHECK(TB::l0_minimization(fm) == 40);  // beta from 1e-3 by sqrt(2) to 1e3
  double moved = 0;
  for(std::size_t i = 0; i < before.size(); ++i)
    moved = (std::max)(moved, (fm.points[i] - before[i]).norm());
  CHECK_MESSAGE(moved < 1e-9, "L0 minimization moved a flat regular grid by " << moved);
}

// Impulsive noise: a tenth or a fifth of the vertices moved along their normals by
// Gaussian noise of 0.5 or 1 mean edge length (seed 7, as benchmark_denoising), the others
// left clean. The noise level, a median, reads the clean majority, and the filters
// stopped on it left the impulses and blurred the detail around them: without the
// outlier test (remove_impulses()) the results were 6.92 and 18.8 degrees of MAD on
// fandisk (0.5 on 10 %, 1 on 20 %), 11.5 on elephant (1 on 10 %) and 13.2 on head (0.5 on
// 20 %), hardly better than the noisy inputs (6.69, 20.2, 11.0, 16.7) or worse. Bounds:
// the measured values with the test plus about 15 %; BNF at its paper's defaults, the
// best of the published filters on most of these rows, in the same run; the RMS vertex
// error below the noisy input's (the outliers move along their rings' normals).
void test_impulsive_noise()
{
  struct Case
  {
    const char* file;
    double fraction, noise, bound;
  };
  for(const Case c : {Case{"fandisk.off", 0.1, 0.5, 1.8}, Case{"fandisk.off", 0.2, 1., 5.2},
                      Case{"elephant.off", 0.1, 1., 3.0}, Case{"head.off", 0.2, 0.5, 9.3}})
  {
    const Mesh clean = test_support::load<Mesh>(c.file);
    Mesh noisy = clean;
    test_support::add_impulsive_noise(noisy, c.fraction, c.noise, 7);
    Mesh denoised = noisy;
    const HD::Denoising_report report = HD::denoise_mesh(denoised);
    const double noisy_mad = mean_angle_deviation(clean, noisy), mad = mean_angle_deviation(clean, denoised);
    const double noisy_rms = rms_distance(clean, noisy), rms = rms_distance(clean, denoised);
    std::cout << c.file << ", impulses of " << c.noise << " mean edge length on " << 100 * c.fraction
              << " % of the vertices: MAD " << noisy_mad << " -> " << mad << ", RMS " << noisy_rms << " -> " << rms
              << " mean edge lengths, " << report.impulses << " outliers moved";
    CHECK(all_finite(denoised));
    CHECK_MESSAGE(report.impulses > 0, c.file << ": no outlier found");
    CHECK_MESSAGE(mad < c.bound, c.file << ", impulses: MAD " << mad << " vs the bound " << c.bound);
    CHECK_MESSAGE(rms < noisy_rms, c.file << ", impulses: RMS " << rms << " vs noisy " << noisy_rms);
    if(!test_support::under_sanitizers)
    {
      Mesh bilateral_normal = noisy;
      test_support::baselines::bilateral_normal_filtering(bilateral_normal);
      const double bnf = mean_angle_deviation(clean, bilateral_normal);
      std::cout << ", BNF " << bnf;
      CHECK_MESSAGE(mad < bnf, c.file << ", impulses: MAD " << mad << " vs BNF " << bnf);
    }
    std::cout << std::endl;
  }
}

// Weak noise on CAD parts, where one width of the normal weights for every face (0.45)
// leaked across the creases: fandisk at 0.1 mean edge length along the normals (seed 5)
// gave 2.16 degrees and anchor_dense at 0.1 in random directions (seed 6) 3.48, against
// 1.51 and 3.08 for Bilateral Normal Filtering. With widths per face adapted to the noise
// and the shape (crease_preserving_widths()), denoise_mesh() is ahead of BNF and GNF
// (the papers' defaults) on both, in the same run, and keeps the volume.
void test_weak_noise_on_cad()
{
  struct Case
  {
    const char* file;
    bool random_directions;
  };
  for(const Case c : {Case{"fandisk.off", false}, Case{"anchor_dense.off", true}})
  {
    const Mesh clean = test_support::load<Mesh>(c.file);
    Mesh noisy = clean;
    if(c.random_directions)
      test_support::add_random_direction_noise(noisy, 0.1, 6);
    else
      test_support::add_normal_noise(noisy, 0.1, 5);
    Mesh denoised = noisy, guided = noisy, bilateral_normal = noisy;
    HD::denoise_mesh(denoised);
    test_support::baselines::guided_normal_filtering(guided);
    test_support::baselines::bilateral_normal_filtering(bilateral_normal);
    const double mad = mean_angle_deviation(clean, denoised);
    const double guided_mad = mean_angle_deviation(clean, guided);
    const double bilateral_normal_mad = mean_angle_deviation(clean, bilateral_normal);
    const double change = PMP::volume(denoised) / PMP::volume(clean) - 1;
    std::cout << c.file << ", noise 0.1 " << (c.random_directions ? "in random directions" : "along the normals")
              << ": MAD denoise_mesh " << mad << ", GNF " << guided_mad << ", BNF " << bilateral_normal_mad
              << ", volume change " << change << std::endl;
    CHECK_MESSAGE(mad < bilateral_normal_mad, c.file << ": " << mad << " vs BNF " << bilateral_normal_mad);
    CHECK_MESSAGE(mad < guided_mad, c.file << ": " << mad << " vs GNF " << guided_mad);
    CHECK_MESSAGE(std::abs(change) < 0.01, c.file << ": volume change " << change);
  }
}

// Clean meshes are left as they are. On fandisk, anchor_dense and rotor_small the noise
// estimate reads rounding errors or the facets of needles as noise, and the roughness
// left by the crease-preserving phase is as large as that estimate; on elephant the
// noise level of second differences is all detail. The filters used to move them (MAD
// 0.15, 2.96, 16.2 and 4.32 degrees). Weak noise is still removed, and no longer
// replaced by a loss of detail: fandisk with 0.02 mean edge length of noise, elephant
// with 0.05 in random directions (MAD 3.42 before denoising, 4.92 with the former stop).
// Noise below the roughness of the shape is not answered by a loss of shape: b9_mesh (a
// CAD export of needles) with 0.1 mean edge length along the normals, MAD 13.2 degrees,
// went to 15.3 when the flow's stop ignored that its residual was correlated from the
// shortest time on (see rough_shape_margin), and goes to 12.7.
void test_clean_meshes()
{
  for(const char* file : {"fandisk.off", "anchor_dense.off", "rotor_small.off", "elephant.off"})
  {
    const Mesh clean = test_support::load<Mesh>(file);
    Mesh denoised = clean;
    HD::denoise_mesh(denoised);
    double largest_move = 0;
    for(auto v : clean.vertices())
      largest_move = (std::max)(largest_move, std::sqrt(CGAL::squared_distance(clean.point(v), denoised.point(v))));
    const double edge = test_support::mean_edge_length(clean);
    std::cout << file << ", clean: largest move " << largest_move / edge << " mean edge lengths, MAD "
              << mean_angle_deviation(clean, denoised) << std::endl;
    CHECK_MESSAGE(largest_move <= 1e-9 * edge, file << ": a clean mesh moved by " << largest_move / edge
                                                    << " mean edge lengths");
  }
  struct Case
  {
    const char* file;
    double noise;
    bool random_directions;
    double largest_ratio;  // of the MAD after denoising to the noisy input's
  };
  for(const Case c : {Case{"fandisk.off", 0.02, false, 0.7}, Case{"elephant.off", 0.05, true, 0.99},
                      Case{"b9_mesh.off", 0.1, false, 0.99}})
  {
    const Mesh clean = test_support::load<Mesh>(c.file);
    Mesh noisy = clean;
    if(c.random_directions)
      test_support::add_random_direction_noise(noisy, c.noise, 6);
    else
      test_support::add_normal_noise(noisy, c.noise, 5);
    Mesh denoised = noisy;
    HD::denoise_mesh(denoised);
    const double noisy_mad = mean_angle_deviation(clean, noisy), mad = mean_angle_deviation(clean, denoised);
    std::cout << c.file << ", noise " << c.noise << (c.random_directions ? " in random directions" : " along the normals")
              << ": MAD " << noisy_mad << " -> " << mad << std::endl;
    CHECK_MESSAGE(mad < c.largest_ratio * noisy_mad, c.file << ": weak noise not removed: " << noisy_mad << " -> " << mad);
  }
}

// Meshes whose parts are a few faces thick (anchor) or whose needles span curved holes
// (cheese) used to collapse: the filters moved every vertex inward (anchor, clean: 49
// degrees of MAD and -38 % of volume; cheese with 0.1 mean edge length of noise: 69.8
// degrees and -90 %, worse than the noisy input's 30.5). The filters now stop before
// their mean displacement along the normals turns one-way, and a mesh of needles whose
// smoothed copy shrinks it is smoothed by the relinearised flow stopped where its
// residual turns correlated, rescaled to the input's volume: anchor, clean, 0.12 degrees
// and 0.0 %, at 0.3 noise 31.6 (below the tuned smooth_shape()'s 31.2 plus 10 %), cheese
// at 0.1 10.3 and +0.6 % (the flow with the input's operator: 36.8 and 14.8; the copy at
// a halved time: 2.60, 46.0 and 15.3; the shrinkage stop alone 7.09 and -8.7 %, 27.4 and
// -11 %). A thin-walled part whose rims the
// crease-preserving filter erodes (turbine at 0.3 noise: 15.2 degrees and -7.6 %) is
// smoothed by the flow with the input's operator instead: 8.17 and -0.06 %. Bounds: those
// plus about 15 % (anchor: 0.5).
void test_no_collapse()
{
  struct Case
  {
    const char* file;
    double noise;
    double bound;
  };
  for(const Case c : {Case{"anchor.off", 0., 0.5}, Case{"anchor.off", 0.3, 36.3}, Case{"cheese.off", 0.1, 11.9},
                      Case{"turbine.off", 0.3, 9.4}, Case{"couplingdown.off", 0.1, 16.5},
                      Case{"rotor_small.off", 0.1, 8.6}})
  {
    const Mesh clean = test_support::load<Mesh>(c.file);
    Mesh noisy = clean;
    if(c.noise > 0)
      test_support::add_normal_noise(noisy, c.noise, 5);
    Mesh denoised = noisy;
    HD::denoise_mesh(denoised);
    const double noisy_mad = mean_angle_deviation(clean, noisy), mad = mean_angle_deviation(clean, denoised);
    // Against the noisy input's volume: the noise alone changes anchor's by 5.6 % at 0.3.
    const double change = PMP::volume(denoised) / PMP::volume(noisy) - 1;
    std::cout << c.file << ", noise " << c.noise << ": MAD " << noisy_mad << " -> " << mad << ", volume change "
              << change << " from the noisy input" << std::endl;
    CHECK_MESSAGE(std::abs(change) < 0.01, c.file << ": volume change " << change);
    CHECK_MESSAGE(mad < c.bound, c.file << ": MAD " << mad);
    if(c.noise > 0)
      CHECK_MESSAGE(mad < noisy_mad, c.file << ": MAD " << mad << " against the noisy input's " << noisy_mad);
  }
}

// The package-frame points `points` (by the vertex index of `ncc`, on the mesh of
// `ncc`) written to the points of `mesh`, a copy of that mesh, as denoise_mesh()
// writes its result.
auto point_writer(Mesh& mesh, const HD::Normal_controlled_coordinates<Mesh>& ncc)
{
  return [&mesh, &ncc](const std::vector<Eigen::Vector3d>& points) {
    for(auto v : mesh.vertices())
    {
      const Eigen::Vector3d p = ncc.indexed_mesh().to_user_frame(points[ncc.vertex_index(v)]);
      mesh.point(v) = Epick::Point_3(p.x(), p.y(), p.z());
    }
  };
}

// The untangling of the denoised mesh (untangle_self_intersections()). Noise in random
// directions folds faces over within the surface, which the filter does not always undo:
// fandisk and couplingdown at 0.5 mean edge length (seed 6, as the benchmark) kept 479
// and 81 intersecting face pairs, at 9.90 and 31.62 degrees of MAD. Local smoothing of
// the vertices of the intersecting faces removes them all: the MAD goes down (7.64,
// 30.83), and fewer than a fifth of the faces turn (a sixth on fandisk). A result
// without intersections is left as it is.
void test_untangling()
{
  struct Case
  {
    const char* file;
    double noise;
    double bound;
  };
  for(const Case c : {Case{"fandisk.off", 0.5, 8.4}, Case{"couplingdown.off", 0.5, 31.2}, Case{"elephant.off", 0.1, 0.}})
  {
    const Mesh clean = test_support::load<Mesh>(c.file);
    Mesh noisy = clean;
    test_support::add_random_direction_noise(noisy, c.noise, 6);
    // The filter's result, before the untangling, and after it.
    const HD::Normal_controlled_coordinates<Mesh> ncc(noisy);
    const HD::internal::Indexed_mesh& indexed = ncc.indexed_mesh();
    const std::vector<Eigen::Vector3d> filtered =
        HD::internal::filter_normals(indexed, HD::internal::Normal_filtering_options(), HD::internal::Progress());
    Mesh untangled = noisy;
    const auto write_back = point_writer(untangled, ncc);
    write_back(filtered);
    const Mesh before = untangled;
    std::vector<Eigen::Vector3d> points = filtered;
    HD::internal::untangle_self_intersections(
        untangled, untangled.points(), Epick(), indexed, [&](Mesh::Vertex_index v) { return ncc.vertex_index(v); },
        write_back, points);
    Mesh denoised = noisy;
    HD::denoise_mesh(denoised);
    // Faces turned by the untangling (the volume rescaling turns none).
    std::size_t turned = 0, differing = 0;
    for(auto f : before.faces())
      turned += PMP::compute_face_normal(f, before) * PMP::compute_face_normal(f, untangled) < 1 - 1e-12 ? 1 : 0;
    for(auto v : denoised.vertices())
      differing += denoised.point(v) != untangled.point(v) ? 1 : 0;
    const std::size_t found = count_self_intersections(before), left = count_self_intersections(untangled);
    const double mad_before = mean_angle_deviation(clean, before), mad = mean_angle_deviation(clean, untangled);
    std::cout << c.file << ", noise " << c.noise << " in random directions: intersecting pairs " << found << " -> "
              << left << ", MAD " << mad_before << " -> " << mad << ", " << turned << " faces turned" << std::endl;
    CHECK_MESSAGE(differing == 0, c.file << ": denoise_mesh() ends with the untangling");
    CHECK(left == 0);
    if(found == 0)
    {
      CHECK_MESSAGE(points == filtered, c.file << ": vertices moved without intersections");
      continue;
    }
    CHECK_MESSAGE(mad < c.bound && mad < mad_before, c.file << ": MAD " << mad_before << " -> " << mad);
    CHECK_MESSAGE(turned < before.number_of_faces() / 5, c.file << ": " << turned << " faces turned");
  }
}

// The untangling's search after a move covers only the faces near those that moved; it
// must find the pairs that a search of the whole mesh finds.
void test_local_intersection_search()
{
  const Mesh clean = test_support::load<Mesh>("fandisk.off");
  Mesh mesh = clean;
  test_support::add_random_direction_noise(mesh, 0.5, 6);
  const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
  const HD::internal::Indexed_mesh& indexed = ncc.indexed_mesh();
  std::vector<Eigen::Vector3d> points =
      HD::internal::filter_normals(indexed, HD::internal::Normal_filtering_options(), HD::internal::Progress());
  auto vertex_index = [&](Mesh::Vertex_index v) { return ncc.vertex_index(v); };
  const auto write_back = point_writer(mesh, ncc);
  typedef HD::internal::Intersecting_face_pairs<Mesh, Mesh::Property_map<Mesh::Vertex_index, Epick::Point_3>, Epick,
                                                decltype(vertex_index)>
      Pairs;
  auto sorted = [](std::vector<Pairs::Face_pair> pairs) {
    for(auto& pair : pairs)
      if(pair.second < pair.first)
        std::swap(pair.first, pair.second);
    std::sort(pairs.begin(), pairs.end());
    return pairs;
  };
  write_back(points);
  const std::vector<Eigen::Vector3d> filtered = points;
  Pairs kept(mesh, mesh.points(), Epick(), vertex_index);
  const auto first = sorted(kept.update(points));
  // The vertices of one face of each intersecting pair take one umbrella step; then
  // they move back. Pairs between a face that moved and one that did not are found
  // only if the search covers the faces near those that moved.
  std::vector<unsigned char> marked(points.size(), 0);
  for(const auto& pair : first)
    for(const auto v : vertices_around_face(mesh.halfedge(pair.first), mesh))
      marked[vertex_index(v)] = 1;
  HD::internal::smooth_marked_vertices(indexed, marked, HD::internal::Untangling_step{0, false}, points);
  std::size_t moved_faces = 0;
  for(const auto f : mesh.faces())
    for(const auto v : vertices_around_face(mesh.halfedge(f), mesh))
      if(marked[vertex_index(v)])
      {
        ++moved_faces;
        break;
      }
  // Under a quarter of the faces: the search after the move is a local one.
  CHECK_MESSAGE(4 * moved_faces < mesh.number_of_faces(), moved_faces << " faces moved");
  const std::vector<Eigen::Vector3d>& smoothed = points;
  for(const std::vector<Eigen::Vector3d>* moved : {&smoothed, &filtered})
  {
    const char* move = moved == &smoothed ? "the umbrella step" : "the move back";
    write_back(*moved);
    const auto local = sorted(kept.update(*moved));
    Pairs fresh(mesh, mesh.points(), Epick(), vertex_index);
    const auto whole = sorted(fresh.update(*moved));
    std::cout << "fandisk, noise 0.5 in random directions: " << first.size() << " intersecting pairs; after " << move
              << " (" << moved_faces << " faces), " << local.size() << " found near the moved faces, "
              << whole.size() << " in the whole mesh" << std::endl;
    CHECK(local == whole);
  }
  CHECK(first.size() > 100);
}

// What the tests of the smoothing flow start from: a mesh's indexed form, its face
// adjacency, its noise level along the normals and its cotangent flow.
struct Flow_setup
{
  explicit Flow_setup(const Mesh& mesh)
      : ncc(mesh), indexed(ncc.indexed_mesh()), adjacency(HD::internal::make_face_adjacency(indexed)),
        noise(HD::internal::plane_fit_noise_level(indexed, adjacency, indexed.points)), flow(indexed, indexed.points)
  {
  }

  const HD::Normal_controlled_coordinates<Mesh> ncc;
  const HD::internal::Indexed_mesh& indexed;
  const HD::internal::Face_adjacency adjacency;
  const double noise;
  HD::internal::Cotangent_flow flow;
};

// The weight of the needle copy (needle_copy_weight()): at the stop of the flow, the
// residual of blade at 0.3 along the normals is correlated by the vertices' sliding
// along its needles, not along the normals (the copy is taken: weight 1), that of
// couplingdown at 0.1 along the normals, by removed shape (the flow is kept: weight 0).
void test_needle_copy_weight()
{
  struct Case
  {
    const char* file;
    double noise;
    double weight;
  };
  for(const Case c : {Case{"blade.off", 0.3, 1.}, Case{"couplingdown.off", 0.1, 0.}})
  {
    Mesh noisy = test_support::load<Mesh>(c.file);
    test_support::add_normal_noise(noisy, c.noise, 5);
    Flow_setup setup(noisy);
    std::vector<Eigen::Vector3d> stopped;
    double time = 0;
    CHECK(HD::internal::smooth_until_residual_is_correlated(setup.indexed, setup.noise, setup.flow, stopped, time));
    const double weight = HD::internal::needle_copy_weight(setup.indexed, setup.adjacency, stopped);
    std::cout << c.file << ", noise " << c.noise << ": needle copy weight " << weight << std::endl;
    CHECK_MESSAGE(weight == c.weight, c.file << ": needle copy weight " << weight);
  }
}

// The matrices of the flow and of the needle fit, assembled in place over the vertices'
// one-rings (Vertex_block_matrix) and applied face by face (Normal_fit_system), against
// the textbook assembly from triplets, on blade at 0.3 along the normals (needles) and
// on a mesh of three components (two fandisks and an elephant) and on an open one
// (elephant with holes: the boundary's one-sided stars): the cotangent stiffness
// matrix is the triplets' to the bit, symmetric with rows summing to 0; the fit's
// product and diagonal blocks are those of its assembled matrix, which is the
// triplets'; the fit (conjugate gradients on the product) solves the assembled system;
// a restarted flow is the flow of its new points.
void test_vertex_systems()
{
  Mesh blade = test_support::load<Mesh>("blade.off");
  test_support::add_normal_noise(blade, 0.3, 5);
  Mesh components = test_support::load<Mesh>("fandisk.off");
  CGAL::copy_face_graph(test_support::load<Mesh>("elephant.off"), components);
  CGAL::copy_face_graph(test_support::load<Mesh>("fandisk.off"), components);
  const Mesh open = test_support::load<Mesh>("elephant-with-holes.off");
  CHECK(!CGAL::is_closed(open));
  for(const Mesh* mesh : std::vector<const Mesh*>{&blade, &components, &open})
  {
    const HD::Normal_controlled_coordinates<Mesh> ncc(*mesh);
    const HD::internal::Indexed_mesh& indexed = ncc.indexed_mesh();
    const std::vector<Eigen::Vector3d>& points = indexed.points;
    const Eigen::Index n = Eigen::Index(points.size());
    typedef Eigen::Triplet<double> Triplet;

    Eigen::SparseMatrix<double> stiffness, reference(n, n);
    std::vector<double> masses;
    HD::internal::cotangent_stiffness(indexed, points, stiffness, masses);
    std::vector<Triplet> triplets;
    for(const auto& t : indexed.triangles)
      for(int c = 0; c < 3; ++c)
      {
        const std::size_t k = t[c], i = t[(c + 1) % 3], j = t[(c + 2) % 3];
        const Eigen::Vector3d a = points[i] - points[k], b = points[j] - points[k];
        const double w = 0.5 * a.dot(b) / a.cross(b).norm();
        triplets.insert(triplets.end(), {Triplet(Eigen::Index(i), Eigen::Index(i), w),
                                         Triplet(Eigen::Index(j), Eigen::Index(j), w),
                                         Triplet(Eigen::Index(i), Eigen::Index(j), -w),
                                         Triplet(Eigen::Index(j), Eigen::Index(i), -w)});
      }
    reference.setFromTriplets(triplets.begin(), triplets.end());
    const double scale = reference.norm();
    CHECK_MESSAGE((stiffness - reference).norm() == 0, "stiffness: " << (stiffness - reference).norm() / scale);
    CHECK((stiffness - Eigen::SparseMatrix<double>(stiffness.transpose())).norm() == 0);
    CHECK((stiffness * Eigen::VectorXd::Ones(n)).lpNorm<Eigen::Infinity>() < 1e-12 * scale);

    // The fit to the normals of the clean-looking copy (the flow of the input), anchored
    // to the input with the package's weight.
    std::vector<Eigen::Vector3d> smoothed, normals, centroids, fitted;
    std::vector<double> areas;
    const double time = 4 * std::pow(HD::internal::mean_edge_length(indexed), 2);
    CHECK(HD::internal::Cotangent_flow(indexed, points).smooth(time, 1, smoothed));
    // A flow restarted from other points, after it has factorised the system of its
    // first ones, is the flow of the new points, to the bit (the relinearised flow
    // restarts one flow for each of its steps).
    {
      HD::internal::Cotangent_flow restarted(indexed, smoothed);
      std::vector<Eigen::Vector3d> again;
      CHECK(restarted.smooth(time, 1, again));
      CHECK(again != smoothed);
      restarted.restart(points);
      CHECK(restarted.smooth(time, 1, again));
      CHECK(again == smoothed);
    }
    HD::internal::face_geometry(indexed, smoothed, normals, areas, centroids);
    const double lambda = HD::internal::needle_fit_anchor_weight;
    std::vector<double> anchor_areas(indexed.triangles.size()), weights = HD::internal::barycentric_masses(indexed, points);
    for(double& weight : weights)
      weight *= lambda;
    triplets.clear();
    for(std::size_t f = 0; f < indexed.triangles.size(); ++f)
    {
      const auto& t = indexed.triangles[f];
      anchor_areas[f] = 0.5 * (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).norm();
      const Eigen::Matrix3d block = anchor_areas[f] * normals[f] * normals[f].transpose();
      for(int e = 0; e < 3; ++e)
      {
        const Eigen::Index i = Eigen::Index(3 * t[e]), j = Eigen::Index(3 * t[(e + 1) % 3]);
        for(int r = 0; r < 3; ++r)
          for(int c = 0; c < 3; ++c)
            triplets.insert(triplets.end(), {Triplet(i + r, i + c, block(r, c)), Triplet(j + r, j + c, block(r, c)),
                                             Triplet(i + r, j + c, -block(r, c)), Triplet(j + r, i + c, -block(r, c))});
      }
    }
    for(Eigen::Index i = 0; i < 3 * n; ++i)
      triplets.emplace_back(i, i, weights[std::size_t(i / 3)]);
    Eigen::SparseMatrix<double> fit_reference(3 * n, 3 * n);
    fit_reference.setFromTriplets(triplets.begin(), triplets.end());
    const HD::internal::Normal_fit_system system(indexed, normals, anchor_areas, weights);
    const Eigen::SparseMatrix<double> assembled = system.assembled();
    const double fit_scale = fit_reference.norm();
    CHECK_MESSAGE((assembled - fit_reference).norm() == 0, "fit: " << (assembled - fit_reference).norm() / fit_scale);
    CGAL::Random random(3);
    Eigen::VectorXd x(3 * n);
    for(Eigen::Index i = 0; i < 3 * n; ++i)
      x[i] = random.get_double(-1, 1);
    const Eigen::VectorXd product = system * x, assembled_product = assembled * x;
    const double product_error = (product - assembled_product).norm() / assembled_product.norm();
    CHECK_MESSAGE(product_error < 1e-14, "fit: product error " << product_error);
    const std::vector<Eigen::Matrix3d> blocks = system.diagonal_blocks();
    double block_error = 0;
    for(Eigen::Index i = 0; i < n; ++i)
      block_error = (std::max)(block_error, (blocks[std::size_t(i)] -
                                             Eigen::Matrix3d(assembled.block(3 * i, 3 * i, 3, 3))).norm());
    CHECK_MESSAGE(block_error < 1e-14 * fit_scale, "fit: diagonal block error " << block_error / fit_scale);

    CHECK(HD::internal::fit_vertices_to_normals_least_squares(indexed, normals, points, lambda, fitted));
    Eigen::VectorXd rhs(3 * n), solution(3 * n);
    for(Eigen::Index i = 0; i < n; ++i)
    {
      rhs.segment<3>(3 * i) = weights[std::size_t(i)] * points[std::size_t(i)];
      solution.segment<3>(3 * i) = fitted[std::size_t(i)];
    }
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > direct(assembled);
    const Eigen::VectorXd exact = direct.solve(rhs);
    const double residual = (assembled * solution - rhs).norm() / rhs.norm(),
                 distance = (solution - exact).norm() / exact.norm();
    std::cout << (mesh == &blade ? "blade, noise 0.3" : mesh == &open ? "elephant with holes" : "three components")
              << ": the fit's relative residual "
              << residual << ", relative distance to the direct solve " << distance << std::endl;
    CHECK_MESSAGE(residual < 1e-9 && distance < 1e-6, "fit: residual " << residual << ", distance " << distance);
  }
}

// The stop of the smoothing flow (smooth_until_residual_is_correlated()): the residual's
// neighbour correlation is 0 for no change, 1 for a translation, near 0 for independent
// noise; on a noisy mesh the flow ends where the correlation of its residual is the
// threshold (interpolated between two times a factor of 2 apart: within 0.05 of it), its
// time between eps^2 and 64 eps^2, and the noise is removed (anchor_dense at 0.3 along
// the normals: 5.5 eps^2, MAD 28.8 to 14.8 degrees). A flow that fails from some time on
// ends the search at the last time below the crossing; one that always fails gives no
// result. What the flow removes first, M^-1 L p, is the limit of its residual over the
// time, and its correlation is negative on noise. On the clean anchor, whose noise
// estimate reads its thin parts (0.36 mean edge length) and whose residual is all shape
// at every time, the flow takes the shortest time, which leaves the mesh where it is.
void test_whiteness_stop()
{
  const Mesh clean = test_support::load<Mesh>("anchor_dense.off"), thin = test_support::load<Mesh>("anchor.off");
  Mesh noisy = clean;
  test_support::add_normal_noise(noisy, 0.3, 5);
  for(const Mesh* mesh : std::vector<const Mesh*>{&noisy, &thin})
  {
    Flow_setup setup(*mesh);
    const HD::internal::Indexed_mesh& indexed = setup.indexed;
    const std::vector<Eigen::Vector3d>& input = indexed.points;
    const double noise = setup.noise;
    const double edge = HD::internal::mean_edge_length(indexed);
    if(mesh == &noisy)
    {
      CHECK(HD::internal::residual_neighbour_correlation(indexed, input, input) == 0);
      std::vector<Eigen::Vector3d> moved = input, perturbed = input;
      CGAL::Random random(17);
      for(std::size_t v = 0; v < input.size(); ++v)
      {
        moved[v] += Eigen::Vector3d(0.3, -0.2, 0.1) * edge;
        perturbed[v] += 0.1 * edge * Eigen::Vector3d(random.get_double(-1, 1), random.get_double(-1, 1),
                                                     random.get_double(-1, 1));
      }
      CHECK(std::abs(HD::internal::residual_neighbour_correlation(indexed, input, moved) - 1) < 1e-12);
      const double white = HD::internal::residual_neighbour_correlation(indexed, input, perturbed);
      CHECK_MESSAGE(std::abs(white) < 0.05, "independent noise: residual correlation " << white);
      // Along the normals: a move of the same length along every unit normal is
      // correlated to 1 whatever moves it adds within the surface; independent noise is
      // white along the normals too.
      std::vector<Eigen::Vector3d> normals, lifted = perturbed;
      HD::internal::area_weighted_normals(indexed, setup.adjacency, input, normals);
      for(std::size_t v = 0; v < input.size(); ++v)
      {
        const Eigen::Vector3d unit = normals[v].normalized();
        const Eigen::Vector3d within = (perturbed[v] - input[v]) - unit * unit.dot(perturbed[v] - input[v]);
        lifted[v] = input[v] + within - 0.1 * edge * unit;
      }
      CHECK(HD::internal::residual_neighbour_correlation(indexed, input, lifted) < 0.9);
      CHECK(std::abs(HD::internal::residual_neighbour_correlation(indexed, input, lifted, &normals) - 1) < 1e-12);
      const double white_along =
          HD::internal::residual_neighbour_correlation(indexed, input, perturbed, &normals);
      CHECK_MESSAGE(std::abs(white_along) < 0.05, "independent noise: along the normals " << white_along);
    }
    std::vector<Eigen::Vector3d> smoothed;
    double time = 0;
    CHECK(HD::internal::smooth_until_residual_is_correlated(indexed, noise, setup.flow, smoothed, time));
    const double correlation = HD::internal::residual_neighbour_correlation(indexed, input, smoothed);
    double largest_move = 0;
    for(std::size_t v = 0; v < input.size(); ++v)
      largest_move = (std::max)(largest_move, (smoothed[v] - input[v]).norm() / edge);
    std::cout << (mesh == &noisy ? "anchor_dense, noise 0.3" : "anchor, clean") << ": flow time "
              << time / (noise * noise) << " eps^2, residual correlation " << correlation << ", largest move "
              << largest_move << " mean edge lengths" << std::endl;
    if(mesh == &noisy)
    {
      CHECK_MESSAGE(std::abs(correlation - HD::internal::whiteness_correlation) < 0.05,
                    "noisy: residual correlation " << correlation);
      CHECK_MESSAGE(time > noise * noise && time < 64 * noise * noise, "noisy: time " << time / (noise * noise));
      Mesh result = noisy;
      for(auto v : result.vertices())
      {
        const Eigen::Vector3d p = indexed.to_user_frame(smoothed[setup.ncc.vertex_index(v)]);
        result.point(v) = Epick::Point_3(p.x(), p.y(), p.z());
      }
      const double noisy_mad = mean_angle_deviation(clean, noisy), mad = mean_angle_deviation(clean, result);
      std::cout << "anchor_dense, noise 0.3: MAD " << noisy_mad << " -> " << mad << " by the flow" << std::endl;
      CHECK_MESSAGE(mad < noisy_mad / 1.5, "noisy: MAD " << noisy_mad << " -> " << mad);
      // A flow that fails above 4 eps^2, below the crossing: the stop keeps the last
      // white time, 4 eps^2, and its result.
      std::vector<Eigen::Vector3d> limited;
      double limited_time = 0;
      const std::vector<Eigen::Vector3d> initial = setup.flow.initial_residual();
      const double initial_correlation = HD::internal::neighbour_correlation(indexed, initial);
      CHECK(initial_correlation == HD::internal::initial_residual_correlation(indexed, setup.flow));
      CHECK(HD::internal::smooth_until_residual_is_correlated(
          indexed, noise, initial_correlation,
          [&](double t, std::vector<Eigen::Vector3d>& out) {
            return t <= 4.001 * noise * noise && setup.flow.smooth(t, HD::internal::flow_substeps, out);
          },
          limited, limited_time));
      CHECK_MESSAGE(std::abs(limited_time / (noise * noise) - 4) < 1e-12, "failing flow: time " << limited_time);
      CHECK(HD::internal::residual_neighbour_correlation(indexed, input, limited) < HD::internal::whiteness_correlation);
      // A flow that always fails: no result.
      CHECK(!HD::internal::smooth_until_residual_is_correlated(
          indexed, noise, initial_correlation, [](double, std::vector<Eigen::Vector3d>&) { return false; }, limited,
          limited_time));
      // What the flow removes first: the residual of a short time t over t tends to it.
      std::vector<Eigen::Vector3d> short_time;
      const double t = std::ldexp(noise * noise, -12);
      CHECK(setup.flow.smooth(t, HD::internal::flow_substeps, short_time));
      double difference = 0, norm = 0;
      for(std::size_t v = 0; v < input.size(); ++v)
      {
        difference += ((input[v] - short_time[v]) / t - initial[v]).squaredNorm();
        norm += initial[v].squaredNorm();
      }
      std::cout << "anchor_dense, noise 0.3: (p - F_t p) / t at t = 2^-12 eps^2 is "
                << std::sqrt(difference / norm) << " from the initial residual, correlation " << initial_correlation
                << std::endl;
      CHECK_MESSAGE(std::sqrt(difference / norm) < 0.05, "initial residual: relative difference "
                                                             << std::sqrt(difference / norm));
      CHECK(initial_correlation < 0);
    }
    else
    {
      CHECK_MESSAGE(std::abs(time / (noise * noise) - std::ldexp(1., -HD::internal::flow_time_doublings)) < 1e-12,
                    "clean: time " << time / (noise * noise));
      CHECK_MESSAGE(largest_move < 0.05, "clean: largest move " << largest_move);
    }
  }
}

// The volume rescaling of the smoothing flows (restore_component_volumes()) on a mesh of
// three closed components (fandisk, elephant and a second fandisk, side by side; CGAL's
// blobby_3cc has holes): after the flow and a different scaling of each
// component, each one is brought back to its own volume, its face normals unchanged
// (a scaling about a point turns no face), and the largest volume change reads 0.
void test_component_volume_restoration()
{
  Mesh mesh = test_support::load<Mesh>("fandisk.off");
  const Mesh elephant = test_support::load<Mesh>("elephant.off");
  Mesh shifted = mesh;
  for(auto v : shifted.vertices())
    shifted.point(v) = shifted.point(v) + Epick::Vector_3(10., 0., 0.);
  CGAL::copy_face_graph(elephant, mesh);
  CGAL::copy_face_graph(shifted, mesh);
  const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
  const HD::internal::Indexed_mesh& indexed = ncc.indexed_mesh();
  const std::vector<Eigen::Vector3d>& reference = indexed.points;
  const std::vector<std::size_t> component = HD::internal::vertex_components(indexed);
  std::vector<std::size_t> labels(component);
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  CHECK_MESSAGE(labels.size() == 3, "three components: " << labels.size() << " components");

  std::vector<Eigen::Vector3d> points;
  CHECK(HD::internal::Cotangent_flow(indexed, reference)
            .smooth(4. * std::pow(HD::internal::mean_edge_length(indexed), 2), 8, points));
  for(std::size_t v = 0; v < points.size(); ++v)
  {
    const double scale = 0.6 + 0.3 * double(std::lower_bound(labels.begin(), labels.end(), component[v]) - labels.begin());
    points[v] *= scale;
  }
  const double before = HD::internal::largest_volume_change(indexed, reference, points);
  CHECK_MESSAGE(before > 0.1, "three components: volume change before the rescaling " << before);
  std::vector<Eigen::Vector3d> restored = points;
  HD::internal::restore_component_volumes(indexed, reference, restored);
  const double after = HD::internal::largest_volume_change(indexed, reference, restored);
  std::cout << "three components: largest volume change " << before << " -> " << after << std::endl;
  CHECK_MESSAGE(after < 1e-9, "three components: volume change after the rescaling " << after);
  const HD::internal::Component_volumes volumes = HD::internal::component_volumes(indexed, reference, restored);
  for(std::size_t c : labels)
    CHECK_MESSAGE(volumes.closed[c] && std::abs(volumes.volume[c] / volumes.reference_volume[c] - 1) < 1e-9,
                  "three components: component " << c << " volume " << volumes.volume[c] << " against "
                                            << volumes.reference_volume[c]);
  double largest_turn = 0;
  for(const auto& t : indexed.triangles)
  {
    const Eigen::Vector3d a = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).normalized();
    const Eigen::Vector3d b = (restored[t[1]] - restored[t[0]]).cross(restored[t[2]] - restored[t[0]]).normalized();
    largest_turn = (std::max)(largest_turn, (a - b).norm());
  }
  CHECK_MESSAGE(largest_turn < 1e-9, "three components: a face turned by " << largest_turn);
}

// b9_mesh has small closed components that the smoothing flattens; the volume
// restoration must leave them as they are, not blow them up about the centroid of a
// volume near zero (without its bounds, a vertex goes 20700 mean edge lengths away at
// 0.3 along the normals; with the supernodal factorisation of earlier versions, 49 at
// 0.1 in random directions).
void test_collapsed_components()
{
  const Mesh clean = test_support::load<Mesh>("b9_mesh.off");
  const double edge = test_support::mean_edge_length(clean);
  for(const bool along_normals : {false, true})
  {
    Mesh mesh = clean;
    if(along_normals)
      test_support::add_normal_noise(mesh, 0.3, 5);
    else
      test_support::add_random_direction_noise(mesh, 0.1, 6);
    HD::denoise_mesh(mesh);
    double largest = 0;
    for(auto v : mesh.vertices())
      largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(mesh.point(v), clean.point(v))) / edge);
    std::cout << "b9_mesh, noise " << (along_normals ? "0.3 along the normals" : "0.1 in random directions")
              << ": largest distance to the clean mesh's vertex " << largest << " mean edge lengths" << std::endl;
    CHECK_MESSAGE(largest < 5, "b9_mesh: a vertex moved " << largest << " mean edge lengths");
  }
}

// The iterations stop once the vertices have moved as far as the estimated noise
// times the limit (checked after each iteration, so limits closer than one
// iteration's move may give the same result): a larger limit never moves them less,
// and a limit five times larger moves them further (elephant, where it matters).
void test_displacement_limit()
{
  Mesh noisy = test_support::load<Mesh>("elephant.off");
  test_support::add_normal_noise(noisy, 0.2, 3);
  std::vector<double> moves;
  for(double limit : {0.8, 1.5, 4.})
  {
    Mesh denoised = noisy;
    HD::denoise_mesh(denoised, HD::parameters::displacement_limit(limit));
    double squares = 0;
    for(auto v : noisy.vertices())
      squares += CGAL::squared_distance(noisy.point(v), denoised.point(v));
    moves.push_back(std::sqrt(squares / double(noisy.number_of_vertices())));
  }
  CHECK_MESSAGE(moves[1] >= moves[0] && moves[2] >= moves[1], moves[0] << ", " << moves[1] << ", " << moves[2]);
  CHECK_MESSAGE(moves[2] > 1.2 * moves[0], moves[0] << " then " << moves[2]);
}

// A few iterations on elephant (three of normal filtering, one of signature
// diffusion): Surface_mesh with EPICK and EPECK, and Polyhedron_3
// with Simple_cartesian<double>, agree (all compute in double on the same numbers).
template <typename Target>
std::vector<Cartesian::Point_3> denoise_copy(const Mesh& source, HD::Denoising_method method)
{
  Target target;
  CGAL::copy_face_graph(source, target);
  const unsigned int iterations = method == HD::Denoising_method::normal_filtering ? 3 : 1;
  HD::denoise_mesh(target, HD::parameters::combine(CGAL::parameters::number_of_iterations(iterations),
                                                   HD::parameters::number_of_eigenpairs(60),
                                                   HD::parameters::denoising_method(method)));
  std::vector<Cartesian::Point_3> points;
  for(auto v : vertices(target))
  {
    const auto& p = get(CGAL::vertex_point, target, v);
    points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  return points;
}

double max_distance(const std::vector<Cartesian::Point_3>& a, const std::vector<Cartesian::Point_3>& b)
{
  double d = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    d = (std::max)(d, std::sqrt(CGAL::squared_distance(a[i], b[i])));
  return d;
}

void test_kernels_and_mesh_types()
{
  Mesh mesh = test_support::load<Mesh>("elephant.off");
  test_support::add_normal_noise(mesh, 0.2, 7);
  const double edge = test_support::mean_edge_length(mesh);
  for(HD::Denoising_method method : {HD::Denoising_method::normal_filtering, HD::Denoising_method::signature_diffusion})
  {
    const std::vector<Cartesian::Point_3> epick = denoise_copy<Mesh>(mesh, method);
    const std::vector<Cartesian::Point_3> epeck = denoise_copy<CGAL::Surface_mesh<Epeck::Point_3> >(mesh, method);
    const std::vector<Cartesian::Point_3> polyhedron = denoise_copy<CGAL::Polyhedron_3<Cartesian> >(mesh, method);
    CHECK(epick.size() == mesh.number_of_vertices() && epeck.size() == epick.size() &&
          polyhedron.size() == epick.size());
    std::vector<Cartesian::Point_3> input;
    for(auto v : mesh.vertices())
      input.emplace_back(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z());
    CHECK_MESSAGE(max_distance(epick, input) > 0.01 * edge, "the iterations move the vertices");
    CHECK_MESSAGE(max_distance(epick, epeck) < 1e-9 * edge, max_distance(epick, epeck));
    CHECK_MESSAGE(max_distance(epick, polyhedron) < 1e-9 * edge, max_distance(epick, polyhedron));
  }
}

// NCC, the rescaled kernel and the area-normalised anchors are dimensionless: the
// result of a scaled mesh is the scaled result.
// rotor_small, a mesh of needles, takes the path of the smoothed copy and its volume
// rescaling (normal filtering only).
void test_scale_invariance()
{
  for(const char* file : {"elephant.off", "rotor_small.off"})
  {
    Mesh mesh = test_support::load<Mesh>(file);
    test_support::add_normal_noise(mesh, 0.2, 11);
    const double edge = test_support::mean_edge_length(mesh);
    const bool needles = std::string(file) == "rotor_small.off";
    for(HD::Denoising_method method : {HD::Denoising_method::normal_filtering, HD::Denoising_method::signature_diffusion})
      for(double scale : {1e-3, 1e3})
      {
        if(needles && method == HD::Denoising_method::signature_diffusion)
          continue;
        Mesh reference = mesh, scaled = mesh;
        for(auto v : scaled.vertices())
          scaled.point(v) = CGAL::ORIGIN + scale * (scaled.point(v) - CGAL::ORIGIN);
        // Normal filtering: its defaults, with the displacement limit.
        const bool filtering = method == HD::Denoising_method::normal_filtering;
        const auto np = HD::parameters::combine(CGAL::parameters::number_of_iterations(filtering ? 100 : 2),
                                                HD::parameters::number_of_eigenpairs(60),
                                                HD::parameters::denoising_method(method));
        HD::denoise_mesh(reference, np);
        HD::denoise_mesh(scaled, np);
        double error = 0;
        for(auto v : mesh.vertices())
          error = (std::max)(error, std::sqrt(CGAL::squared_distance(
                                        reference.point(v), CGAL::ORIGIN + (scaled.point(v) - CGAL::ORIGIN) / scale)));
        CHECK_MESSAGE(error < 1e-7 * edge, file << ", scale " << scale << ": " << error / edge << " mean edge lengths");
      }
  }
}

// The noise estimate, the weights and the stop rules use no direction and no absolute
// length: a rotated and translated mesh gives the rotated and translated result.
// fandisk takes the crease-preserving path, rotor_small (needles) the blend of the
// needle copy with the flow and its volume rescaling, anchor (needles, whose thin parts
// the smoothed copy erodes) the flow stopped by its residual's correlation.
void test_rigid_motion_invariance()
{
  for(const char* file : {"fandisk.off", "rotor_small.off", "anchor.off"})
  {
    Mesh mesh = test_support::load<Mesh>(file);
    test_support::add_normal_noise(mesh, 0.3, 13);
    const double edge = test_support::mean_edge_length(mesh);
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const Eigen::Vector3d translation(3.5, -20, 7);
    auto move = [&](const Epick::Point_3& p) {
      const Eigen::Vector3d x = rotation * Eigen::Vector3d(p.x(), p.y(), p.z()) + translation;
      return Epick::Point_3(x.x(), x.y(), x.z());
    };
    Mesh reference = mesh, moved = mesh;
    for(auto v : moved.vertices())
      moved.point(v) = move(moved.point(v));
    HD::denoise_mesh(reference);
    HD::denoise_mesh(moved);
    double error = 0;
    for(auto v : mesh.vertices())
      error = (std::max)(error, std::sqrt(CGAL::squared_distance(move(reference.point(v)), moved.point(v))));
    CHECK_MESSAGE(error < 1e-6 * edge, file << ": " << error / edge << " mean edge lengths");
  }
}

void test_parameters()
{
  Mesh mesh = test_support::load<Mesh>("elephant.off");
  const Mesh input = mesh;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::sigma(0.)), std::invalid_argument, "sigma");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::sigma(nan)), std::invalid_argument, "sigma");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::time(-1.)), std::invalid_argument, "time");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::time(inf)), std::invalid_argument, "time");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::number_of_steps(-1)), std::invalid_argument, "number_of_steps");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::number_of_eigenpairs(0)), std::invalid_argument,
               "number_of_eigenpairs");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::anchor_weight(0.)), std::invalid_argument, "anchor_weight");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::anchor_weight(nan)), std::invalid_argument, "anchor_weight");
  CHECK_THROWS(HD::denoise_mesh(mesh, CGAL::parameters::number_of_iterations(-2)), std::invalid_argument,
               "number_of_iterations");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::normal_sigma(0.)), std::invalid_argument, "normal_sigma");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::normal_sigma(nan)), std::invalid_argument, "normal_sigma");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::normal_sigma(inf)), std::invalid_argument, "normal_sigma");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::displacement_limit(0.)), std::invalid_argument,
               "displacement_limit");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::displacement_limit(nan)), std::invalid_argument,
               "displacement_limit");
  CHECK_THROWS(HD::denoise_mesh(mesh, HD::parameters::denoising_method(static_cast<HD::Denoising_method>(7))),
               std::invalid_argument, "denoising_method");
  // A cancelled normal filtering throws and leaves the mesh untouched.
  Mesh noisy = mesh;
  test_support::add_normal_noise(noisy, 0.2, 5);
  const Mesh noisy_input = noisy;
  std::size_t calls = 0;
  const std::function<bool(double)> cancel = [&calls](double fraction) {
    ++calls;
    return fraction < 0.015;
  };
  CHECK_THROWS(HD::denoise_mesh(noisy, HD::parameters::combine(HD::parameters::progress_callback(cancel),
                                                               CGAL::parameters::number_of_iterations(100))),
               std::runtime_error, "cancelled");
  CHECK_MESSAGE(calls == 2, calls);
  bool untouched = true;
  for(auto v : noisy.vertices())
    untouched = untouched && noisy.point(v) == noisy_input.point(v);
  CHECK(untouched);
  // Rejected parameters, and zero iterations, leave the mesh untouched.
  HD::denoise_mesh(mesh, CGAL::parameters::number_of_iterations(0));
  bool unchanged = true;
  for(auto v : mesh.vertices())
    unchanged = unchanged && mesh.point(v) == input.point(v);
  CHECK(unchanged);
  // An empty mesh is not an error.
  Mesh empty;
  HD::denoise_mesh(empty);
  CHECK(empty.number_of_vertices() == 0);
}

// What denoise_mesh() reports, and that its adaptive defaults are the same whether the
// parameters are left out or given as empty std::optional (as the front ends give them).
void test_report()
{
  namespace P = HD::parameters;
  const Mesh clean = test_support::load<Mesh>("fandisk.off");
  Mesh noisy = clean;
  test_support::add_normal_noise(noisy, 0.3, 5);
  Mesh plain = noisy, empty = noisy;
  const HD::Denoising_report report = HD::denoise_mesh(plain);
  const HD::Denoising_report empty_report = HD::denoise_mesh(
      empty, P::normal_sigma(std::optional<double>())
                 .displacement_limit(std::optional<double>())
                 .number_of_steps(std::optional<std::size_t>())
                 .denoising_method(std::optional<HD::Denoising_method>())
                 .number_of_iterations(std::optional<unsigned>()));
  bool same = true;
  for(auto v : plain.vertices())
    same = same && plain.point(v) == empty.point(v);
  CHECK_MESSAGE(same, "empty optionals change denoise_mesh()'s result");
  CHECK(report.method == HD::Denoising_method::normal_filtering);
  // fandisk is piecewise flat: the crease-preserving filter runs on to its fixed point
  CHECK(report.stage == HD::Denoising_stage::piecewise_flat);
  // the estimate reads the noise of 0.3 mean edge length, about (its bias is measured in the manual)
  CHECK_MESSAGE(report.noise_level > 0.2 && report.noise_level < 0.4, report.noise_level);
  CHECK(report.iterations >= 1 && report.iterations <= HD::defaults::denoising::normal_filtering_iterations);
  CHECK(empty_report.stage == report.stage && empty_report.noise_level == report.noise_level &&
        empty_report.iterations == report.iterations);

  // a clean mesh: what the estimate reads is the shape's own roughness, left as it is
  Mesh unchanged = clean;
  CHECK(HD::denoise_mesh(unchanged).stage == HD::Denoising_stage::unchanged);
  // the user's width, and the paper's pipeline with the kernel that automatic selects
  Mesh with_width = noisy;
  CHECK(HD::denoise_mesh(with_width, P::normal_sigma(0.3)).stage == HD::Denoising_stage::user_normal_sigma);
  Mesh signature = noisy;
  const HD::Denoising_report paper = HD::denoise_mesh(signature, P::denoising_method(HD::Denoising_method::signature_diffusion));
  CHECK(paper.stage == HD::Denoising_stage::signature_diffusion && paper.kernel_method == HD::Heat_kernel_method::local);
  CHECK(paper.iterations == HD::defaults::denoising::signature_diffusion_iterations);
}

} // namespace

void run()
{
  test_report();
  test_parameters();
  test_kernels_and_mesh_types();
  test_scale_invariance();
  test_displacement_limit();
  test_rigid_motion_invariance();
  test_quality();
  test_random_direction_noise();
  test_impulsive_noise();
  test_no_sliding();
  test_l0_baseline();
  test_weak_noise_on_cad();
  test_clean_meshes();
  test_no_collapse();
  test_vertex_systems();
  test_whiteness_stop();
  test_needle_copy_weight();
  test_untangling();
  test_local_intersection_search();
  test_component_volume_restoration();
  test_collapsed_components();
}

const test_support::Suite_registration registration("test_denoising", &run);

} // namespace test_denoising
