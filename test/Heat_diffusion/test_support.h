// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shared by the test programs: checks that count failures instead of aborting (so
// one run reports every failing property), CGAL's meshes, and seeded noise.

#ifndef CGAL_HEAT_DIFFUSION_TEST_SUPPORT_H
#define CGAL_HEAT_DIFFUSION_TEST_SUPPORT_H

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>

namespace test_support {

inline int& failures()
{
  static int count = 0;
  return count;
}
inline int& checks()
{
  static int count = 0;
  return count;
}

inline void check(bool condition, const std::string& what, const char* file, int line)
{
  ++checks();
  if(!condition)
  {
    ++failures();
    std::cerr << file << ":" << line << ": FAILED: " << what << std::endl;
  }
}

// The closing line CTest users see; the exit code tells CTest.
inline int report(const std::string& suite)
{
  std::cout << suite << ": " << (checks() - failures()) << " passed, " << failures() << " failed" << std::endl;
  return failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

inline std::string data_path(const std::string& name)
{
  return std::string(CGAL_HEAT_DIFFUSION_DATA_DIR) + "/" + name;
}

template <typename Mesh>
Mesh load(const std::string& name)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(data_path(name), mesh) || num_faces(mesh) == 0)
    throw std::runtime_error("cannot read the test mesh " + data_path(name));
  return mesh;
}

template <typename Mesh>
double mean_edge_length(const Mesh& mesh)
{
  double sum = 0;
  for(auto e : edges(mesh))
    sum += std::sqrt(CGAL::to_double(
        CGAL::squared_distance(mesh.point(source(halfedge(e, mesh), mesh)), mesh.point(target(halfedge(e, mesh), mesh)))));
  return sum / double(num_edges(mesh));
}

// Moves every vertex along its normal by Gaussian noise of standard deviation
// `relative_sigma` times the mean edge length (seeded: the same mesh every run).
template <typename Mesh>
void add_normal_noise(Mesh& mesh, double relative_sigma, unsigned seed)
{
  typedef typename CGAL::Kernel_traits<typename Mesh::Point>::Kernel K;
  const double sigma = relative_sigma * mean_edge_length(mesh);
  auto normals = mesh.template add_property_map<typename Mesh::Vertex_index, typename K::Vector_3>("v:noise_normal").first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
  std::mt19937 generator(seed);
  std::normal_distribution<double> gaussian(0., sigma);
  for(auto v : mesh.vertices())
    mesh.point(v) = mesh.point(v) + gaussian(generator) * normals[v];
  mesh.remove_property_map(normals);
}

} // namespace test_support

#define CHECK(condition) test_support::check((condition), #condition, __FILE__, __LINE__)
#define CHECK_MESSAGE(condition, message)                                                   \
  do                                                                                        \
  {                                                                                         \
    std::ostringstream check_stream__;                                                      \
    check_stream__ << #condition << " -- " << message;                                      \
    test_support::check((condition), check_stream__.str(), __FILE__, __LINE__);            \
  } while(false)

// Checks that `statement` throws `Exception` whose message contains `fragment`.
#define CHECK_THROWS(statement, Exception, fragment)                                         \
  do                                                                                        \
  {                                                                                         \
    bool thrown__ = false;                                                                  \
    std::string message__;                                                                  \
    try                                                                                     \
    {                                                                                       \
      statement;                                                                            \
    }                                                                                       \
    catch(const Exception& e)                                                               \
    {                                                                                       \
      thrown__ = true;                                                                      \
      message__ = e.what();                                                                 \
    }                                                                                       \
    CHECK_MESSAGE(thrown__ && message__.find(fragment) != std::string::npos,                \
                  "expected " #Exception " containing '" << fragment << "', got '" << message__ << "'"); \
  } while(false)

#endif // CGAL_HEAT_DIFFUSION_TEST_SUPPORT_H
