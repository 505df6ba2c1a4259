// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Multi-scale feature detection on a diffused scalar field: paper, section 7.

#ifndef CGAL_HEAT_DIFFUSION_MULTISCALE_FEATURES_H
#define CGAL_HEAT_DIFFUSION_MULTISCALE_FEATURES_H

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/internal/errors.h>
#include <CGAL/Heat_diffusion/internal/feature_detection.h>
#include <CGAL/Heat_diffusion/internal/vertex_fields.h>
#include <CGAL/Heat_diffusion/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionApplications
/// The features of a field at one scale k, as `detect_multiscale_features()` returns
/// them for several scales at once. Both lists are sorted by vertex index.
template <typename VertexDescriptor>
struct Features_at_scale
{
  std::size_t number_of_steps = 0;          ///< the scale k of \f$ F^k \f$
  std::vector<VertexDescriptor> convex;     ///< the strict 2-ring maxima above the threshold
  std::vector<VertexDescriptor> concave;    ///< the strict 2-ring minima below the threshold
};

/// \ingroup PkgHeatDiffusionApplications
/// Detects the convex and concave features of the scalar field `field` of `tm` at the
/// scales k of `steps` (paper, section 7), reusing the operator \f$ A_t \f$ of
/// `diffusion`: the fields \f$ F^k = A_t^k F^0 \f$ are computed in one pass.
///
/// Vertex \f$ v_i \f$ is a <em>convex feature</em> at scale k if \f$ F^k(i) > F^k(j) \f$ for
/// every other vertex \f$ v_j \f$ of its 2-ring and \f$ F^k(i) > c \max F^k \f$; it is a
/// <em>concave feature</em> if \f$ F^k(i) < F^k(j) \f$ for every such \f$ v_j \f$ and
/// \f$ F^k(i) < c \min F^k \f$. The comparisons are strict: on a plateau there is no
/// feature. With the Normal Signature as field, convex features lie on convex parts of
/// the shape (positive NS) and concave ones on concave parts.
///
/// @tparam TriangleMesh, GeomTraits the template parameters of `diffusion`
/// @tparam VertexFieldMap a model of `ReadablePropertyMap` with the `vertex_descriptor`
///   of `TriangleMesh` as key and a floating-point type as value type
///
/// @param diffusion the diffusion operator, built on the mesh of `field`
/// @param field the field \f$ F^0 \f$
/// @param steps the scales k, in any order, repetitions allowed
/// @param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{feature_threshold}
///     \cgalParamDescription{the threshold c of the criterion: only the extrema beyond
///       c times the field's extreme value are features; 0 keeps every strict 2-ring
///       extremum of the right sign}
///     \cgalParamType{`double` in [0, 1]}
///     \cgalParamDefault{`0.8` (the paper's value)}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{the diffusion's, as for `Anisotropic_heat_diffusion::diffuse()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns one `Features_at_scale` per entry of `steps`, in the same order.
///
/// \throws std::invalid_argument if a value of `field` is not finite or if c is not in [0, 1].
/// \throws std::runtime_error if the `progress_callback` cancels.
///
/// Complexity: \f$ O(k_{\max}\, \mathrm{nnz}(A_t)) \f$ for the diffusion (see
/// `Anisotropic_heat_diffusion::diffuse()`) plus, per scale, one visit of every 2-ring:
/// \f$ O(\sum_i d_i^2) \f$ for vertex degrees \f$ d_i \f$, linear in the mesh size.
template <typename TriangleMesh, typename GeomTraits, typename VertexFieldMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::vector<Features_at_scale<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> >
detect_multiscale_features(const Anisotropic_heat_diffusion<TriangleMesh, GeomTraits>& diffusion,
                           const VertexFieldMap& field, const std::vector<std::size_t>& steps,
                           const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const char* const function = "detect_multiscale_features";
  const double c = internal::checked_feature_threshold(
      internal::parameter_value(np, internal_np::feature_threshold, defaults::feature_threshold),
      function);

  const TriangleMesh& tm = diffusion.normal_controlled_coordinates().mesh();
  const std::size_t n = diffusion.number_of_vertices();
  const auto index_of = [&diffusion](vertex_descriptor v) { return diffusion.vertex_index(v); };
  std::vector<vertex_descriptor> vertex_of_index(n);
  for(vertex_descriptor v : vertices(tm))
    vertex_of_index[index_of(v)] = v;
  const Eigen::VectorXd f0 = internal::read_vertex_field(tm, n, field, index_of, function);

  const internal::Vertex_adjacency adjacency =
      internal::make_vertex_adjacency(diffusion.normal_controlled_coordinates().indexed_mesh());
  const std::vector<Eigen::VectorXd> fields = diffusion.diffuse(f0, steps, np);
  std::vector<Features_at_scale<vertex_descriptor> > result(steps.size());
  std::vector<std::size_t> convex, concave;
  for(std::size_t s = 0; s < steps.size(); ++s)
  {
    convex.clear();
    concave.clear();
    internal::detect_features(adjacency, fields[s], c, convex, concave);
    result[s].number_of_steps = steps[s];
    for(std::size_t i : convex)
      result[s].convex.push_back(vertex_of_index[i]);
    for(std::size_t i : concave)
      result[s].concave.push_back(vertex_of_index[i]);
  }
  return result;
}

