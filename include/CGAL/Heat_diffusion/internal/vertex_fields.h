// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Scalar fields between the user's vertex property maps and the vectors by vertex
// index that the package computes with.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_FIELDS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_FIELDS_H

#include <CGAL/Heat_diffusion/internal/errors.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <cstddef>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The values of `field` at the vertices of `tm`, at the indices index_of(v) < n,
// checked finite (`where` names the caller, `what` the values in the message).
template <typename TriangleMesh, typename FieldMap, typename IndexOf>
Eigen::VectorXd read_vertex_field(const TriangleMesh& tm, std::size_t n, const FieldMap& field, const IndexOf& index_of,
                                  const char* where, const char* what = "field value")
{
  Eigen::VectorXd values(static_cast<Eigen::Index>(n));
  for(auto v : vertices(tm))
    values[Eigen::Index(index_of(v))] = CGAL::to_double(get(field, v));
  check_finite_values(values, where, what);
  return values;
}

// Writes the values at the indices index_of(v) to `field`, converted to its value type.
template <typename TriangleMesh, typename FieldMap, typename IndexOf>
void write_vertex_field(const TriangleMesh& tm, const Eigen::VectorXd& values, FieldMap field, const IndexOf& index_of)
{
  typedef typename boost::property_traits<FieldMap>::value_type Value;
  for(auto v : vertices(tm))
    put(field, v, Value(values[Eigen::Index(index_of(v))]));
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_FIELDS_H
