// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A point set as the surface every algorithm of the package runs on: each point's local
// fan, the Delaunay triangulation of its nearest neighbours projected on its tangent
// plane (Sharp and Crane, "A Laplacian for Nonmanifold Triangle Meshes", SGP 2020,
// section 5.7), gives its NCC; the union of the fans gives the neighbour graph and the
// triangles of the heat operators.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_POINT_SET_SURFACE_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_POINT_SET_SURFACE_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/ncc_weights.h>
#include <CGAL/Heat_diffusion/internal/parallel_for.h>
#include <CGAL/Heat_diffusion/internal/point_set_orientation.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The surface of a point set, in the layout of a mesh's Indexed_mesh, so that the heat
// regions, the local kernel, the balancing and the features run on it unchanged:
// - mesh.points: the points, in the normalised frame of Indexed_mesh;
// - mesh.fan: the neighbours of each point in the graph of the union of all fans'
//   triangles, in increasing order (the graph of L and B: for a mesh, the one-ring is
//   that graph; here it is not a fan, and nothing reads it as one);
// - mesh.fan_is_closed: whether the point's own fan is closed (0: a border point);
// - mesh.triangles: the distinct triangles of the fans, corners in increasing order
//   (two fans can hold one triangle with opposite orientations);
// - ncc: the NCC data of each point from its own fan, the weights aligned with mesh.fan
//   (0 at graph neighbours outside the point's fan).
struct Point_set_surface
{
  Indexed_mesh mesh;
  std::vector<double> triangle_weights;  // (number of fans holding the triangle) / 3
  // Each point's own fan, as Indexed_mesh::fan orders one: neighbours clockwise around
  // the normal, consecutive ones spanning the triangle (u_k, i, u_k+1), the last and
  // first one too if the fan is closed.
  std::vector<std::size_t> local_fan_begin, local_fan;
  Ncc_data ncc;
  // Estimated normals: the triangles that two fans list in opposite orientations.
  std::size_t orientation_conflicts = 0;

  std::size_t number_of_points() const { return mesh.number_of_vertices(); }
};

struct Point_set_surface_options
{
  std::size_t k = 0;             // neighbours per point (with a radius: at most k, 0 for no limit)
  double neighbor_radius = 0.;   // in user units; 0: the k nearest neighbours
};

// What went wrong at a point in a parallel loop, reported afterwards for the point of
// smallest index, so that the message does not depend on the threads.
struct Point_problems
{
  explicit Point_problems(std::size_t n) : code(n, 0), other(n, 0) {}
  std::vector<unsigned char> code;  // 0: fine
  std::vector<std::size_t> other;   // a second point, for the messages that name one
  std::size_t first() const
  {
    return std::size_t(std::find_if(code.begin(), code.end(), [](unsigned char c) { return c != 0; }) -
                       code.begin());
  }
};

// CGAL's kd-tree over the points, in the normalised frame, queried point by point (the
// queries only read it: they run in parallel).
class Point_neighbour_search
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Pointer_property_map<K::Point_3>::type Point_of_index;
  typedef CGAL::Search_traits_3<K> Base_traits;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_of_index, Base_traits> Traits;
  typedef CGAL::Distance_adapter<std::size_t, Point_of_index, CGAL::Euclidean_distance<Base_traits> > Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance> Search;
  typedef Search::Tree Tree;

public:
  explicit Point_neighbour_search(const std::vector<Eigen::Vector3d>& points)
    : points_(points), cgal_points_(points.size()), traits_(CGAL::make_property_map(cgal_points_)),
      distance_(CGAL::make_property_map(cgal_points_))
  {
    for(std::size_t i = 0; i < points.size(); ++i)
      cgal_points_[i] = K::Point_3(points[i].x(), points[i].y(), points[i].z());
    std::vector<std::size_t> indices(points.size());
    std::iota(indices.begin(), indices.end(), std::size_t(0));
    tree_.reset(new Tree(indices.begin(), indices.end(), Tree::Splitter(), traits_));
    tree_->build();  // before the parallel queries
  }
  Point_neighbour_search(const Point_neighbour_search&) = delete;
  Point_neighbour_search& operator=(const Point_neighbour_search&) = delete;

  // (squared distance, index) of the points within `radius` of point i (the nearest k of
  // them if k > 0), or else of its k nearest, nearest first, point i among them.
  std::vector<std::pair<double, std::size_t> > query(std::size_t i, std::size_t k, double radius) const
  {
    std::vector<std::pair<double, std::size_t> > found;
    if(radius > 0)
    {
      const CGAL::Fuzzy_sphere<Traits> sphere(i, radius, 0., traits_);
      // (the kd-tree assigns its output iterator, which a lambda's is not)
      const std::function<void(std::size_t)> add = [&](std::size_t j) {
        found.emplace_back((points_[j] - points_[i]).squaredNorm(), j);
      };
      tree_->search(boost::make_function_output_iterator(add), sphere);
      std::sort(found.begin(), found.end());
      if(k > 0 && found.size() > k)
        found.resize(k);
    }
    else
    {
      const Search search(*tree_, cgal_points_[i], unsigned(k), 0., true, distance_);
      for(const auto& result : search)
        found.emplace_back((points_[result.first] - points_[i]).squaredNorm(), result.first);
      std::sort(found.begin(), found.end());
    }
    return found;
  }

