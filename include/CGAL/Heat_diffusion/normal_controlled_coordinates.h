// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Normal-Controlled Coordinates (NCC) and the Normal Signature (NS): paper, section 3.

#ifndef CGAL_HEAT_DIFFUSION_NORMAL_CONTROLLED_COORDINATES_H
#define CGAL_HEAT_DIFFUSION_NORMAL_CONTROLLED_COORDINATES_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/ncc_weights.h>
#include <CGAL/Heat_diffusion/internal/vertex_normals_from_parameters.h>
#include <CGAL/Heat_diffusion/parameters.h>
#include <CGAL/Heat_diffusion/vertex_normals.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/internal/named_params_helper.h>

#include <Eigen/Sparse>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionNCC
/// The Normal-Controlled Coordinates of a triangle mesh, computed once and queried
/// many times: the NCC \f$ \delta'_i \f$ (paper, eq. 4), the Normal Signature
/// \f$ s_i = \delta'_i \cdot n_i \f$, the normals and mixed Voronoi areas they are made
/// of, and the NCC operator \f$ \mathbf{N} \f$ of eq. 6.
///
/// The NCC of a vertex is \f$ \delta'_i = a_i^{-1/2} \sum_j \omega_{ij} (v_i - v_j) \f$,
/// with \f$ \omega_{ij} \f$ the mean value weights of the one-ring projected onto the
/// tangent plane (signed angles), normalised to sum 1, and \f$ a_i \f$ the mixed Voronoi
/// area of Meyer et al. It is parallel to the vertex normal and invariant under
/// rigid motions and uniform scaling: it is dimensionless.
///
/// <b>Boundary vertices.</b> On an open fan, mean value weights (with one angle
/// less) lose their linear precision: the differential coordinate
/// \f$ r_i = (\mathbf{N}\mathbf{V})_i \f$ gets a tangential part, the "tangential
/// tension" of Laplacian coordinates (paper, Fig. 3). The NCC is its normal component,
/// \f$ \delta'_i = (r_i \cdot n_i)\, n_i \f$, so NCC are parallel to the normals on
/// boundary vertices too, and `reconstruct_from_normal_signature()` holds the
/// tangential part fixed as local parameterisation, so that an unedited open mesh is
/// reproduced. On interior vertices the tangential part vanishes up to rounding (the
/// parallel property of the paper's appendix), and taking the normal component only
/// removes that rounding.
///
/// <b>Folded fans.</b> Where the mean value weights are undefined (a neighbour that
/// projects onto the vertex, or weights that nearly cancel on a badly folded fan:
/// the absolute value of their sum is below a tenth of the sum of their absolute
/// values; a fan folded over the vertex, with a negative sum, is fine), the vertex uses
/// uniform weights; its differential coordinate then has a tangential part, which is
/// treated as on boundary vertices.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// @tparam GeomTraits a model of `Kernel`; its `Vector_3` is the type of the NCC
///
/// All computations are done in double precision, whatever the kernel.
template <typename TriangleMesh,
          typename GeomTraits = typename CGAL::Kernel_traits<typename boost::property_traits<
              typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel>
class Normal_controlled_coordinates
{
public:
  /// The vertex type of `TriangleMesh`.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// The vector type of the NCC and the normals.
  typedef typename GeomTraits::Vector_3 Vector_3;
  /// The number type of `GeomTraits`.
  typedef typename GeomTraits::FT FT;
  /// The sparse matrix type of the NCC operator.
  typedef Eigen::SparseMatrix<double> Sparse_matrix;

