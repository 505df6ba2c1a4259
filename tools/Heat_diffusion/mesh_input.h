// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The tool's mesh type and the reading of its input mesh.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_MESH_INPUT_H
#define CGAL_HEAT_DIFFUSION_TOOLS_MESH_INPUT_H

#include "cli_errors.h"
#include "fast_mesh_input.h"
#include "mesh_input_checks.h"
#include "mesh_repair.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace heat_diffusion_cli {

namespace fs = std::filesystem;

// The mesh type of the tool.
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

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

// What CGAL's readers print on std::cerr while this object lives, kept instead of
// printed: the tool says one thing per failure, and puts what they knew (a line
// number) into its own message.
class Captured_error_stream
{
public:
  Captured_error_stream() : previous_(std::cerr.rdbuf(text_.rdbuf())) {}
  ~Captured_error_stream() { std::cerr.rdbuf(previous_); }
  Captured_error_stream(const Captured_error_stream&) = delete;
  Captured_error_stream& operator=(const Captured_error_stream&) = delete;

  // What was printed, on one line, in parentheses after a space; empty if nothing.
  std::string note() const
  {
    std::string text = text_.str();
    std::replace(text.begin(), text.end(), '\n', ' ');
    while(!text.empty() && text.back() == ' ')
      text.pop_back();
    return text.empty() ? text : " (CGAL's reader: " + text + ")";
  }

private:
  std::ostringstream text_;
  std::streambuf* previous_;
};

// The lower-case extension of `path`, with its dot.
inline std::string lower_case_extension(const std::string& path)
{
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char ch) { return char(std::tolower(ch)); });
  return extension;
}

// Reads any format CGAL::IO::read_polygon_soup reads (OFF, OBJ, PLY, STL, GOCAD, ...)
// to its points and polygons, with what that function leaves unchecked checked first:
// the counts of OFF and PLY files, and the face indices of every format. Returns false
// where CGAL's reader fails, with what it printed in `note`; throws Input_error (the
// message starts with `path`) on a hostile file.
template <typename Point>
bool read_checked_polygon_soup(const std::string& path, std::vector<Point>& points,
                               std::vector<std::vector<std::size_t> >& polygons, std::string& note)
{
  const std::string extension = lower_case_extension(path);
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
    bool read = false;
    {
      // Verbose for PLY, whose reader then says which line it could not read (kept for the
      // message); the others print progress on std::cout, or their errors anyway.
      const Captured_error_stream errors;
      read = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(extension == ".ply"));
      note = errors.note();
    }
    if(!read)
      return false;
    check_face_indices(polygons, points.size(), extension == ".obj");
    return true;
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

// The mesh CGAL::IO::read_polygon_mesh builds from the soup of read_checked_polygon_soup(),
// without repair (a soup that is not a manifold mesh is rejected: false).
template <typename Mesh>
bool read_checked_polygon_mesh(const std::string& path, Mesh& mesh, std::string& note)
{
  std::vector<typename Mesh::Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!read_checked_polygon_soup(path, points, polygons, note))
    return false;
  try
  {
    return fast_input::build_mesh(soup_of(points, polygons), mesh);
  }
  catch(const Input_error& e)
  {
    throw Input_error(path + ": " + e.what());
  }
  catch(const std::exception& e)
  {
    throw Input_error(path + ": cannot read a polygon mesh (" + e.what() + ")");
  }
}

template <typename Mesh>
bool read_checked_polygon_mesh(const std::string& path, Mesh& mesh)
{
  std::string note;
  return read_checked_polygon_mesh(path, mesh, note);
}

// The soup of a file: the fast parsers' where they read it, else CGAL's readers'.
template <typename Point>
bool read_any_polygon_soup(const std::string& path, std::vector<Point>& points,
                           std::vector<std::vector<std::size_t> >& polygons, std::string& note)
{
  fast_input::Soup soup;
  bool fast = false;
  try
  {
    fast = fast_input::read_soup(path, soup);
  }
  catch(const std::bad_alloc&)  // CGAL's reader reports it as before
  {
  }
  if(!fast)
    return read_checked_polygon_soup(path, points, polygons, note);
  points.clear();
  polygons.clear();
  for(std::size_t i = 0; i < soup.number_of_vertices(); ++i)
    points.emplace_back(soup.coordinates[3 * i], soup.coordinates[3 * i + 1], soup.coordinates[3 * i + 2]);
  for(std::size_t f = 0; f < soup.number_of_faces(); ++f)
    polygons.emplace_back(soup.indices.begin() + std::ptrdiff_t(soup.starts[f]),
                          soup.indices.begin() + std::ptrdiff_t(soup.starts[f + 1]));
  return true;
}

