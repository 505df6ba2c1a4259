// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_INDEXED_MESH_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_INDEXED_MESH_H

#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/parallel_for.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// A validated, array-based copy of a triangle mesh, in which all numerical work of
// the package is done (in double, whatever the kernel of the input).
//
// Positions are stored in a normalised frame, p = (x - center) * scale, where scale
// is the power of two that brings the bounding-box diagonal into [0.5, 1). Every
// quantity the package computes is invariant under translation and uniform scaling,
// so this changes no result, but it lets meshes with coordinates of 1e300 or 1e-300
// be processed without overflow or underflow, and a power of two is exact.
struct Indexed_mesh
{
  std::vector<Eigen::Vector3d> points;                 // normalised frame
  std::vector<std::array<std::size_t, 3> > triangles;  // consistently oriented
  Eigen::Vector3d center = Eigen::Vector3d::Zero();    // in user coordinates
  double scale = 1.;                                   // user length * scale = normalised length
  int scale_exponent = 0;                              // scale = 2^scale_exponent (scale may overflow, this not)

  // One-ring fans in compressed rows: the neighbours of vertex i are
  // fan[fan_begin[i] .. fan_begin[i+1]), ordered so that consecutive neighbours
  // (u_k, u_k+1) span the incident triangle (u_k, i, u_k+1). A closed fan also has the
  // triangle (u_last, i, u_0); an open (boundary) fan has not.
  std::vector<std::size_t> fan_begin;
  std::vector<std::size_t> fan;
  std::vector<unsigned char> fan_is_closed;

  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t degree(std::size_t i) const { return fan_begin[i + 1] - fan_begin[i]; }
  // (p_b - p_a) x (p_c - p_a): twice the vector area of the triangle (a, b, c).
  Eigen::Vector3d cross_product(std::size_t a, std::size_t b, std::size_t c) const
  {
    return (points[b] - points[a]).cross(points[c] - points[a]);
  }

  Eigen::Vector3d to_user_frame(const Eigen::Vector3d& p) const
  {
    return Eigen::Vector3d(std::ldexp(p.x(), -scale_exponent), std::ldexp(p.y(), -scale_exponent),
                           std::ldexp(p.z(), -scale_exponent)) +
           center;
  }
};

// The smallest extent of a face or of a point's neighbourhood in the normalised frame,
// whose half diagonal is below 1, as a power of two: the last place of a coordinate is
// at most 2^-52 there, so that anything smaller than 2^-32 is known to fewer than six
// digits. A vertex or point far from all the others (a corrupt line of a file)
// stretches the frame until the others fall below it.
constexpr int smallest_resolved_exponent = -32;