  /// Computes the NCC of every vertex of `tm`.
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `GeomTraits::Point_3` as value type}
  ///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_index_map}
  ///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in `[0, n)`, `n` the number of vertices in `vertices(tm)` (removed vertices of a `Surface_mesh` are not counted), the row of the vertex in `operator_matrix()`}
  ///     \cgalParamExtra{without it, meshes of at least 100000 vertices are numbered along a Hilbert curve (see `vertex_index()`)}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `std::size_t` as value type}
  ///     \cgalParamDefault{the rank of the vertex in `vertices(tm)`, so that a `Surface_mesh` with removed elements needs no `collect_garbage()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_normal_map}
  ///     \cgalParamDescription{the vertex normals to measure the NCC against (they are normalised)}
  ///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `GeomTraits::Vector_3` as value type}
  ///     \cgalParamDefault{normals computed by the `vertex_normal_rule`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_normal_rule}
  ///     \cgalParamDescription{how normals are computed when no `vertex_normal_map` is given}
  ///     \cgalParamType{a model of `VertexNormalRule`: `Area_weighted_vertex_normals` or `Polygon_mesh_processing_vertex_normals`}
  ///     \cgalParamDefault{`Area_weighted_vertex_normals()` (the paper's MWAAT normals)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{geom_traits}
  ///     \cgalParamDescription{an instance of a geometric traits class}
  ///     \cgalParamType{`GeomTraits`}
  ///     \cgalParamDefault{a default-constructed `GeomTraits`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws std::invalid_argument if `tm` has a face that is not a triangle, a face of
  ///   zero area (or of corners collinear up to rounding), an isolated or non-manifold vertex, a non-finite coordinate, or a
  ///   vertex without a usable normal; the message names the element.
  ///
  /// Complexity: linear in the size of `tm` (parallel over vertices with TBB).
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Normal_controlled_coordinates(const TriangleMesh& tm,
                                         const NamedParameters& np = parameters::default_values())
    : tm_(tm), index_(get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm))
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, tm));
    const GeomTraits gt = choose_parameter<GeomTraits>(get_parameter(np, CGAL::internal_np::geom_traits));
    // The user's numbering, or the order of vertices(tm) (not the mesh's own index
    // map, which has gaps where a Surface_mesh has removed vertices): the numbers of
    // the vertices in the messages of make_indexed_mesh().
    internal::number_vertices(tm, np, index_);
    // Large meshes are then numbered along a Hilbert curve (memory order of the
    // diffusion), unless the user gave the numbering; the curve is computed while
    // the mesh is copied and checked.
    std::vector<std::size_t> hilbert_rank;
    if(parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_index_t>::value &&
       internal::number_of_listed_vertices(tm) >= internal::spatial_order_threshold)
      internal::parallel_invoke([&] { hilbert_rank = internal::ranks_along_hilbert_curve(tm, vpm); },
                                [&] { mesh_ = internal::make_indexed_mesh(tm, vpm, index_); });
    else
      mesh_ = internal::make_indexed_mesh(tm, vpm, index_);
    if(!hilbert_rank.empty())
    {
      internal::renumber_vertices(mesh_, hilbert_rank);
      for(auto v : vertices(tm))
        put(index_, v, hilbert_rank[get(index_, v)]);
      try
      {
        data_ = internal::compute_ncc_data(mesh_, internal::vertex_normals(mesh_, tm, vpm, index_, gt, np));
        return;
      }
      catch(const std::invalid_argument&)
      {
        // again in the order of vertices(tm), so that the message numbers the vertices
        // as the mesh lists them
        internal::number_vertices(tm, np, index_);
        mesh_ = internal::make_indexed_mesh(tm, vpm, index_);
      }
    }
    data_ = internal::compute_ncc_data(mesh_, internal::vertex_normals(mesh_, tm, vpm, index_, gt, np));
  }

  /// The row of `v` in `operator_matrix()`: its index in the vertex index map if one
  /// was given; otherwise, for meshes of at least 100000 vertices, its rank along a
  /// Hilbert curve of the vertices (the memory-bound sparse products of the diffusion
  /// then read nearly sequentially; the user manual's Performance section gives the
  /// gain), and its rank in `vertices(tm)` for smaller meshes (the mesh's
  /// own index when it has no removed elements).
  std::size_t vertex_index(vertex_descriptor v) const { return get(index_, v); }

  /// The NCC \f$ \delta'_v = s_v n_v \f$ of `v` (dimensionless).
  Vector_3 ncc(vertex_descriptor v) const
  {
    const std::size_t i = vertex_index(v);
    const Eigen::Vector3d d = data_.signature[i] * data_.normals[i];
    return Vector_3(d.x(), d.y(), d.z());
  }

  /// The Normal Signature \f$ s_v = \delta'_v \cdot n_v \f$ of `v`: positive where `v`
  /// lies outside its neighbours' weighted average along the (outward) normal, i.e.
  /// at convex vertices, negative at concave ones, zero on flat regions.
  double normal_signature(vertex_descriptor v) const { return data_.signature[vertex_index(v)]; }

  /// The unit normal of `v` the NCC was measured against.
  Vector_3 normal(vertex_descriptor v) const
  {
    const Eigen::Vector3d& n = data_.normals[vertex_index(v)];
    return Vector_3(n.x(), n.y(), n.z());
  }

  /// The mixed Voronoi area \f$ a_v \f$ of `v`, in the units of the mesh.
  double voronoi_area(vertex_descriptor v) const
  {
    return data_.areas[vertex_index(v)] / (mesh_.scale * mesh_.scale);
  }

  /// The tangential part of the differential coordinate of `v` (see the class
  /// description): non-zero on boundary vertices and on folded fans only.
  Vector_3 tangential_part(vertex_descriptor v) const
  {
    const Eigen::Vector3d& t = data_.tangential_part[vertex_index(v)];
    return Vector_3(t.x(), t.y(), t.z());
  }

  /// The NCC operator \f$ \mathbf{N} \f$ of eq. 6, in the units of the mesh:
  /// \f$ N_{ii} = a_i^{-1/2} \f$, \f$ N_{ij} = -\omega_{ij} a_i^{-1/2} \f$, so that
  /// \f$ \mathbf{N} \mathbf{V} = \boldsymbol{\delta}' \f$ for the matrix \f$ \mathbf{V} \f$ of the
  /// vertex positions (one row per vertex, in the order of `vertex_index()`), plus
  /// the tangential parts (see the class description). Every row sums to 0.
  Sparse_matrix operator_matrix() const { return internal_operator_matrix() * mesh_.scale; }

  /// \cond SKIP_IN_MANUAL
  const TriangleMesh& mesh() const { return tm_; }
  const internal::Indexed_mesh& indexed_mesh() const { return mesh_; }
  const internal::Ncc_data& data() const { return data_; }

  // N in the normalised frame of indexed_mesh().
  Sparse_matrix internal_operator_matrix() const { return internal::ncc_operator_matrix(mesh_, data_); }
  /// \endcond

