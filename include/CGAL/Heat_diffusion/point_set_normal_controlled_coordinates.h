// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Normal-Controlled Coordinates (NCC) and the Normal Signature (NS) of a point set:
// paper, section 3, on the local fans of the points.

#ifndef CGAL_HEAT_DIFFUSION_POINT_SET_NORMAL_CONTROLLED_COORDINATES_H
#define CGAL_HEAT_DIFFUSION_POINT_SET_NORMAL_CONTROLLED_COORDINATES_H

#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/point_set_surface.h>
#include <CGAL/Heat_diffusion/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Whether a range without a normal_map parameter has normals of its own: a
// Point_set_3 may have a normal property; other ranges have none.
template <typename PointRange>
bool has_own_normals(const PointRange&)
{
  return false;
}

template <typename Point, typename Vector>
bool has_own_normals(const CGAL::Point_set_3<Point, Vector>& points)
{
  return points.has_normal_map();
}

// The points of a range, its normals if it has some (else empty), and the options of its
// surface, as Point_set_processing_3 reads its named parameters.
struct Point_set_input
{
  std::vector<Eigen::Vector3d> points, normals;
  Point_set_surface_options options;
};

template <typename PointRange, typename NamedParameters>
Point_set_input read_point_set_input(const PointRange& points, unsigned int k, const NamedParameters& np)
{
  typedef CGAL::Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  const auto point_map = NP_helper::get_const_point_map(points, np);
  const bool given_normals =
      !parameters::is_default_parameter<NamedParameters, CGAL::internal_np::normal_t>::value ||
      has_own_normals(points);
  Point_set_input input;
  for(const auto& item : points)
  {
    const auto& x = get(point_map, item);
    input.points.emplace_back(CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z()));
  }
  if(given_normals)
  {
    const auto normal_map = NP_helper::get_normal_map(points, np);
    for(const auto& item : points)
    {
      const auto& v = get(normal_map, item);
      input.normals.emplace_back(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
    }
  }
  input.options.k = k;
  input.options.neighbor_radius = CGAL::to_double(
      parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::neighbor_radius), 0.));
  return input;
}

template <typename PointRange, typename NamedParameters>
Point_set_surface make_point_set_surface(const PointRange& points, unsigned int k, const NamedParameters& np)
{
  Point_set_input input = read_point_set_input(points, k, np);
  return make_point_set_surface(std::move(input.points), std::move(input.normals), input.options);
}

} // namespace internal

/// \ingroup PkgHeatDiffusionNCC
/// The Normal-Controlled Coordinates of a point set, computed once and queried many
/// times: for each point, the NCC \f$ \delta'_i \f$ (paper, eq. 4), the Normal
/// Signature \f$ s_i \f$, the normal and the Voronoi area they are made of.
///
/// <b>The surface of the points.</b> Each point gets a one-ring of its own, its
/// <em>fan</em>: the Delaunay triangulation (`CGAL::Delaunay_triangulation_2`) of its
/// `k` nearest neighbours (or those within `neighbor_radius`) projected on its tangent
/// plane, of which the triangles at the point are kept (Sharp and Crane, "A Laplacian
/// for Nonmanifold Triangle Meshes", SGP 2020, section 5.7). The NCC of the point is that
/// of a mesh vertex whose one-ring is its fan: mean value weights on the tangent plane
/// and the mixed Voronoi area of the fan's triangles at the point, so that where the fan
/// is a mesh's one-ring, the NS is the mesh's. A point that lies on the hull of its
/// projected neighbours has an open fan: a <em>border point</em>, treated as a boundary
/// vertex of a mesh (its NCC is the normal component of its differential coordinate).
///
/// <b>Normals.</b> The tangent plane is that of the given normals (the `normal_map`,
/// or the normal property of a `CGAL::Point_set_3` that has one), which the NCC is then
/// measured against. They also choose the neighbours: the fan of a point is made of the
/// `k` nearest points on its side of the surface (\f$ n_i \cdot n_j > 0 \f$, searched among
/// up to `8k` nearest points; with `neighbor_radius`, those within it), so that the two
/// sides of a thin part, or of a sharp crease, do not make one fan. Without normals, the tangent plane is that of
/// `CGAL::jet_estimate_normals()`, oriented by `CGAL::mst_orient_normals()` (both over
/// the `k` nearest neighbours; with a radius and `k = 0`, as many as the point with the
/// fewest neighbours within the radius has), and the NCC is measured against the
/// area-weighted normal of the point's fan, as for a mesh (the paper's MWAAT normals).
/// Two fans that hold the same triangle list it in the same orientation exactly when
/// their normals agree: a normal that disagrees with most of its neighbours' in this
/// sense is flipped, and if the triangles listed in opposite orientations are then
/// still more than 1 % of the points (`mst_orient_normals()` crossed a thin part of the
/// shape and flipped a region: measured on the vertices of CGAL's `elephant.off`), the
/// construction throws; give the normals then.
///
/// Points are numbered by their position in the range, `0` to `number_of_points() - 1`.
///
/// @tparam PointRange a model of `ConstRange` whose iterator type is `InputIterator`
/// @tparam GeomTraits a model of `Kernel`; its `Vector_3` is the type of the NCC
template <typename PointRange,
          typename GeomTraits = typename CGAL::Point_set_processing_3_np_helper<
              PointRange, parameters::Default_named_parameters>::Geom_traits>