private:
  const std::vector<Eigen::Vector3d>& points_;
  std::vector<K::Point_3> cgal_points_;
  Traits traits_;
  Distance distance_;
  std::unique_ptr<Tree> tree_;
};

// The neighbours of every point (without the point itself), nearest first: the k nearest,
// or those within the radius (nearest k of them if k > 0).
inline std::vector<std::vector<std::size_t> > find_neighbours(const Point_neighbour_search& search,
                                                              std::size_t n, std::size_t k, double radius)
{
  std::vector<std::vector<std::size_t> > neighbours(n);
  parallel_for(n, [&](std::size_t i) {
    // (k + 1: the point itself is among them)
    auto& list = neighbours[i];
    for(const auto& f : search.query(i, k > 0 ? k + 1 : 0, radius))
      if(f.second != i)
        list.push_back(f.second);
    if(list.size() > (k > 0 ? k : list.size()))
      list.resize(k);  // the point itself was not among the k + 1 (it has duplicates)
  });
  return neighbours;
}

// Throws, naming the point, if two points coincide, or if the neighbourhood of a point
// is too small for the normalised frame of `mesh` to resolve it: its farthest neighbour
// within 2^smallest_resolved_exponent of the frame's unit. A point far from all the
// others stretches the box so that the others' neighbourhoods shrink to nothing: at
// 5.6e78 among points 1 apart, their coordinates along it round to one value, and
// CGAL's jet fitting divides by their spread. The message then names the point
// farthest from its nearest neighbour, the one to remove.
inline void check_resolved_neighbourhoods(const Indexed_mesh& mesh,
                                          const std::vector<std::vector<std::size_t> >& neighbours, double extent)
{
  const std::vector<Eigen::Vector3d>& points = mesh.points;
  const std::size_t n = points.size();
  std::size_t bad = n, farthest = n;
  double bad_radius = 0, farthest_distance = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    if(neighbours[i].empty())
      continue;
    double radius = 0;
    for(std::size_t j : neighbours[i])
      radius = (std::max)(radius, (points[j] - points[i]).norm());
    if(bad == n && radius < std::ldexp(1., smallest_resolved_exponent))
    {
      bad = i;
      bad_radius = radius;
    }
    const double nearest = (points[neighbours[i].front()] - points[i]).norm();
    if(nearest > farthest_distance)
    {
      farthest_distance = nearest;
      farthest = i;
    }
  }
  if(bad == n)
  {
    for(std::size_t i = 0; i < n; ++i)
      if(!neighbours[i].empty() && points[neighbours[i].front()] == points[i])
      {
        std::ostringstream os;
        os << "coincides with point " << neighbours[i].front() << "; the package needs distinct points"
           << " (CGAL::grid_simplify_point_set() merges duplicates)";
        throw_point_error(i, os.str());
      }
    return;
  }
  // (in user units: the frame scales by 2^scale_exponent)
  std::ostringstream os;
  os << "has its " << neighbours[bad].size() << " neighbours within " << std::ldexp(bad_radius, -mesh.scale_exponent)
     << " of it, too close for double precision to resolve in a bounding box whose largest side is " << extent
     << " (their distances must be at least " << std::ldexp(1., smallest_resolved_exponent)
     << " of its half diagonal); point " << farthest << ", at " << std::ldexp(farthest_distance, -mesh.scale_exponent)
     << " from its nearest neighbour, is the farthest from the others: a point far from all the others stretches"
     << " the box (remove it)";
  throw_point_error(bad, os.str());
}