private:
  const TriangleMesh& tm_;
  typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::const_type index_;
  internal::Indexed_mesh mesh_;
  internal::Ncc_data data_;
};

/// \ingroup PkgHeatDiffusionNCC
/// Computes the Normal-Controlled Coordinates (paper, eq. 4) of every vertex of `tm`
/// and writes them to `ncc_map`. See `Normal_controlled_coordinates` for the
/// definition, the rule on boundary vertices and folded fans, and the named parameters
/// (the same are accepted here).
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// @tparam VertexNCCMap a model of `WritablePropertyMap` with `vertex_descriptor` as key
///   and `GeomTraits::Vector_3` as value type
///
/// \throws std::invalid_argument on input the package cannot process (see
///   `Normal_controlled_coordinates`). An empty mesh is not an error: nothing is written.
///
/// Complexity: linear in the size of `tm`.
template <typename TriangleMesh, typename VertexNCCMap,
          typename NamedParameters = parameters::Default_named_parameters>
void compute_normal_controlled_coordinates(const TriangleMesh& tm, VertexNCCMap ncc_map,
                                           const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GeomTraits;
  const Normal_controlled_coordinates<TriangleMesh, GeomTraits> ncc(tm, np);
  for(auto v : vertices(tm))
    put(ncc_map, v, ncc.ncc(v));
}

/// \ingroup PkgHeatDiffusionNCC
/// Computes the Normal Signature \f$ s_v = \delta'_v \cdot n_v \f$ of every vertex
/// of `tm` and writes it to `ns_map`: a scale- and rigid-motion-invariant scalar field,
/// positive at convex vertices, negative at concave ones, zero on flat regions.
/// Named parameters, errors and complexity as `compute_normal_controlled_coordinates()`.
///
/// @tparam VertexNSMap a model of `WritablePropertyMap` with `vertex_descriptor` as key
///   and a floating-point type (or `GeomTraits::FT`) as value type
template <typename TriangleMesh, typename VertexNSMap,
          typename NamedParameters = parameters::Default_named_parameters>
void compute_normal_signature(const TriangleMesh& tm, VertexNSMap ns_map,
                              const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GeomTraits;
  typedef typename boost::property_traits<VertexNSMap>::value_type Value;
  const Normal_controlled_coordinates<TriangleMesh, GeomTraits> ncc(tm, np);
  for(auto v : vertices(tm))
    put(ns_map, v, Value(ncc.normal_signature(v)));
}

/// \ingroup PkgHeatDiffusionNCC
/// Returns the NCC operator \f$ \mathbf{N} \f$ of eq. 6 of `tm`, with one row and
/// column per vertex in the order of the vertex index map (see
/// `Normal_controlled_coordinates::operator_matrix()`).
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Eigen::SparseMatrix<double> normal_controlled_coordinates_matrix(
    const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GeomTraits;
  return Normal_controlled_coordinates<TriangleMesh, GeomTraits>(tm, np).operator_matrix();
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_NORMAL_CONTROLLED_COORDINATES_H