/// \ingroup PkgHeatDiffusionApplications
/// Detects the convex and concave features of the scalar field `field` of `tm` at one
/// scale k, the named parameter `number_of_steps` (paper, section 7). The criterion is
/// that of the overload above: strict extrema over the 2-ring of \f$ F^k = A_t^k F^0 \f$,
/// beyond c times the extreme value of \f$ F^k \f$.
///
/// For k > 0 the heat kernel and \f$ A_t \f$ are built from `np`; to detect features at
/// several scales, or of several fields, build an `Anisotropic_heat_diffusion` once and
/// use the overload above. For k = 0 (the default) the field is taken as it is and no
/// kernel is computed: this is how the maxima of the heat kernel signature (the
/// baseline of the paper's Fig. 7) are found, with a property map filled from
/// `Edge_weighted_heat_kernel::heat_kernel_signature()`. The signature being positive,
/// its concave output stays empty: the HKS cannot tell convex from concave.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// @tparam VertexFieldMap a model of `ReadablePropertyMap` with `vertex_descriptor` as
///   key and a floating-point type as value type
/// @tparam ConvexOutputIterator, ConcaveOutputIterator models of `OutputIterator`
///   accepting `vertex_descriptor`
///
/// @param tm the triangle mesh
/// @param field the field \f$ F^0 \f$
/// @param convex_out receives the convex features, in increasing vertex index order
/// @param concave_out receives the concave features, in increasing vertex index order
/// @param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_steps}
///     \cgalParamDescription{the scale k: the number of diffusion steps applied to `field`}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{feature_threshold}
///     \cgalParamDescription{the threshold c of the criterion}
///     \cgalParamType{`double` in [0, 1]}
///     \cgalParamDefault{`0.8`}
///   \cgalParamNEnd
///   \cgalParamNBegin{time, sigma, number_of_eigenpairs, scale_invariant_kernel, progress_callback, vertex_point_map, vertex_normal_rule, geom_traits, ...}
///     \cgalParamDescription{the diffusion, as for `Anisotropic_heat_diffusion` (used for k > 0 only;
///       its construction fills the progress bar, the k products after it only check for cancellation)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique
///       index in `[0, n)`, `n` the number of vertices in `vertices(tm)` (removed vertices of a `Surface_mesh` are not counted); it sets the order of the outputs}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the two output iterators past the last features written.
///
/// \throws std::invalid_argument if a value of `field` is not finite, if c is not in
///   [0, 1], or (k > 0) on a mesh or parameter the diffusion rejects.
/// \throws std::runtime_error (k > 0) if the eigen solve fails or is cancelled.
///
/// Complexity: linear in the size of `tm` for k = 0; for k > 0 that of building an
/// `Anisotropic_heat_diffusion`, plus k sparse products.
template <typename TriangleMesh, typename VertexFieldMap, typename ConvexOutputIterator,
          typename ConcaveOutputIterator, typename NamedParameters = parameters::Default_named_parameters>
std::pair<ConvexOutputIterator, ConcaveOutputIterator>
detect_multiscale_features(const TriangleMesh& tm, const VertexFieldMap& field, ConvexOutputIterator convex_out,
                           ConcaveOutputIterator concave_out,
                           const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GeomTraits;
  const char* const function = "detect_multiscale_features";
  const auto steps = internal::parameter_value(np, internal_np::number_of_steps, 0);
  if(!(double(steps) >= 0))
    internal::throw_invalid_input("detect_multiscale_features: number_of_steps must not be negative");

  if(steps != 0)
  {
    const Anisotropic_heat_diffusion<TriangleMesh, GeomTraits> diffusion(tm, np);
    // The construction fills the progress bar; the k products after it only check for
    // cancellation.
    const auto features = detect_multiscale_features(diffusion, field, {std::size_t(steps)},
                                                     internal::with_progress(np, internal::progress_of(np).part(1., 1.)));
    convex_out = std::copy(features.front().convex.begin(), features.front().convex.end(), convex_out);
    concave_out = std::copy(features.front().concave.begin(), features.front().concave.end(), concave_out);
    return {convex_out, concave_out};
  }

  const double c = internal::checked_feature_threshold(
      internal::parameter_value(np, internal_np::feature_threshold, defaults::feature_threshold),
      function);
  // The user's numbering or the rank in vertices(tm), without gaps where a
  // Surface_mesh has removed vertices.
  const auto vim = internal::vertex_numbering(tm, np);
  const std::size_t n = internal::number_of_listed_vertices(tm);
  const auto index_of = [&vim](vertex_descriptor v) { return std::size_t(get(vim, v)); };
  std::vector<vertex_descriptor> vertex_of_index(n);
  for(vertex_descriptor v : vertices(tm))
    vertex_of_index[index_of(v)] = v;
  const Eigen::VectorXd f0 = internal::read_vertex_field(tm, n, field, index_of, function);
  const internal::Vertex_adjacency adjacency = internal::make_vertex_adjacency(tm, n, index_of);
  std::vector<std::size_t> convex, concave;
  internal::detect_features(adjacency, f0, c, convex, concave);
  for(std::size_t i : convex)
    *convex_out++ = vertex_of_index[i];
  for(std::size_t i : concave)
    *concave_out++ = vertex_of_index[i];
  return {convex_out, concave_out};
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_MULTISCALE_FEATURES_H
