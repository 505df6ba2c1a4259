// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The coarse-level kernel (paper, eq. 21): its error against the full computation is
// measured on CGAL's fandisk and armadillo, and heat is conserved exactly on the fine
// mesh.

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include "test_support.h"

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

namespace test_coarse_level {

namespace HD = CGAL::Heat_diffusion;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef HD::Edge_weighted_heat_kernel<Mesh> Kernel;
typedef HD::Anisotropic_heat_diffusion<Mesh> Diffusion;

// Meshes of 100000 vertices and more are numbered along a Hilbert curve unless a
// vertex index map is given: the renumbering must be invisible through vertex_index().
void test_hilbert_numbering()
{
  Mesh mesh = test_support::load<Mesh>("fandisk.off");
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  CHECK(mesh.number_of_vertices() >= CGAL::Heat_diffusion::internal::spatial_order_threshold);
  typedef HD::Normal_controlled_coordinates<Mesh> NCC;
  const NCC renumbered(mesh);
  const NCC given(mesh, CGAL::parameters::vertex_index_map(get(CGAL::vertex_index, mesh)));
  const std::size_t n = mesh.number_of_vertices();
  std::vector<unsigned char> seen(n, 0);
  std::size_t moved = 0;
  double edge_distance_mesh = 0, edge_distance_package = 0, ns_difference = 0, ns_largest = 0;
  for(Vertex v : mesh.vertices())
  {
    const std::size_t i = renumbered.vertex_index(v);
    CHECK(i < n && !seen[i]);
    seen[i] = 1;
    moved += i != std::size_t(v.idx()) ? 1 : 0;
    CHECK(given.vertex_index(v) == std::size_t(v.idx()));
    // the same up to the order of floating-point sums
    ns_difference = (std::max)(ns_difference, std::abs(renumbered.normal_signature(v) - given.normal_signature(v)));
    ns_largest = (std::max)(ns_largest, std::abs(given.normal_signature(v)));
  }
  CHECK(moved > n / 2);
#ifdef CGAL_LINKED_WITH_TBB
  // the numbering (a parallel Hilbert sort) does not depend on the number of threads
  std::unique_ptr<NCC> one_thread;
  tbb::task_arena(1).execute([&] { one_thread = std::make_unique<NCC>(mesh); });
  std::size_t renumbered_differently = 0;
  for(Vertex v : mesh.vertices())
    renumbered_differently += one_thread->vertex_index(v) != renumbered.vertex_index(v) ? 1 : 0;
  CHECK_MESSAGE(renumbered_differently == 0, renumbered_differently << " vertices numbered differently on one thread");
#endif
  CHECK_MESSAGE(ns_difference <= 1e-12 * ns_largest, "NS differ by " << ns_difference << " (largest " << ns_largest << ")");
  for(auto e : mesh.edges())
  {
    const Vertex a = mesh.vertex(e, 0), b = mesh.vertex(e, 1);
    edge_distance_mesh += std::abs(double(a.idx()) - double(b.idx()));
    edge_distance_package +=
        std::abs(double(renumbered.vertex_index(a)) - double(renumbered.vertex_index(b)));
  }
  std::cout << "Hilbert numbering of fandisk subdivided to " << n << " vertices: mean index distance along edges "
            << edge_distance_mesh / double(mesh.number_of_edges()) << " -> "
            << edge_distance_package / double(mesh.number_of_edges()) << std::endl;
  CHECK(edge_distance_package < edge_distance_mesh / 10);
  // The mesh is copied in the order of vertices(tm), while the curve is computed, then
  // renumbered: the same arrays as a copy made with the curve's numbering.
  {
    auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), mesh);
    for(Vertex v : mesh.vertices())
      put(index, v, renumbered.vertex_index(v));
    const CGAL::Heat_diffusion::internal::Indexed_mesh direct =
        CGAL::Heat_diffusion::internal::make_indexed_mesh(mesh, mesh.points(), index);
    const CGAL::Heat_diffusion::internal::Indexed_mesh& copied = renumbered.indexed_mesh();
    CHECK(direct.points == copied.points);
    CHECK(direct.triangles == copied.triangles);
    CHECK(direct.fan_begin == copied.fan_begin && direct.fan == copied.fan);
    CHECK(direct.fan_is_closed == copied.fan_is_closed);
    CHECK(direct.center == copied.center && direct.scale == copied.scale);
  }
  // A defect is reported with the vertex's number in vertices(tm), not along the curve.
  {
    Mesh broken = mesh;
    const Vertex v(12345);
    broken.point(v) = Mesh::Point(std::numeric_limits<double>::quiet_NaN(), 0., 0.);
    std::string message;
    try
    {
      const NCC ncc(broken);
    }
    catch(const std::invalid_argument& e)
    {
      message = e.what();
    }
    CHECK_MESSAGE(message.find("vertex 12345 ") != std::string::npos, "message: " << message);
  }
  // the NCC operator, row and column by vertex_index()
  const NCC::Sparse_matrix a = renumbered.operator_matrix(), b = given.operator_matrix();
  CHECK(a.nonZeros() == b.nonZeros());
  double difference = 0;
  const double largest = b.coeffs().cwiseAbs().maxCoeff();
  for(auto h : mesh.halfedges())
  {
    const Vertex u = mesh.source(h), v = mesh.target(h);
    for(const Vertex w : {u, v})
      difference = (std::max)(difference, std::abs(a.coeff(Eigen::Index(renumbered.vertex_index(u)),
                                                             Eigen::Index(renumbered.vertex_index(w))) -
                                                     b.coeff(Eigen::Index(u.idx()), Eigen::Index(w.idx()))));
  }
  CHECK_MESSAGE(difference <= 1e-12 * largest, "operator entries differ by " << difference << " (largest " << largest << ")");
}