// The fan of point i: the neighbours of its Delaunay triangulation among `neighbours`
// projected on the plane orthogonal to `normal`, clockwise around the normal (the order
// of Indexed_mesh::fan), written to `fan`; returns whether it is closed (false: i is on
// the hull of the projection, a border point). Returns 0 and leaves `fan` empty if the
// projections are collinear. A neighbour whose projection coincides with that of i or
// of a nearer neighbour is left out.
inline int local_delaunay_fan(const std::vector<Eigen::Vector3d>& points, std::size_t i,
                              const std::vector<std::size_t>& neighbours, const Eigen::Vector3d& normal,
                              std::vector<std::size_t>& fan)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::size_t, K> Vb;
  typedef CGAL::Triangulation_data_structure_2<Vb> Tds;
  typedef CGAL::Delaunay_triangulation_2<K, Tds> Delaunay;
  // (t1, t2, normal) is direct: counterclockwise in (t1, t2) is counterclockwise around the normal
  const Eigen::Vector3d t1 = normal.unitOrthogonal(), t2 = normal.cross(t1);
  Delaunay dt;
  const auto center = dt.insert(K::Point_2(0., 0.));
  center->info() = i;
  for(std::size_t j : neighbours)
  {
    const Eigen::Vector3d e = points[j] - points[i];
    const std::size_t before = dt.number_of_vertices();
    const auto v = dt.insert(K::Point_2(e.dot(t1), e.dot(t2)));
    // (a vertex that was there keeps the point it was made for)
    if(dt.number_of_vertices() > before)
      v->info() = j;
  }
  fan.clear();
  if(dt.dimension() < 2)
    return 0;
  // Counterclockwise around i, starting after the infinite vertex if there is one.
  std::vector<std::size_t> around;
  std::size_t infinite_position = std::size_t(-1);
  auto circulator = dt.incident_vertices(center), done = circulator;
  do
  {
    if(dt.is_infinite(circulator))
      infinite_position = around.size();
    else
      around.push_back(circulator->info());
  } while(++circulator != done);
  const bool closed = infinite_position == std::size_t(-1);
  const std::size_t d = around.size(), start = closed ? 0 : infinite_position % (d == 0 ? 1 : d);
  for(std::size_t q = 0; q < d; ++q)
    fan.push_back(around[(start + d - 1 - q) % d]);  // reversed: clockwise
  return closed ? 2 : 1;
}

// Removes from the fan of point i (as local_delaunay_fan() makes it) the triangles whose
// area is not resolved (has_resolved_area()): points that are collinear in space, as on
// the border rows of a scanner's grid, project onto points that rounding may leave
// barely off a line, and the exact predicates of the triangulation then make a
// triangle of them. Returns false if the triangles left are not one run (no fan), or
// none; the fan is then an open one where a triangle was removed.
inline bool keep_resolved_triangles(const Indexed_mesh& mesh, std::size_t i, std::vector<std::size_t>& fan,
                                    bool& closed)
{
  const std::size_t d = fan.size(), m = closed ? d : d - 1;
  std::vector<unsigned char> good(m);
  std::size_t bad = m;
  for(std::size_t q = 0; q < m; ++q)
  {
    good[q] = has_resolved_area(mesh, {fan[q], i, fan[(q + 1) % d]});
    if(!good[q])
      bad = q;
  }
  if(bad == m)
    return true;
  // The runs of good triangles, from just after a bad one if the fan is closed.
  const std::size_t start = closed ? bad + 1 : 0;
  std::size_t runs = 0, first = 0, length = 0;
  for(std::size_t a = 0; a < m; ++a)
  {
    const std::size_t q = (start + a) % m;
    if(good[q] && (a == 0 || !good[(q + m - 1) % m]))
    {
      ++runs;
      first = q;
    }
    if(good[q])
      ++length;
  }
  if(runs != 1)
    return false;
  std::vector<std::size_t> kept;
  for(std::size_t a = 0; a <= length; ++a)
    kept.push_back(fan[(first + a) % d]);
  fan.swap(kept);
  closed = false;
  return true;
}

