// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The normals of a point set without given normals: estimated and oriented by CGAL's
// Point_set_processing_3, then checked and repaired against the orientations of the
// points' fans (internal/point_set_surface.h).

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_POINT_SET_ORIENTATION_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_POINT_SET_ORIENTATION_H

#include <CGAL/Heat_diffusion/internal/errors.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Throws std::invalid_argument with "point i what".
[[noreturn]] inline void throw_point_error(std::size_t i, const std::string& what)
{
  std::ostringstream os;
  os << "point " << i << " " << what;
  throw_invalid_input(os.str());
}

// Unit normals of the points, in the normalised frame, by CGAL::jet_estimate_normals()
// and oriented by CGAL::mst_orient_normals(), over the k nearest neighbours. (Not over
// a radius: Point_set_processing_3 limits a radius search to the first k points the
// kd-tree meets, not the nearest, and without a limit its neighbourhoods can be large
// enough for mst_orient_normals() to cross thin parts; both made fandisk fail.)
// Throws, naming a point, where a normal is not usable or cannot be oriented.
inline std::vector<Eigen::Vector3d> estimate_oriented_normals(const std::vector<Eigen::Vector3d>& points,
                                                              std::size_t k)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef std::tuple<K::Point_3, K::Vector_3, std::size_t> Item;
  const std::size_t n = points.size();
  std::vector<Item> items(n);
  for(std::size_t i = 0; i < n; ++i)
    items[i] = Item(K::Point_3(points[i].x(), points[i].y(), points[i].z()), K::Vector_3(0, 0, 0), i);
  const auto np = CGAL::parameters::point_map(CGAL::Nth_of_tuple_property_map<0, Item>())
                      .normal_map(CGAL::Nth_of_tuple_property_map<1, Item>())
                      // a quadric needs 6 points: the point and 5 neighbours; a plane 3
                      .degree_fitting(k >= 5 ? 2 : 1);
  // (Point_set_processing_3 counts the point itself among its k)
  const unsigned psp_k = unsigned(k + 1);
  CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(items, psp_k, np);
  for(const Item& item : items)
  {
    const K::Vector_3& v = std::get<1>(item);
    const Eigen::Vector3d normal(v.x(), v.y(), v.z());
    if(!normal.allFinite() || !(normal.norm() > 0))
      throw_point_error(std::get<2>(item), "has no usable estimated normal (its neighbourhood is degenerate); "
                                           "give normals with the normal_map named parameter");
  }
  const auto unoriented = CGAL::mst_orient_normals(items, psp_k, np);
  if(unoriented != items.end())
  {
    std::ostringstream os;
    os << "has a normal that CGAL::mst_orient_normals() could not orient (with "
       << (items.end() - unoriented - 1) << " other points): its neighbourhood graph does not reach the"
       << " point the orientation starts from (several connected components, or too few neighbours);"
       << " give oriented normals with the normal_map named parameter, or more neighbours";
    std::size_t first = n;
    for(auto it = unoriented; it != items.end(); ++it)
      first = (std::min)(first, std::get<2>(*it));
    throw_point_error(first, os.str());
  }
  std::vector<Eigen::Vector3d> normals(n);
  for(const Item& item : items)
  {
    const K::Vector_3& v = std::get<1>(item);
    normals[std::get<2>(item)] = Eigen::Vector3d(v.x(), v.y(), v.z()).normalized();
  }
  return normals;
}

// The pairs of points whose fans hold a same triangle, with the relation of their
// orientations: two fans list a triangle clockwise around their own normals, so that
// they list it in the same orientation exactly when the two normals are consistently
// oriented. relation = +1: consistent as they are; -1: one of the normals must flip.
struct Shared_triangle
{
  std::size_t p, q;
  int relation;
};

