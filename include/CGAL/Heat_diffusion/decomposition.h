// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Hierarchical decomposition of a scalar field into detail bands, weighted
// re-synthesis, and shape filtering through the Normal Signature: paper, eq. 24-26.

#ifndef CGAL_HEAT_DIFFUSION_DECOMPOSITION_H
#define CGAL_HEAT_DIFFUSION_DECOMPOSITION_H

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/internal/detail_bands.h>
#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/vertex_fields.h>
#include <CGAL/Heat_diffusion/parameters.h>
#include <CGAL/Heat_diffusion/reconstruction.h>

#include <CGAL/Dynamic_property_map.h>

#include <Eigen/Core>

#include <cmath>
#include <iterator>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionApplications
/// Decomposes the scalar field \f$ S = F^0 \f$ into detail bands and a residual
/// (paper, eq. 24):
/// \f[ S = \sum_{j=1}^{L} D^j + S^L, \qquad D^j = F^{(j-1)s} - F^{js}, \qquad S^L = F^{Ls}, \f]
/// where \f$ F^k = A_t^k F^0 \f$ is the diffusion of `diffusion`, L is the number of
/// maps in `detail_maps` and s the named parameter `steps_per_level` (the paper: "one
/// level could contain several steps"). \f$ D^1 \f$ holds the finest details. Because
/// \f$ A_t \f$ conserves heat, every band sums to zero, \f$ \sum_i D^j(i) = 0 \f$ (eq. 25),
/// up to rounding; the bands and the residual add up to \f$ S \f$, up to rounding.
///
/// @tparam TriangleMesh, GeomTraits the template parameters of `diffusion`
/// @tparam VertexFieldMap a model of `ReadablePropertyMap` with the `vertex_descriptor`
///   of `TriangleMesh` as key and a floating-point type as value type
/// @tparam DetailMapRange a model of `ConstRange` whose value type is a model of
///   `WritablePropertyMap` with `vertex_descriptor` as key and a floating-point value type
/// @tparam VertexResidualMap a model of `WritablePropertyMap` with `vertex_descriptor`
///   as key and a floating-point type as value type
///
/// @param diffusion the diffusion operator, built on the mesh of `field`
/// @param field the field \f$ S \f$
/// @param detail_maps receive \f$ D^1, \dots, D^L \f$, in this order
/// @param residual receives \f$ S^L \f$
/// @param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{steps_per_level}
///     \cgalParamDescription{the number s of diffusion steps of one level. With one step
///       per level (eq. 24 as printed) consecutive bands hold nearly the same
///       frequencies: on fandisk (`sigma` = 0.1) the shape filters of `filter_shape()`
///       then change the variance of the NS by 1 to 2 %, against 4 to 6 % with 5 steps}
///     \cgalParamType{`std::size_t`, positive}
///     \cgalParamDefault{`5`}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{called on the calling thread after each diffusion step with the
///       fraction of the \f$ L s \f$ steps done; returning `false` cancels the decomposition
///       with a `std::runtime_error`}
///     \cgalParamType{a callable `bool(double)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument if a value of `field` is not finite or if
///   `steps_per_level` is not a positive integer.
/// \throws std::runtime_error if the `progress_callback` cancels.
///
/// Complexity: \f$ L s \f$ sparse products by \f$ A_t \f$, \f$ O(L s\, \mathrm{nnz}(A_t)) \f$.
template <typename TriangleMesh, typename GeomTraits, typename VertexFieldMap, typename DetailMapRange,
          typename VertexResidualMap, typename NamedParameters = parameters::Default_named_parameters>
void decompose_field(const Anisotropic_heat_diffusion<TriangleMesh, GeomTraits>& diffusion,
                     const VertexFieldMap& field, const DetailMapRange& detail_maps, VertexResidualMap residual,
                     const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const std::size_t steps_per_level = internal::checked_steps_per_level(
      double(internal::parameter_value(np, internal_np::steps_per_level, defaults::decomposition_steps_per_level)),
      "decompose_field");
  const TriangleMesh& tm = diffusion.normal_controlled_coordinates().mesh();
  const auto index_of = [&diffusion](vertex_descriptor v) { return diffusion.vertex_index(v); };
  const Eigen::VectorXd f0 =
      internal::read_vertex_field(tm, diffusion.number_of_vertices(), field, index_of, "decompose_field");

  const std::size_t levels = std::size_t(std::distance(std::begin(detail_maps), std::end(detail_maps)));
  const std::vector<Eigen::VectorXd> bands =
      internal::decompose(diffusion, f0, levels, steps_per_level, internal::progress_of(np));
  std::size_t j = 0;
  for(auto detail_map : detail_maps)
    internal::write_vertex_field(tm, bands[j++], detail_map, index_of);
  internal::write_vertex_field(tm, bands.back(), residual, index_of);
}

