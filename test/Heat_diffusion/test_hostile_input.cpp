// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Hostile input through the API: every public function, on every mesh of the
// corpus test/Heat_diffusion/data/ (and on meshes built here), either gives a
// correct result or throws an exception that names the problem. Never a crash, a
// NaN, or a silently wrong answer.
//
// To add a mesh: put a tiny OFF file into data/ and a line into `corpus()` below,
// with the expected outcome; the CLI cases are in test_hostile_cli.sh.

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/decomposition.h>
#include <CGAL/Heat_diffusion/denoising.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/reconstruction.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>

#include "fast_ply_output.h"  // the tool's fast output of fields
#include "mesh_input.h"  // the tool's reading: its pre-checks and its fast reader
#include "test_support.h"

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace test_hostile_input {

namespace HD = CGAL::Heat_diffusion;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef HD::Edge_weighted_heat_kernel<Mesh> Kernel;
typedef HD::Anisotropic_heat_diffusion<Mesh> Diffusion;

namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();
const double inf = std::numeric_limits<double>::infinity();

std::string corpus_path(const std::string& name)
{
  return std::string(CGAL_HEAT_DIFFUSION_HOSTILE_DATA_DIR) + "/" + name;
}

// The user's way to get a Surface_mesh from an OFF stream (CGAL's BGL reader, which
// keeps isolated and duplicated vertices as they are).
bool read_mesh(const std::string& name, Mesh& mesh)
{
  std::ifstream is(corpus_path(name));
  CHECK_MESSAGE(is.good(), "cannot open " << corpus_path(name));
  return CGAL::IO::read_OFF(is, mesh);
}

// Connected components by vertex index (through the faces).
std::vector<std::size_t> component_of_vertex(const Mesh& mesh)
{
  std::vector<std::size_t> component(mesh.number_of_vertices(), std::size_t(-1));
  std::size_t count = 0;
  for(Vertex s : mesh.vertices())
  {
    if(component[s.idx()] != std::size_t(-1))
      continue;
    std::vector<Vertex> stack(1, s);
    component[s.idx()] = count;
    while(!stack.empty())
    {
      const Vertex v = stack.back();
      stack.pop_back();
      for(Vertex u : vertices_around_target(mesh.halfedge(v), mesh))
        if(component[u.idx()] == std::size_t(-1))
        {
          component[u.idx()] = count;
          stack.push_back(u);
        }
    }
    ++count;
  }
  return component;
}

bool all_finite(const Eigen::MatrixXd& m) { return m.allFinite(); }

// Everything the package computes on a mesh it accepts, checked for finiteness and
// for the properties that hold on any valid mesh.
void check_accepted_mesh(const Mesh& mesh, const std::string& name)
{
  const std::size_t n = mesh.number_of_vertices();

  // NCC: finite, parallel to the normals, positive areas, rows of N summing to 0.
  const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
  bool finite = true, parallel = true, positive_areas = true;
  for(Vertex v : mesh.vertices())
  {
    const auto d = ncc.ncc(v), nv = ncc.normal(v);
    finite = finite && std::isfinite(ncc.normal_signature(v)) && std::isfinite(d.x()) && std::isfinite(d.y()) &&
             std::isfinite(d.z());
    parallel = parallel && std::sqrt(CGAL::cross_product(d, nv).squared_length()) <=
                               1e-9 * (std::max)(1., std::abs(ncc.normal_signature(v)));
    // in user units, an area overflows at 1e300 and underflows at 1e-300: inf and 0
    // are what a double can say, but never NaN or a negative value
    positive_areas = positive_areas && ncc.voronoi_area(v) >= 0 && !std::isnan(ncc.voronoi_area(v));
  }
  for(double a : ncc.data().areas)
    positive_areas = positive_areas && a > 0 && std::isfinite(a);
  CHECK_MESSAGE(finite, name << ": NCC / NS not finite");
  CHECK_MESSAGE(parallel, name << ": NCC not parallel to the normal");
  CHECK_MESSAGE(positive_areas, name << ": Voronoi area not positive and finite");
  const Eigen::SparseMatrix<double> N = ncc.internal_operator_matrix();
  const Eigen::VectorXd row_sums = N * Eigen::VectorXd::Ones(Eigen::Index(n));
  const Eigen::VectorXd diagonal = N.diagonal();
  CHECK_MESSAGE(row_sums.cwiseAbs().maxCoeff() <= 1e-9 * diagonal.cwiseAbs().maxCoeff(),
                name << ": rows of N do not sum to 0");

  // Reconstruction from its own NS returns the mesh (up to rounding).
  {
    Mesh copy = mesh;
    std::map<Vertex, double> ns;
    for(Vertex v : mesh.vertices())
      ns[v] = ncc.normal_signature(v);
    HD::reconstruct_from_normal_signature(copy, boost::make_assoc_property_map(ns));
    double worst = 0;
    for(Vertex v : mesh.vertices())
    {
      const Point& a = mesh.point(v);
      const Point& b = copy.point(v);
      worst = (std::max)({worst, std::abs(a.x() - b.x()), std::abs(a.y() - b.y()), std::abs(a.z() - b.z())});
    }
    // compared in units of the mesh size (the coordinates may be 1e300 or 1e-300)
    double extent = 0;
    for(Vertex v : mesh.vertices())
      extent = (std::max)({extent, std::abs(mesh.point(v).x()), std::abs(mesh.point(v).y()),
                           std::abs(mesh.point(v).z())});
    CHECK_MESSAGE(std::isfinite(worst) && worst <= 1e-6 * extent,
                  name << ": reconstruction from the own NS moved a vertex by " << worst << " (extent " << extent
                       << ")");
  }

  // The kernel, with the default sigma, an isotropic one and the scale-invariant one;
  // m = 10 is more than most corpus meshes have vertices (it is clamped).
  const std::vector<std::size_t> component = component_of_vertex(mesh);
  const std::size_t components = *std::max_element(component.begin(), component.end()) + 1;
  for(int variant = 0; variant < 3; ++variant)
  {
    const std::string label = name + (variant == 0 ? " (sigma 0.1)" : variant == 1 ? " (sigma inf)" : " (eq. 14)");
    const Kernel kernel(mesh, HD::parameters::combine(HD::parameters::number_of_eigenpairs(10),
                                                      HD::parameters::sigma(variant == 1 ? inf : 0.1),
                                                      HD::parameters::scale_invariant_kernel(variant == 2)));
    const std::size_t m = kernel.number_of_eigenpairs();
    CHECK_MESSAGE(m == (std::min)(std::size_t(10), n), label << ": m = " << m << ", expected min(10, n)");
    CHECK_MESSAGE(kernel.number_of_connected_components() == components,
                  label << ": " << kernel.number_of_connected_components() << " components, expected " << components);
    const Eigen::VectorXd& lambda = kernel.eigenvalues();
    const Eigen::MatrixXd& phi = kernel.eigenvectors();
    CHECK_MESSAGE(all_finite(lambda) && all_finite(phi), label << ": eigenpairs not finite");
    const double top = (std::max)(1., std::abs(lambda[lambda.size() - 1]));
    CHECK_MESSAGE(lambda.minCoeff() >= -1e-8 * top, label << ": negative eigenvalue " << lambda.minCoeff());
    std::size_t zeros = 0;
    for(Eigen::Index k = 0; k < lambda.size(); ++k)
      zeros += std::abs(lambda[k]) <= 1e-8 * top ? 1 : 0;
    CHECK_MESSAGE(zeros >= (std::min)(components, m), label << ": " << zeros << " zero eigenvalues for "
                                                            << components << " components");
    const Eigen::MatrixXd gram = phi.transpose() * (kernel.mass_matrix() * phi);
    CHECK_MESSAGE((gram - Eigen::MatrixXd::Identity(Eigen::Index(m), Eigen::Index(m))).cwiseAbs().maxCoeff() <= 1e-8,
                  label << ": eigenvectors not B-orthonormal");
    bool kernel_finite = true;
    for(Vertex v : mesh.vertices())
      kernel_finite = kernel_finite && std::isfinite(kernel.heat_kernel_signature(v, 1.)) &&
                      std::isfinite(kernel.heat_kernel_signature(v, 1e-3)) &&
                      std::isfinite(kernel.heat_kernel_signature(v, 1e6));
    CHECK_MESSAGE(kernel_finite, label << ": heat kernel signature not finite");

    // Diffusion: finite, conserving the heat of every connected component (A_t does
    // not carry heat between components), for small and large t.
    for(double t : {1e-3, 1., 1e3})
    {
      const Diffusion diffusion(kernel, t);
      Eigen::VectorXd f0(static_cast<Eigen::Index>(n));
      for(Eigen::Index i = 0; i < f0.size(); ++i)
        f0[i] = 2. + std::sin(double(i));
      const std::vector<Eigen::VectorXd> fields = diffusion.diffuse(f0, std::vector<std::size_t>{0, 1, 7, 60});
      bool fields_finite = true;
      double worst_leak = 0;
      for(const Eigen::VectorXd& f : fields)
      {
        fields_finite = fields_finite && f.allFinite();
        std::vector<double> before(components, 0.), after(components, 0.);
        for(Vertex v : mesh.vertices())
        {
          before[component[v.idx()]] += f0[Eigen::Index(kernel.vertex_index(v))];
          after[component[v.idx()]] += f[Eigen::Index(kernel.vertex_index(v))];
        }
        for(std::size_t c = 0; c < components; ++c)
          worst_leak = (std::max)(worst_leak, std::abs(after[c] - before[c]) / std::abs(before[c]));
      }
      CHECK_MESSAGE(fields_finite, label << ", t = " << t << ": diffused field not finite");
      CHECK_MESSAGE(worst_leak <= 1e-12, label << ", t = " << t << ": heat of a component changed by " << worst_leak);

      // Features at k = 0 and k = 7: valid vertices, finite.
      if(variant == 0 && t == 1.)
      {
        std::map<Vertex, double> field;
        for(Vertex v : mesh.vertices())
          field[v] = f0[Eigen::Index(kernel.vertex_index(v))];
        const auto features =
            HD::detect_multiscale_features(diffusion, boost::make_assoc_property_map(field), {0, 7});
        bool valid = features.size() == 2;
        for(const auto& scale : features)
          for(const auto* list : {&scale.convex, &scale.concave})
            for(Vertex v : *list)
              valid = valid && mesh.is_valid(v) && !mesh.is_removed(v);
        CHECK_MESSAGE(valid, label << ": invalid feature vertices");
      }
    }
  }
}

// One mesh of the corpus and its documented outcome through the API.
struct Corpus_case
{
  std::string file;
  bool readable;      // CGAL::IO::read_OFF into a Surface_mesh succeeds
  std::string error;  // empty: the package gives a result; else a fragment of the std::invalid_argument
};

std::vector<Corpus_case> corpus()
{
  return {
      // accepted meshes: a result, checked by check_accepted_mesh()
      {"needle.off", true, ""},
      {"duplicated_vertex.off", true, ""},  // a seam: both copies are boundary vertices
      {"two_neighbours.off", true, ""},
      {"two_components.off", true, ""},
      {"three_components.off", true, ""},
      {"single_triangle.off", true, ""},
      {"open_strip.off", true, ""},
      {"hole.off", true, ""},
      {"octahedron.off", true, ""},
      {"huge_coordinates.off", true, ""},
      {"tiny_coordinates.off", true, ""},
      // rejected by the package, with a message that names the element
      {"quad_faces.off", true, "face 0 has 4 vertices"},
      {"zero_area.off", true, "face 0 (vertices 0, 1, 2) has zero area"},
      // a needle whose corners 0 and 3 are one unit in the last place apart (a fuzzing
      // find: the NCC of vertex 3 was NaN)
      {"rounding_collinear_face.off", true, "face 2 (vertices 0, 3, 2) has zero area up to rounding"},
      {"isolated_vertex.off", true, "vertex 4 is isolated"},
      {"pillow.off", true, "vertex 0 has no usable normal"},
      // rejected by CGAL's reader (not a manifold mesh, or not a valid OFF file)
      {"nonmanifold_edge.off", false, ""},
      {"nonmanifold_vertex.off", false, ""},
      {"nan_coordinate.off", false, ""},
      {"inf_coordinate.off", false, ""},
      {"overflow_coordinate.off", false, ""},
      {"truncated.off", false, ""},
      {"header_only.off", false, ""},
      {"garbage.off", false, ""},
      // (negative_index.off is not read here: CGAL's reader converts -1 to std::size_t,
      // undefined behaviour; the tool rejects the file before, see test_hostile_cli.sh)
      {"index_out_of_range.off", false, ""},
      {"fractional_index.off", false, ""},
      {"missing_normal.off", false, ""},
  };
}

void check_corpus()
{
  for(const Corpus_case& c : corpus())
  {
    Mesh mesh;
    const bool readable = read_mesh(c.file, mesh);
    CHECK_MESSAGE(readable == c.readable, c.file << ": read_OFF returned " << readable);
    if(!readable || !c.readable)
      continue;
    if(c.error.empty())
    {
      try
      {
        check_accepted_mesh(mesh, c.file);
      }
      catch(const std::exception& e)
      {
        CHECK_MESSAGE(false, c.file << ": unexpected exception " << e.what());
      }
      continue;
    }
    // Every entry point rejects the mesh with the same message.
    std::map<Vertex, double> values;
    std::map<Vertex, K::Vector_3> vectors;
    for(Vertex v : mesh.vertices())
      values[v] = 1.;
    auto ns_map = boost::make_assoc_property_map(values);
    CHECK_THROWS(HD::Normal_controlled_coordinates<Mesh>{mesh}, std::invalid_argument, c.error);
    CHECK_THROWS(HD::compute_normal_signature(mesh, ns_map), std::invalid_argument, c.error);
    CHECK_THROWS(HD::compute_normal_controlled_coordinates(mesh, boost::make_assoc_property_map(vectors)),
                 std::invalid_argument, c.error);
    CHECK_THROWS(HD::normal_controlled_coordinates_matrix(mesh), std::invalid_argument, c.error);
    Mesh copy = mesh;
    CHECK_THROWS(HD::reconstruct_from_normal_signature(copy, ns_map), std::invalid_argument, c.error);
    CHECK_THROWS(Kernel(mesh, HD::parameters::number_of_eigenpairs(5)), std::invalid_argument, c.error);
    CHECK_THROWS(Diffusion(mesh, HD::parameters::number_of_eigenpairs(5)), std::invalid_argument, c.error);
    CHECK_THROWS(HD::anisotropic_heat_diffusion(mesh, ns_map, ns_map, HD::parameters::number_of_eigenpairs(5)),
                 std::invalid_argument, c.error);
    std::vector<Vertex> convex, concave;
    CHECK_THROWS(HD::detect_multiscale_features(mesh, ns_map, std::back_inserter(convex), std::back_inserter(concave),
                                                HD::parameters::number_of_steps(2)),
                 std::invalid_argument, c.error);
  }
}

// The tool's fast reader (tools/Heat_diffusion/fast_mesh_input.h) against what the
// tool did before it, the pre-check and CGAL::IO::read_polygon_mesh: on what it reads,
// the identical mesh; everything else, and every hostile file, it leaves to them.
namespace fast_reader {

namespace fi = heat_diffusion_cli::fast_input;

std::string scratch(const std::string& name)
{
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "test_hostile_input_fast_reader";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

void write_text(const std::string& path, const std::string& text)
{
  std::ofstream os(path, std::ios::binary);
  os << text;
}

// The tool's reading without the fast reader: true if the file passes its checks and
// CGAL's soup reader and builder read it. The mesh is the one CGAL::IO::read_polygon_mesh
// reads (checked here: the tool builds it with its own code).
bool read_like_before(const std::string& path, Mesh& mesh)
{
  try
  {
    if(!heat_diffusion_cli::read_checked_polygon_mesh(path, mesh))
      return false;
  }
  catch(const heat_diffusion_cli::Input_error&)
  {
    return false;
  }
  Mesh cgal;
  CHECK_MESSAGE(CGAL::IO::read_polygon_mesh(path, cgal) && fi::identical_meshes(mesh, cgal, false),
                path << ": the tool's checked reading and CGAL::IO::read_polygon_mesh differ");
  return true;
}

// The fast reader reads `path`, to the mesh CGAL's reader gives.
void check_reads_identically(const std::string& path)
{
  Mesh fast, before;
  const bool fast_read = fi::read_mesh_fast(path, fast);
  CHECK_MESSAGE(fast_read, path << ": the fast reader declined");
  CHECK_MESSAGE(read_like_before(path, before), path << ": CGAL's reader failed");
  CHECK_MESSAGE(fast_read && fi::identical_meshes(fast, before), path << ": the meshes differ");
}

// The fast reader leaves `path` to the pre-check and CGAL's reader: it declines,
// with the mesh left empty.
void check_declines(const std::string& path)
{
  Mesh fast;
  CHECK_MESSAGE(!fi::read_mesh_fast(path, fast) && is_empty(fast), path << ": the fast reader did not decline");
}

void put_big_endian(std::string& s, std::uint32_t u)
{
  for(int shift = 24; shift >= 0; shift -= 8)
    s += char((u >> shift) & 0xff);
}

// `mesh` as binary OFF (big-endian float32 coordinates, int32 sizes and indices).
std::string binary_off(const Mesh& mesh)
{
  std::string s = "OFF BINARY\n";
  put_big_endian(s, std::uint32_t(mesh.number_of_vertices()));
  put_big_endian(s, std::uint32_t(mesh.number_of_faces()));
  put_big_endian(s, 0);
  for(Vertex v : mesh.vertices())
    for(int k = 0; k < 3; ++k)
    {
      const float x = float(mesh.point(v)[k]);
      std::uint32_t u;
      std::memcpy(&u, &x, 4);
      put_big_endian(s, u);
    }
  for(auto f : mesh.faces())
  {
    put_big_endian(s, std::uint32_t(mesh.degree(f)));
    for(Vertex v : vertices_around_face(mesh.halfedge(f), mesh))
      put_big_endian(s, std::uint32_t(v.idx()));
  }
  return s;
}

void check_meshes()
{
  // Real meshes in each format, written by CGAL's writers with all digits.
  for(const std::string name : {"fandisk.off", "armadillo.off"})
  {
    const std::string path = test_support::data_path(name);
    check_reads_identically(path);
    Mesh mesh;
    CHECK(CGAL::IO::read_polygon_mesh(path, mesh));
    const std::string stem = scratch(name.substr(0, name.size() - 4));
    {
      std::ofstream os(stem + "_binary.ply", std::ios::binary);
      CGAL::IO::set_binary_mode(os);
      CHECK(CGAL::IO::write_PLY(os, mesh));
    }
    {
      std::ofstream os(stem + "_ascii.ply");
      CHECK(CGAL::IO::write_PLY(os, mesh, CGAL::parameters::stream_precision(17)));
    }
    CHECK(CGAL::IO::write_OBJ(stem + ".obj", mesh, CGAL::parameters::stream_precision(17)));
    write_text(stem + "_binary.off", binary_off(mesh));
    for(const std::string suffix : {"_binary.ply", "_ascii.ply", ".obj", "_binary.off"})
      check_reads_identically(stem + suffix);
    // STL, which only CGAL's readers read: the tool's checked reading gives CGAL's mesh
    CHECK(CGAL::IO::write_STL(stem + ".stl", mesh, CGAL::parameters::stream_precision(17)));
    Mesh stl;
    CHECK_MESSAGE(read_like_before(stem + ".stl", stl) && stl.number_of_faces() == mesh.number_of_faces(),
                  stem << ".stl: not read");
  }
  // The variants the readers accept beyond what CGAL writes.
  write_text(scratch("comments_crlf.off"),
             "# a comment line\r\nOFF\r\n# another\r\n5 5 0\r\n0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n\r\n0.5 0.5 1\r\n"
             "4 3 2 1 0\r\n3 0 1 4\r\n3 1 2 4\r\n3 2 3 4\r\n3 3 0 4\r\n");
  write_text(scratch("slashes.obj"), "# pyramid\r\nmtllib x.mtl\no pyramid\nv 0 0 0\nv 1 0 0\nv 1 1 0 0.5 0.5 0.5\n"
                                     "v 0 1 0\nv 0.5 0.5 1\nvn 0 0 1\nvt 0 0\ns off\nf 4/1/1 3/1/1 2/1/1 1/1/1\n"
                                     "f 1//1 2//1 5//1\nf 2/1 3/1 5/1\r\nf  3 4 5 \nf 4 1 5\n");
  write_text(scratch("float_colours.ply"),
             "ply\nformat ascii 1.0\ncomment colours are dropped\nelement vertex 5\nproperty float x\nproperty float y\n"
             "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nelement face 5\n"
             "property list uchar uint vertex_index\nend_header\n0 0 0 255 0 0\n1 0 0 0 255 0\n1 1 0 0 0 255\n"
             "0.1 1 0 9 9 9\n0.5 0.5 1.3 1 2 3\n4 3 2 1 0\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n");
  {
    // big-endian, float32 coordinates between other properties, int16 list lengths
    std::string s = "ply\r\nformat binary_big_endian 1.0\r\nelement vertex 5\r\nproperty float x\r\n"
                    "property int16 quality\r\nproperty float y\r\nproperty float z\r\nelement face 5\r\n"
                    "property list short int vertex_indices\r\nend_header\n";
    const float points[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0.5f, 1.1f}};
    for(const auto& p : points)
      for(int k = 0; k < 3; ++k)
      {
        std::uint32_t u;
        std::memcpy(&u, &p[k], 4);
        put_big_endian(s, u);
        if(k == 0)
          s += std::string("\x01\x02", 2);
      }
    const int faces[5][4] = {{3, 2, 1, 0}, {0, 1, 4, -1}, {1, 2, 4, -1}, {2, 3, 4, -1}, {3, 0, 4, -1}};
    for(const auto& f : faces)
    {
      const int k = f[3] < 0 ? 3 : 4;
      s += char(0);
      s += char(k);
      for(int j = 0; j < k; ++j)
        put_big_endian(s, std::uint32_t(f[j]));
    }
    write_text(scratch("big_endian.ply"), s);
  }
  for(const std::string name : {"comments_crlf.off", "slashes.obj", "float_colours.ply", "big_endian.ply"})
    check_reads_identically(scratch(name));
  // What they leave to CGAL's reader, valid or not: it reads the same as before.
  write_text(scratch("colours.off"), "COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 0 255 0\n0 1 0 0 0 255\n3 0 1 2\n");
  write_text(scratch("relative.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n");
  write_text(scratch("tabs.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf\t1\t2\t3\n");
  write_text(scratch("edges.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                   "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                   "element edge 0\nproperty int vertex1\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  write_text(scratch("inner_comment.off"), "OFF\n3 1 0\n0 0 0\n# here\n1 0 0\n0 1 0\n3 0 1 2\n");
  write_text(scratch("extra_number.off"), "OFF\n3 1 0\n0 0 0 1\n1 0 0\n0 1 0\n3 0 1 2\n");
  for(const std::string name : {"colours.off", "relative.obj", "tabs.obj", "edges.ply", "inner_comment.off",
                                "extra_number.off"})
  {
    check_declines(scratch(name));
    Mesh mesh;
    if(read_like_before(scratch(name), mesh))
    {
      // and the tool's reading, which falls back on it, gives CGAL's mesh
      Mesh tool;
      heat_diffusion_cli::read_triangle_mesh(scratch(name), tool);
      CHECK_MESSAGE(fi::identical_meshes(tool, mesh), name << ": the tool's mesh differs from CGAL's");
    }
  }
}

// Every file of the hostile corpus, and broken PLY and OBJ files: what the fast reader
// accepts, the pre-check and CGAL's reader accept, to the same mesh; what they reject,
// it declines. Files it declines although they are valid go the old way: also fine.
void check_hostile()
{
  std::size_t accepted = 0, files = 0;
  for(const auto& entry : std::filesystem::directory_iterator(CGAL_HEAT_DIFFUSION_HOSTILE_DATA_DIR))
  {
    const std::string path = entry.path().string();
    Mesh fast, before;
    const bool fast_read = fi::read_mesh_fast(path, fast), read = read_like_before(path, before);
    CHECK_MESSAGE(!fast_read || (read && fi::identical_meshes(fast, before)),
                  path << ": the fast reader accepts what the tool rejected, or reads it differently");
    accepted += fast_read ? 1 : 0;
    ++files;
  }
  // the well-formed meshes of the corpus are read fast (most of it: not a vacuous check)
  for(const std::string name : {"octahedron.off", "needle.off", "hole.off", "quad_faces.off", "pillow.off",
                                "tiny_coordinates.off", "three_components.off"})
    check_reads_identically(corpus_path(name));
  CHECK_MESSAGE(accepted >= 7 && accepted < files, accepted << " of " << files << " corpus files read fast");
  for(const std::string name : {"nan_coordinate.off", "inf_coordinate.off", "overflow_coordinate.off", "truncated.off",
                                "huge_counts.off", "huge_counts.ply", "huge_face_size.off", "huge_face_size_ascii.ply",
                                "huge_face_size_binary.ply", "index_out_of_range.off", "negative_index.off",
                                "fractional_index.off", "garbage.off", "header_only.off", "empty.off",
                                "nonmanifold_edge.off", "nonmanifold_vertex.off", "bad_color.off", "missing_normal.off"})
    check_declines(corpus_path(name));

  // broken PLY and OBJ files
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  const std::vector<std::pair<std::string, std::string>> broken = {
      {"index.ply", header + vertices + "3 0 1 3\n"},
      {"negative.ply", header + vertices + "3 0 -1 2\n"},
      {"short_face.ply", header + vertices + "2 0 1\n"},
      {"truncated.ply", header + vertices + "3 0 1"},
      {"nan.ply", header + "0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n"},
      {"overflow.ply", header + "0 0 0\n1e39 0 0\n0 1 0\n3 0 1 2\n"},
      {"length.ply", header + vertices + "300 0 1 2\n"},
      {"no_z.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nelement face 1\n"
                   "property list uchar int vertex_indices\nend_header\n0 0\n1 0\n0 1\n3 0 1 2\n"},
      {"binary_truncated.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                               "property float y\nproperty float z\nelement face 1\n"
                               "property list uchar int vertex_indices\nend_header\n" + std::string(30, '\0')},
      {"index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"},
      {"zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"},
      {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"},
      {"short.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n"},
      {"unknown.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nbogus 1\n"},
      {"repeated.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n"},
      // a relative index before the first vertex, though within the count of the file
      {"relative_before_first.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\nv 0 0 1\n"},
      {"binary_index.off", "OFF BINARY\n" + std::string("\0\0\0\3\0\0\0\1\0\0\0\0", 12) + std::string(36, '\0') +
                               std::string("\0\0\0\3\0\0\0\0\0\0\0\1\0\0\0\3", 16)},
      // a keyword that only starts with BINARY: the counts after it are not read as ASCII
      {"binary_prefix.off", "OFF\nBINARY4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n"
                            "3 1 2 3\n"},
      {"binary_truncated.off", "OFF BINARY\n" + std::string("\0\0\0\3\0\0\0\1\0\0\0\0", 12) + std::string(20, '\0')},
  };
  for(const auto& file : broken)
  {
    write_text(scratch(file.first), file.second);
    check_declines(scratch(file.first));
  }
  // The tool rejects a face index out of range in any format with a message that names
  // the face (CGAL's reader, to which the fast reader leaves them, read out of bounds).
  const std::vector<std::pair<std::string, std::string>> bad_indices = {
      {"index.ply", "index.ply: face 0 has the vertex index 3, not one of 0..2"},
      {"negative.ply", "negative.ply: face 0 has the vertex index -1, not one of 0..2"},
      {"index.obj", "index.obj: face 1 refers to a vertex the file does not have (it has 3 vertices"},
      {"zero.obj", "zero.obj: face 1 refers to a vertex the file does not have"},
      {"relative_before_first.obj", "relative_before_first.obj: face 1 refers to a vertex the file does not have"},
  };
  for(const auto& file : bad_indices)
  {
    Mesh mesh;
    CHECK_THROWS(heat_diffusion_cli::read_triangle_mesh(scratch(file.first), mesh), heat_diffusion_cli::Input_error,
                 file.second);
  }
}

}  // namespace fast_reader


// Non-manifold polygon soups: not a polygon mesh as they are; the documented repair
// (PMP::orient_polygon_soup duplicates non-manifold vertices and edges) gives a mesh
// the package processes.
void check_polygon_soups()
{
  for(const std::string file : {"nonmanifold_edge.off", "nonmanifold_vertex.off"})
  {
    std::vector<Point> points;
    std::vector<std::vector<std::size_t> > polygons;
    std::ifstream is(corpus_path(file));
    CHECK_MESSAGE(CGAL::IO::read_OFF(is, points, polygons), file << ": not read as a polygon soup");
    CHECK_MESSAGE(!PMP::is_polygon_soup_a_polygon_mesh(polygons), file << ": the soup is a polygon mesh");
    PMP::orient_polygon_soup(points, polygons);
    CHECK_MESSAGE(PMP::is_polygon_soup_a_polygon_mesh(polygons), file << ": orient_polygon_soup did not repair it");
    Mesh mesh;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
    CHECK_MESSAGE(points.size() > 5 && mesh.number_of_vertices() == points.size(),
                  file << ": no vertex was duplicated");
    check_accepted_mesh(mesh, file + " (repaired)");
  }
}

// The mesh of `file` in the normalised position of the octahedron: NS and
// eigenvalues do not depend on the scale, even at 1e300 and 1e-300.
void check_extreme_scales()
{
  Mesh reference, huge, tiny;
  CHECK(read_mesh("octahedron.off", reference));
  CHECK(read_mesh("huge_coordinates.off", huge));
  CHECK(read_mesh("tiny_coordinates.off", tiny));
  const HD::Normal_controlled_coordinates<Mesh> a(reference), b(huge), c(tiny);
  const Kernel ka(reference), kb(huge), kc(tiny);
  double worst_ns = 0, worst_lambda = 0;
  for(Vertex v : reference.vertices())
    worst_ns = (std::max)({worst_ns, std::abs(a.normal_signature(v) - b.normal_signature(v)),
                           std::abs(a.normal_signature(v) - c.normal_signature(v))});
  for(Eigen::Index k = 0; k < ka.eigenvalues().size(); ++k)
    worst_lambda = (std::max)({worst_lambda, std::abs(ka.eigenvalues()[k] - kb.eigenvalues()[k]),
                               std::abs(ka.eigenvalues()[k] - kc.eigenvalues()[k])});
  CHECK_MESSAGE(worst_ns <= 1e-9, "NS at 1e300 / 1e-300 differ from the unit octahedron's by " << worst_ns);
  CHECK_MESSAGE(worst_lambda <= 1e-9, "eigenvalues at 1e300 / 1e-300 differ by " << worst_lambda);
  // The Voronoi areas are in user units: 1e600 overflows, 1e-600 underflows; the
  // package reports what a double can hold (inf, 0) but computes everything else
  // in its normalised frame.
  bool finite_normals = true;
  for(Vertex v : huge.vertices())
    finite_normals = finite_normals && std::isfinite(b.normal(v).squared_length());
  CHECK(finite_normals);
}

// Meshes built point by point: non-finite coordinates, the empty mesh.
Mesh triangle_pair(const Point& last)
{
  Mesh mesh;
  const Vertex a = mesh.add_vertex(Point(0, 0, 0)), b = mesh.add_vertex(Point(1, 0, 0)),
               c = mesh.add_vertex(Point(1, 1, 0)), d = mesh.add_vertex(last);
  mesh.add_face(a, b, c);
  mesh.add_face(a, c, d);
  return mesh;
}

void check_built_meshes()
{
  for(const Point& p : {Point(0, 1, nan), Point(inf, 1, 0), Point(0, -inf, 0)})
  {
    const Mesh mesh = triangle_pair(p);
    CHECK_THROWS(HD::Normal_controlled_coordinates<Mesh>{mesh}, std::invalid_argument,
                 "vertex 3 has a non-finite coordinate");
    CHECK_THROWS(Kernel{mesh}, std::invalid_argument, "vertex 3 has a non-finite coordinate");
  }
  // 1e308: differences of coordinates overflow, the normalised frame does not.
  {
    Mesh mesh;
    const double x = 1.7e308;
    const Vertex a = mesh.add_vertex(Point(-x, -x, 0)), b = mesh.add_vertex(Point(x, -x, 0)),
                 c = mesh.add_vertex(Point(x, x, x)), d = mesh.add_vertex(Point(-x, x, 0));
    mesh.add_face(a, b, c);
    mesh.add_face(a, c, d);
    const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
    bool finite = true;
    for(Vertex v : mesh.vertices())
      finite = finite && std::isfinite(ncc.normal_signature(v));
    CHECK_MESSAGE(finite, "NS not finite with coordinates of 1.7e308");
    check_accepted_mesh(mesh, "coordinates of 1.7e308");
  }
  // Subnormal coordinates (1e-310): the normalised frame is exact, the NS those of
  // the octahedron.
  {
    Mesh reference, mesh;
    CHECK(read_mesh("octahedron.off", reference));
    mesh = reference;
    for(Vertex v : mesh.vertices())
      mesh.point(v) = CGAL::ORIGIN + (mesh.point(v) - CGAL::ORIGIN) * 1e-310;
    const HD::Normal_controlled_coordinates<Mesh> a(reference), b(mesh);
    double worst = 0;
    for(Vertex v : mesh.vertices())
      worst = (std::max)(worst, std::abs(a.normal_signature(v) - b.normal_signature(v)));
    CHECK_MESSAGE(worst <= 1e-9, "NS at 1e-310 differ from the octahedron's by " << worst);
    check_accepted_mesh(mesh, "coordinates of 1e-310");
  }
  // Broken halfedge structures: an error that says so, never an endless circulation.
  {
    // next() of a halfedge of face 0 leads into a face whose cycle never comes back
    Mesh mesh;
    CHECK(read_mesh("octahedron.off", mesh));
    const auto h = halfedge(*faces(mesh).begin(), mesh);
    for(auto f : faces(mesh))
    {
      bool touches = false;
      for(auto g : halfedges_around_face(halfedge(f, mesh), mesh))
        for(auto e : halfedges_around_face(h, mesh))
          touches = touches || g == e || g == opposite(e, mesh);
      if(!touches)
      {
        mesh.set_next(h, halfedge(f, mesh));
        break;
      }
    }
    CHECK_THROWS(HD::Normal_controlled_coordinates<Mesh>{mesh}, std::invalid_argument,
                 "the halfedges around face 0 do not form a cycle");
    // PMP::triangulate_faces() on the non-planar faces of this soup (found by fuzzing)
    // leaves faces whose triangles are cycles but whose vertices' halfedges are not
    std::vector<Point> points;
    std::vector<std::vector<std::size_t> > polygons;
    std::ifstream is(corpus_path("broken_by_triangulation.off"));
    CHECK(CGAL::IO::read_OFF(is, points, polygons));
    PMP::repair_polygon_soup(points, polygons);
    CHECK(PMP::orient_polygon_soup(points, polygons));
    Mesh triangulated;
    PMP::polygon_soup_to_polygon_mesh(points, polygons, triangulated);
    PMP::triangulate_faces(triangulated);
    if(CGAL::is_valid_polygon_mesh(triangulated))
      check_accepted_mesh(triangulated, "broken_by_triangulation.off, triangulated");  // a fixed CGAL
    else
      CHECK_THROWS(HD::Normal_controlled_coordinates<Mesh>{triangulated}, std::invalid_argument,
                   "do not form a cycle: the halfedge structure is broken");
  }
  // A face that is tiny next to the rest of the mesh is lost to rounding in the
  // normalised frame: refused, naming the vertex that stretches the box.
  CHECK_THROWS(HD::Normal_controlled_coordinates<Mesh>{triangle_pair(Point(-1.5e308, 1.7e308, 1e308))},
               std::invalid_argument,
               "face 0 (vertices 0, 1, 2) is too small for double precision to resolve in a bounding box whose "
               "largest side is 1.7e+308; vertex 3, at ");
  // So are the faces beside one far vertex in a face of its own, from about 1e10 on
  // (at 5.6e78 the others' x coordinates round to one value, and their faces turn
  // silently into faces of another shape): refused, naming the far vertex.
  for(double far : {1e12, 5.5555555555555555e78, 1e300})
  {
    Mesh mesh = triangle_pair(Point(0, 1, 0.5));
    const Vertex b = *std::next(mesh.vertices().begin()), c = *std::next(mesh.vertices().begin(), 2);
    mesh.add_face(b, mesh.add_vertex(Point(far, 0.5, 0)), c);
    CHECK_THROWS(HD::Normal_controlled_coordinates<Mesh>{mesh}, std::invalid_argument,
                 "is too small for double precision to resolve");
    CHECK_THROWS(HD::Normal_controlled_coordinates<Mesh>{mesh}, std::invalid_argument,
                 "vertex 4, at ");
  }
  // The empty mesh: nothing to compute, no kernel.
  {
    const Mesh empty;
    std::map<Vertex, double> ns;
    HD::compute_normal_signature(empty, boost::make_assoc_property_map(ns));
    CHECK(ns.empty());
    CHECK_THROWS(Kernel{empty}, std::invalid_argument, "the mesh is empty");
  }
  // A null user normal.
  {
    const Mesh mesh = triangle_pair(Point(0, 1, 0.5));
    std::map<Vertex, K::Vector_3> normals;
    for(Vertex v : mesh.vertices())
      normals[v] = K::Vector_3(0, 0, 1);
    normals[Vertex(2)] = K::Vector_3(0, 0, 0);
    CHECK_THROWS(HD::Normal_controlled_coordinates<Mesh>(
                     mesh, CGAL::parameters::vertex_normal_map(boost::make_assoc_property_map(normals))),
                 std::invalid_argument, "vertex 2 has no usable normal");
    normals[Vertex(2)] = K::Vector_3(0, nan, 1);
    CHECK_THROWS(HD::Normal_controlled_coordinates<Mesh>(
                     mesh, CGAL::parameters::vertex_normal_map(boost::make_assoc_property_map(normals))),
                 std::invalid_argument, "vertex 2 has no usable normal");
  }
}

// m > n, sigma <= 0, t <= 0, k < 0, non-finite fields, and the like.
void check_parameters()
{
  Mesh mesh;
  CHECK(read_mesh("two_components.off", mesh));
  const std::size_t n = mesh.number_of_vertices();
  std::map<Vertex, double> values;
  for(Vertex v : mesh.vertices())
    values[v] = double(v.idx());
  auto field = boost::make_assoc_property_map(values);

  // m larger than the vertex count: clamped.
  for(std::size_t m : {n, n + 1, std::size_t(1000), std::numeric_limits<std::size_t>::max()})
    CHECK_MESSAGE(Kernel(mesh, HD::parameters::number_of_eigenpairs(m)).number_of_eigenpairs() == n,
                  "m = " << m << " is not clamped to " << n);
  CHECK_THROWS(Kernel(mesh, HD::parameters::number_of_eigenpairs(0)), std::invalid_argument,
               "number_of_eigenpairs must be positive");
  CHECK_THROWS(Kernel(mesh, HD::parameters::number_of_eigenpairs(-1)), std::invalid_argument,
               "number_of_eigenpairs must be positive");

  // sigma <= 0 or NaN.
  for(double sigma : {0., -0., -1., -inf, nan})
    CHECK_THROWS(Kernel(mesh, HD::parameters::sigma(sigma)), std::invalid_argument, "sigma must be positive");
  // a tiny positive sigma: every weight underflows to 0 but nothing breaks
  check_accepted_mesh(mesh, "two_components.off");
  {
    const Kernel kernel(mesh, HD::parameters::sigma(1e-300));
    CHECK(kernel.eigenvalues().allFinite() && kernel.eigenvectors().allFinite());
    const Diffusion diffusion(kernel, 1.);
    Eigen::VectorXd f0 = Eigen::VectorXd::LinSpaced(Eigen::Index(n), 1., 2.);
    const Eigen::VectorXd f = diffusion.diffuse(f0, 10);
    CHECK_MESSAGE(f.allFinite() && std::abs(f.sum() - f0.sum()) <= 1e-12 * f0.sum(), "sigma = 1e-300: " << f.transpose());
  }

  // t <= 0, infinite or NaN.
  const Kernel kernel(mesh, HD::parameters::number_of_eigenpairs(8));
  for(double t : {0., -0., -1., inf, -inf, nan})
  {
    CHECK_THROWS(Diffusion(kernel, t), std::invalid_argument, "time must be positive and finite");
    CHECK_THROWS(Diffusion(mesh, HD::parameters::time(t)), std::invalid_argument, "time must be positive and finite");
  }
  // a huge and a tiny t: finite fields
  for(double t : {1e-300, 1e300})
  {
    const Eigen::VectorXd f = Diffusion(kernel, t).diffuse(Eigen::VectorXd::Ones(Eigen::Index(n)), 3);
    CHECK_MESSAGE(f.allFinite() && std::abs(f.sum() - double(n)) <= 1e-12 * double(n), "t = " << t);
  }

  // k < 0 (the named parameter is signed when the user passes an int).
  CHECK_THROWS(HD::anisotropic_heat_diffusion(mesh, field, field, HD::parameters::number_of_steps(-1)),
               std::invalid_argument, "number_of_steps must not be negative");
  std::vector<Vertex> convex, concave;
  CHECK_THROWS(HD::detect_multiscale_features(mesh, field, std::back_inserter(convex), std::back_inserter(concave),
                                              HD::parameters::number_of_steps(-2)),
               std::invalid_argument, "number_of_steps must not be negative");
  // k = 0: the field itself
  {
    std::map<Vertex, double> out;
    HD::anisotropic_heat_diffusion(mesh, field, boost::make_assoc_property_map(out),
                                   HD::parameters::number_of_steps(0));
    bool same = true;
    for(Vertex v : mesh.vertices())
      same = same && out[v] == values[v];
    CHECK_MESSAGE(same, "k = 0 changed the field");
  }

  // Fields with NaN or infinity, of the wrong size.
  const Diffusion diffusion(kernel, 1.);
  for(double bad : {nan, inf})
  {
    Eigen::VectorXd f = Eigen::VectorXd::Ones(Eigen::Index(n));
    f[3] = bad;
    CHECK_THROWS(diffusion.diffuse(f, 2), std::invalid_argument, "Anisotropic_heat_diffusion: the field value at vertex 3 is");
    std::map<Vertex, double> bad_values = values;
    bad_values[Vertex(5)] = bad;
    CHECK_THROWS(HD::reconstruct_from_normal_signature(mesh, boost::make_assoc_property_map(bad_values)),
                 std::invalid_argument, "reconstruct_from_normal_signature: the normal signature at vertex 5 is");
    CHECK_THROWS(HD::detect_multiscale_features(diffusion, boost::make_assoc_property_map(bad_values), {0, 1}),
                 std::invalid_argument, "detect_multiscale_features");
  }
  CHECK_THROWS(diffusion.diffuse(Eigen::VectorXd::Ones(Eigen::Index(n + 1)), 2), std::invalid_argument,
               "the field has the wrong size");
  for(double w : {0., -1., inf, nan})
    CHECK_THROWS(HD::reconstruct_from_normal_signature(mesh, field, HD::parameters::anchor_weight(w)),
                 std::invalid_argument, "anchor_weight must be positive and finite");
}

// The iterative eigensolver (n > 400) on three components: a zero eigenvalue of
// multiplicity 3, the hard case of Lanczos.
void check_iterative_solver_on_components()
{
  Mesh sphere;
  CGAL::make_icosahedron(sphere, Point(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(sphere, CGAL::parameters::number_of_iterations(2));
  Mesh mesh;
  for(int c = 0; c < 3; ++c)
  {
    Mesh copy = sphere;
    for(Vertex v : copy.vertices())
      copy.point(v) = copy.point(v) + K::Vector_3(3. * c, 0.1 * c, 0) + 0.05 * std::sin(double(v.idx())) *
                                                                      (copy.point(v) - CGAL::ORIGIN);
    CGAL::copy_face_graph(copy, mesh);
  }
  CHECK_MESSAGE(mesh.number_of_vertices() > 400, "only " << mesh.number_of_vertices() << " vertices");
  const Kernel kernel(mesh, HD::parameters::number_of_eigenpairs(10));
  CHECK(!kernel.used_dense_solver());
  check_accepted_mesh(mesh, "three subdivided spheres");
}

} // namespace

// A mesh with removed elements, as CGAL's editing leaves it: vertex `removed` taken
// out with Euler::remove_center_vertex() and its hole triangulated, without
// collect_garbage(). num_vertices() still counts the removed vertex.
template <typename PolygonMesh>
void remove_a_vertex(PolygonMesh& mesh, std::size_t removed)
{
  auto v = *std::next(vertices(mesh).begin(), std::ptrdiff_t(removed));
  CGAL::Euler::remove_center_vertex(halfedge(v, mesh), mesh);
  PMP::triangulate_faces(mesh);
}

// Values per vertex, keyed by position: collect_garbage() renumbers the vertices.
typedef std::map<Point, double> Field_by_point;

template <typename PolygonMesh, typename Map>
Field_by_point by_point(const PolygonMesh& mesh, const Map& map)
{
  Field_by_point result;
  for(auto v : vertices(mesh))
    result[get(CGAL::vertex_point, mesh, v)] = double(get(map, v));
  return result;
}

template <typename PolygonMesh>
std::map<Point, Point> points_by_point(const PolygonMesh& before, const PolygonMesh& after)
{
  // after has the vertices of before, in the same order
  std::map<Point, Point> result;
  auto a = vertices(after).begin();
  for(auto v : vertices(before))
    result[get(CGAL::vertex_point, before, v)] = get(CGAL::vertex_point, after, *a++);
  return result;
}

double largest_difference(const Field_by_point& a, const Field_by_point& b)
{
  if(a.size() != b.size())
    return inf;
  double worst = 0, scale = 0;
  for(auto i = a.begin(), j = b.begin(); i != a.end(); ++i, ++j)
  {
    if(i->first != j->first)
      return inf;
    worst = (std::max)(worst, std::abs(i->second - j->second));
    scale = (std::max)(scale, std::abs(i->second));
  }
  return worst / (std::max)(scale, 1e-300);
}

double largest_difference(const std::map<Point, Point>& a, const std::map<Point, Point>& b)
{
  if(a.size() != b.size())
    return inf;
  double worst = 0;
  for(auto i = a.begin(), j = b.begin(); i != a.end(); ++i, ++j)
  {
    if(i->first != j->first)
      return inf;
    worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(i->second, j->second)));
  }
  return worst;
}

template <typename PolygonMesh, typename VertexRange>
std::set<Point> points_of(const PolygonMesh& mesh, const VertexRange& range)
{
  std::set<Point> result;
  for(auto v : range)
    result.insert(get(CGAL::vertex_point, mesh, v));
  return result;
}

// Every public function on a Surface_mesh with a removed vertex gives what it gives
// after collect_garbage() (the same values at the same positions, up to the rounding
// of a different vertex order); so does a Polyhedron_3 whose vertex ids have the gap
// of the removed vertex. A user's vertex_index_map is honoured, and one with gaps is
// rejected with a message that says why.
void check_removed_elements()
{
  const std::size_t removed = 100;
  Mesh garbage = test_support::load<Mesh>("elephant.off");
  remove_a_vertex(garbage, removed);
  CHECK(garbage.has_garbage() && num_vertices(garbage) == garbage.number_of_vertices() + 1);
  Mesh clean = garbage;
  clean.collect_garbage();
  // What goes through the local heat kernel agrees to its truncation only: the
  // regions it grows, hence what it truncates, follow the vertex order.
  auto close = [&](double error, const std::string& what, double tolerance = 1e-9) {
    CHECK_MESSAGE(error <= tolerance, "removed elements: " << what << " differs after collect_garbage() by "
                                                           << error);
  };

  // NCC, NS, the NCC operator.
  try
  {
    auto ns_garbage = garbage.add_property_map<Vertex, double>("v:ns_test", 0.).first;
    auto ns_clean = clean.add_property_map<Vertex, double>("v:ns_test", 0.).first;
    HD::compute_normal_signature(garbage, ns_garbage);
    HD::compute_normal_signature(clean, ns_clean);
    close(largest_difference(by_point(garbage, ns_garbage), by_point(clean, ns_clean)), "compute_normal_signature");

    auto ncc_garbage = garbage.add_property_map<Vertex, K::Vector_3>("v:ncc_test").first;
    HD::compute_normal_controlled_coordinates(garbage, ncc_garbage);
    double worst = 0;
    for(Vertex v : garbage.vertices())
      worst = (std::max)(worst, std::abs(ncc_garbage[v] * ncc_garbage[v] - ns_garbage[v] * ns_garbage[v]));
    close(worst, "compute_normal_controlled_coordinates");

    // N applied to the x coordinates, read back at each vertex's row.
    const HD::Normal_controlled_coordinates<Mesh> ncc(garbage);
    const Eigen::SparseMatrix<double> N = HD::normal_controlled_coordinates_matrix(garbage);
    CHECK(std::size_t(N.rows()) == garbage.number_of_vertices());
    Eigen::VectorXd x(N.cols());
    for(Vertex v : garbage.vertices())
      x[Eigen::Index(ncc.vertex_index(v))] = garbage.point(v).x();
    const Eigen::VectorXd y = N * x;
    const HD::Normal_controlled_coordinates<Mesh> ncc_clean(clean);
    const Eigen::SparseMatrix<double> N_clean = HD::normal_controlled_coordinates_matrix(clean);
    Eigen::VectorXd x_clean(N_clean.cols());
    for(Vertex v : clean.vertices())
      x_clean[Eigen::Index(ncc_clean.vertex_index(v))] = clean.point(v).x();
    const Eigen::VectorXd y_clean = N_clean * x_clean;
    std::map<Vertex, double> ny, ny_clean;
    for(Vertex v : garbage.vertices())
      ny[v] = y[Eigen::Index(ncc.vertex_index(v))];
    for(Vertex v : clean.vertices())
      ny_clean[v] = y_clean[Eigen::Index(ncc_clean.vertex_index(v))];
    close(largest_difference(by_point(garbage, boost::make_assoc_property_map(ny)),
                             by_point(clean, boost::make_assoc_property_map(ny_clean))),
          "normal_controlled_coordinates_matrix");

    // The heat kernel (spectral: its diagonal at t = 1) and the diffusion.
    const Kernel kernel(garbage, HD::parameters::number_of_eigenpairs(20));
    const Kernel kernel_clean(clean, HD::parameters::number_of_eigenpairs(20));
    std::map<Vertex, double> k_garbage, k_clean;
    for(Vertex v : garbage.vertices())
      k_garbage[v] = kernel.heat_kernel_signature(v, 1.);
    for(Vertex v : clean.vertices())
      k_clean[v] = kernel_clean.heat_kernel_signature(v, 1.);
    // the eigen solver converges to 1e-10 from a start that depends on the order
    CHECK_MESSAGE(largest_difference(by_point(garbage, boost::make_assoc_property_map(k_garbage)),
                                     by_point(clean, boost::make_assoc_property_map(k_clean))) <= 1e-6,
                  "removed elements: Edge_weighted_heat_kernel differs after collect_garbage()");

    auto out_garbage = garbage.add_property_map<Vertex, double>("v:out_test", 0.).first;
    auto out_clean = clean.add_property_map<Vertex, double>("v:out_test", 0.).first;
    HD::anisotropic_heat_diffusion(garbage, ns_garbage, out_garbage, HD::parameters::number_of_steps(3));
    HD::anisotropic_heat_diffusion(clean, ns_clean, out_clean, HD::parameters::number_of_steps(3));
    close(largest_difference(by_point(garbage, out_garbage), by_point(clean, out_clean)), "anisotropic_heat_diffusion", 1e-6);

    // Features, without and with diffusion.
    for(std::size_t k : {std::size_t(0), std::size_t(2)})
    {
      std::vector<Vertex> convex, concave, convex_clean, concave_clean;
      HD::detect_multiscale_features(garbage, ns_garbage, std::back_inserter(convex), std::back_inserter(concave),
                                     HD::parameters::number_of_steps(k));
      HD::detect_multiscale_features(clean, ns_clean, std::back_inserter(convex_clean),
                                     std::back_inserter(concave_clean), HD::parameters::number_of_steps(k));
      CHECK_MESSAGE(!convex.empty() && points_of(garbage, convex) == points_of(clean, convex_clean) &&
                        points_of(garbage, concave) == points_of(clean, concave_clean),
                    "removed elements: detect_multiscale_features (k = " << k << ") differs after collect_garbage()");
    }

    // Decomposition, synthesis.
    std::vector<decltype(out_garbage)> bands_garbage, bands_clean;
    for(int j = 0; j < 2; ++j)
    {
      bands_garbage.push_back(garbage.add_property_map<Vertex, double>("v:band_test" + std::to_string(j), 0.).first);
      bands_clean.push_back(clean.add_property_map<Vertex, double>("v:band_test" + std::to_string(j), 0.).first);
    }
    HD::decompose_field(garbage, ns_garbage, bands_garbage, out_garbage);
    HD::decompose_field(clean, ns_clean, bands_clean, out_clean);
    close(largest_difference(by_point(garbage, bands_garbage[1]), by_point(clean, bands_clean[1])), "decompose_field", 1e-6);
    const std::vector<double> weights = {2., 1.};
    HD::synthesize_field(garbage, bands_garbage, out_garbage, weights, out_garbage);
    HD::synthesize_field(clean, bands_clean, out_clean, weights, out_clean);
    close(largest_difference(by_point(garbage, out_garbage), by_point(clean, out_clean)), "synthesize_field", 1e-6);

    // What moves the vertices: compared by where each vertex goes.
    auto moved = [&](const std::string& what, auto&& edit) {
      Mesh a = garbage, b = clean;
      edit(a);
      edit(b);
      CHECK_MESSAGE(largest_difference(points_by_point(garbage, a), points_by_point(clean, b)) <= 1e-6,
                    "removed elements: " << what << " differs after collect_garbage()");
    };
    moved("reconstruct_from_normal_signature", [&](Mesh& m) {
      std::map<Vertex, double> ns;
      const HD::Normal_controlled_coordinates<Mesh> own(m);
      for(Vertex v : m.vertices())
        ns[v] = 1.5 * own.normal_signature(v);
      HD::reconstruct_from_normal_signature(m, boost::make_assoc_property_map(ns));
    });
    moved("filter_shape", [](Mesh& m) { HD::filter_shape(m, std::vector<double>{1., 2.}); });
    moved("denoise_mesh", [](Mesh& m) { HD::denoise_mesh(m); });
  }
  catch(const std::exception& e)
  {
    CHECK_MESSAGE(false, "removed elements: unexpected exception: " << e.what());
  }

  // The user's numbering is honoured (here the reverse of vertices(garbage)); one with
  // the gaps of the removed vertex is rejected, and says why.
  {
    std::map<Vertex, std::size_t> reverse;
    std::size_t k = garbage.number_of_vertices();
    for(Vertex v : garbage.vertices())
      reverse[v] = --k;
    const HD::Normal_controlled_coordinates<Mesh> ncc(
        garbage, CGAL::parameters::vertex_index_map(boost::make_assoc_property_map(reverse)));
    bool honoured = true;
    for(Vertex v : garbage.vertices())
      honoured = honoured && ncc.vertex_index(v) == reverse[v];
    CHECK_MESSAGE(honoured, "removed elements: the user's vertex_index_map is not honoured");
    CHECK_THROWS(HD::Normal_controlled_coordinates<Mesh>(
                     garbage, CGAL::parameters::vertex_index_map(get(CGAL::vertex_index, garbage))),
                 std::invalid_argument, "collect_garbage()");
  }

  // Polyhedron_3 with vertex ids numbered before the removal: the ids have a gap.
  {
    typedef CGAL::Polyhedron_3<K, CGAL::Polyhedron_items_with_id_3> Polyhedron;
    Polyhedron polyhedron = test_support::load<Polyhedron>("elephant.off");
    std::size_t id = 0;
    for(auto v : vertices(polyhedron))
      v->id() = id++;
    remove_a_vertex(polyhedron, removed);
    std::map<Polyhedron::Vertex_handle, double> ns, out;
    try
    {
      HD::compute_normal_signature(polyhedron, boost::make_assoc_property_map(ns));
      auto ns_clean = clean.property_map<Vertex, double>("v:ns_test").first;
      close(largest_difference(by_point(polyhedron, boost::make_assoc_property_map(ns)), by_point(clean, ns_clean)),
            "compute_normal_signature on a Polyhedron_3");
      HD::anisotropic_heat_diffusion(polyhedron, boost::make_assoc_property_map(ns),
                                     boost::make_assoc_property_map(out), HD::parameters::number_of_steps(3));
      auto out_clean = clean.add_property_map<Vertex, double>("v:out_polyhedron", 0.).first;
      HD::anisotropic_heat_diffusion(clean, ns_clean, out_clean, HD::parameters::number_of_steps(3));
      close(largest_difference(by_point(polyhedron, boost::make_assoc_property_map(out)), by_point(clean, out_clean)),
            "anisotropic_heat_diffusion on a Polyhedron_3", 1e-6);
    }
    catch(const std::exception& e)
    {
      CHECK_MESSAGE(false, "removed elements, Polyhedron_3: unexpected exception: " << e.what());
    }
  }
}

// The tool's fast PLY output of fields writes the bytes CGAL::IO::write_PLY writes for
// the mesh with the fields and their colours as property maps: on a real mesh, with
// and without fields, and on a mesh with a removed vertex (the file numbers the
// vertices left); it declines, writing nothing, on a mesh with other properties.
void check_fast_ply_output()
{
  namespace fo = heat_diffusion_cli::fast_output;
  typedef std::vector<std::pair<std::string, std::vector<double> > > Fields;
  auto color_of_first = [](const Fields& fields) {
    return [&fields](std::size_t v) {
      const double x = fields.front().second[v];
      return CGAL::IO::Color((unsigned char)(int(std::abs(x) * 1000) % 256), 7, (unsigned char)(x < 0 ? 200 : 30));
    };
  };
  auto with_cgal = [&](const Mesh& input, const Fields& fields) {
    Mesh mesh = input;
    for(const auto& field : fields)
    {
      auto map = mesh.add_property_map<Vertex, double>("v:" + field.first, 0.).first;
      for(Vertex v : mesh.vertices())
        map[v] = field.second[v.idx()];
    }
    if(!fields.empty())
    {
      auto colors = mesh.add_property_map<Vertex, CGAL::IO::Color>("v:color").first;
      for(Vertex v : mesh.vertices())
        colors[v] = color_of_first(fields)(v.idx());
    }
    std::ostringstream os(std::ios::binary);
    CGAL::IO::set_binary_mode(os);
    CGAL::IO::write_PLY(os, mesh, "a comment", CGAL::parameters::use_binary_mode(true));
    return os.str();
  };
  auto fast = [&](const Mesh& mesh, const Fields& fields, bool& written) {
    std::ostringstream os(std::ios::binary);
    CGAL::IO::set_binary_mode(os);
    written = fo::write_fields_ply(os, mesh, "a comment", fields, color_of_first(fields));
    return os.str();
  };
  auto fields_of = [](const Mesh& mesh) {
    Fields fields{{"first", {}}, {"second", {}}};
    for(Vertex v : vertices(mesh))  // (sized num_vertices(): a removed vertex keeps its slot)
    {
      fields[0].second.resize(mesh.num_vertices());
      fields[1].second.resize(mesh.num_vertices());
      fields[0].second[v.idx()] = std::sin(3 * mesh.point(v).x()) - 0.25;
      fields[1].second[v.idx()] = double(v.idx()) / 7.;
    }
    return fields;
  };
  Mesh garbage = test_support::load<Mesh>("elephant.off");
  remove_a_vertex(garbage, 100);
  for(const auto& named : {std::make_pair(std::string("fandisk.off"), test_support::load<Mesh>("fandisk.off")),
                           std::make_pair(std::string("elephant.off with a removed vertex"), garbage)})
  {
    const Mesh& mesh = named.second;
    for(const Fields& fields : {fields_of(mesh), Fields()})
    {
      bool written = false;
      const std::string bytes = fast(mesh, fields, written);
      CHECK_MESSAGE(written, named.first << ": the fast PLY output declined");
      CHECK_MESSAGE(bytes == with_cgal(mesh, fields),
                    named.first << " with " << fields.size() << " fields: the fast PLY output differs from CGAL's");
    }
  }
  CHECK(garbage.has_garbage());
  Mesh with_normals = test_support::load<Mesh>("fandisk.off");
  with_normals.add_property_map<Vertex, CGAL::Epick::Vector_3>("v:normal");
  bool written = true;
  CHECK_MESSAGE(fast(with_normals, fields_of(with_normals), written).empty() && !written,
                "the fast PLY output did not decline a mesh with another property");
}

// Meshes of 100000 vertices or more are numbered along a Hilbert curve inside the
// package. A message about a field value still names the vertex by its rank in
// vertices(tm), the row of the user's arrays; it used to give the Hilbert index alone,
// which names another vertex. Fandisk subdivided twice: 103,570 vertices.
void check_vertex_names_on_large_meshes()
{
  Mesh mesh = test_support::load<Mesh>("fandisk.off");
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(2));
  CHECK(mesh.number_of_vertices() >= 100000);
  const Diffusion diffusion(mesh);
  const Vertex bad(12345);  // the mesh has no removed vertices: its rank is its index
  const std::size_t index = diffusion.vertex_index(bad);
  CHECK_MESSAGE(index != 12345, "the vertices are not renumbered: the check below cannot fail");
  const std::string name = "vertex 12345 (index " + std::to_string(index) + " of vertex_index())";

  auto field = mesh.add_property_map<Vertex, double>("v:hostile_field", 1.).first;
  auto out = mesh.add_property_map<Vertex, double>("v:hostile_out", 0.).first;
  field[bad] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS(diffusion.diffuse(field, out, 1), std::invalid_argument,
               "Anisotropic_heat_diffusion: the field value at " + name + " is nan, not a finite number");
  CHECK_THROWS(HD::detect_multiscale_features(diffusion, field, {0, 1}), std::invalid_argument,
               "detect_multiscale_features: the field value at " + name + " is nan");
  std::vector<decltype(out)> bands{mesh.add_property_map<Vertex, double>("v:hostile_band", 0.).first};
  CHECK_THROWS(HD::decompose_field(diffusion, field, bands, out), std::invalid_argument,
               "decompose_field: the field value at " + name + " is nan");
  // The vector interface: rows in the order of vertex_index().
  Eigen::VectorXd values = Eigen::VectorXd::Ones(Eigen::Index(diffusion.number_of_vertices()));
  values[Eigen::Index(index)] = std::numeric_limits<double>::infinity();
  CHECK_THROWS(diffusion.diffuse(values, 1), std::invalid_argument,
               "Anisotropic_heat_diffusion: the field value at " + name + " is inf");
  // Where the two numbers agree, the message gives one.
  const Mesh fandisk = test_support::load<Mesh>("fandisk.off");
  const Diffusion small(fandisk);
  Eigen::VectorXd small_values = Eigen::VectorXd::Ones(Eigen::Index(small.number_of_vertices()));
  small_values[7] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS(small.diffuse(small_values, 1), std::invalid_argument, "the field value at vertex 7 is nan");
}

void run()
{
  try
  {
    check_corpus();
    fast_reader::check_meshes();
    fast_reader::check_hostile();
    check_polygon_soups();
    check_extreme_scales();
    check_built_meshes();
    check_parameters();
    check_iterative_solver_on_components();
    check_removed_elements();
    check_fast_ply_output();
    check_vertex_names_on_large_meshes();
  }
  catch(const std::exception& e)
  {
    std::cerr << "unexpected exception: " << e.what() << std::endl;
    test_support::check(false, "no unexpected exception", __FILE__, __LINE__);
  }
}

const test_support::Suite_registration registration("test_hostile_input", &run);

} // namespace test_hostile_input