// Whether the area of triangle t is above the rounding error of computing it: twice
// the area must exceed a small multiple of the machine epsilon times the longest edge
// squared (the smallest angle's sine is then at least that multiple of epsilon). Below
// it the corners are collinear up to rounding: the cross product can vanish or not
// depending on the corner it starts from, and the normal, cotangents and Voronoi areas
// computed from it are noise (a Voronoi area of 0 made the NCC NaN; a fuzzing find).
// The OFF meshes of CGAL's data set without faces of zero area are at least 10^7 times
// above the bound.
inline bool has_resolved_area(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const double rounding_bound = 64 * std::numeric_limits<double>::epsilon();
  const double longest_squared = (std::max)({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return (b - a).cross(c - a).norm() > rounding_bound * longest_squared;
}

inline bool has_resolved_area(const Indexed_mesh& mesh, const std::array<std::size_t, 3>& t)
{
  return has_resolved_area(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
}

inline double longest_edge_squared(const Indexed_mesh& mesh, const std::array<std::size_t, 3>& t)
{
  const Eigen::Vector3d &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
  return (std::max)({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
}

// Whether the triangle of the user points a, b, c has a resolved area in a frame of its
// own (translated to a, scaled by a power of two to its extent): a triangle that has one
// there but not in the normalised frame of the whole mesh is lost to the size of the
// bounding box, which a vertex far from all the others stretches.
inline bool has_resolved_area_in_its_own_frame(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                               const Eigen::Vector3d& c)
{
  // (halves: the differences of coordinates near the largest double do not overflow)
  const Eigen::Vector3d u = 0.5 * b - 0.5 * a, v = 0.5 * c - 0.5 * a;
  const double extent = (std::max)(u.cwiseAbs().maxCoeff(), v.cwiseAbs().maxCoeff());
  if(!(extent > 0))
    return false;
  int exponent = 0;
  std::frexp(extent, &exponent);
  auto scaled = [exponent](const Eigen::Vector3d& x) {
    return Eigen::Vector3d(std::ldexp(x.x(), -exponent), std::ldexp(x.y(), -exponent), std::ldexp(x.z(), -exponent));
  };
  return has_resolved_area(Eigen::Vector3d::Zero(), scaled(u), scaled(v));
}

// The vertex farthest from the coordinate-wise median of `points`, and its distance:
// the one that stretches the bounding box where a vertex lies far from all the others.
inline std::pair<std::size_t, double> farthest_from_median(const std::vector<Eigen::Vector3d>& points)
{
  Eigen::Vector3d median;
  for(int axis = 0; axis < 3; ++axis)
  {
    std::vector<double> values;
    for(const Eigen::Vector3d& p : points)
      values.push_back(p[axis]);
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
    median[axis] = values[values.size() / 2];
  }
  std::pair<std::size_t, double> farthest(0, 0.);
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    // (stableNorm(): the distance of 1e300 from -1e300 overflows as a square)
    const double d = (0.5 * points[i] - 0.5 * median).stableNorm();
    if(d > farthest.second)
      farthest = std::make_pair(i, d);
  }
  farthest.second *= 2;  // (infinite if it overflows: then beyond the largest double)
  return farthest;
}

// The mean of `values` over the one-ring neighbours of vertex i, which must have some.
inline Eigen::Vector3d fan_mean(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& values, std::size_t i)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
    sum += values[mesh.fan[k]];
  return sum / double(mesh.degree(i));
}

// The number of vertices that `vertices(tm)` lists. `num_vertices()` of a
// Surface_mesh counts its removed vertices too, until `collect_garbage()`: it is an
// upper bound on the indices, not the number of vertices.
template <typename TriangleMesh>
std::size_t number_of_listed_vertices(const TriangleMesh& tm)
{
  std::size_t n = 0;
  for(auto v : vertices(tm))
  {
    static_cast<void>(v);
    ++n;
  }
  return n;
}

// Writes to `index` the number of every vertex of `tm` in [0, n), n the number of
// vertices `vertices(tm)` lists, and returns n: the user's `vertex_index_map` if `np`
// has one (it must be a bijection onto [0, n)), else the rank of the vertex in
// `vertices(tm)`. The mesh's own index map is not used: that of a Surface_mesh with
// removed elements has gaps, and that of a Polyhedron_3 may not be initialised.
template <typename TriangleMesh, typename NamedParameters, typename VertexIndexMap>
std::size_t number_vertices(const TriangleMesh& tm, const NamedParameters& np, VertexIndexMap index)
{
  const std::size_t n = number_of_listed_vertices(tm);
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_index_t>::value)
  {
    std::size_t k = 0;
    for(auto v : vertices(tm))
      put(index, v, k++);
  }
  else
  {
    const auto user_index = CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_index);
    std::vector<unsigned char> seen(n, 0);
    for(auto v : vertices(tm))
    {
      const auto i = get(user_index, v);
      bool negative = false;
      if constexpr(std::is_signed<std::decay_t<decltype(i)> >::value)
        negative = i < 0;
      if(negative || static_cast<std::size_t>(i) >= n || seen[static_cast<std::size_t>(i)])
      {
        std::ostringstream os;
        os << "the vertex_index_map is not a bijection onto [0, " << n << "), " << n
           << " the number of vertices (without removed ones; a Surface_mesh's own index map has gaps"
           << " until collect_garbage())";
        throw_invalid_input(os.str());
      }
      seen[static_cast<std::size_t>(i)] = 1;
      put(index, v, static_cast<std::size_t>(i));
    }
  }
  return n;
}

// The numbering of number_vertices(), in a new property map.
template <typename TriangleMesh, typename NamedParameters>
auto vertex_numbering(const TriangleMesh& tm, const NamedParameters& np)
{
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  number_vertices(tm, np, index);
  return index;
}

// Meshes of at least this many vertices get vertex indices along a Hilbert curve
// (unless the user gives a vertex index map).
constexpr std::size_t spatial_order_threshold = 100000;

// The rank of every vertex along a Hilbert curve of the vertex positions
// (CGAL::hilbert_sort, deterministic), by the vertex's rank in vertices(tm): numbered
// so, neighbouring vertices get close indices, and the sparse products of the
// diffusion, which are memory-bound, read the field nearly sequentially. A
// Loop-subdivided mesh numbers its new vertices edge by edge, far from their
// neighbours (benchmark_scale_curve --order measures a diffusion step in both orders).
// Empty if a coordinate is not finite (make_indexed_mesh() reports it).
template <typename TriangleMesh, typename VertexPointMap>
std::vector<std::size_t> ranks_along_hilbert_curve(const TriangleMesh& tm, VertexPointMap vpm)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::vector<K::Point_3> points;
  points.reserve(number_of_listed_vertices(tm));
  for(auto v : vertices(tm))
  {
    const auto& p = get(vpm, v);
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      return {};
    points.emplace_back(x, y, z);
  }
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  typedef CGAL::Spatial_sort_traits_adapter_3<K, typename CGAL::Pointer_property_map<K::Point_3>::type> Traits;
  // The parallel sort splits at the same medians as the sequential one: the same order.
  CGAL::hilbert_sort<CGAL::Parallel_if_available_tag>(order.begin(), order.end(),
                                                      Traits(CGAL::make_property_map(points)));
  std::vector<std::size_t> rank(order.size());
  for(std::size_t k = 0; k < order.size(); ++k)
    rank[order[k]] = k;
  return rank;
}

