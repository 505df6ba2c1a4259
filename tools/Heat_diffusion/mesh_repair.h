// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The repair of an input that is not a mesh the package can process (STL exports,
// polygon soups, scans with non-manifold vertices), with CGAL's own functions, for the
// front ends: the tool repairs by default and reports what changed, the Python module's
// repair() returns it. The library itself never repairs: it refuses with a message that
// names the repair.

#ifndef CGAL_HEAT_DIFFUSION_TOOLS_MESH_REPAIR_H
#define CGAL_HEAT_DIFFUSION_TOOLS_MESH_REPAIR_H

#include "cli_errors.h"

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace heat_diffusion_cli {

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
template <typename Mesh>
bool triangulate_polygon_faces(Mesh& mesh)
{
  typedef typename Mesh::Point Point;
  double largest = 0;
  for(auto v : vertices(mesh))
  {
    const Point& p = mesh.point(v);
    largest = (std::max)({largest, std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
  }
  if(!std::isfinite(largest))
    return false;  // (not scaled either: the package rejects such a mesh anyway)
  int exponent = 0;
  std::frexp(largest, &exponent);
  Mesh scaled = mesh;
  for(auto v : vertices(scaled))
  {
    const Point& p = mesh.point(v);
    scaled.point(v) = Point(std::ldexp(p.x(), -exponent), std::ldexp(p.y(), -exponent), std::ldexp(p.z(), -exponent));
  }
  if(!CGAL::Polygon_mesh_processing::triangulate_faces(scaled, CGAL::parameters::use_delaunay_triangulation(false)) ||
     !CGAL::is_valid_polygon_mesh(scaled))
    return false;
  for(auto v : vertices(scaled))
    scaled.point(v) = mesh.point(v);
  mesh = std::move(scaled);
  return true;
}

// What a repair changed, in the terms of CGAL's repair functions; `origin` maps the
// result back to the input.
struct Repair_report
{
  std::size_t points_merged = 0;             // points at the position of an earlier point, merged into it
  std::size_t polygons_removed = 0;          // polygons with fewer than 3 distinct points, and duplicates
  std::size_t faces_reoriented = 0;          // polygons reversed to agree with their neighbours
  std::size_t vertices_split = 0;            // copies made where one point carried several fans
  std::size_t isolated_vertices_removed = 0;  // points on no polygon
  std::size_t degenerate_faces_removed = 0;   // faces of zero area, removed with their shortest edges
  std::size_t polygons_triangulated = 0;
  // For each vertex of the result (in the order of vertices(mesh)), the index of the
  // input point it comes from: the first of the input points at its position.
  std::vector<std::size_t> origin;

  bool changed() const
  {
    return points_merged + polygons_removed + faces_reoriented + vertices_split + isolated_vertices_removed +
               degenerate_faces_removed + polygons_triangulated >
           0;
  }
  // Whether vertex i of the result is input point i for every i.
  bool keeps_vertices() const
  {
    for(std::size_t i = 0; i < origin.size(); ++i)
      if(origin[i] != i)
        return false;
    return true;
  }
};

// Whether a triangle mesh needs a repair before the package can process it: it has an
// isolated vertex, a vertex whose faces form several fans, or a face of zero area
// (decided with exact predicates, as the package decides it). Linear in the size of the
// mesh: a vertex is non-manifold when the circulation around it crosses the border more
// than once (its fans are linked through their border halfedges), or when it misses some
// of the halfedges that point to it (Polygon_mesh_processing::is_non_manifold_vertex()
// asks the whole mesh, for each vertex). A mesh with a non-finite coordinate is left to
// the package, which refuses it (the exact predicates cannot take it).
template <typename Mesh>
bool needs_repair(const Mesh& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  for(auto v : vertices(mesh))
  {
    const auto& p = mesh.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      return false;
  }
  std::vector<std::size_t> incoming(num_vertices(mesh), 0);
  for(auto h : halfedges(mesh))
    ++incoming[std::size_t(target(h, mesh))];
  for(auto v : vertices(mesh))
  {
    if(halfedge(v, mesh) == boost::graph_traits<Mesh>::null_halfedge())
      return true;
    std::size_t around = 0, borders = 0;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, mesh), mesh))
    {
      ++around;
      borders += is_border(h, mesh) ? 1 : 0;
    }
    if(borders > 1 || around != incoming[std::size_t(v)])
      return true;
  }
  for(auto f : faces(mesh))
    if(PMP::is_degenerate_triangle_face(f, mesh))
      return true;
  return false;
}

namespace internal {

typedef std::map<std::array<double, 3>, std::size_t> Point_numbering;

template <typename Point>
std::size_t number_of(const Point& p, Point_numbering& numbering)
{
  return numbering.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, numbering.size()).first->second;
}

// The points of a polygon as numbers of their positions, rotated to start at the
// smallest: two polygons have the same key when they have the same points in the same
// cyclic order, whichever copies of a point they use.
template <typename Point>
std::vector<std::size_t> cyclic_key(const std::vector<Point>& polygon, Point_numbering& numbering)
{
  std::vector<std::size_t> key;
  for(const Point& p : polygon)
    key.push_back(number_of(p, numbering));
  std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
  return key;
}

} // namespace internal

