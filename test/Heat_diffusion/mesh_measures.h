// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shared by the tests and the benchmarks, so that both measure the same way: the mean
// edge length, seeded noise along the normals (Gaussian on every vertex, or impulsive),
// 2-rings and the re-detection of features within them, the bilateral denoising
// baseline, and points sampled uniformly on a surface.

#ifndef CGAL_HEAT_DIFFUSION_MESH_MEASURES_H
#define CGAL_HEAT_DIFFUSION_MESH_MEASURES_H

#include <CGAL/squared_distance_3.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace test_support {

// Points uniform on the surface of a triangle mesh: a face drawn by area, then uniform
// barycentric coordinates in it (three draws of `random`, in this order), so that the
// samples of a seed are the same wherever they are drawn.
template <typename Mesh>
class Uniform_surface_sampler
{
public:
  typedef typename Mesh::Face_index Face;
  typedef typename Mesh::Point Point;

  explicit Uniform_surface_sampler(const Mesh& mesh) : mesh_(mesh), faces_(mesh.faces().begin(), mesh.faces().end())
  {
    for(Face f : faces_)
      cumulative_.push_back(total_ += CGAL::Polygon_mesh_processing::face_area(f, mesh));
  }

  // A point, and the face it lies in in `face` if not null.
  template <typename Generator>
  Point operator()(Generator& random, Face* face = nullptr) const
  {
    std::uniform_real_distribution<double> uniform(0., 1.);
    const std::size_t f = std::size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), uniform(random) * total_) -
                                      cumulative_.begin());
    const Face chosen = faces_[(std::min)(f, faces_.size() - 1)];
    if(face != nullptr)
      *face = chosen;
    const auto h = mesh_.halfedge(chosen);
    const Point &a = mesh_.point(mesh_.source(h)), &b = mesh_.point(mesh_.target(h)),
                &c = mesh_.point(mesh_.target(mesh_.next(h)));
    double u = uniform(random), v = uniform(random);
    if(u + v > 1)
    {
      u = 1 - u;
      v = 1 - v;
    }
    return a + u * (b - a) + v * (c - a);
  }

private:
  const Mesh& mesh_;
  std::vector<Face> faces_;
  std::vector<double> cumulative_;
  double total_ = 0;
};

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

// Impulsive noise: moves a random `fraction` of the vertices (chosen without
// repetition, seeded) along their normals by Gaussian noise of standard deviation
// `relative_sigma` times the mean edge length, and leaves the others where they are.
template <typename Mesh>
void add_impulsive_noise(Mesh& mesh, double fraction, double relative_sigma, unsigned seed)
{
  typedef typename CGAL::Kernel_traits<typename Mesh::Point>::Kernel K;
  const double sigma = relative_sigma * mean_edge_length(mesh);
  auto normals = mesh.template add_property_map<typename Mesh::Vertex_index, typename K::Vector_3>("v:noise_normal").first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
  std::vector<typename Mesh::Vertex_index> chosen(mesh.vertices().begin(), mesh.vertices().end());
  std::mt19937 generator(seed);
  // A Fisher-Yates prefix of the vertices: the same choice on every platform
  // (std::shuffle's algorithm is not specified).
  const std::size_t count = std::size_t(std::lround(fraction * double(chosen.size())));
  for(std::size_t i = 0; i < count && i + 1 < chosen.size(); ++i)
  {
    const std::size_t j = i + std::size_t(generator() % (chosen.size() - i));
    std::swap(chosen[i], chosen[j]);
  }
  std::normal_distribution<double> gaussian(0., sigma);
  for(std::size_t i = 0; i < count && i < chosen.size(); ++i)
    mesh.point(chosen[i]) = mesh.point(chosen[i]) + gaussian(generator) * normals[chosen[i]];
  mesh.remove_property_map(normals);
}