// The staged simplification of a mesh of more than four times the coarse size: its
// proposals are computed in parallel, so one thread must give the same coarse level
// bit for bit; its progress moves forward to 1, and a cancelling callback stops it.
void test_staged_simplification()
{
  Mesh mesh = test_support::load<Mesh>("fandisk.off");
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  const HD::internal::Indexed_mesh fine =
      HD::internal::make_indexed_mesh(mesh, mesh.points(), get(CGAL::vertex_index, mesh));
  const std::size_t target = 5000;
  CHECK(fine.number_of_vertices() > HD::internal::prepass_factor * target);
  std::vector<double> fractions;
  const HD::internal::Progress progress([&](double f) {
    fractions.push_back(f);
    return true;
  });
  const HD::internal::Coarse_level parallel = HD::internal::make_coarse_level(fine, target, progress);
  HD::internal::Coarse_level sequential;
#ifdef CGAL_LINKED_WITH_TBB
  tbb::task_arena one_thread(1);
  one_thread.execute([&] { sequential = HD::internal::make_coarse_level(fine, target); });
#else
  sequential = HD::internal::make_coarse_level(fine, target);
#endif
  CHECK(parallel.mesh.number_of_vertices() == sequential.mesh.number_of_vertices());
  CHECK(parallel.mesh.points == sequential.mesh.points && parallel.mesh.triangles == sequential.mesh.triangles);
  CHECK(parallel.prolongation.nonZeros() == sequential.prolongation.nonZeros() &&
        Eigen::SparseMatrix<double>(parallel.prolongation - sequential.prolongation).norm() == 0.);
  std::cout << "staged simplification of " << fine.number_of_vertices() << " vertices to "
            << parallel.mesh.number_of_vertices() << ": " << fractions.size() << " progress reports" << std::endl;
  CHECK(fractions.size() >= 10 && fractions.front() == 0. && fractions.back() == 1.);
  CHECK(std::is_sorted(fractions.begin(), fractions.end()));
  CHECK_THROWS(HD::internal::make_coarse_level(fine, target, HD::internal::Progress([](double f) { return f < 0.2; })),
               std::runtime_error, "simplification of the coarse level cancelled");
}

