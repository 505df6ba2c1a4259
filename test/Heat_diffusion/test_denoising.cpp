// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tests of denoise_mesh(): quality on noisy fandisk against CGAL's smooth_shape and
// bilateral mesh denoising (Fleishman et al. 2003), and the target (MAD below
// 3.5 degrees at 0.3 mean edge length of noise); validity of the result (no
// self-intersection, same vertices, finite); the displacement limit; agreement across
// kernels and mesh types and scale invariance, for both denoising methods; parameter
// checking.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Heat_diffusion/denoising.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <vector>

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

// The best MAD CGAL's smooth_shape reaches from `noisy` over a small grid of time
// steps and iteration counts (the time step is in the units of fandisk, whose mean
// edge length is about 0.009; larger steps than 1e-4 only make it worse there).
double best_smooth_shape(const Mesh& clean, const Mesh& noisy, std::string& best)
{
  double best_mad = std::numeric_limits<double>::infinity();
  for(double time : {1e-5, 3e-5, 1e-4})
    for(unsigned int iterations : {1u, 2u, 3u, 5u, 10u})
    {
      Mesh smoothed = noisy;
      PMP::smooth_shape(smoothed, time, CGAL::parameters::number_of_iterations(iterations));
      const double mad = mean_angle_deviation(clean, smoothed);
      if(mad < best_mad)
      {
        best_mad = mad;
        std::ostringstream os;
        os << "time " << time << ", " << iterations << " iterations";
        best = os.str();
      }
    }
  return best_mad;
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

void test_fandisk_quality()
{
  const Mesh clean = test_support::load<Mesh>("fandisk.off");
  // The target is 3.5 degrees at 0.3 noise; measured (seed 5): 2.38 and 2.72.
  const double bounds[] = {3., 3.5};
  int k = 0;
  for(double noise : {0.2, 0.3})
  {
    Mesh noisy = clean;
    test_support::add_normal_noise(noisy, noise, 5);
    Mesh denoised = noisy;
    HD::denoise_mesh(denoised);

    std::string best_smooth, best_bilateral_setting;
    const double noisy_mad = mean_angle_deviation(clean, noisy);
    const double denoised_mad = mean_angle_deviation(clean, denoised);
    const double smooth_shape_mad = best_smooth_shape(clean, noisy, best_smooth);
    const double bilateral_mad = best_bilateral(clean, noisy, best_bilateral_setting);
    std::cout << "fandisk, noise " << noise << " mean edge length: MAD noisy " << noisy_mad << ", denoise_mesh "
              << denoised_mad << ", best smooth_shape " << smooth_shape_mad << " (" << best_smooth
              << "), best bilateral " << bilateral_mad << " (" << best_bilateral_setting << ")" << std::endl;

    CHECK(denoised.number_of_vertices() == clean.number_of_vertices());
    CHECK(denoised.number_of_faces() == clean.number_of_faces());
    CHECK(all_finite(denoised));
    CHECK_MESSAGE(denoised_mad < 0.15 * noisy_mad, denoised_mad << " vs noisy " << noisy_mad);
    CHECK_MESSAGE(denoised_mad < bounds[k], denoised_mad << " vs the bound " << bounds[k]);
    CHECK_MESSAGE(denoised_mad < 0.5 * smooth_shape_mad, denoised_mad << " vs smooth_shape " << smooth_shape_mad);
    CHECK_MESSAGE(denoised_mad < 0.6 * bilateral_mad, denoised_mad << " vs bilateral " << bilateral_mad);
    // EPICK: the self-intersection test is decided with exact predicates.
    CHECK(!PMP::does_self_intersect(denoised));
    ++k;
  }
}

// The iterations stop once the vertices have moved as far as the estimated noise
// times the limit: a smaller limit moves them less (elephant, where it matters).
void test_displacement_limit()
{
  Mesh noisy = test_support::load<Mesh>("elephant.off");
  test_support::add_normal_noise(noisy, 0.2, 3);
  double previous = 0;
  for(double limit : {0.3, 0.8, 1.5})
  {
    Mesh denoised = noisy;
    HD::denoise_mesh(denoised, HD::parameters::displacement_limit(limit));
    double squares = 0;
    for(auto v : noisy.vertices())
      squares += CGAL::squared_distance(noisy.point(v), denoised.point(v));
    const double rms = std::sqrt(squares / double(noisy.number_of_vertices()));
    CHECK_MESSAGE(rms > previous, "limit " << limit << ": " << rms << " after " << previous);
    previous = rms;
  }
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
void test_scale_invariance()
{
  Mesh mesh = test_support::load<Mesh>("elephant.off");
  test_support::add_normal_noise(mesh, 0.2, 11);
  const double edge = test_support::mean_edge_length(mesh);
  for(HD::Denoising_method method : {HD::Denoising_method::normal_filtering, HD::Denoising_method::signature_diffusion})
    for(double scale : {1e-3, 1e3})
    {
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
      CHECK_MESSAGE(error < 1e-7 * edge, "scale " << scale << ": " << error / edge << " mean edge lengths");
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

} // namespace

int main()
{
  test_parameters();
  test_kernels_and_mesh_types();
  test_scale_invariance();
  test_displacement_limit();
  test_fandisk_quality();
  return test_support::report("test_denoising");
}
