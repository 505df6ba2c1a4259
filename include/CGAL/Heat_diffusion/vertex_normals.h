// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Vertex normal rules: how the package obtains the normals that NCC are measured against.

#ifndef CGAL_HEAT_DIFFUSION_VERTEX_NORMALS_H
#define CGAL_HEAT_DIFFUSION_VERTEX_NORMALS_H

#include <CGAL/Heat_diffusion/parameters.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionNormals
/// The paper's vertex normals (MWAAT, "mean weighted by areas of adjacent
/// triangles"): the sum of the un-normalised cross products of the incident faces,
/// normalised. This is the default rule of the package. Model of `VertexNormalRule`.
///
/// The computation is done in double. A vertex whose incident face normals cancel
/// exactly gets the null vector, which the package's functions reject with an
/// exception naming the vertex.
struct Area_weighted_vertex_normals
{
  /// Writes the unit normal of every vertex of `tm` to `normals`.
  template <typename TriangleMesh, typename VertexPointMap, typename VertexNormalMap, typename GeomTraits>
  void operator()(const TriangleMesh& tm, VertexPointMap vpm, VertexNormalMap normals,
                  const GeomTraits&) const
  {
    typedef typename boost::property_traits<VertexNormalMap>::value_type Vector_3;
    typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
    auto sum = get(CGAL::dynamic_vertex_property_t<Eigen::Vector3d>(), tm);
    for(vertex_descriptor v : vertices(tm))
      put(sum, v, Eigen::Vector3d::Zero());
    auto as_eigen = [&](vertex_descriptor v) {
      const auto& p = get(vpm, v);
      return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    };
    for(auto f : faces(tm))
    {
      const auto h = halfedge(f, tm);
      const vertex_descriptor a = source(h, tm), b = target(h, tm), c = target(next(h, tm), tm);
      const Eigen::Vector3d cross = (as_eigen(b) - as_eigen(a)).cross(as_eigen(c) - as_eigen(a));
      for(vertex_descriptor v : {a, b, c})
        put(sum, v, Eigen::Vector3d(get(sum, v) + cross));
    }
    for(vertex_descriptor v : vertices(tm))
    {
      const Eigen::Vector3d s = get(sum, v);
      const double length = s.norm();
      const Eigen::Vector3d u = length > 0 ? Eigen::Vector3d(s / length) : Eigen::Vector3d::Zero();
      put(normals, v, Vector_3(u.x(), u.y(), u.z()));
    }
  }
};

/// \ingroup PkgHeatDiffusionNormals
/// CGAL's own vertex normals, `CGAL::Polygon_mesh_processing::compute_vertex_normals()`
/// (a weighting of the incident face normals by the angles they subtend, with a
/// fallback for degenerate cases). Model of `VertexNormalRule`.
struct Polygon_mesh_processing_vertex_normals
{
  /// Writes the unit normal of every vertex of `tm` to `normals`.
  template <typename TriangleMesh, typename VertexPointMap, typename VertexNormalMap, typename GeomTraits>
  void operator()(const TriangleMesh& tm, VertexPointMap vpm, VertexNormalMap normals,
                  const GeomTraits& gt) const
  {
    CGAL::Polygon_mesh_processing::compute_vertex_normals(
        tm, normals, CGAL::parameters::vertex_point_map(vpm).geom_traits(gt));
  }
};

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_VERTEX_NORMALS_H
