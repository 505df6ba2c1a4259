// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Normal-Controlled Coordinates, Normal Signature, the NCC operator and the
// reconstruction (paper, section 3 and eq. 23), on CGAL's real meshes and on built
// ones, across kernels and mesh data structures, and on bad input.

#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/reconstruction.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/aff_transformation_tags.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include "test_support.h"

#include <boost/property_map/function_property_map.hpp>

#include <limits>
#include <map>
#include <sstream>
#include <vector>

namespace test_normal_controlled_coordinates {

namespace HD = CGAL::Heat_diffusion;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef CGAL::Simple_cartesian<double> Cartesian;
typedef CGAL::Surface_mesh<Epick::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;

// Properties the paper proves, on one mesh.
void check_paper_properties(const Mesh& mesh, const std::string& name)
{
  const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
  const double bound = 1e-10;

  // NCC parallel to the normal (eq. 4, appendix): by construction for the NCC, and
  // the paper's theorem for the differential coordinate of interior vertices:
  // mean value weights on the tangent plane have linear precision.
  double worst_ncc = 0, worst_interior = 0;
  std::size_t boundary = 0;
  for(Vertex v : mesh.vertices())
  {
    const auto d = ncc.ncc(v), n = ncc.normal(v);
    worst_ncc = (std::max)(worst_ncc, std::sqrt(CGAL::cross_product(d, n).squared_length()));
    if(CGAL::is_border(v, mesh))
      ++boundary;
    else
      worst_interior = (std::max)(worst_interior, std::sqrt(ncc.tangential_part(v).squared_length()));
  }
  CHECK_MESSAGE(worst_ncc <= bound, name << ": max |NCC x n| = " << worst_ncc);
  CHECK_MESSAGE(worst_interior <= bound, name << ": max interior |tangential part| = " << worst_interior);
  std::cout << name << ": " << mesh.number_of_vertices() << " vertices (" << boundary
            << " on the boundary), max |NCC x n| = " << worst_ncc
            << ", max interior tangential part = " << worst_interior << std::endl;

  // N V = NCC + tangential parts, and the rows of N sum to 0.
  const Eigen::SparseMatrix<double> N = ncc.operator_matrix();
  Eigen::MatrixXd V(mesh.number_of_vertices(), 3);
  for(Vertex v : mesh.vertices())
    V.row(ncc.vertex_index(v)) << mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z();
  const Eigen::MatrixXd NV = N * V;
  const Eigen::VectorXd row_sums = N * Eigen::VectorXd::Ones(N.cols());
  double worst_operator = 0;
  for(Vertex v : mesh.vertices())
  {
    const auto expected = ncc.ncc(v) + ncc.tangential_part(v);
    const Eigen::Vector3d e(expected.x(), expected.y(), expected.z());
    worst_operator = (std::max)(worst_operator, (NV.row(ncc.vertex_index(v)).transpose() - e).norm());
  }
  CHECK_MESSAGE(worst_operator <= 1e-9, name << ": max |N V - (NCC + tangential)| = " << worst_operator);
  CHECK_MESSAGE(row_sums.cwiseAbs().maxCoeff() <= 1e-9 * N.coeffs().cwiseAbs().maxCoeff(),
                name << ": max |row sum of N| = " << row_sums.cwiseAbs().maxCoeff());

  // Scale invariance (eq. 7), absolute: NCC are dimensionless.
  for(double s : {1e-3, 1., 1e3})
  {
    Mesh scaled = mesh;
    for(Vertex v : scaled.vertices())
      scaled.point(v) = Epick::Point_3(s * mesh.point(v).x(), s * mesh.point(v).y(), s * mesh.point(v).z());
    const HD::Normal_controlled_coordinates<Mesh> scaled_ncc(scaled);
    double worst = 0;
    for(Vertex v : mesh.vertices())
      worst = (std::max)(worst, std::sqrt((scaled_ncc.ncc(v) - ncc.ncc(v)).squared_length()));
    CHECK_MESSAGE(worst <= 1e-9, name << ": NCC of " << s << " * M differ by " << worst);
  }

  // NS invariant under rotation and translation.
  {
    const double c = std::cos(0.7), si = std::sin(0.7);
    const CGAL::Aff_transformation_3<Epick> motion(c, -si, 0, 12.5, si, c, 0, -3., 0, 0, 1, 40.);
    const CGAL::Aff_transformation_3<Epick> tilt(1, 0, 0, 0, 0, c, -si, 0, 0, si, c, 0);
    Mesh moved = mesh;
    for(Vertex v : moved.vertices())
      moved.point(v) = tilt(motion(mesh.point(v)));
    const HD::Normal_controlled_coordinates<Mesh> moved_ncc(moved);
    double worst = 0;
    for(Vertex v : mesh.vertices())
      worst = (std::max)(worst, std::abs(moved_ncc.normal_signature(v) - ncc.normal_signature(v)));
    CHECK_MESSAGE(worst <= 1e-9, name << ": NS changes by " << worst << " under a rigid motion");
  }

  // Reconstruction of the unedited mesh from its own NS and normals (eq. 23).
  {
    Mesh copy = mesh;
    std::vector<double> ns(mesh.number_of_vertices());
    for(Vertex v : mesh.vertices())
      ns[v.idx()] = ncc.normal_signature(v);
    HD::reconstruct_from_normal_signature(
        copy, boost::make_function_property_map<Vertex>([&](Vertex v) { return ns[v.idx()]; }));
    const CGAL::Bbox_3 box = PMP::bbox(mesh);
    const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                      CGAL::square(box.zmax() - box.zmin()));
    double worst = 0;
    for(Vertex v : mesh.vertices())
      worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(copy.point(v), mesh.point(v))));
    CHECK_MESSAGE(worst <= 1e-8 * diagonal, name << ": unedited reconstruction moves a vertex by " << worst / diagonal
                                                 << " of the bounding-box diagonal");
    std::cout << name << ": unedited reconstruction error " << worst / diagonal << " of the diagonal" << std::endl;
  }
}