// Throws the Input_error of a file that is read but holds no face: a point set (the
// tool's subcommands need a mesh), or nothing.
[[noreturn]] inline void throw_no_faces(const std::string& path, std::size_t points)
{
  if(points > 0)
    throw Input_error(path + ": this file holds points and no faces (" + std::to_string(points) +
                      " points): the subcommands need a triangle mesh");
  throw Input_error(path + ": the mesh has no faces");
}

// The points of a file that CGAL::IO::read_points() reads (XYZ, PWN, PLY, OFF without
// faces, LAS), for the message about a point set; 0 where it reads none.
inline std::size_t number_of_points_in(const std::string& path)
{
  const std::string extension = lower_case_extension(path);
  if(extension != ".xyz" && extension != ".pwn")
    return 0;
  std::vector<Kernel::Point_3> points;
  const Captured_error_stream errors;  // (its messages: this file is refused for another reason)
  try
  {
    if(!CGAL::IO::read_points(path, std::back_inserter(points)))
      return 0;
  }
  catch(const std::exception&)
  {
    return 0;
  }
  return points.size();
}

// Reads a mesh file as read_checked_polygon_mesh() does, and triangulates polygon
// faces. OFF, PLY and OBJ files usually take the fast reader, which reads the same
// mesh; it declines every file it does not read, and those go to
// read_checked_polygon_mesh(). Returns the number of faces that were triangulated.
// With `repair`, a file that is no mesh the package can process (a polygon soup that
// is not a manifold mesh, isolated or non-manifold vertices, faces of zero area) is read
// as a soup and repaired (repair_polygon_soup_to_mesh()): `repair` then says what
// changed, and how the vertices relate to the file's; it is left empty where the file's
// mesh needs no repair.
template <typename Mesh>
std::size_t read_triangle_mesh(const std::string& path, Mesh& mesh, Repair_report* repair = nullptr)
{
  std::error_code ec;
  if(!fs::is_regular_file(path, ec))
    throw Input_error(path + ": no such file");
  std::string note;
  const bool read = fast_input::read_mesh_fast(path, mesh) || read_checked_polygon_mesh(path, mesh, note);
  std::size_t polygons = 0;
  if(read && faces(mesh).size() > 0)
  {
    for(auto f : faces(mesh))
      polygons += CGAL::is_triangle(halfedge(f, mesh), mesh) ? 0 : 1;
    const bool triangulated = polygons == 0 || triangulate_polygon_faces(mesh);
    if(repair == nullptr || (triangulated && !needs_repair(mesh)))
    {
      if(!triangulated)
        throw Input_error(path + ": cannot triangulate its polygon faces");
      return polygons;
    }
  }
  else if(read)
    throw_no_faces(path, mesh.number_of_vertices());
  else if(repair == nullptr)
  {
    if(const std::size_t points = number_of_points_in(path); points > 0)
      throw_no_faces(path, points);
    throw Input_error(path + ": cannot read a polygon mesh (unknown format, unreadable or broken file, "
                             "or a polygon soup that is not a manifold mesh: the tool repairs such soups "
                             "unless --no-repair is given)" + note);
  }

  // The repair, from the file's polygon soup.
  mesh.clear();
  std::vector<typename Mesh::Point> points;
  std::vector<std::vector<std::size_t> > soup;
  if(!read_any_polygon_soup(path, points, soup, note))
  {
    if(const std::size_t count = number_of_points_in(path); count > 0)
      throw_no_faces(path, count);
    throw Input_error(path + ": cannot read a polygon mesh (unknown format, unreadable or broken file)" + note);
  }
  if(soup.empty())
    throw_no_faces(path, points.size());
  try
  {
    *repair = repair_polygon_soup_to_mesh(std::move(points), std::move(soup), mesh);
  }
  catch(const Input_error& e)
  {
    throw Input_error(path + ": cannot be repaired into a mesh: " + e.what());
  }
  catch(const std::exception& e)  // CGAL's assertions, std::bad_alloc
  {
    throw Input_error(path + ": cannot be repaired into a mesh (" + e.what() + ")");
  }
  return repair->polygons_triangulated;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_MESH_INPUT_H