inline std::vector<Shared_triangle> shared_triangles(const std::vector<std::vector<std::size_t> >& fans,
                                                     const std::vector<unsigned char>& closed)
{
  struct Entry
  {
    std::array<std::size_t, 3> key;
    std::size_t point;
    int parity;  // +1 if (u_k, i, u_k+1) is an even permutation of the sorted key
  };
  std::vector<Entry> entries;
  for(std::size_t i = 0; i < fans.size(); ++i)
  {
    const std::size_t d = fans[i].size();
    for(std::size_t q = 0; q + 1 < d || (closed[i] && q < d); ++q)
    {
      std::array<std::size_t, 3> t = {fans[i][q], i, fans[i][(q + 1) % d]};
      int parity = 1;
      for(int pass = 0; pass < 2; ++pass)  // (a bubble sort of three, counting the swaps)
        for(int a = 0; a < 2; ++a)
          if(t[a] > t[a + 1])
          {
            std::swap(t[a], t[a + 1]);
            parity = -parity;
          }
      entries.push_back(Entry{t, i, parity});
    }
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.key < b.key || (a.key == b.key && a.point < b.point);
  });
  std::vector<Shared_triangle> shared;
  for(std::size_t a = 0; a < entries.size();)
  {
    std::size_t b = a + 1;
    while(b < entries.size() && entries[b].key == entries[a].key)
      ++b;
    for(std::size_t c = a; c < b; ++c)
      for(std::size_t e = c + 1; e < b; ++e)
        shared.push_back(Shared_triangle{entries[c].point, entries[e].point, entries[c].parity * entries[e].parity});
    a = b;
  }
  return shared;
}

// Flips the normals (and fans) of the points most of whose shared triangles disagree
// with their neighbours' orientation, sweep after sweep until none does (or 20 sweeps):
// an orientation wrong on a few isolated points is repaired.
inline void orient_by_majority(std::vector<std::vector<std::size_t> >& fans, const std::vector<unsigned char>& closed,
                               std::vector<Eigen::Vector3d>& normals)
{
  const std::size_t n = fans.size();
  std::vector<std::vector<std::pair<std::size_t, int> > > edges(n);
  for(const Shared_triangle& t : shared_triangles(fans, closed))
  {
    edges[t.p].emplace_back(t.q, t.relation);
    edges[t.q].emplace_back(t.p, t.relation);
  }
  std::vector<int> sign(n, 1);
  for(int sweep = 0; sweep < 20; ++sweep)
  {
    bool changed = false;
    for(std::size_t p = 0; p < n; ++p)
    {
      int score = 0;
      for(const auto& e : edges[p])
        score += e.second * sign[p] * sign[e.first];
      if(score < 0)
      {
        sign[p] = -sign[p];
        changed = true;
      }
    }
    if(!changed)
      break;
  }
  for(std::size_t i = 0; i < n; ++i)
    if(sign[i] < 0)
    {
      normals[i] = -normals[i];
      std::reverse(fans[i].begin(), fans[i].end());
    }
}

// The number of triangles that two fans list in opposite orientations, after
// orient_by_majority(); throws, naming the first point of such a triangle, if they are
// more than 1 % of the points.
inline std::size_t check_orientation(const std::vector<std::vector<std::size_t> >& fans,
                                     const std::vector<unsigned char>& closed)
{
  const std::size_t n = fans.size();
  // mst_orient_normals() walks the nearest-neighbour graph, which can cross a thin part
  // (an ear, a trunk) from one side to the other and flip a whole region: the fans
  // there then list their shared triangles in opposite orientations. Measured with
  // k = 8 on the vertices of CGAL's meshes: 0 such triangles on fandisk and
  // mech-holes-shark, 25 on armadillo (26002 points, 8 normals off the mesh's), 320
  // on elephant (2775 points, 1785 normals flipped), and 375 on fandisk with k = 10
  // (mst_orient_normals() flips a region there): a bound of 1 % of the points.
  std::size_t conflicts = 0, first = n;
  for(const Shared_triangle& t : shared_triangles(fans, closed))
    if(t.relation < 0)
    {
      ++conflicts;
      first = (std::min)({first, t.p, t.q});
    }
  if(conflicts > n / 100)
  {
    std::ostringstream os;
    os << "has a normal that CGAL::mst_orient_normals() oriented against its neighbours': " << conflicts
       << " triangles shared by two points' fans have opposite orientations in them (more than 1 % of the "
       << n << " points), which happens where the nearest-neighbour graph crosses a thin part of the shape;"
       << " give oriented normals with the normal_map named parameter";
    throw_point_error(first, os.str());
  }
  return conflicts;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_POINT_SET_ORIENTATION_H
