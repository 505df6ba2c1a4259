// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Least-squares reconstruction of vertex positions from a Normal Signature (paper, eq. 23).

#ifndef CGAL_HEAT_DIFFUSION_RECONSTRUCTION_H
#define CGAL_HEAT_DIFFUSION_RECONSTRUCTION_H

#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/ncc_reconstruction.h>
#include <CGAL/Heat_diffusion/internal/vertex_fields.h>
#include <CGAL/Heat_diffusion/internal/vertex_normals_from_parameters.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>

#include <Eigen/Core>

#include <cmath>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionNCC
/// Moves the vertices of `tm` so that their NCC match the Normal Signature `ns_map`
/// along the target normals, in the least-squares sense (paper, eq. 23):
/// \f[ \min_{\mathbf{V}'} \; \|\mathbf{N}\mathbf{V}' - \mathbf{S}'\mathbf{n}'\|^2
///     + \sum_i \frac{w^2}{a_i} \|v'_i - v_i\|^2 , \f]
/// where \f$ \mathbf{N} \f$ is the NCC operator of the current mesh (its weights, the
/// "local parameterisation", are kept, and so are the tangential parts of the
/// differential coordinates of boundary vertices, added to the target as
/// `Normal_controlled_coordinates` explains), \f$ \mathbf{S}' \f$ the given signature,
/// \f$ \mathbf{n}' \f$ the target normals, \f$ v_i \f$ the current positions acting as
/// anchors, \f$ a_i \f$ the mixed Voronoi areas and \f$ w \f$ the `anchor_weight`.
/// Dividing the anchors by \f$ \sqrt{a_i} \f$ gives both terms the same unit (NCC are
/// dimensionless), so the result does not depend on the scale of the mesh. The paper
/// weights the anchors by the NS, which can be zero or negative; the package uses
/// this positive weight instead.
///
/// The normal equations \f$ (\mathbf{N}^T\mathbf{N} + \mathbf{W}^2)\mathbf{V}' =
/// \mathbf{N}^T\mathbf{S}'\mathbf{n}' + \mathbf{W}^2\mathbf{V} \f$ are factorised once
/// (sparse Cholesky) and solved for the three coordinates. With the mesh's own NS
/// and normals the input is returned (up to rounding), open meshes included.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// @tparam VertexNSMap a model of `ReadablePropertyMap` with `vertex_descriptor` as
///   key and a floating-point type as value type
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`; the new positions are written to it}
///     \cgalParamType{a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and `GeomTraits::Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_normal_map}
///     \cgalParamDescription{the target normals \f$ n'_i \f$ (normalised before use)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `GeomTraits::Vector_3` as value type}
///     \cgalParamDefault{the normals of the current mesh, from the `vertex_normal_rule`}
///   \cgalParamNEnd
///   \cgalParamNBegin{anchor_weight}
///     \cgalParamDescription{the weight \f$ w \f$ of the positional anchors: larger keeps vertices closer to their current positions}
///     \cgalParamType{`double`, positive and finite}
///     \cgalParamDefault{`1.0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_normal_rule}
///     \cgalParamDescription{how the normals of the current mesh are computed (they define \f$ \mathbf{N} \f$)}
///     \cgalParamType{a model of `VertexNormalRule`}
///     \cgalParamDefault{`Area_weighted_vertex_normals()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in `[0, n)`, `n` the number of vertices in `vertices(tm)` (removed vertices of a `Surface_mesh` are not counted)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{a \cgal kernel deduced from the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument on a mesh the package cannot process (see
///   `Normal_controlled_coordinates`), a non-finite signature value, an unusable target
///   normal, or an `anchor_weight` that is not positive and finite.
/// \throws std::runtime_error if the sparse factorisation fails.
///
/// Complexity: one sparse Cholesky factorisation of an n x n matrix with the sparsity
/// of the two-ring, and three solves.
template <typename TriangleMesh, typename VertexNSMap,
          typename NamedParameters = parameters::Default_named_parameters>
void reconstruct_from_normal_signature(TriangleMesh& tm, const VertexNSMap& ns_map,
                                       const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GeomTraits;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np::vertex_normal_rule_t,
                                                             NamedParameters,
                                                             Area_weighted_vertex_normals>::type Rule;

  const double anchor_weight = internal::checked_positive(
      internal::parameter_value(np, internal_np::anchor_weight, defaults::reconstruction_anchor_weight), "reconstruct_from_normal_signature",
      "anchor_weight");

  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, tm));
  // The user's numbering or the rank in vertices(tm), without gaps where a
  // Surface_mesh has removed vertices.
  const auto vim = internal::vertex_numbering(tm, np);
  const GeomTraits gt = choose_parameter<GeomTraits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const Rule rule = choose_parameter<Rule>(get_parameter(np, internal_np::vertex_normal_rule));

  // N comes from the current mesh and its own normals; the vertex_normal_map, if
  // any, gives the target normals only.
  const Normal_controlled_coordinates<TriangleMesh, GeomTraits> ncc(
      tm, parameters::vertex_normal_rule(rule).vertex_point_map(vpm).vertex_index_map(vim).geom_traits(gt));
  const internal::Indexed_mesh& mesh = ncc.indexed_mesh();
  const std::size_t n = mesh.number_of_vertices();
  if(n == 0)
    return;

  // The target normals: the user's, or else the current ones, already computed.
  const bool user_normals = !parameters::is_default_parameter<NamedParameters,
                                                              CGAL::internal_np::vertex_normal_map_t>::value;
  const std::vector<Eigen::Vector3d> target_normals =
      user_normals ? internal::vertex_normals(mesh, tm, vpm, vim, gt, np) : ncc.data().normals;

  const Eigen::VectorXd signature = internal::read_vertex_field(
      tm, n, ns_map, [&ncc](auto v) { return ncc.vertex_index(v); }, "reconstruct_from_normal_signature",
      "normal signature");
  const Eigen::MatrixXd solution = internal::reconstruct_positions(mesh, ncc.data(), signature, target_normals,
                                                                   anchor_weight, "reconstruct_from_normal_signature");
  for(auto v : vertices(tm))
  {
    const Eigen::Vector3d x = mesh.to_user_frame(solution.row(Eigen::Index(ncc.vertex_index(v))).transpose());
    put(vpm, v, Point_3(x.x(), x.y(), x.z()));
  }
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_RECONSTRUCTION_H