// Where the normals are the user's, the neighbours of each point's fan are those on its
// side of the surface (n_i . n_j > 0). Across a thin part (an ear, a trunk, a thin wall)
// the nearest neighbours include points of the other side, whose projections on the
// tangent plane fall among those of the point's own side and make one fan of both; the
// far side of a sharp crease, whose projections fold onto the point's side, is left out
// too. The k nearest are searched again among 2k, 4k then 8k points until k on the
// point's side are found (with a radius: those within it). A point with fewer than two
// neighbours on its side (a normal against its neighbours') keeps its nearest ones.
inline void keep_neighbours_on_the_same_side(const Point_neighbour_search& search,
                                             const std::vector<Eigen::Vector3d>& normals, std::size_t k,
                                             double radius, std::vector<std::vector<std::size_t> >& neighbours)
{
  const std::size_t n = normals.size();
  parallel_for(n, [&](std::size_t i) {
    std::vector<std::size_t>& list = neighbours[i];
    const auto same_side = [&](std::size_t j) { return normals[i].dot(normals[j]) > 0; };
    if(std::all_of(list.begin(), list.end(), same_side))
      return;
    std::vector<std::size_t> kept;
    for(std::size_t wider = 2 * k;; wider *= 2)
    {
      kept.clear();
      const std::size_t asked = radius > 0 ? 0 : (std::min)(wider + 1, n);
      for(const auto& found : search.query(i, asked, radius))
        if(found.second != i && same_side(found.second))
          kept.push_back(found.second);
      if(radius > 0 || kept.size() >= k || wider >= 8 * k || asked == n)
        break;
    }
    if(k > 0 && kept.size() > k)
      kept.resize(k);
    if(kept.size() >= 2)
      list.swap(kept);
  });
}

// The points in the normalised frame of Indexed_mesh, their neighbours and unit normals:
// what every point-set algorithm of the package starts from.
struct Point_set_neighbourhoods
{
  std::vector<std::vector<std::size_t> > neighbours;  // per point, nearest first
  std::vector<Eigen::Vector3d> normals;               // the user's (normalised) or estimated and oriented
};

// Checks the input, puts the points (user coordinates) in the normalised frame of `mesh`
// and finds their neighbours and normals (`user_normals` if not empty, in user
// orientation, else estimated and oriented). Throws std::invalid_argument, naming the
// point, where the package cannot process the input: a non-finite coordinate or normal,
// a null normal, fewer than k + 1 points, coinciding points, a normal that cannot be
// estimated or oriented. An empty input gives empty neighbourhoods. With given normals
// and `neighbours_on_the_same_side` (the fans'), the neighbours are those of
// keep_neighbours_on_the_same_side().
inline Point_set_neighbourhoods prepare_point_set(std::vector<Eigen::Vector3d> user_points,
                                                  std::vector<Eigen::Vector3d> user_normals,
                                                  const Point_set_surface_options& options, Indexed_mesh& mesh,
                                                  bool neighbours_on_the_same_side = false)
{
  const std::size_t n = user_points.size();
  const bool given_normals = !user_normals.empty();
  Point_set_neighbourhoods result;
  if(n == 0)
    return result;
  if(!(options.neighbor_radius >= 0) || !std::isfinite(options.neighbor_radius))
    throw_invalid_input("neighbor_radius must be positive and finite (or 0: the k nearest neighbours)");
  if(options.neighbor_radius == 0 && options.k < 2)
    throw_invalid_input("the neighbour count k must be at least 2 (or a neighbor_radius given)");
  if(options.neighbor_radius <= 0 && n < options.k + 1)
  {
    std::ostringstream os;
    os << "the point set has " << n << " points, fewer than k + 1 = " << options.k + 1
       << " (each point needs k neighbours)";
    throw_invalid_input(os.str());
  }
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for(std::size_t i = 0; i < n; ++i)
  {
    if(!user_points[i].allFinite())
    {
      std::ostringstream os;
      os << "has a non-finite coordinate (" << user_points[i].transpose() << ")";
      throw_point_error(i, os.str());
    }
    // (stableNorm(): a normal of 1e-200 or 1e308 is one; its square under- or overflows)
    if(given_normals && (!user_normals[i].allFinite() || !(user_normals[i].stableNorm() > 0)))
    {
      std::ostringstream os;
      os << "has a null or non-finite normal (" << user_normals[i].transpose() << ")";
      throw_point_error(i, os.str());
    }
    lo = lo.cwiseMin(user_points[i]);
    hi = hi.cwiseMax(user_points[i]);
  }
  mesh.points = std::move(user_points);
  set_normalised_frame(mesh, lo, hi);
  const std::vector<Eigen::Vector3d>& p = mesh.points;
  // (a radius in user units is scaled like the points; a power of two, exact)
  const double radius = std::ldexp(options.neighbor_radius, mesh.scale_exponent);

  // (released before the normals are estimated, which build trees of their own)
  std::unique_ptr<const Point_neighbour_search> search(new Point_neighbour_search(p));
  const double extent = 2 * (0.5 * hi - 0.5 * lo).maxCoeff();
  result.neighbours = find_neighbours(*search, n, options.k, radius);
  for(std::size_t i = 0; i < n; ++i)
    if(result.neighbours[i].size() < 2)  // (only with a radius: else there are k >= 2)
    {
      std::ostringstream os;
      os << "has " << result.neighbours[i].size() << " neighbour(s) within the neighbor_radius; a fan needs 2";
      throw_point_error(i, os.str());
    }
  check_resolved_neighbourhoods(mesh, result.neighbours, extent);
  if(given_normals)
  {
    result.normals = std::move(user_normals);
    for(Eigen::Vector3d& v : result.normals)
      v.stableNormalize();
    if(neighbours_on_the_same_side)
      keep_neighbours_on_the_same_side(*search, result.normals, options.k, radius, result.neighbours);
  }
  else
  {
    search.reset();
    // (with a radius and no limit: as many neighbours as the point with the fewest has)
    std::size_t k = options.k;
    if(k == 0)
    {
      k = n;
      for(const auto& list : result.neighbours)
        k = (std::min)(k, list.size());
    }
    result.normals = estimate_oriented_normals(p, k);
  }
  return result;
}