// The mesh of a polygon soup that CGAL's repair makes processable, in this order:
// Polygon_mesh_processing::repair_polygon_soup() (duplicate points merged, degenerate and
// duplicate polygons and isolated points removed), orient_polygon_soup() (consistent
// orientation; it copies the points where a manifold orientation needs it),
// polygon_soup_to_polygon_mesh(), the polygons triangulated, duplicate_non_manifold_vertices(),
// remove_isolated_vertices() and remove_degenerate_faces(). Throws Input_error, saying why,
// where no repair makes a mesh of it.
template <typename Mesh>
Repair_report repair_polygon_soup_to_mesh(std::vector<typename Mesh::Point> points,
                                          std::vector<std::vector<std::size_t> > polygons, Mesh& mesh)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef typename Mesh::Point Point;
  Repair_report report;
  const std::vector<Point> input_points = points;
  const std::size_t input_polygons = polygons.size();
  for(std::size_t i = 0; i < points.size(); ++i)  // (CGAL's exact predicates cannot take them)
    if(!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()) || !std::isfinite(points[i].z()))
      throw Input_error("vertex " + std::to_string(i) + " has a non-finite coordinate");

  // The first input point at each position: where every vertex of the result comes from.
  std::map<std::array<double, 3>, std::size_t> first_at;
  for(std::size_t i = 0; i < input_points.size(); ++i)
    first_at.emplace(std::array<double, 3>{input_points[i].x(), input_points[i].y(), input_points[i].z()}, i);
  report.points_merged = input_points.size() - first_at.size();

  PMP::repair_polygon_soup(points, polygons);
  report.polygons_removed = input_polygons > polygons.size() ? input_polygons - polygons.size() : 0;
  report.isolated_vertices_removed = first_at.size() - points.size();
  if(polygons.empty())
    throw Input_error("no face is left once the degenerate and duplicate polygons are removed");

  // Orientation: a polygon that comes out with its points in another cyclic order (the
  // reverse) was reoriented.
  std::vector<std::vector<Point> > before;
  for(const auto& polygon : polygons)
  {
    before.emplace_back();
    for(std::size_t i : polygon)
      before.back().push_back(points[i]);
  }
  internal::Point_numbering numbering;
  auto count_reoriented = [&](auto&& polygon_points) {
    std::size_t count = 0;
    for(std::size_t f = 0; f < before.size(); ++f)
      if(internal::cyclic_key(polygon_points(f), numbering) != internal::cyclic_key(before[f], numbering))
        ++count;
    return count;
  };
  const std::size_t points_before = points.size();
  PMP::orient_polygon_soup(points, polygons);
  report.vertices_split = points.size() - points_before;
  report.faces_reoriented = count_reoriented([&](std::size_t f) {
    std::vector<Point> polygon;
    for(std::size_t i : polygons[f])
      polygon.push_back(points[i]);
    return polygon;
  });
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw Input_error("its polygons cannot be made into a mesh, even oriented and with the points that carry "
                      "several fans copied");
  mesh.clear();
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);

  for(auto f : faces(mesh))
    report.polygons_triangulated += CGAL::is_triangle(halfedge(f, mesh), mesh) ? 0 : 1;
  if(report.polygons_triangulated > 0 && !triangulate_polygon_faces(mesh))
    throw Input_error("cannot triangulate its polygon faces (CGAL's hole filling fails on one of them)");
  // orient_polygon_soup() makes the orientation consistent, not outward: where it
  // reoriented faces, each closed component is turned outward (Polygon_mesh_processing::orient()),
  // as a file's own consistent orientation is left as it is. The faces of the mesh are the
  // polygons, in their order, unless some were triangulated (then the count is the soup's).
  if(report.faces_reoriented > 0 && CGAL::is_closed(mesh))
  {
    PMP::orient(mesh);
    if(report.polygons_triangulated == 0)
      report.faces_reoriented = count_reoriented([&](std::size_t f) {
        std::vector<Point> polygon;
        for(auto v : vertices_around_face(halfedge(typename Mesh::Face_index(typename Mesh::size_type(f)), mesh), mesh))
          polygon.push_back(mesh.point(v));
        return polygon;
      });
  }

  report.vertices_split += PMP::duplicate_non_manifold_vertices(mesh);
  report.isolated_vertices_removed += PMP::remove_isolated_vertices(mesh);
  const std::size_t faces_before = faces(mesh).size();
  PMP::remove_degenerate_faces(mesh);
  mesh.collect_garbage();
  report.degenerate_faces_removed = faces_before - faces(mesh).size();
  if(faces(mesh).size() == 0)
    throw Input_error("no face is left once the faces of zero area are removed");

  for(auto v : vertices(mesh))
  {
    const Point& p = mesh.point(v);
    const auto found = first_at.find(std::array<double, 3>{p.x(), p.y(), p.z()});
    if(found == first_at.end())  // (CGAL's repairs move no point: they merge, copy and remove)
      throw Input_error("the repair made a vertex at " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " +
                        std::to_string(p.z()) + ", which is no point of the input");
    report.origin.push_back(found->second);
  }
  return report;
}

// A one-line account of what a repair changed, "3 duplicate points merged, 1 vertex
// split", or empty if nothing did.
inline std::string repair_summary(const Repair_report& r)
{
  std::string text;
  auto add = [&](std::size_t count, const char* one, const char* many) {
    if(count > 0)
      text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + (count == 1 ? one : many);
  };
  add(r.points_merged, "duplicate point merged", "duplicate points merged");
  add(r.polygons_removed, "degenerate or duplicate polygon removed", "degenerate or duplicate polygons removed");
  add(r.faces_reoriented, "face reoriented", "faces reoriented");
  add(r.vertices_split, "vertex split (non-manifold)", "vertices split (non-manifold)");
  add(r.isolated_vertices_removed, "isolated vertex removed", "isolated vertices removed");
  add(r.degenerate_faces_removed, "face of zero area removed", "faces of zero area removed");
  add(r.polygons_triangulated, "polygon triangulated", "polygons triangulated");
  return text;
}

} // namespace heat_diffusion_cli

#endif // CGAL_HEAT_DIFFUSION_TOOLS_MESH_REPAIR_H