// NS = 0 on flat patches, > 0 at convex vertices, < 0 at concave ones.
void check_signs()
{
  // A flat grid with the centre vertex raised, flat, or lowered.
  for(double height : {0.3, 0., -0.3})
  {
    Mesh grid;
    const int k = 6;
    std::vector<Vertex> ids;
    for(int i = 0; i <= k; ++i)
      for(int j = 0; j <= k; ++j)
        ids.push_back(grid.add_vertex(Epick::Point_3(i, j, (i == k / 2 && j == k / 2) ? height : 0.)));
    for(int i = 0; i < k; ++i)
      for(int j = 0; j < k; ++j)
      {
        const Vertex a = ids[i * (k + 1) + j], b = ids[(i + 1) * (k + 1) + j], c = ids[(i + 1) * (k + 1) + j + 1],
                     d = ids[i * (k + 1) + j + 1];
        grid.add_face(a, b, c);
        grid.add_face(a, c, d);
      }
    const HD::Normal_controlled_coordinates<Mesh> ncc(grid);
    const Vertex centre = ids[(k / 2) * (k + 1) + k / 2];
    // the grid is oriented with normal +z
    if(height > 0)
      CHECK_MESSAGE(ncc.normal_signature(centre) > 0.1, "raised centre NS " << ncc.normal_signature(centre));
    else if(height < 0)
      CHECK_MESSAGE(ncc.normal_signature(centre) < -0.1, "lowered centre NS " << ncc.normal_signature(centre));
    double far_from_centre = 0;
    for(int i = 0; i <= k; ++i)
      for(int j = 0; j <= k; ++j)
        if(std::abs(i - k / 2) > 1 || std::abs(j - k / 2) > 1)
          far_from_centre = (std::max)(far_from_centre, std::abs(ncc.normal_signature(ids[i * (k + 1) + j])));
    CHECK_MESSAGE(far_from_centre <= 1e-12, "NS on the flat part (boundary included): " << far_from_centre);
  }

  // A convex real mesh: NS > 0 everywhere.
  {
    const Mesh sphere = test_support::load<Mesh>("sphere966.off");
    const HD::Normal_controlled_coordinates<Mesh> ncc(sphere);
    double smallest = std::numeric_limits<double>::infinity();
    for(Vertex v : sphere.vertices())
      smallest = (std::min)(smallest, ncc.normal_signature(v));
    CHECK_MESSAGE(smallest > 0, "sphere966: smallest NS " << smallest);
  }

  // The cube: flat face interiors 0, convex edges and corners > 0.
  {
    const Mesh cube = test_support::load<Mesh>("cube-meshed.off");
    const HD::Normal_controlled_coordinates<Mesh> ncc(cube);
    std::size_t flat = 0, convex = 0, wrong = 0;
    for(Vertex v : cube.vertices())
    {
      const auto& p = cube.point(v);
      int on_faces = 0;  // how many coordinates are at +-1 (the cube is [-1,1]^3 or [0,1]^3 shaped)
      const CGAL::Bbox_3 box = PMP::bbox(cube);
      for(int a = 0; a < 3; ++a)
        on_faces += (std::abs(p[a] - box.min(a)) < 1e-9 || std::abs(p[a] - box.max(a)) < 1e-9) ? 1 : 0;
      const double s = ncc.normal_signature(v);
      if(on_faces == 1)
      {
        ++flat;
        wrong += std::abs(s) <= 1e-12 ? 0 : 1;
      }
      else
      {
        ++convex;
        wrong += s > 0 ? 0 : 1;
      }
    }
    CHECK_MESSAGE(wrong == 0 && flat > 0 && convex > 0,
                  "cube-meshed: " << wrong << " wrong signs among " << flat << " flat and " << convex << " convex");
  }

  // Fandisk: the ridge between its two big faces is convex and the groove is concave; check
  // both extremes exist, with MWAAT and with PMP normals.
  {
    const Mesh fandisk = test_support::load<Mesh>("fandisk.off");
    for(int rule = 0; rule < 2; ++rule)
    {
      std::vector<double> ns(fandisk.number_of_vertices());
      const auto run = [&](const auto& np) {
        const HD::Normal_controlled_coordinates<Mesh> ncc(fandisk, np);
        for(Vertex v : fandisk.vertices())
          ns[v.idx()] = ncc.normal_signature(v);
      };
      if(rule == 0)
        run(HD::parameters::vertex_normal_rule(HD::Area_weighted_vertex_normals()));
      else
        run(HD::parameters::vertex_normal_rule(HD::Polygon_mesh_processing_vertex_normals()));
      const double lo = *std::min_element(ns.begin(), ns.end()), hi = *std::max_element(ns.begin(), ns.end());
      CHECK_MESSAGE(lo < -0.1 && hi > 0.1, "fandisk NS range [" << lo << ", " << hi << "] with rule " << rule);
    }
  }
}

