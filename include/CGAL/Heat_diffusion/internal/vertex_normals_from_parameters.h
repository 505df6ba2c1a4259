// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The unit vertex normals on the package's indexed copy of a mesh, as the named
// parameters ask for them (a normal map, or a rule of vertex_normals.h).

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_NORMALS_FROM_PARAMETERS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_NORMALS_FROM_PARAMETERS_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/parameters.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Core>

#include <sstream>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

struct Area_weighted_vertex_normals;  // the default rule (vertex_normals.h)

namespace internal {


// The MWAAT rule on the normalised indexed copy: the same normals as
// Area_weighted_vertex_normals, but safe from overflow for huge coordinates.
inline std::vector<Eigen::Vector3d> area_weighted_vertex_normals(const Indexed_mesh& mesh)
{
  std::vector<Eigen::Vector3d> normals(mesh.number_of_vertices(), Eigen::Vector3d::Zero());
  for(const auto& t : mesh.triangles)
  {
    const Eigen::Vector3d cross = mesh.cross_product(t[0], t[1], t[2]);
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
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_NORMALS_FROM_PARAMETERS_H