// Renumbers the vertices of `mesh`: vertex i becomes new_index[i] (a permutation). The
// result is the mesh make_indexed_mesh() builds with the new numbering: the same
// triangles in the same order, and each fan in the same order.
inline void renumber_vertices(Indexed_mesh& mesh, const std::vector<std::size_t>& new_index)
{
  const std::size_t n = mesh.number_of_vertices();
  std::vector<Eigen::Vector3d> points(n);
  std::vector<std::size_t> fan_begin(n + 1, 0);
  std::vector<unsigned char> fan_is_closed(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    points[new_index[i]] = mesh.points[i];
    fan_begin[new_index[i] + 1] = mesh.degree(i);
    fan_is_closed[new_index[i]] = mesh.fan_is_closed[i];
  }
  for(std::size_t i = 0; i < n; ++i)
    fan_begin[i + 1] += fan_begin[i];
  std::vector<std::size_t> fan(mesh.fan.size());
  parallel_for(n, [&](std::size_t i) {
    std::size_t* out = fan.data() + fan_begin[new_index[i]];
    for(std::size_t q = mesh.fan_begin[i]; q < mesh.fan_begin[i + 1]; ++q)
      *out++ = new_index[mesh.fan[q]];
  });
  parallel_for(mesh.triangles.size(), [&](std::size_t t) {
    for(std::size_t& v : mesh.triangles[t])
      v = new_index[v];
  });
  mesh.points = std::move(points);
  mesh.fan_begin = std::move(fan_begin);
  mesh.fan = std::move(fan);
  mesh.fan_is_closed = std::move(fan_is_closed);
}

