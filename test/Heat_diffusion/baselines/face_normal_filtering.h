// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What the face-normal filters of the baselines (bilateral_normal_filtering.h,
// guided_normal_filtering.h) share: the mesh as arrays, face geometry, the faces
// around each vertex and around each face, and the vertex update of Sun et al. 2007
// that both papers use to fit the vertices to filtered normals.

#ifndef CGAL_HEAT_DIFFUSION_BASELINES_FACE_NORMAL_FILTERING_H
#define CGAL_HEAT_DIFFUSION_BASELINES_FACE_NORMAL_FILTERING_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace test_support {
namespace baselines {

// A triangle mesh as arrays (vertex i is the i-th of vertices(mesh)), with its
// adjacency: faces around each vertex, faces sharing a vertex with each face (without
// the face itself), faces sharing an edge with each face.
struct Face_mesh
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::vector<std::size_t> > vertex_faces, vertex_neighbours, edge_neighbours;
  std::vector<Eigen::Vector3d> normals, centroids;
  std::vector<double> areas;

  void update_geometry()
  {
    const std::size_t m = triangles.size();
    normals.resize(m);
    centroids.resize(m);
    areas.resize(m);
    for(std::size_t f = 0; f < m; ++f)
    {
      const auto& t = triangles[f];
      const Eigen::Vector3d cross = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
      const double length = cross.norm();
      areas[f] = 0.5 * length;
      normals[f] = length > 0 ? Eigen::Vector3d(cross / length) : Eigen::Vector3d::Zero();
      centroids[f] = (points[t[0]] + points[t[1]] + points[t[2]]) / 3.;
    }
  }

  // The mean distance between the centroids of edge-adjacent faces: the spatial scale
  // of both papers.
  double mean_centroid_distance() const
  {
    double sum = 0;
    std::size_t count = 0;
    for(std::size_t f = 0; f < triangles.size(); ++f)
      for(std::size_t g : edge_neighbours[f])
      {
        sum += (centroids[f] - centroids[g]).norm();
        ++count;
      }
    return count > 0 ? sum / double(count) : 0.;
  }
};

template <typename Mesh>
Face_mesh make_face_mesh(const Mesh& mesh)
{
  if(!CGAL::is_triangle_mesh(mesh))
    throw std::invalid_argument("baselines: the mesh must be a triangle mesh");
  Face_mesh result;
  std::vector<std::size_t> index(num_vertices(mesh) + 1);
  std::size_t n = 0;
  for(auto v : vertices(mesh))
  {
    const auto& p = get(CGAL::vertex_point, mesh, v);
    index.at(std::size_t(v)) = n++;
    result.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  result.vertex_faces.resize(n);
  for(auto f : faces(mesh))
  {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      t[k++] = index.at(std::size_t(v));
    for(std::size_t v : t)
      result.vertex_faces[v].push_back(result.triangles.size());
    result.triangles.push_back(t);
  }
  const std::size_t m = result.triangles.size();
  result.vertex_neighbours.resize(m);
  result.edge_neighbours.resize(m);
  std::vector<std::size_t> ring;
  for(std::size_t f = 0; f < m; ++f)
  {
    ring.clear();
    for(std::size_t v : result.triangles[f])
      for(std::size_t g : result.vertex_faces[v])
        if(g != f)
          ring.push_back(g);
    std::sort(ring.begin(), ring.end());
    for(std::size_t k = 0; k < ring.size();)
    {
      std::size_t l = k;
      while(l < ring.size() && ring[l] == ring[k])
        ++l;
      result.vertex_neighbours[f].push_back(ring[k]);
      if(l - k >= 2)
        result.edge_neighbours[f].push_back(ring[k]);
      k = l;
    }
  }
  result.update_geometry();
  return result;
}

// Writes the points back, in the order of vertices(mesh).
template <typename Mesh>
void write_points(const Face_mesh& source, Mesh& mesh)
{
  typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type
      Point;
  std::size_t i = 0;
  for(auto v : vertices(mesh))
  {
    const Eigen::Vector3d& p = source.points[i++];
    put(get(CGAL::vertex_point, mesh), v, Point(p.x(), p.y(), p.z()));
  }
}

// The vertex update of Sun et al. 2007, used by Zheng et al. 2011 and Zhang et al.
// 2015: `iterations` steps of v_i <- v_i + 1/|F_i| sum_{f in F_i} n_f (n_f . (c_f - v_i)),
// the centroids recomputed at every step. Leaves the geometry of `mesh` updated.
inline void update_vertices(Face_mesh& mesh, const std::vector<Eigen::Vector3d>& target_normals,
                            std::size_t iterations)
{
  std::vector<Eigen::Vector3d> next(mesh.points.size());
  for(std::size_t it = 0; it < iterations; ++it)
  {
    mesh.update_geometry();
    for(std::size_t i = 0; i < mesh.points.size(); ++i)
    {
      Eigen::Vector3d move = Eigen::Vector3d::Zero();
      for(std::size_t f : mesh.vertex_faces[i])
        move += target_normals[f] * target_normals[f].dot(mesh.centroids[f] - mesh.points[i]);
      next[i] = mesh.vertex_faces[i].empty() ? mesh.points[i] : Eigen::Vector3d(mesh.points[i] + move / double(mesh.vertex_faces[i].size()));
    }
    mesh.points.swap(next);
  }
  mesh.update_geometry();
}

inline Eigen::Vector3d normalised_or(const Eigen::Vector3d& v, const Eigen::Vector3d& fallback)
{
  const double length = v.norm();
  return length > 0 && std::isfinite(length) ? Eigen::Vector3d(v / length) : fallback;
}

} // namespace baselines
} // namespace test_support

#endif // CGAL_HEAT_DIFFUSION_BASELINES_FACE_NORMAL_FILTERING_H