// Builds the surface of `points` (user coordinates): neighbours, normals (`user_normals`
// if not empty, in user orientation, else estimated and oriented), fans, NCC and the
// graph. Throws std::invalid_argument, naming the point, where the package cannot
// process the input: prepare_point_set()'s errors, a neighbourhood that is collinear on
// its tangent plane, a normal that cannot be oriented consistently with the fans.
//
// The NCC's normal of a point is the user's, or else the area-weighted normal of its
// own fan (MWAAT, the mesh's default rule), oriented by the estimated normal: where the
// fan is the mesh's one-ring, the point's NS is then the vertex's.
inline Point_set_surface make_point_set_surface(std::vector<Eigen::Vector3d> user_points,
                                                std::vector<Eigen::Vector3d> user_normals,
                                                const Point_set_surface_options& options)
{
  const std::size_t n = user_points.size();
  const bool given_normals = !user_normals.empty();
  Point_set_surface surface;
  Indexed_mesh& mesh = surface.mesh;
  if(n == 0)
    return surface;
  Point_set_neighbourhoods prepared =
      prepare_point_set(std::move(user_points), std::move(user_normals), options, mesh, true);
  const std::vector<Eigen::Vector3d>& p = mesh.points;
  const std::vector<std::vector<std::size_t> >& neighbours = prepared.neighbours;
  std::vector<Eigen::Vector3d>& normals = prepared.normals;

  // The fans, the NCC normals and the Voronoi areas, point by point.
  std::vector<std::vector<std::size_t> > fans(n);
  std::vector<unsigned char> closed(n, 0);
  std::vector<double> areas(n, 0.);
  std::vector<Eigen::Vector3d> ncc_normals(n);
  Point_problems problems(n);
  parallel_for(n, [&](std::size_t i) {
    std::vector<std::size_t>& fan = fans[i];
    const int kind = local_delaunay_fan(p, i, neighbours[i], normals[i], fan);
    if(kind == 0)
    {
      problems.code[i] = 1;
      return;
    }
    bool is_closed = kind == 2;
    if(!keep_resolved_triangles(mesh, i, fan, is_closed))
    {
      problems.code[i] = 2;
      return;
    }
    closed[i] = is_closed;
    const std::size_t d = fan.size();
    Eigen::Vector3d area_weighted = Eigen::Vector3d::Zero();
    for(std::size_t q = 0; q + 1 < d || (closed[i] && q < d); ++q)
    {
      const std::size_t a = fan[q], b = fan[(q + 1) % d];
      area_weighted += mesh.cross_product(a, i, b);
      areas[i] += mixed_voronoi_corner_areas(p[a], p[i], p[b])[1];
    }
    ncc_normals[i] = given_normals ? normals[i] : Eigen::Vector3d(area_weighted.normalized());
  });
  const std::size_t bad = problems.first();
  if(bad < n)
  {
    std::ostringstream os;
    if(problems.code[bad] == 1)
      os << "has a degenerate neighbourhood: its " << neighbours[bad].size()
         << " neighbours project on its tangent plane onto a line, so that they form no fan around it"
         << " (more neighbours, or a normal_map, may help)";
    else
      os << "has no fan: the triangles of its neighbourhood's triangulation that are not collinear to double"
         << " precision do not form one fan around it";
    throw_point_error(bad, os.str());
  }

  if(!given_normals)
  {
    orient_by_majority(fans, closed, normals);
    for(std::size_t i = 0; i < n; ++i)
      if(ncc_normals[i].dot(normals[i]) < 0)
        ncc_normals[i] = -ncc_normals[i];
    surface.orientation_conflicts = check_orientation(fans, closed);
  }

  // The fans in Indexed_mesh's layout, for the NCC.
  mesh.fan_begin.assign(n + 1, 0);
  for(std::size_t i = 0; i < n; ++i)
    mesh.fan_begin[i + 1] = mesh.fan_begin[i] + fans[i].size();
  mesh.fan.resize(mesh.fan_begin[n]);
  for(std::size_t i = 0; i < n; ++i)
    std::copy(fans[i].begin(), fans[i].end(), mesh.fan.begin() + std::ptrdiff_t(mesh.fan_begin[i]));
  mesh.fan_is_closed = closed;
  Ncc_data fan_ncc = compute_ncc_data(mesh, std::move(ncc_normals), std::move(areas));
  for(std::size_t i = 0; i < n; ++i)
    if(!std::isfinite(fan_ncc.signature[i]) || !(fan_ncc.areas[i] > 0))
      throw_point_error(i, "has a fan whose NCC is not finite (a Voronoi area of 0)");

  // The triangles of the fans, each once, weighted by the number of fans holding it / 3
  // (Sharp and Crane: a triangle that all three of its corners see counts fully).
  std::vector<std::array<std::size_t, 3> > triangles;
  triangles.reserve(2 * mesh.fan.size());
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::size_t d = mesh.degree(i);
    for(std::size_t q = 0; q + 1 < d || (closed[i] && q < d); ++q)
    {
      std::array<std::size_t, 3> t = {fans[i][q], i, fans[i][(q + 1) % d]};
      std::sort(t.begin(), t.end());
      triangles.push_back(t);
    }
  }
  std::sort(triangles.begin(), triangles.end());
  for(std::size_t a = 0; a < triangles.size();)
  {
    std::size_t b = a;
    while(b < triangles.size() && triangles[b] == triangles[a])
      ++b;
    mesh.triangles.push_back(triangles[a]);
    surface.triangle_weights.push_back(double(b - a) / 3.);
    a = b;
  }
  std::vector<std::array<std::size_t, 3> >().swap(triangles);

  // The graph: the edges of those triangles, per point in increasing order.
  std::vector<std::vector<std::size_t> > graph(n);
  for(const auto& t : mesh.triangles)
    for(int a = 0; a < 3; ++a)
      for(int b = 0; b < 3; ++b)
        if(a != b)
          graph[t[a]].push_back(t[b]);
  surface.local_fan_begin = std::move(mesh.fan_begin);
  surface.local_fan = std::move(mesh.fan);
  mesh.fan_begin.assign(n + 1, 0);
  for(std::size_t i = 0; i < n; ++i)
  {
    std::sort(graph[i].begin(), graph[i].end());
    graph[i].erase(std::unique(graph[i].begin(), graph[i].end()), graph[i].end());
    mesh.fan_begin[i + 1] = mesh.fan_begin[i] + graph[i].size();
  }
  mesh.fan.resize(mesh.fan_begin[n]);
  for(std::size_t i = 0; i < n; ++i)
    std::copy(graph[i].begin(), graph[i].end(), mesh.fan.begin() + std::ptrdiff_t(mesh.fan_begin[i]));

  // The NCC weights moved from the fans to the graph (every fan neighbour is a graph one).
  surface.ncc = std::move(fan_ncc);
  std::vector<double> weights(mesh.fan.size(), 0.);
  for(std::size_t i = 0; i < n; ++i)
  {
    const auto first = mesh.fan.begin() + std::ptrdiff_t(mesh.fan_begin[i]);
    const auto last = mesh.fan.begin() + std::ptrdiff_t(mesh.fan_begin[i + 1]);
    for(std::size_t q = surface.local_fan_begin[i]; q < surface.local_fan_begin[i + 1]; ++q)
      weights[std::size_t(std::lower_bound(first, last, surface.local_fan[q]) - mesh.fan.begin())] =
          surface.ncc.weights[q];
  }
  surface.ncc.weights = std::move(weights);
  return surface;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_POINT_SET_SURFACE_H