// Moves mesh.points, in user coordinates within the box [lo, hi], to the normalised
// frame of Indexed_mesh, and sets center, scale and scale_exponent.
inline void set_normalised_frame(Indexed_mesh& mesh, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi)
{
  // Halves first, so that coordinates near the largest double do not overflow.
  mesh.center = 0.5 * lo + 0.5 * hi;
  const Eigen::Vector3d half_extent = 0.5 * hi - 0.5 * lo;
  const double largest_half_extent = half_extent.maxCoeff();
  if(largest_half_extent > 0)
  {
    // The half diagonal itself can overflow (half extents of 1.7e308), so its
    // exponent is that of the largest half extent plus that of the diagonal of the
    // box scaled by a power of two to that extent.
    int exponent = 0, diagonal_exponent = 0;
    std::frexp(largest_half_extent, &exponent);
    // std::ldexp scales exactly, without overflow for tiny (subnormal) extents.
    auto times_power_of_two = [](const Eigen::Vector3d& x, int e) {
      return Eigen::Vector3d(std::ldexp(x.x(), e), std::ldexp(x.y(), e), std::ldexp(x.z(), e));
    };
    std::frexp(times_power_of_two(half_extent, -exponent).norm(), &diagonal_exponent);
    exponent += diagonal_exponent;  // half_diagonal in [2^(e-1), 2^e)
    for(Eigen::Vector3d& p : mesh.points)
      p = times_power_of_two(0.5 * p - 0.5 * mesh.center, -exponent);  // = (p - center) * scale
    // diagonal * scale = half_diagonal * 2^-e, in [0.5, 1)
    mesh.scale_exponent = -1 - exponent;
    mesh.scale = std::ldexp(1., mesh.scale_exponent);
  }
  else
    for(Eigen::Vector3d& p : mesh.points)
      p.setZero();
}

