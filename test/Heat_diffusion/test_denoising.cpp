// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Tests of denoise_mesh(): quality on noisy fandisk against CGAL's smooth_shape,
// validity of the result (no self-intersection, same vertices, finite), agreement
// across kernels and mesh types, scale invariance, and parameter checking.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Heat_diffusion/denoising.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/smooth_shape.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include "test_support.h"

#include <algorithm>
#include <cmath>
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

void test_fandisk_quality()
{
  const Mesh clean = test_support::load<Mesh>("fandisk.off");
  for(double noise : {0.2, 0.3})
  {
    Mesh noisy = clean;
    test_support::add_normal_noise(noisy, noise, 5);
    Mesh denoised = noisy;
    HD::denoise_mesh(denoised);

    std::string best;
    const double noisy_mad = mean_angle_deviation(clean, noisy);
    const double denoised_mad = mean_angle_deviation(clean, denoised);
    const double smooth_shape_mad = best_smooth_shape(clean, noisy, best);
    std::cout << "fandisk, noise " << noise << " mean edge length: MAD noisy " << noisy_mad << ", denoise_mesh "
              << denoised_mad << ", best smooth_shape " << smooth_shape_mad << " (" << best << ")" << std::endl;

    CHECK(denoised.number_of_vertices() == clean.number_of_vertices());
    CHECK(denoised.number_of_faces() == clean.number_of_faces());
    CHECK(all_finite(denoised));
    CHECK_MESSAGE(denoised_mad < 0.5 * noisy_mad, denoised_mad << " vs noisy " << noisy_mad);
    CHECK_MESSAGE(denoised_mad < smooth_shape_mad, denoised_mad << " vs smooth_shape " << smooth_shape_mad);
    // EPICK: the self-intersection test is decided with exact predicates.
    CHECK(!PMP::does_self_intersect(denoised));
  }
}

// One iteration on elephant: Surface_mesh with EPICK and EPECK, and Polyhedron_3
// with Simple_cartesian<double>, agree (all compute in double on the same numbers).
template <typename Target>
std::vector<Cartesian::Point_3> denoise_copy(const Mesh& source)
{
  Target target;
  CGAL::copy_face_graph(source, target);
  HD::denoise_mesh(target, HD::parameters::combine(CGAL::parameters::number_of_iterations(1),
                                                   HD::parameters::number_of_eigenpairs(60)));
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
  const std::vector<Cartesian::Point_3> epick = denoise_copy<Mesh>(mesh);
  const std::vector<Cartesian::Point_3> epeck = denoise_copy<CGAL::Surface_mesh<Epeck::Point_3> >(mesh);
  const std::vector<Cartesian::Point_3> polyhedron = denoise_copy<CGAL::Polyhedron_3<Cartesian> >(mesh);
  CHECK(epick.size() == mesh.number_of_vertices() && epeck.size() == epick.size() && polyhedron.size() == epick.size());
  std::vector<Cartesian::Point_3> input;
  for(auto v : mesh.vertices())
    input.emplace_back(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z());
  CHECK_MESSAGE(max_distance(epick, input) > 0.01 * edge, "one iteration moves the vertices");
  CHECK_MESSAGE(max_distance(epick, epeck) < 1e-9 * edge, max_distance(epick, epeck));
  CHECK_MESSAGE(max_distance(epick, polyhedron) < 1e-9 * edge, max_distance(epick, polyhedron));
}

// NCC, the rescaled kernel and the area-normalised anchors are dimensionless: the
// result of a scaled mesh is the scaled result.
void test_scale_invariance()
{
  Mesh mesh = test_support::load<Mesh>("elephant.off");
  test_support::add_normal_noise(mesh, 0.2, 11);
  const double edge = test_support::mean_edge_length(mesh);
  for(double scale : {1e-3, 1e3})
  {
    Mesh reference = mesh, scaled = mesh;
    for(auto v : scaled.vertices())
      scaled.point(v) = CGAL::ORIGIN + scale * (scaled.point(v) - CGAL::ORIGIN);
    const auto np = HD::parameters::combine(CGAL::parameters::number_of_iterations(2),
                                            HD::parameters::number_of_eigenpairs(60));
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
  test_fandisk_quality();
  return test_support::report("test_denoising");
}