/// \ingroup PkgHeatDiffusionApplications
/// Decomposes the scalar field `field` of `tm` as the overload above does, with an
/// `Anisotropic_heat_diffusion` built from `np` for this call only (build it yourself
/// to decompose several fields).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{steps_per_level}
///     \cgalParamDescription{the number s of diffusion steps of one level}
///     \cgalParamType{`std::size_t`, positive}
///     \cgalParamDefault{`5`}
///   \cgalParamNEnd
///   \cgalParamNBegin{time, sigma, number_of_eigenpairs, scale_invariant_kernel, progress_callback, vertex_point_map, vertex_index_map, vertex_normal_rule, geom_traits, ...}
///     \cgalParamDescription{the diffusion, as for `Anisotropic_heat_diffusion` (whose
///       construction fills the progress bar; the products after it only check for cancellation)}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument as the overload above, and on a mesh or parameter
///   the diffusion rejects.
/// \throws std::runtime_error if the eigen solve fails or is cancelled.
///
/// Complexity: that of building an `Anisotropic_heat_diffusion`, plus \f$ L s \f$ sparse products.
template <typename TriangleMesh, typename VertexFieldMap, typename DetailMapRange, typename VertexResidualMap,
          typename NamedParameters = parameters::Default_named_parameters>
void decompose_field(const TriangleMesh& tm, const VertexFieldMap& field, const DetailMapRange& detail_maps,
                     VertexResidualMap residual, const NamedParameters& np = parameters::default_values())
{
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GeomTraits;
  const Anisotropic_heat_diffusion<TriangleMesh, GeomTraits> diffusion(tm, np);
  decompose_field(diffusion, field, detail_maps, residual,
                  internal::with_progress(np, internal::progress_of(np).part(1., 1.)));
}

/// \ingroup PkgHeatDiffusionApplications
/// Re-synthesises a field from its detail bands and residual with band weights
/// (paper, eq. 26): \f$ \tilde S = \sum_{j=1}^{L} w_j D^j + S^L \f$. Weights all 1 give
/// back the decomposed field; \f$ w = (0, \dots, 0) \f$ gives the residual, the smoothest
/// part; weights above 1 enhance the details of their band.
///
/// @tparam TriangleMesh a model of `VertexListGraph`
/// @tparam DetailMapRange a model of `ConstRange` whose value type is a model of
///   `ReadablePropertyMap` with `vertex_descriptor` as key and a floating-point value type
/// @tparam VertexResidualMap a model of `ReadablePropertyMap` with `vertex_descriptor`
///   as key and a floating-point type as value type
/// @tparam WeightRange a model of `ConstRange` of floating-point numbers
/// @tparam VertexOutputMap a model of `WritablePropertyMap` with `vertex_descriptor`
///   as key and a floating-point type as value type
///
/// @param tm the mesh the fields live on
/// @param detail_maps \f$ D^1, \dots, D^L \f$, as `decompose_field()` writes them
/// @param residual \f$ S^L \f$
/// @param weights \f$ w_1, \dots, w_L \f$, one per detail band
/// @param output receives \f$ \tilde S \f$; it may be `residual` itself
///
/// \throws std::invalid_argument if `weights` and `detail_maps` differ in size or a
///   weight is not finite.
///
/// Complexity: \f$ O(L n) \f$.
template <typename TriangleMesh, typename DetailMapRange, typename VertexResidualMap, typename WeightRange,
          typename VertexOutputMap>
void synthesize_field(const TriangleMesh& tm, const DetailMapRange& detail_maps, const VertexResidualMap& residual,
                      const WeightRange& weights, VertexOutputMap output)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<VertexOutputMap>::value_type Value;
  const std::vector<double> w = internal::checked_weights(weights, "synthesize_field");
  const std::size_t levels = std::size_t(std::distance(std::begin(detail_maps), std::end(detail_maps)));
  if(w.size() != levels)
  {
    std::ostringstream os;
    os << "synthesize_field: " << w.size() << " weights for " << levels << " detail bands";
    internal::throw_invalid_input(os.str());
  }
  for(vertex_descriptor v : vertices(tm))
  {
    // Same order of summation as the decomposition's internal re-synthesis.
    double value = CGAL::to_double(get(residual, v));
    std::size_t j = 0;
    for(const auto& detail_map : detail_maps)
      value += w[j++] * CGAL::to_double(get(detail_map, v));
    put(output, v, Value(value));
  }
}