// The same NS with Simple_cartesian, EPICK and EPECK points, on Surface_mesh and
// Polyhedron_3, with user-given normals, and with named parameters in any order.
template <typename Kernel, typename TriangleMesh>
std::vector<double> ns_on(const Mesh& source)
{
  TriangleMesh mesh;
  CGAL::copy_face_graph(source, mesh);
  std::vector<double> ns;
  std::map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, double> values;
  HD::compute_normal_signature(mesh, boost::make_assoc_property_map(values));
  // copy_face_graph keeps the vertex order of `source`
  for(auto v : vertices(mesh))
    ns.push_back(values[v]);
  return ns;
}

void check_kernels_and_structures()
{
  Mesh elephant = test_support::load<Mesh>("elephant.off");
  const std::vector<double> reference = ns_on<Epick, Mesh>(elephant);
  const std::vector<std::pair<std::string, std::vector<double> > > others = {
      {"Simple_cartesian Surface_mesh", ns_on<Cartesian, CGAL::Surface_mesh<Cartesian::Point_3> >(elephant)},
      {"EPECK Surface_mesh", ns_on<Epeck, CGAL::Surface_mesh<Epeck::Point_3> >(elephant)},
      {"EPICK Polyhedron_3", ns_on<Epick, CGAL::Polyhedron_3<Epick> >(elephant)},
      {"Simple_cartesian Polyhedron_3", ns_on<Cartesian, CGAL::Polyhedron_3<Cartesian> >(elephant)}};
  for(const auto& other : others)
  {
    double worst = 0;
    for(std::size_t i = 0; i < reference.size(); ++i)
      worst = (std::max)(worst, std::abs(other.second[i] - reference[i]));
    CHECK_MESSAGE(other.second.size() == reference.size() && worst <= 1e-10,
                  other.first << " differs from EPICK Surface_mesh by " << worst);
  }

  // NCC through the free function equal those of the class.
  {
    auto ncc_map = elephant.add_property_map<Vertex, Epick::Vector_3>("v:test_ncc").first;
    HD::compute_normal_controlled_coordinates(elephant, ncc_map);
    const HD::Normal_controlled_coordinates<Mesh> ncc(elephant);
    double worst = 0;
    for(Vertex v : elephant.vertices())
      worst = (std::max)(worst, std::sqrt((ncc_map[v] - ncc.ncc(v)).squared_length()));
    CHECK(worst == 0);
  }

  // User normals equal to the MWAAT normals give the same NS; CGAL's and the
  // package's named parameters in either order, and the combined pack still works
  // with PMP.
  {
    const HD::Normal_controlled_coordinates<Mesh> ncc(elephant);
    std::map<Vertex, Epick::Vector_3> normals;
    for(Vertex v : elephant.vertices())
      normals[v] = ncc.normal(v);
    const auto normal_map = boost::make_assoc_property_map(normals);
    const auto vpm = get(CGAL::vertex_point, elephant);
    const auto np1 = HD::parameters::combine(CGAL::parameters::vertex_normal_map(normal_map).vertex_point_map(vpm),
                                             HD::parameters::sigma(0.1), HD::parameters::time(2.));
    const auto np2 = HD::parameters::sigma(0.1).vertex_normal_map(normal_map);
    const HD::Normal_controlled_coordinates<Mesh> user1(elephant, np1), user2(elephant, np2);
    double worst = 0;
    for(Vertex v : elephant.vertices())
      worst = (std::max)({worst, std::abs(user1.normal_signature(v) - ncc.normal_signature(v)),
                          std::abs(user2.normal_signature(v) - ncc.normal_signature(v))});
    CHECK_MESSAGE(worst <= 1e-14, "user normals change NS by " << worst);
    CHECK(HD::parameters::choose_parameter(HD::parameters::get_parameter(np1, HD::internal_np::sigma), 1.) == 0.1);
    CHECK(HD::parameters::choose_parameter(HD::parameters::get_parameter(np1, HD::internal_np::time), 1.) == 2.);
    CHECK(std::abs(PMP::area(elephant, np1) - PMP::area(elephant)) == 0);
    // the last pack wins
    const auto np3 = HD::parameters::combine(HD::parameters::sigma(0.1), HD::parameters::sigma(0.5));
    CHECK(HD::parameters::choose_parameter(HD::parameters::get_parameter(np3, HD::internal_np::sigma), 1.) == 0.5);

    // Chains, CGAL style: the package's parameters after each other, and mixed with
    // CGAL's in any order once the chain starts in HD::parameters. The packs still go
    // to PMP, with the overloads a CGAL pack selects (PMP::area of a mesh and of a
    // face range).
    using HD::parameters::choose_parameter;
    using HD::parameters::get_parameter;
    const auto chain1 = HD::parameters::sigma(0.1).time(2.);
    const auto chain2 = HD::parameters::vertex_normal_map(normal_map).sigma(0.1).vertex_point_map(vpm).time(2.);
    const auto chain3 = HD::parameters::sigma(0.1).vertex_point_map(vpm).number_of_steps(3).geom_traits(Epick());
    CHECK(choose_parameter(get_parameter(chain1, HD::internal_np::sigma), 1.) == 0.1);
    CHECK(choose_parameter(get_parameter(chain1, HD::internal_np::time), 1.) == 2.);
    CHECK(choose_parameter(get_parameter(chain2, HD::internal_np::sigma), 1.) == 0.1);
    CHECK(choose_parameter(get_parameter(chain2, HD::internal_np::time), 1.) == 2.);
    CHECK(choose_parameter(get_parameter(chain3, HD::internal_np::number_of_steps), 0) == 3);
    CHECK((!HD::parameters::is_default_parameter<decltype(chain2), CGAL::internal_np::vertex_normal_map_t>::value));
    const HD::Normal_controlled_coordinates<Mesh> chained(elephant, chain2);
    double chained_worst = 0;
    for(Vertex v : elephant.vertices())
      chained_worst = (std::max)(chained_worst, std::abs(chained.normal_signature(v) - ncc.normal_signature(v)));
    CHECK_MESSAGE(chained_worst <= 1e-14, "a chained pack changes NS by " << chained_worst);
    const double area = PMP::area(elephant);
    CHECK(PMP::area(elephant, chain2) == area && PMP::area(elephant, chain3) == area &&
          PMP::area(faces(elephant), elephant, chain3) == area);
    const auto combined = HD::parameters::combine(CGAL::parameters::vertex_point_map(vpm), chain1);
    CHECK(choose_parameter(get_parameter(combined, HD::internal_np::time), 1.) == 2.);
    CHECK(PMP::area(elephant, combined) == area);
  }
}

