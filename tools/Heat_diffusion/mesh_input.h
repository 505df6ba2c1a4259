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
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

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
         scaled, CGAL::parameters::use_delaunay_triangulation(false)))
    return false;
  for(auto v : vertices(scaled))
    scaled.point(v) = mesh.point(v);
  mesh = std::move(scaled);
  return true;
}

// Reads any format CGAL::IO::read_polygon_mesh reads (OFF, OBJ, PLY, STL, VTP, GOCAD,
// ...), repairing the polygon soup on the way, and triangulates polygon faces.
// Returns the number of faces that were triangulated.
template <typename Mesh>
std::size_t read_triangle_mesh(const std::string& path, Mesh& mesh)
{
  std::error_code ec;
  if(!fs::is_regular_file(path, ec))
    throw Input_error(path + ": no such file");
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  const bool fast = fast_input::read_mesh_fast(path, mesh);  // declines what it does not read
  if(!fast && (extension == ".off" || extension == ".ply"))
  {
    std::ifstream is(path, std::ios::binary);
    try
    {
      if(extension == ".off")
        check_off_stream(is, fs::file_size(path, ec));
      else
        check_ply_stream(is, fs::file_size(path, ec));
    }
    catch(const Input_error& e)
    {
      throw Input_error(path + ": " + e.what());
    }
  }
  bool read = fast;
  try
  {
    read = read || CGAL::IO::read_polygon_mesh(path, mesh);
  }
  catch(const std::exception& e)  // std::bad_alloc, CGAL's assertions
  {
    throw Input_error(path + ": cannot read a polygon mesh (" + e.what() + ")");
  }
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