/// \ingroup PkgHeatDiffusionApplications
/// Filters the shape of `tm` through its Normal Signature (paper, Fig. 10): the NS is
/// decomposed into L = `weights.size()` detail bands and a residual by
/// `decompose_field()`, re-synthesised with the band weights by `synthesize_field()`,
/// and the vertices are moved by `reconstruct_from_normal_signature()` to match the new
/// signature along their current normals. The paper's smoothing filter is
/// \f$ w = (0, 0, 1) \f$ (the two finest bands removed), its enhancement filter
/// \f$ w = (1, 3, 3) \f$; weights all 1 return the input (up to rounding).
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// @tparam WeightRange a model of `ConstRange` of floating-point numbers
///
/// @param tm the mesh, modified in place
/// @param weights the band weights \f$ w_1, \dots, w_L \f$, finest band first
/// @param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{steps_per_level}
///     \cgalParamDescription{the number of diffusion steps of one level}
///     \cgalParamType{`std::size_t`, positive}
///     \cgalParamDefault{`2` (chosen with `anchor_weight` by measurement: see the user manual)}
///   \cgalParamNEnd
///   \cgalParamNBegin{sigma, time, kernel_method, operator_normalization, number_of_eigenpairs, scale_invariant_kernel, progress_callback}
///     \cgalParamDescription{the diffusion, as for `Anisotropic_heat_diffusion`}
///   \cgalParamNEnd
///   \cgalParamNBegin{anchor_weight}
///     \cgalParamDescription{the weight of the positional anchors of the reconstruction: smaller lets the shape follow the new signature further}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{`0.03`: with 2 steps per level and `sigma` = 0.1, the enhancement (1, 3, 3)
///       reaches half or more of the variance of the Normal Signature that it asks for on CGAL's
///       armadillo, bunny, elephant and fandisk without creating self-intersections; 0.02 folded
///       elephant, and 0.1 or more barely moves the shape (see the user manual)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, vertex_index_map, vertex_normal_rule, geom_traits}
///     \cgalParamDescription{as for `reconstruct_from_normal_signature()`; the vertex point map must be writable}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument on a mesh or parameter the diffusion or the
///   reconstruction rejects, or a weight that is not finite.
/// \throws std::runtime_error if the eigen solve or the sparse factorisation fails.
///
/// Complexity: that of building an `Anisotropic_heat_diffusion`, plus \f$ L s \f$ sparse
/// products and one reconstruction (a sparse Cholesky factorisation).
template <typename TriangleMesh, typename WeightRange,
          typename NamedParameters = parameters::Default_named_parameters>
void filter_shape(TriangleMesh& tm, const WeightRange& weights,
                  const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GeomTraits;
  const std::vector<double> w = internal::checked_weights(weights, "filter_shape");
  const std::size_t steps_per_level = internal::checked_steps_per_level(
      double(internal::parameter_value(np, internal_np::steps_per_level, defaults::shape_filter_steps_per_level)),
      "filter_shape");
  const double anchor_weight = internal::parameter_value(np, internal_np::anchor_weight, defaults::shape_filter_anchor_weight);

  auto signature = get(CGAL::dynamic_vertex_property_t<double>(), tm);
  {
    // The diffusion refers to the current shape: it must be gone before the shape moves.
    const Anisotropic_heat_diffusion<TriangleMesh, GeomTraits> diffusion(tm, np);
    const auto& ncc = diffusion.normal_controlled_coordinates();
    const auto index_of = [&diffusion](vertex_descriptor v) { return diffusion.vertex_index(v); };
    Eigen::VectorXd s(Eigen::Index(diffusion.number_of_vertices()));
    for(vertex_descriptor v : vertices(tm))
      s[Eigen::Index(index_of(v))] = ncc.normal_signature(v);
    // The construction fills the progress bar; the products only check for cancellation.
    const Eigen::VectorXd edited = internal::synthesize(
        internal::decompose(diffusion, s, w.size(), steps_per_level, internal::progress_of(np).part(1., 1.)), w);
    internal::write_vertex_field(tm, edited, signature, index_of);
  }
  reconstruct_from_normal_signature(tm, signature, parameters::combine(np, parameters::anchor_weight(anchor_weight)));
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_DECOMPOSITION_H