// Bad input: a clear exception naming the element, or a documented behaviour.
void check_bad_input()
{
  auto triangle_mesh = [](std::vector<Epick::Point_3> points, std::vector<std::vector<int> > faces) {
    Mesh mesh;
    std::vector<Vertex> ids;
    for(const auto& p : points)
      ids.push_back(mesh.add_vertex(p));
    for(const auto& f : faces)
    {
      std::vector<Vertex> face;
      for(int i : f)
        face.push_back(ids[std::size_t(i)]);
      mesh.add_face(face);
    }
    return mesh;
  };
  auto ns_of = [](const Mesh& mesh) {
    const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
    return ncc;
  };
  typedef Epick::Point_3 P;

  // a quad
  CHECK_THROWS(ns_of(triangle_mesh({P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0)}, {{0, 1, 2, 3}})),
               std::invalid_argument, "face 0 has 4 vertices");
  // a zero-area face
  CHECK_THROWS(ns_of(triangle_mesh({P(0, 0, 0), P(1, 0, 0), P(2, 0, 0), P(0, 1, 0)}, {{0, 1, 2}, {0, 2, 3}})),
               std::invalid_argument, "face 0 (vertices 0, 1, 2) has zero area");
  // an isolated vertex
  CHECK_THROWS(ns_of(triangle_mesh({P(0, 0, 0), P(1, 0, 0), P(0, 1, 0), P(5, 5, 5)}, {{0, 1, 2}})),
               std::invalid_argument, "vertex 3 is isolated");
  // NaN and infinite coordinates
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS(ns_of(triangle_mesh({P(0, 0, 0), P(1, nan, 0), P(0, 1, 0)}, {{0, 1, 2}})), std::invalid_argument,
               "vertex 1 has a non-finite coordinate");
  CHECK_THROWS(ns_of(triangle_mesh({P(0, 0, inf), P(1, 0, 0), P(0, 1, 0)}, {{0, 1, 2}})), std::invalid_argument,
               "vertex 0 has a non-finite coordinate");
  // an empty mesh: nothing to compute, no error
  {
    Mesh empty;
    std::map<Vertex, double> ns;
    HD::compute_normal_signature(empty, boost::make_assoc_property_map(ns));
    HD::reconstruct_from_normal_signature(empty, boost::make_assoc_property_map(ns));
    CHECK(ns.empty());
  }
  // vertices with fewer than three neighbours: a single triangle and the corners of a
  // strip are flat (NS = 0), and reconstruction returns them
  {
    Mesh strip = triangle_mesh({P(0, 0, 0), P(1, 0, 0), P(2, 0, 0.5), P(0, 1, 0), P(1, 1, 0.2), P(2, 1, 0)},
                               {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}});
    Mesh single = triangle_mesh({P(0, 0, 0), P(1, 0, 0), P(0, 1, 0)}, {{0, 1, 2}});
    for(Mesh* mesh : {&strip, &single})
    {
      const HD::Normal_controlled_coordinates<Mesh> ncc(*mesh);
      std::vector<double> ns;
      bool finite = true;
      for(Vertex v : mesh->vertices())
      {
        ns.push_back(ncc.normal_signature(v));
        finite = finite && std::isfinite(ns.back());
        if(mesh->degree(v) == 2)
          CHECK_MESSAGE(std::abs(ns.back()) <= 1e-12, "a vertex with two neighbours has NS " << ns.back());
      }
      CHECK(finite);
      Mesh copy = *mesh;
      HD::reconstruct_from_normal_signature(
          copy, boost::make_function_property_map<Vertex>([&](Vertex v) { return ns[v.idx()]; }));
      double worst = 0;
      for(Vertex v : mesh->vertices())
        worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(copy.point(v), mesh->point(v))));
      CHECK_MESSAGE(worst <= 1e-12, "reconstruction of a strip/triangle moves a vertex by " << worst);
    }
  }
  // huge and tiny coordinates: the computation is scale invariant and does not overflow
  {
    const Mesh elephant = test_support::load<Mesh>("elephant.off");
    const HD::Normal_controlled_coordinates<Mesh> reference(elephant);
    for(double s : {1e300, 1e-300})
    {
      Mesh scaled = elephant;
      for(Vertex v : scaled.vertices())
        scaled.point(v) = P(s * elephant.point(v).x(), s * elephant.point(v).y(), s * elephant.point(v).z());
      const HD::Normal_controlled_coordinates<Mesh> ncc(scaled);
      double worst = 0;
      for(Vertex v : scaled.vertices())
        worst = (std::max)(worst, std::abs(ncc.normal_signature(v) - reference.normal_signature(v)));
      CHECK_MESSAGE(worst <= 1e-9, "NS of the elephant scaled by " << s << " differ by " << worst);
    }
  }
  // reconstruction parameters
  {
    Mesh mesh = test_support::load<Mesh>("elephant.off");
    std::map<Vertex, double> ns;
    for(Vertex v : mesh.vertices())
      ns[v] = 0.;
    CHECK_THROWS(HD::reconstruct_from_normal_signature(mesh, boost::make_assoc_property_map(ns),
                                                       HD::parameters::anchor_weight(0.)),
                 std::invalid_argument, "anchor_weight must be positive");
    ns[*mesh.vertices().begin()] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS(HD::reconstruct_from_normal_signature(mesh, boost::make_assoc_property_map(ns)),
                 std::invalid_argument, "normal signature at vertex 0 is nan, not a finite number");
  }
}

