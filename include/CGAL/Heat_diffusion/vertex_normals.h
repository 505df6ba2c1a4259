// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Vertex normal rules: how the package obtains the normals that NCC are measured against.

#ifndef CGAL_HEAT_DIFFUSION_VERTEX_NORMALS_H
#define CGAL_HEAT_DIFFUSION_VERTEX_NORMALS_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/parameters.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <sstream>
#include <type_traits>
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

/// \cond SKIP_IN_MANUAL
namespace internal {

// The MWAAT rule on the normalised indexed copy: the same normals as
// Area_weighted_vertex_normals, but safe from overflow for huge coordinates.
inline std::vector<Eigen::Vector3d> area_weighted_vertex_normals(const Indexed_mesh& mesh)
{
  std::vector<Eigen::Vector3d> normals(mesh.number_of_vertices(), Eigen::Vector3d::Zero());
  for(const auto& t : mesh.triangles)
  {
    const Eigen::Vector3d cross =
        (mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]);
    for(std::size_t i : t)
      normals[i] += cross;
  }
  for(Eigen::Vector3d& n : normals)
  {
    const double length = n.norm();
    n = length > 0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
  }
  return normals;
}

// Unit vertex normals as the named parameters ask for them: `vertex_normal_map`
// when given (its vectors are normalised), else the `vertex_normal_rule`
// (default: Area_weighted_vertex_normals). Throws if a normal is null or not finite.
template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap, typename GeomTraits,
          typename NamedParameters>
std::vector<Eigen::Vector3d> vertex_normals(const Indexed_mesh& mesh, const TriangleMesh& tm,
                                            VertexPointMap vpm, VertexIndexMap vim, const GeomTraits& gt,
                                            const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename GeomTraits::Vector_3 Vector_3;

  std::vector<Eigen::Vector3d> normals;
  auto read_back = [&](auto normal_map) {
    normals.resize(mesh.number_of_vertices());
    for(auto v : vertices(tm))
    {
      const Vector_3& n = get(normal_map, v);
      normals[static_cast<std::size_t>(get(vim, v))] =
          Eigen::Vector3d(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
    }
  };

  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::vertex_normal_map_t,
                                                             NamedParameters,
                                                             CGAL::internal_np::Param_not_found>::type
      User_normals;
  typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np::vertex_normal_rule_t,
                                                             NamedParameters,
                                                             Area_weighted_vertex_normals>::type Rule;
  if constexpr(!std::is_same<User_normals, CGAL::internal_np::Param_not_found>::value)
    read_back(get_parameter(np, CGAL::internal_np::vertex_normal_map));
  else if constexpr(std::is_same<Rule, Area_weighted_vertex_normals>::value)
    normals = area_weighted_vertex_normals(mesh);
  else
  {
    auto normal_map = get(CGAL::dynamic_vertex_property_t<Vector_3>(), tm);
    const Rule rule = choose_parameter<Rule>(get_parameter(np, internal_np::vertex_normal_rule));
    rule(tm, vpm, normal_map, gt);
    read_back(normal_map);
  }

  for(std::size_t i = 0; i < normals.size(); ++i)
  {
    const double length = normals[i].norm();
    if(!(length > 0) || !std::isfinite(length))
    {
      std::ostringstream os;
      os << "vertex " << i << " has no usable normal (" << normals[i].transpose()
         << "); its incident face normals cancel, or the given normal is null or not finite";
      throw_invalid_input(os.str());
    }
    normals[i] /= length;
  }
  return normals;
}

} // namespace internal
/// \endcond

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_VERTEX_NORMALS_H