// Builds the indexed copy of `tm`, and rejects what the package cannot process with
// an exception that names the element and the problem: a non-triangle face, a
// non-finite coordinate, a zero-area face, an isolated vertex, a non-manifold vertex.
// Vertex numbers in messages and in the arrays are those of `vim`, which must number
// the vertices that `vertices(tm)` lists in [0, their number) (see number_vertices()).
template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap>
Indexed_mesh make_indexed_mesh(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  Indexed_mesh mesh;
  const std::size_t n = number_of_listed_vertices(tm);
  mesh.points.resize(n);
  std::vector<unsigned char> seen(n, 0);

  auto user_point = [&](typename GT::vertex_descriptor v) {
    const auto& p = get(vpm, v);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  // User coordinates, checked for finiteness, and their bounding box.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for(auto v : vertices(tm))
  {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    if(i >= n || seen[i])
      throw_invalid_input("the vertex index map is not a bijection onto [0, number of vertices)");
    seen[i] = 1;
    const Eigen::Vector3d x = user_point(v);
    if(!x.allFinite())
    {
      std::ostringstream os;
      os << "vertex " << i << " has a non-finite coordinate (" << x.transpose() << ")";
      throw_invalid_input(os.str());
    }
    mesh.points[i] = x;
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  if(n == 0)
    return mesh;

  set_normalised_frame(mesh, lo, hi);

  auto throw_broken_structure = [](const char* element, std::size_t number) {
    std::ostringstream os;
    os << "the halfedges around " << element << " " << number << " do not form a cycle: the halfedge structure"
       << " is broken (CGAL::is_valid_polygon_mesh() fails)";
    throw_invalid_input(os.str());
  };
  // (num_halfedges() counts removed halfedges too: a bound, not the number)
  const std::size_t halfedge_bound = static_cast<std::size_t>(num_halfedges(tm));

  // Triangles.
  mesh.triangles.reserve(2 * n);  // a hint (num_faces() counts removed faces too)
  std::size_t face_number = 0;
  for(auto f : faces(tm))
  {
    std::array<std::size_t, 3> t;
    std::array<typename GT::vertex_descriptor, 3> corners;
    std::size_t k = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
    {
      if(k < 3)
      {
        corners[k] = target(h, tm);
        t[k] = static_cast<std::size_t>(get(vim, corners[k]));
      }
      // On a broken halfedge structure, next() may never lead back to the face's
      // halfedge: the circulation would not end.
      if(++k > halfedge_bound)
        throw_broken_structure("face", face_number);
    }
    if(k != 3)
    {
      std::ostringstream os;
      os << "face " << face_number << " has " << k << " vertices; the package works on triangle meshes"
         << " (CGAL::Polygon_mesh_processing::triangulate_faces() triangulates a polygon mesh)";
      throw_invalid_input(os.str());
    }
    // (CGAL's meshes have no face below 3e-4 of the frame's unit)
    const bool resolved_size = longest_edge_squared(mesh, t) >= std::ldexp(1., 2 * smallest_resolved_exponent);
    if(!resolved_size || !has_resolved_area(mesh, t))
    {
      std::ostringstream os;
      os << "face " << face_number << " (vertices " << t[0] << ", " << t[1] << ", " << t[2] << ") ";
      if(!resolved_size ||
         has_resolved_area_in_its_own_frame(user_point(corners[0]), user_point(corners[1]), user_point(corners[2])))
      {
        std::vector<Eigen::Vector3d> user_points(n);
        for(auto v : vertices(tm))
          user_points[static_cast<std::size_t>(get(vim, v))] = user_point(v);
        const std::pair<std::size_t, double> farthest = farthest_from_median(user_points);
        os << "is too small for double precision to resolve in a bounding box whose largest side is "
           << 2 * (0.5 * hi - 0.5 * lo).maxCoeff() << "; vertex " << farthest.first << ", at " << farthest.second
           << " from the median of the vertices, is the farthest from the others: a vertex far from all the others"
           << " stretches the box (remove it)";
      }
      else if(mesh.cross_product(t[0], t[1], t[2]).squaredNorm() > 0)
        os << "has zero area up to rounding (its corners are collinear to double precision);"
           << " CGAL::Polygon_mesh_processing::experimental::remove_almost_degenerate_faces() removes such faces";
      else
        os << "has zero area; CGAL::Polygon_mesh_processing::remove_degenerate_faces() removes such faces";
      throw_invalid_input(os.str());
    }
    mesh.triangles.push_back(t);
    ++face_number;
  }

  // Fans. The number of halfedges pointing to a vertex tells whether the cycle
  // around it sees all of its incident edges (a manifold vertex) or only one of
  // several umbrellas (a non-manifold vertex).
  std::vector<std::size_t> incoming(n, 0);
  for(halfedge_descriptor h : halfedges(tm))
    ++incoming[static_cast<std::size_t>(get(vim, target(h, tm)))];

  mesh.fan_begin.assign(n + 1, 0);
  mesh.fan_is_closed.assign(n, 1);
  mesh.fan.reserve(6 * n);  // a hint
  std::vector<halfedge_descriptor> cycle;
  for(auto v : vertices(tm))
  {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    const halfedge_descriptor h0 = halfedge(v, tm);
    if(incoming[i] == 0 || h0 == GT::null_halfedge())
    {
      std::ostringstream os;
      os << "vertex " << i << " is isolated (it has no incident face);"
         << " CGAL::Polygon_mesh_processing::remove_isolated_vertices() removes such vertices";
      throw_invalid_input(os.str());
    }
    cycle.clear();
    std::size_t border_count = 0;
    for(halfedge_descriptor h : halfedges_around_target(h0, tm))
    {
      // A valid structure leads back to h0 before it has seen each halfedge into the
      // vertex once; a broken one may never lead back.
      if(cycle.size() == incoming[i])
        throw_broken_structure("vertex", i);
      border_count += is_border(h, tm) ? 1 : 0;
      cycle.push_back(h);
    }
    if(cycle.size() != incoming[i] || border_count > 1)
    {
      std::ostringstream os;
      os << "vertex " << i << " is non-manifold (its incident faces form several fans);"
         << " CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices() splits it";
      throw_invalid_input(os.str());
    }
    mesh.fan_is_closed[i] = border_count == 0;
    mesh.fan_begin[i + 1] = cycle.size();
  }
  for(std::size_t i = 0; i < n; ++i)
    mesh.fan_begin[i + 1] += mesh.fan_begin[i];
  mesh.fan.resize(mesh.fan_begin[n]);
  for(auto v : vertices(tm))
  {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    cycle.clear();
    std::size_t border_position = 0;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, tm), tm))
    {
      if(is_border(h, tm))
        border_position = cycle.size();
      cycle.push_back(h);
    }
    // For h_k around the target, h_k+1 = opposite(next(h_k)) and face(h_k) is the
    // triangle (source(h_k), v, source(h_k+1)). An open fan starts right after the
    // border halfedge, so that it ends with that halfedge's source.
    const std::size_t d = cycle.size();
    const std::size_t start = mesh.fan_is_closed[i] ? 0 : border_position + 1;
    for(std::size_t k = 0; k < d; ++k)
      mesh.fan[mesh.fan_begin[i] + k] =
          static_cast<std::size_t>(get(vim, source(cycle[(start + k) % d], tm)));
  }
  return mesh;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_INDEXED_MESH_H