// Editing the NS moves the surface the expected way: doubling the signature
// exaggerates the shape (the mesh gets further from its smoothed version), a zero
// signature flattens it.
void check_reconstruction_edits()
{
  const Mesh fandisk = test_support::load<Mesh>("fandisk.off");
  const HD::Normal_controlled_coordinates<Mesh> ncc(fandisk);
  const double area = PMP::area(fandisk);
  for(double factor : {0., 2.})
  {
    Mesh copy = fandisk;
    HD::reconstruct_from_normal_signature(
        copy, boost::make_function_property_map<Vertex>([&](Vertex v) { return factor * ncc.normal_signature(v); }),
        HD::parameters::anchor_weight(0.1));
    const HD::Normal_controlled_coordinates<Mesh> edited(copy);
    double total = 0, original = 0;
    for(Vertex v : fandisk.vertices())
    {
      total += std::abs(edited.normal_signature(v));
      original += std::abs(ncc.normal_signature(v));
    }
    std::cout << "fandisk: NS scaled by " << factor << " -> mean |NS| " << total / fandisk.number_of_vertices()
              << " (was " << original / fandisk.number_of_vertices() << "), area " << PMP::area(copy) / area
              << " of the original" << std::endl;
    if(factor == 0.)
      CHECK_MESSAGE(total < 0.8 * original, "flattening reduces |NS|: " << total << " vs " << original);
    else
      CHECK_MESSAGE(total > 1.2 * original, "exaggerating increases |NS|: " << total << " vs " << original);
  }
}

void run()
{
  try
  {
    for(const std::string name : {"fandisk.off", "elephant.off", "elephant-with-holes.off", "armadillo.off"})
      check_paper_properties(test_support::load<Mesh>(name), name);
    {
      Mesh noisy = test_support::load<Mesh>("fandisk.off");
      test_support::add_normal_noise(noisy, 0.2, 7u);
      check_paper_properties(noisy, "fandisk + 0.2 edge-length noise");
    }
    check_signs();
    check_kernels_and_structures();
    check_bad_input();
    check_reconstruction_edits();
  }
  catch(const std::exception& e)
  {
    std::cerr << "unexpected exception: " << e.what() << std::endl;
    test_support::check(false, "no unexpected exception", __FILE__, __LINE__);
  }
}

const test_support::Suite_registration registration("test_normal_controlled_coordinates", &run);

} // namespace test_normal_controlled_coordinates