class Point_set_normal_controlled_coordinates
{
public:
  /// The vector type of the NCC and the normals.
  typedef typename GeomTraits::Vector_3 Vector_3;

  /// Computes the NCC of every point of `points`.
  ///
  /// @param points the points
  /// @param k the number of neighbours of each point (with `neighbor_radius`: at most
  ///   that many of the neighbours within the radius, the nearest; 0 for no limit)
  /// @param np the named parameters below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{point_map}
  ///     \cgalParamDescription{a property map associating points to the elements of the point range}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with value type `GeomTraits::Point_3`}
  ///     \cgalParamDefault{`CGAL::Identity_property_map<GeomTraits::Point_3>` (the point map of a `CGAL::Point_set_3`)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{normal_map}
  ///     \cgalParamDescription{oriented normals of the points (they are normalised), outward for a closed surface}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with value type `GeomTraits::Vector_3`}
  ///     \cgalParamDefault{the normal map of a `CGAL::Point_set_3` that has one; else the normals are estimated (see above)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{neighbor_radius}
  ///     \cgalParamDescription{the radius of the neighbourhoods, in the units of the points}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{`0`: the `k` nearest neighbours}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{geom_traits}
  ///     \cgalParamDescription{an instance of a geometric traits class}
  ///     \cgalParamType{`GeomTraits`}
  ///     \cgalParamDefault{the kernel of the point type}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws std::invalid_argument, naming the point, on input the package cannot
  ///   process: a non-finite coordinate or normal, a null normal, fewer than `k + 1`
  ///   points, two points that coincide, a neighbourhood whose projection on the tangent
  ///   plane is collinear (no fan), an estimated normal that `CGAL::mst_orient_normals()`
  ///   cannot orient (for example on a point set of several connected components) or
  ///   orients inconsistently with the fans (see above): give the normals then; if `k < 2`
  ///   without a radius, or a radius that is negative or not finite.
  ///
  /// Complexity: \f$ O(n \log n) \f$ for the neighbour search, then linear in the number
  /// of points for fixed `k` (parallel over points with TBB).
  template <typename NamedParameters = parameters::Default_named_parameters>
  Point_set_normal_controlled_coordinates(const PointRange& points, unsigned int k,
                                          const NamedParameters& np = parameters::default_values())
    : surface_(internal::make_point_set_surface(points, k, np))
  {}

  /// The number of points.
  std::size_t number_of_points() const { return surface_.number_of_points(); }

  /// The NCC \f$ \delta'_i = s_i n_i \f$ of point `i` (dimensionless).
  Vector_3 ncc(std::size_t i) const
  {
    const Eigen::Vector3d d = surface_.ncc.signature[i] * surface_.ncc.normals[i];
    return Vector_3(d.x(), d.y(), d.z());
  }

  /// The Normal Signature \f$ s_i \f$ of point `i`: positive where the surface is
  /// convex (along the outward normal), negative where it is concave.
  double normal_signature(std::size_t i) const { return surface_.ncc.signature[i]; }

  /// The unit normal the NCC of point `i` was measured against.
  Vector_3 normal(std::size_t i) const
  {
    const Eigen::Vector3d& n = surface_.ncc.normals[i];
    return Vector_3(n.x(), n.y(), n.z());
  }

  /// The mixed Voronoi area of point `i` in its fan, in the units of the points.
  double voronoi_area(std::size_t i) const
  {
    return surface_.ncc.areas[i] / (surface_.mesh.scale * surface_.mesh.scale);
  }

  /// Whether the fan of point `i` is open: `i` lies on the hull of its projected
  /// neighbours (the border of a scan, or a sampling too sparse around it).
  bool is_border_point(std::size_t i) const { return surface_.mesh.fan_is_closed[i] == 0; }

  /// The neighbours of point `i` in its fan, clockwise around its normal.
  std::vector<std::size_t> fan(std::size_t i) const
  {
    return std::vector<std::size_t>(surface_.local_fan.begin() + std::ptrdiff_t(surface_.local_fan_begin[i]),
                                    surface_.local_fan.begin() + std::ptrdiff_t(surface_.local_fan_begin[i + 1]));
  }

  /// \cond SKIP_IN_MANUAL
  const internal::Point_set_surface& surface() const { return surface_; }
  /// \endcond

private:
  internal::Point_set_surface surface_;
};

/// \ingroup PkgHeatDiffusionNCC
/// Computes the Normal Signature of every point of `points` and writes it to `ns_map`.
/// See `Point_set_normal_controlled_coordinates` for the definition, the named
/// parameters, the errors and the complexity.
///
/// @tparam PointRange a model of `ConstRange` whose iterator type is `InputIterator`
/// @tparam PointNSMap a model of `WritablePropertyMap` with the value type of the
///   range as key (the `Index` of a `CGAL::Point_set_3`) and a floating-point value type
template <typename PointRange, typename PointNSMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_point_set_normal_signature(const PointRange& points, unsigned int k, PointNSMap ns_map,
                                        const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::Point_set_processing_3_np_helper<PointRange, NamedParameters>::Geom_traits GeomTraits;
  typedef typename boost::property_traits<PointNSMap>::value_type Value;
  const Point_set_normal_controlled_coordinates<PointRange, GeomTraits> ncc(points, k, np);
  std::size_t i = 0;
  for(const auto& item : points)
    put(ns_map, item, Value(ncc.normal_signature(i++)));
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_POINT_SET_NORMAL_CONTROLLED_COORDINATES_H