void run()
{
  try
  {
    test_hilbert_numbering();
    test_staged_simplification();
    const std::vector<std::size_t> steps = {1, 10, 40};
    // The bound on the relative L2 error of the diffused NS for a 5000-vertex coarse
    // level at t = 4 ln 10 / lambda_m, where the truncated kernel is valid: about twice
    // the worst value this test measured (0.097 on fandisk at k = 1, 0.054 on
    // armadillo), so that a regression of the coarse path is caught. At t = 1 the
    // truncated kernels themselves are far from the heat kernel and the coarse one
    // differs from the full one by 27 to 97 % (printed, not asserted; see the manual).
    const std::map<std::string, double> bound_5000 = {{"fandisk.off", 0.2}, {"armadillo.off", 0.2}};
    for(const char* name : {"fandisk.off", "armadillo.off"})
    {
      const Mesh mesh = test_support::load<Mesh>(name);
      const auto base = HD::parameters::combine(HD::parameters::sigma(1.), HD::parameters::number_of_eigenpairs(150));
      const Kernel full(mesh, HD::parameters::combine(base, HD::parameters::coarse_vertex_count(0)));
      CHECK(full.coarse_vertex_count() == 0);
      // t = 1 (the paper's default) and t = 4 ln 10 / lambda_m, from where on the
      // truncated kernel is accurate (see the user manual, "Truncation").
      const double t_valid = 4. * std::log(10.) / full.eigenvalues()[full.eigenvalues().size() - 1];
      for(double t : {1., t_valid})
      {
      const Diffusion full_diffusion(full, t);
      Eigen::VectorXd f0(Eigen::Index(mesh.number_of_vertices()));
      for(Vertex v : mesh.vertices())
        f0[Eigen::Index(full.vertex_index(v))] = full.normal_controlled_coordinates().normal_signature(v);
      const std::vector<Eigen::VectorXd> reference = full_diffusion.diffuse(f0, steps);

      for(std::size_t coarse : {1000, 2000, 5000})
      {
        const Kernel kernel(mesh, HD::parameters::combine(base, HD::parameters::coarse_vertex_count(coarse)));
        const Diffusion diffusion(kernel, t);
        const std::vector<Eigen::VectorXd> fields = diffusion.diffuse(f0, steps);
        std::cout << name << ", t = " << t << ": coarse level of " << kernel.coarse_vertex_count() << " vertices, regions mean "
                  << diffusion.region_statistics().mean_size << " (full " << full_diffusion.region_statistics().mean_size
                  << "), collapsed " << diffusion.region_statistics().collapsed_regions << " (full "
                  << full_diffusion.region_statistics().collapsed_regions << "); relative L2 error of F^k:";
        double worst = 0;
        for(std::size_t s = 0; s < steps.size(); ++s)
        {
          const double error = (fields[s] - reference[s]).norm() / reference[s].norm();
          worst = (std::max)(worst, error);
          std::cout << " k=" << steps[s] << ": " << error;
        }
        std::cout << std::endl;
        CHECK(kernel.coarse_vertex_count() > 0 && kernel.coarse_vertex_count() <= coarse + coarse / 10);
        // heat is conserved exactly on the fine mesh in coarse mode too (1000 steps
        // where the regions are small; 100 where they have thousands of vertices)
        const Eigen::VectorXd last = diffusion.diffuse(f0, t > 1. ? 100 : 1000);
        const double drift = std::abs(last.sum() - f0.sum()) / f0.cwiseAbs().sum();
        CHECK_MESSAGE(drift <= 1e-12, name << ", coarse " << coarse << ": heat drift " << drift);
        if(coarse == 5000 && t > 1.)
          CHECK_MESSAGE(worst <= bound_5000.at(name), name << ": coarse 5000 error " << worst);
      }
      }
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "unexpected exception: " << e.what() << std::endl;
    test_support::check(false, "no unexpected exception", __FILE__, __LINE__);
  }
}

const test_support::Suite_registration registration("test_coarse_level", &run);

} // namespace test_coarse_level