// Moves every vertex by Gaussian noise of standard deviation `relative_sigma` times
// the mean edge length along a direction drawn uniformly on the sphere (seeded): noise
// that also moves vertices within the surface, which distorts the triangles.
template <typename Mesh>
void add_random_direction_noise(Mesh& mesh, double relative_sigma, unsigned seed)
{
  typedef typename CGAL::Kernel_traits<typename Mesh::Point>::Kernel K;
  const double sigma = relative_sigma * mean_edge_length(mesh);
  std::mt19937 generator(seed);
  std::normal_distribution<double> gaussian(0., 1.);
  for(auto v : mesh.vertices())
  {
    typename K::Vector_3 direction(0, 0, 0);
    double length = 0;
    while(!(length > 1e-6))
    {
      direction = typename K::Vector_3(gaussian(generator), gaussian(generator), gaussian(generator));
      length = std::sqrt(CGAL::to_double(direction.squared_length()));
    }
    mesh.point(v) = mesh.point(v) + (sigma * gaussian(generator) / length) * direction;
  }
}

// The 2-ring of every vertex of a Surface_mesh, by index, without the vertex itself.
template <typename Mesh>
std::vector<std::set<std::size_t> > two_rings(const Mesh& mesh)
{
  std::vector<std::set<std::size_t> > rings(mesh.number_of_vertices());
  for(auto v : mesh.vertices())
    for(auto u : vertices_around_target(v, mesh))
    {
      rings[v.idx()].insert(u.idx());
      for(auto w : vertices_around_target(u, mesh))
        if(w != v)
          rings[v.idx()].insert(w.idx());
    }
  return rings;
}

// How many vertices of `wanted` have a vertex of `found` within their 2-ring (itself
// included): the re-detection of features.
template <typename Vertex>
std::size_t count_found_nearby(const std::vector<Vertex>& wanted, const std::vector<Vertex>& found,
                               const std::vector<std::set<std::size_t> >& rings)
{
  std::set<std::size_t> found_indices;
  for(Vertex v : found)
    found_indices.insert(v.idx());
  std::size_t hits = 0;
  for(Vertex v : wanted)
  {
    bool hit = found_indices.count(v.idx()) != 0;
    for(std::size_t u : rings[v.idx()])
      hit = hit || found_indices.count(u) != 0;
    hits += hit ? 1 : 0;
  }
  return hits;
}

// One iteration of bilateral mesh denoising (Fleishman, Drori, Cohen-Or, SIGGRAPH
// 2003), the baseline of the denoising test and benchmark: each vertex moves along its
// normal n by the bilaterally weighted mean of the heights h = n . (q - v) of the
// vertices q within distance 2 sigma_c (reached over edges), with weights
// exp(-|q - v|^2 / 2 sigma_c^2) exp(-h^2 / 2 sigma_s^2).
template <typename Mesh>
void bilateral_denoising_iteration(Mesh& mesh, double sigma_c, double sigma_s)
{
  typedef typename Mesh::Vertex_index Vertex;
  typedef typename Mesh::Point Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
  auto normals = mesh.template add_property_map<Vertex, Vector>("v:bilateral_normal").first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
  std::vector<Point> moved(mesh.number_of_vertices());
  std::vector<std::size_t> stamp(mesh.number_of_vertices(), std::size_t(-1));
  std::vector<Vertex> queue;
  const double radius2 = 4 * sigma_c * sigma_c;
  for(Vertex v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    const Vector& n = normals[v];
    double sum = 0, normaliser = 0;
    queue.assign(1, v);
    stamp[v.idx()] = v.idx();
    for(std::size_t k = 0; k < queue.size(); ++k)
      for(Vertex q : CGAL::vertices_around_target(mesh.halfedge(queue[k]), mesh))
      {
        if(stamp[q.idx()] == v.idx())
          continue;
        stamp[q.idx()] = v.idx();
        const double d2 = CGAL::to_double(CGAL::squared_distance(p, mesh.point(q)));
        if(d2 > radius2)
          continue;
        queue.push_back(q);
        const double h = CGAL::to_double(n * (mesh.point(q) - p));
        const double w = std::exp(-d2 / (2 * sigma_c * sigma_c)) * std::exp(-h * h / (2 * sigma_s * sigma_s));
        sum += w * h;
        normaliser += w;
      }
    moved[v.idx()] = normaliser > 0 ? p + (sum / normaliser) * n : p;
  }
  for(Vertex v : mesh.vertices())
    mesh.point(v) = moved[v.idx()];
  mesh.remove_property_map(normals);
}

} // namespace test_support

#endif // CGAL_HEAT_DIFFUSION_MESH_MEASURES_H
