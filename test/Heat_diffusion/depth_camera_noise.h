// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The noise of a depth camera, simulated on a clean mesh for the denoising benchmark
// and tests: what scans made with structured light (Kinect v1 and its kind) carry, and
// what Gaussian noise along the normals does not.

#ifndef CGAL_HEAT_DIFFUSION_DEPTH_CAMERA_NOISE_H
#define CGAL_HEAT_DIFFUSION_DEPTH_CAMERA_NOISE_H

#include "mesh_measures.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace test_support {

// Moves the vertices of `mesh` as a depth camera would measure them. Six cameras look
// at the centre of the bounding box from 1.5 of its diagonal away, along the six axis
// directions turned by 20 degrees about (1, 1, 1) (so that no camera faces a CAD part's
// faces squarely). Each vertex is measured by the camera that sees it most frontally
// among those whose view of it no face blocks (the most frontal of all if none sees
// it), and moves along that camera's ray only:
//  - Gaussian noise of standard deviation sigma(z) = level e (z / z0)^2, e the mean edge
//    length, z the distance from the camera, z0 that of the centre: the axial noise of
//    structured light grows with the square of the depth (Khoshelham and Elberink 2012;
//    Nguyen, Izadi and Lovell 2012);
//  - low-frequency bumps, 2 sigma(z) b_c(p), b_c a smooth random field of root mean
//    square 1 per camera (a sum of 8 plane waves of wavelengths 4 to 12 e in random
//    directions): the depth distortion that calibration and fusion leave, correlated over
//    several edges and larger than the white part, with seams where the cameras meet;
//  - quantisation of the depth in steps of disparity (1 / z), of 2 level e at z0:
//    terraces, as the sensor's sub-pixel disparity steps make them;
//  - flying points: one in five of the vertices seen at grazing incidence (the cosine of
//    the normal and the ray below 0.2) pushed away from the camera by 2 to 6 sigma(z),
//    as pixels that mix the silhouette with the background.
// Seeded: the same mesh every run.
template <typename Mesh>
void add_depth_camera_noise(Mesh& mesh, double level, unsigned seed)
{
  typedef typename Mesh::Point Point;
  typedef typename CGAL::Kernel_traits<Point>::Kernel K;
  typedef typename K::Vector_3 Vector;
  typedef typename Mesh::Vertex_index Vertex;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh> > > Tree;
  auto eigen = [](const Point& p) {
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  const double e = mean_edge_length(mesh);
  const double sigma_0 = level * e;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for(Vertex v : mesh.vertices())
  {
    lo = lo.cwiseMin(eigen(mesh.point(v)));
    hi = hi.cwiseMax(eigen(mesh.point(v)));
  }
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double z_0 = 1.5 * (hi - lo).norm();
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(20. * CGAL_PI / 180., Eigen::Vector3d(1, 1, 1).normalized()).matrix();
  std::vector<Eigen::Vector3d> cameras;
  for(int axis = 0; axis < 3; ++axis)
    for(double sign : {1., -1.})
      cameras.push_back(centre + z_0 * turn * (sign * Eigen::Vector3d::Unit(axis)));

  std::mt19937 generator(seed);
  std::normal_distribution<double> gaussian(0., 1.);
  std::uniform_real_distribution<double> uniform(0., 1.);
  // The bump fields, one per camera.
  struct Wave
  {
    Eigen::Vector3d frequency;
    double phase;
  };
  std::vector<std::array<Wave, 8> > bumps(cameras.size());
  for(auto& field : bumps)
    for(Wave& wave : field)
    {
      Eigen::Vector3d direction(gaussian(generator), gaussian(generator), gaussian(generator));
      direction.normalize();
      const double wavelength = (4. + 8. * uniform(generator)) * e;
      wave.frequency = direction * (2. * CGAL_PI / wavelength);
      wave.phase = 2. * CGAL_PI * uniform(generator);
    }

  auto normals = mesh.template add_property_map<Vertex, Vector>("v:depth_camera_normal").first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
  const Tree tree(faces(mesh).first, faces(mesh).second, mesh);
  const double disparity_step = 2. * sigma_0 / (z_0 * z_0);
  std::vector<Point> moved;
  moved.reserve(mesh.number_of_vertices());
  for(Vertex v : mesh.vertices())
  {
    const Eigen::Vector3d p = eigen(mesh.point(v));
    const Eigen::Vector3d n(CGAL::to_double(normals[v].x()), CGAL::to_double(normals[v].y()),
                            CGAL::to_double(normals[v].z()));
    // The most frontal camera that sees p, or the most frontal one.
    std::size_t best = 0;
    double best_cosine = -2, best_visible_cosine = -2;
    std::size_t best_visible = cameras.size();
    for(std::size_t c = 0; c < cameras.size(); ++c)
    {
      const Eigen::Vector3d to_camera = (cameras[c] - p).normalized();
      const double cosine = n.dot(to_camera);
      if(cosine > best_cosine)
      {
        best_cosine = cosine;
        best = c;
      }
      if(cosine > 0 && cosine > best_visible_cosine)
      {
        const Eigen::Vector3d start = p + 1e-3 * e * to_camera;
        const typename K::Segment_3 sight(Point(start.x(), start.y(), start.z()),
                                          Point(cameras[c].x(), cameras[c].y(), cameras[c].z()));
        if(!tree.do_intersect(sight))
        {
          best_visible_cosine = cosine;
          best_visible = c;
        }
      }
    }
    const std::size_t c = best_visible < cameras.size() ? best_visible : best;
    const double cosine = best_visible < cameras.size() ? best_visible_cosine : best_cosine;
    const Eigen::Vector3d ray = p - cameras[c];
    const double z = ray.norm();
    const Eigen::Vector3d u = ray / z;  // away from the camera
    const double sigma = sigma_0 * (z / z_0) * (z / z_0);
    double bump = 0;
    for(const Wave& wave : bumps[c])
      bump += std::sqrt(2. / 8.) * std::sin(wave.frequency.dot(p) + wave.phase);
    const double measured = z + sigma * (gaussian(generator) + 2. * bump);
    double depth = 1. / (disparity_step * std::round(1. / (measured * disparity_step)));
    const double flying = uniform(generator);
    if(std::abs(cosine) < 0.2 && flying < 0.2)
      depth += (2. + 4. * uniform(generator)) * sigma;
    const Eigen::Vector3d q = cameras[c] + depth * u;
    moved.emplace_back(q.x(), q.y(), q.z());
  }
  std::size_t i = 0;
  for(Vertex v : mesh.vertices())
    mesh.point(v) = moved[i++];
  mesh.remove_property_map(normals);
}

} // namespace test_support

#endif // CGAL_HEAT_DIFFUSION_DEPTH_CAMERA_NOISE_H
