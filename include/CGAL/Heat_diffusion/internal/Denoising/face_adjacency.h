// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The face geometry and the face neighbourhoods on which the normal filter of
// denoise_mesh() works.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_FACE_ADJACENCY_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_FACE_ADJACENCY_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Face normals, areas and centroids of `points` on the triangles of `mesh`.
inline void face_geometry(const Indexed_mesh& mesh, const std::vector<Eigen::Vector3d>& points,
                          std::vector<Eigen::Vector3d>& normals, std::vector<double>& areas,
                          std::vector<Eigen::Vector3d>& centroids)
{
  const std::size_t m = mesh.triangles.size();
  normals.resize(m);
  areas.resize(m);
  centroids.resize(m);
  for(std::size_t f = 0; f < m; ++f)
  {
    const auto& t = mesh.triangles[f];
    const Eigen::Vector3d cross = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
    const double length = cross.norm();
    areas[f] = 0.5 * length;
    normals[f] = length > 0 ? Eigen::Vector3d(cross / length) : Eigen::Vector3d::Zero();
    centroids[f] = (points[t[0]] + points[t[1]] + points[t[2]]) / 3.;
  }
}

// The faces around each vertex, and the faces that share a vertex with each face.
struct Face_adjacency
{
  std::vector<std::size_t> vertex_faces_begin, vertex_faces;
  std::vector<std::size_t> face_faces_begin, face_faces;
};

inline Face_adjacency make_face_adjacency(const Indexed_mesh& mesh)
{
  const std::size_t n = mesh.number_of_vertices(), m = mesh.triangles.size();
  Face_adjacency a;
  a.vertex_faces_begin.assign(n + 1, 0);
  for(const auto& t : mesh.triangles)
    for(std::size_t v : t)
      ++a.vertex_faces_begin[v + 1];
  for(std::size_t i = 0; i < n; ++i)
    a.vertex_faces_begin[i + 1] += a.vertex_faces_begin[i];
  a.vertex_faces.resize(a.vertex_faces_begin[n]);
  std::vector<std::size_t> fill(a.vertex_faces_begin.begin(), a.vertex_faces_begin.end() - 1);
  for(std::size_t f = 0; f < m; ++f)
    for(std::size_t v : mesh.triangles[f])
      a.vertex_faces[fill[v]++] = f;

  a.face_faces_begin.assign(1, 0);
  std::vector<std::size_t> ring;
  for(std::size_t f = 0; f < m; ++f)
  {
    ring.clear();
    for(std::size_t v : mesh.triangles[f])
      for(std::size_t k = a.vertex_faces_begin[v]; k < a.vertex_faces_begin[v + 1]; ++k)
        if(a.vertex_faces[k] != f)
          ring.push_back(a.vertex_faces[k]);
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    a.face_faces.insert(a.face_faces.end(), ring.begin(), ring.end());
    a.face_faces_begin.push_back(a.face_faces.size());
  }
  return a;
}

// The mean length of the edges of the triangles of `mesh` (each interior edge counted
// twice).
inline double mean_edge_length(const Indexed_mesh& mesh)
{
  double sum = 0;
  for(const auto& t : mesh.triangles)
    for(std::size_t e = 0; e < 3; ++e)
      sum += (mesh.points[t[e]] - mesh.points[t[(e + 1) % 3]]).norm();
  return mesh.triangles.empty() ? 0. : sum / (3. * double(mesh.triangles.size()));
}

// Area-weighted vertex normals of `points` (not normalised; zero for isolated vertices).
inline void area_weighted_normals(const Indexed_mesh& mesh, const Face_adjacency& adjacency,
                                  const std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector3d>& normals)
{
  const std::size_t n = points.size();
  normals.assign(n, Eigen::Vector3d::Zero());
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t k = adjacency.vertex_faces_begin[i]; k < adjacency.vertex_faces_begin[i + 1]; ++k)
    {
      const auto& t = mesh.triangles[adjacency.vertex_faces[k]];
      normals[i] += (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
    }
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_FACE_ADJACENCY_H
