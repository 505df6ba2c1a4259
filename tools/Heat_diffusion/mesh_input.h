// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's mesh type and the reading of its input mesh.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_MESH_INPUT_H
#define CGAL_HEAT_DIFFUSION_TOOLS_MESH_INPUT_H

#include "cli_errors.h"
#include "fast_mesh_input.h"
#include "mesh_input_checks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace heat_diffusion_cli {

namespace fs = std::filesystem;

// The mesh type of the tool.
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

// CGAL::Polygon_mesh_processing::triangulate_faces(), made safe on hostile input:
// - It measures face normals and orientations with products of three or four
//   coordinates: beyond about 1e77 they overflow, and the exact fallback of the
//   predicates converts the infinity to a rational, which raises SIGFPE. The faces are
//   triangulated on a copy scaled by a power of two into [-1, 1]: the scaling is exact,
//   so the predicates' signs and the triangles are those of the mesh itself. The copy,
//   which keeps the vertex indices, then takes the original points back.
// - Its default for faces of five or more vertices, a constrained Delaunay
//   triangulation in the plane of the face, reads a null face handle (undefined
//   behaviour) when a non-planar face's projection intersects itself (found by
//   fuzzing). The hole filling it offers instead works in 3D, on any polygon.
// - On a polygon with two vertices at one point, it can leave a broken halfedge
//   structure (a halfedge whose target is no vertex of the mesh: the package then read
//   out of bounds, found by fuzzing). The result is checked as the mesh builder checks
//   a mesh read from a file.
inline bool triangulate_polygon_faces(Mesh& mesh)
{
  double largest = 0;
  for(auto v : vertices(mesh))
  {
    const Kernel::Point_3& p = mesh.point(v);
    largest = (std::max)({largest, std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
  }
  if(!std::isfinite(largest))
    return false;  // (not scaled either: the package rejects such a mesh anyway)
  int exponent = 0;
  std::frexp(largest, &exponent);
  Mesh scaled = mesh;
  for(auto v : vertices(scaled))
  {
    const Kernel::Point_3& p = mesh.point(v);
    scaled.point(v) = Kernel::Point_3(std::ldexp(p.x(), -exponent), std::ldexp(p.y(), -exponent),
                                      std::ldexp(p.z(), -exponent));
  }
  if(!CGAL::Polygon_mesh_processing::triangulate_faces(
         scaled, CGAL::parameters::use_delaunay_triangulation(false)) ||
     !CGAL::is_valid_polygon_mesh(scaled))
    return false;
  for(auto v : vertices(scaled))
    scaled.point(v) = mesh.point(v);
  mesh = std::move(scaled);
  return true;
}

// Throws Input_error when a face of a polygon soup refers to a vertex the soup does
// not have. CGAL's soup readers keep the indices of a file unchecked (a negative PLY
// index wraps to a huge std::size_t), and CGAL's mesh builder indexes its vertex
// array with them: an index out of range read out of bounds and could crash. OBJ
// faces are numbered from 1, as OBJ numbers its elements.
inline void check_face_indices(const std::vector<std::vector<std::size_t> >& polygons, std::size_t number_of_vertices,
                               bool obj)
{
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t index : polygons[f])
    {
      if(index < number_of_vertices)
        continue;
      const std::string face = "face " + std::to_string(obj ? f + 1 : f);
      if(number_of_vertices == 0)
        throw Input_error(face + " has a vertex index, but the file has no vertices");
      if(obj)  // CGAL's reader has already turned 1-based and relative indices into others
        throw Input_error(face + " refers to a vertex the file does not have (it has " +
                          std::to_string(number_of_vertices) +
                          " vertices; OBJ indices count from 1, negative ones back from the last vertex read)");
      throw Input_error(face + " has the vertex index " + std::to_string(static_cast<long long>(index)) +
                        ", not one of 0.." + std::to_string(number_of_vertices - 1));
    }
}

// The soup read by CGAL's readers, as the fast reader's soup.
template <typename Point>
fast_input::Soup soup_of(const std::vector<Point>& points, const std::vector<std::vector<std::size_t> >& polygons)
{
  if(points.size() > std::numeric_limits<std::uint32_t>::max())
    throw Input_error("more than 2^32 - 1 vertices");
  fast_input::Soup soup;
  soup.coordinates.reserve(3 * points.size());
  for(const Point& p : points)
    soup.coordinates.insert(soup.coordinates.end(), {p.x(), p.y(), p.z()});
  for(const std::vector<std::size_t>& polygon : polygons)
  {
    soup.indices.insert(soup.indices.end(), polygon.begin(), polygon.end());
    soup.end_face();
  }
  return soup;
}

// Reads any format CGAL::IO::read_polygon_soup reads (OFF, OBJ, PLY, STL, GOCAD, ...)
// to the mesh CGAL::IO::read_polygon_mesh builds from it, without repair (a soup that
// is not a manifold mesh is rejected), but with what that function leaves unchecked
// checked first: the counts of OFF and PLY files, and the face indices of every
// format. Returns false where CGAL's reader or builder fails; throws Input_error
// (the message starts with `path`) on a hostile file.
template <typename Mesh>
bool read_checked_polygon_mesh(const std::string& path, Mesh& mesh)
{
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  try
  {
    if(extension == ".off" || extension == ".ply")
    {
      std::error_code ec;
      std::ifstream is(path, std::ios::binary);
      if(extension == ".off")
        check_off_stream(is, fs::file_size(path, ec));
      else
        check_ply_stream(is, fs::file_size(path, ec));
    }
    std::vector<typename Mesh::Point> points;
    std::vector<std::vector<std::size_t> > polygons;
    if(!CGAL::IO::read_polygon_soup(path, points, polygons))
      return false;
    check_face_indices(polygons, points.size(), extension == ".obj");
    return fast_input::build_mesh(soup_of(points, polygons), mesh);
  }
  catch(const Input_error& e)
  {
    throw Input_error(path + ": " + e.what());
  }
  catch(const std::exception& e)  // std::bad_alloc, CGAL's assertions
  {
    throw Input_error(path + ": cannot read a polygon mesh (" + e.what() + ")");
  }
}

// Reads a mesh file as read_checked_polygon_mesh() does, and triangulates polygon
// faces. OFF, PLY and OBJ files usually take the fast reader, which reads the same
// mesh; it declines every file it does not read, and those go to
// read_checked_polygon_mesh(). Returns the number of faces that were triangulated.
template <typename Mesh>
std::size_t read_triangle_mesh(const std::string& path, Mesh& mesh)
{
  std::error_code ec;
  if(!fs::is_regular_file(path, ec))
    throw Input_error(path + ": no such file");
  const bool read = fast_input::read_mesh_fast(path, mesh) || read_checked_polygon_mesh(path, mesh);
  if(!read)
    throw Input_error(path + ": cannot read a polygon mesh (unknown format, unreadable or broken file, "
                             "or a polygon soup that is not a manifold mesh)");
  if(is_empty(mesh) || faces(mesh).size() == 0)
    throw Input_error(path + ": the mesh has no faces");
  std::size_t polygons = 0;
  for(auto f : faces(mesh))
    polygons += CGAL::is_triangle(halfedge(f, mesh), mesh) ? 0 : 1;
  if(polygons > 0 && !triangulate_polygon_faces(mesh))
    throw Input_error(path + ": cannot triangulate its polygon faces");
  return polygons;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_MESH_INPUT_H
