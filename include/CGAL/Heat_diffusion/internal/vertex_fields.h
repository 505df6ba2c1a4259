// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Scalar fields between the user's vertex property maps and the vectors by vertex
// index that the package computes with, and the checks of fields given per point.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_FIELDS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_FIELDS_H

#include <CGAL/Heat_diffusion/internal/errors.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// How messages name the vertex of package index `index`: "vertex R", R its rank in
// vertices(tm) (the order of the user's arrays and of make_indexed_mesh()'s messages),
// followed by the index where the two differ (meshes numbered along a Hilbert curve,
// or by a vertex index map of the user's). Linear: for error messages only.
template <typename TriangleMesh, typename IndexOf>
std::string vertex_name(const TriangleMesh& tm, std::size_t index, const IndexOf& index_of)
{
  std::size_t rank = 0;
  for(auto v : vertices(tm))
  {
    if(std::size_t(index_of(v)) == index)
      break;
    ++rank;
  }
  std::string name = "vertex " + std::to_string(rank);
  if(rank != index)
    name += " (index " + std::to_string(index) + " of vertex_index())";
  return name;
}

// Throws std::invalid_argument if a value of `values` (by package index) is not
// finite; the message names the caller, the vertex as vertex_name() does, and the value.
template <typename TriangleMesh, typename IndexOf>
void check_finite_field(const Eigen::VectorXd& values, const TriangleMesh& tm, const IndexOf& index_of,
                        const char* where, const char* what = "field value")
{
  for(Eigen::Index i = 0; i < values.size(); ++i)
    if(!std::isfinite(values[i]))
    {
      std::ostringstream os;
      os << where << ": the " << what << " at " << vertex_name(tm, std::size_t(i), index_of) << " is " << values[i]
         << ", not a finite number";
      throw_invalid_input(os.str());
    }
}

// The values of `field` at the vertices of `tm`, at the indices index_of(v) < n,
// checked finite (`where` names the caller, `what` the values in the message).
template <typename TriangleMesh, typename FieldMap, typename IndexOf>
Eigen::VectorXd read_vertex_field(const TriangleMesh& tm, std::size_t n, const FieldMap& field, const IndexOf& index_of,
                                  const char* where, const char* what = "field value")
{
  Eigen::VectorXd values(static_cast<Eigen::Index>(n));
  for(auto v : vertices(tm))
    values[Eigen::Index(index_of(v))] = CGAL::to_double(get(field, v));
  check_finite_field(values, tm, index_of, where, what);
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

// Throws std::invalid_argument unless `field` has one finite value per point; the
// message names the caller (`where`), the values (`what`) and the first bad point.
inline void check_point_field(const Eigen::VectorXd& field, std::size_t number_of_points, const char* where,
                              const char* what = "field")
{
  if(field.size() != Eigen::Index(number_of_points))
    throw_invalid_input(std::string(where) + ": the " + what + " has " + std::to_string(field.size()) +
                        " values for " + std::to_string(number_of_points) + " points");
  for(Eigen::Index i = 0; i < field.size(); ++i)
    if(!std::isfinite(field[i]))
      throw_invalid_input(std::string(where) + ": the " + what + "'s value at point " + std::to_string(i) +
                          " is not finite");
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_FIELDS_H
