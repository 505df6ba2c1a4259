// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Mesh denoising by anisotropic diffusion of the Normal Signature: paper, section 7, eq. 22-23.

#ifndef CGAL_HEAT_DIFFUSION_DENOISING_H
#define CGAL_HEAT_DIFFUSION_DENOISING_H

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/parameters.h>
#include <CGAL/Heat_diffusion/reconstruction.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/internal/named_params_helper.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The normal update of eq. 22, made robust. The paper's
// n'_i = sum_j s_j n_j / sum_j s_j divides by a sum that vanishes wherever the
// signature changes sign across the ring (every noisy flat region), and flips the
// normal where the sum is negative. The package weights the normals of the closed
// one-ring {i} and N(i) by |s_j| instead: a convex combination of unit normals with
// non-negative weights, which stays inside the cone of the ring's normals and never
// divides by a signed sum. A ring whose weights all vanish, or whose weighted normals
// cancel, keeps the current normal.
inline std::vector<Eigen::Vector3d> signature_weighted_normals(const Indexed_mesh& mesh,
                                                               const std::vector<Eigen::Vector3d>& normals,
                                                               const Eigen::VectorXd& signature)
{
  const std::size_t n = mesh.number_of_vertices();
  std::vector<Eigen::Vector3d> result(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    double total_weight = std::abs(signature[Eigen::Index(i)]);
    Eigen::Vector3d sum = total_weight * normals[i];
    for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
    {
      const std::size_t j = mesh.fan[k];
      const double weight = std::abs(signature[Eigen::Index(j)]);
      sum += weight * normals[j];
      total_weight += weight;
    }
    // The sum of unit vectors weighted by w_j has length at most sum_j w_j; a tenth
    // of a percent of that means the normals nearly cancel (a spike).
    const double length = sum.norm();
    result[i] = length > 1e-3 * total_weight && length > 0 ? Eigen::Vector3d(sum / length) : normals[i];
  }
  return result;
}

} // namespace internal
/// \endcond

/// \ingroup PkgHeatDiffusionApplications
/// Denoises the triangle mesh `tm` by anisotropic diffusion of its Normal Signature
/// (paper, section 7, eq. 22-23). Each of the `number_of_iterations` iterations
///  1. builds the edge-weighted heat kernel and the diffusion operator \f$ A_t \f$ of the
///     current mesh (`Anisotropic_heat_diffusion`, parameters `sigma`, `time`,
///     `number_of_eigenpairs`), and diffuses the Normal Signature:
///     \f$ S' = A_t^k S \f$ with k = `number_of_steps`;
///  2. updates the normals (eq. 22, made robust):
///     \f$ n'_i = \sum_{j \in \{i\} \cup N(i)} |s'_j|\, n_j \,/\, \|\sum_{j} |s'_j|\, n_j\| \f$.
///     The paper's weights \f$ s_j / \sum_j s_j \f$ divide by a sum that vanishes where
///     the signature changes sign across a ring, which noise makes it do everywhere, and
///     flip the normal where that sum is negative; the weights \f$ |s'_j| \f$ make a convex
///     combination of the ring's normals that cannot flip. A ring whose weighted
///     normals cancel keeps its current normal;
///  3. moves the vertices with `reconstruct_from_normal_signature()` (eq. 23), targets
///     \f$ S' \f$ along \f$ n' \f$, anchored to the current positions with `anchor_weight`.
///
/// The connectivity is not changed, only the positions; every position stays finite.
///
/// <b>Defaults, and what they reach.</b> The defaults were chosen by measurement on
/// CGAL's `fandisk.off` with Gaussian noise along the normals of 0.2 and 0.3 mean edge
/// length (see the user manual for the tables). `sigma` = 1 rather than the paper's
/// feature-preserving 0.1: on a noisy mesh the NCC differ by the noise across every
/// edge, so with `sigma` = 0.1 all edge weights underflow, the stiffness matrix is
/// numerically zero and the eigen solve does not converge. The truncated spectral
/// kernel (m = 150, t = 1) is wide (heat regions of about 100 vertices), so one
/// diffusion step already averages the signature over its regions, and more steps
/// change the result by less than 0.1 degree. Two iterations with anchors of weight
/// 0.7 were the best compromise, over 0.1, 0.2 and 0.3 noise, of the settings tried that
/// leave fandisk free of self-intersections (weight 0.5 is better at 0.3 noise and worse
/// at 0.1 and 0.2); more iterations, or weaker anchors, fold the mesh near its corners,
/// where the diffused signature underestimates the sharp creases.
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// @tparam NamedParameters a sequence of named parameters
///
/// @param tm the mesh, denoised in place; its faces must be triangles
/// @param np an optional sequence of named parameters among those below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the number of outer iterations (diffusion, normal update, reconstruction), each on the result of the previous one; 0 leaves `tm` unchanged}
///     \cgalParamType{`unsigned int` (\cgal's own named parameter `CGAL::parameters::number_of_iterations`)}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sigma}
///     \cgalParamDescription{the width of the edge weights of the heat kernel; values much smaller than the noise of the NCC make the eigen solve fail (see above)}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{time}
///     \cgalParamDescription{the time t of one diffusion step, on the mesh rescaled to area = number of vertices}
///     \cgalParamType{`double`, positive and finite}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_steps}
///     \cgalParamDescription{the number k of diffusion steps of the signature per iteration}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_eigenpairs}
///     \cgalParamDescription{the number m of eigenpairs of the truncated heat kernel}
///     \cgalParamType{`std::size_t`, positive}
///     \cgalParamDefault{`150`}
///   \cgalParamNEnd
///   \cgalParamNBegin{anchor_weight}
///     \cgalParamDescription{the weight of the positional anchors of the reconstruction (see `reconstruct_from_normal_signature()`): smaller moves the vertices further per iteration}
///     \cgalParamType{`double`, positive and finite}
///     \cgalParamDefault{`0.7`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`; the denoised positions are written to it}
///     \cgalParamType{a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and `GeomTraits::Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_normal_rule}
///     \cgalParamDescription{how the vertex normals of each iteration's mesh are computed (a `vertex_normal_map` is not used: the normals change with the mesh)}
///     \cgalParamType{a model of `VertexNormalRule`}
///     \cgalParamDefault{`Area_weighted_vertex_normals()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in `[0, num_vertices(tm))`}
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
/// \throws std::invalid_argument if a parameter is out of its range (the message names
///   it), or on a mesh the package cannot process (see `Normal_controlled_coordinates`),
///   which a denoising iteration can produce only from an already degenerate input.
///   `tm` is then left as the previous iteration wrote it.
/// \throws std::runtime_error if an eigen solve or a factorisation fails.
///
/// Complexity: per iteration, one edge-weighted heat kernel (a sparse Cholesky
/// factorisation and a Lanczos iteration of \f$ O(n m^2) \f$ dense work: most of the time),
/// the operator \f$ A_t \f$ (linear in n), k sparse products and one sparse Cholesky
/// factorisation of the reconstruction. Measured on a shared 2-core machine: 0.4 to
/// 1.9 s per iteration on the 6475 vertices of `fandisk.off` (depending on the load),
/// 8 s on the 26002 of `armadillo.off`.
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void denoise_mesh(TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GeomTraits;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np::vertex_normal_rule_t, NamedParameters,
                                                             Area_weighted_vertex_normals>::type Rule;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  // Every parameter is checked before the mesh is touched.
  const double iterations = double(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 2));
  const double sigma = choose_parameter(get_parameter(np, internal_np::sigma), 1.);
  const double time = choose_parameter(get_parameter(np, internal_np::time), 1.);
  const double steps = double(choose_parameter(get_parameter(np, internal_np::number_of_steps), 1));
  const double eigenpairs = double(choose_parameter(get_parameter(np, internal_np::number_of_eigenpairs), 150));
  const double anchor_weight = choose_parameter(get_parameter(np, internal_np::anchor_weight), 0.7);
  if(!(iterations >= 0) || !std::isfinite(iterations))
    internal::throw_invalid_input("denoise_mesh: number_of_iterations must not be negative");
  if(!(sigma > 0))
    internal::throw_invalid_input("denoise_mesh: sigma must be positive");
  if(!(time > 0) || !std::isfinite(time))
    internal::throw_invalid_input("denoise_mesh: time must be positive and finite");
  if(!(steps >= 0) || !std::isfinite(steps))
    internal::throw_invalid_input("denoise_mesh: number_of_steps must not be negative");
  if(!(eigenpairs >= 1) || !std::isfinite(eigenpairs))
    internal::throw_invalid_input("denoise_mesh: number_of_eigenpairs must be positive");
  if(!(anchor_weight > 0) || !std::isfinite(anchor_weight))
    internal::throw_invalid_input("denoise_mesh: anchor_weight must be positive and finite");
  if(num_vertices(tm) == 0)
    return;

  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const GeomTraits gt = choose_parameter<GeomTraits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const Rule rule = choose_parameter<Rule>(get_parameter(np, internal_np::vertex_normal_rule));
  const auto mesh_parameters =
      parameters::combine(CGAL::parameters::vertex_point_map(vpm).vertex_index_map(vim).geom_traits(gt),
                          parameters::vertex_normal_rule(rule));

  auto target_signature = get(CGAL::dynamic_vertex_property_t<double>(), tm);
  auto target_normals = get(CGAL::dynamic_vertex_property_t<Vector_3>(), tm);
  for(std::size_t iteration = 0; iteration < std::size_t(iterations); ++iteration)
  {
    // 1. The kernel of the current mesh, and its Normal Signature diffused.
    const Anisotropic_heat_diffusion<TriangleMesh, GeomTraits> diffusion(
        tm, parameters::combine(mesh_parameters, parameters::sigma(sigma), parameters::time(time),
                                parameters::number_of_eigenpairs(std::size_t(eigenpairs))));
    const Normal_controlled_coordinates<TriangleMesh, GeomTraits>& ncc =
        diffusion.heat_kernel().normal_controlled_coordinates();
    const internal::Ncc_data& data = ncc.data();
    const Eigen::VectorXd signature =
        diffusion.diffuse(Eigen::Map<const Eigen::VectorXd>(data.signature.data(), Eigen::Index(data.signature.size())),
                          std::size_t(steps));

    // 2. The normals, eq. 22 with non-negative weights.
    const std::vector<Eigen::Vector3d> normals =
        internal::signature_weighted_normals(ncc.indexed_mesh(), data.normals, signature);

    // 3. The vertices, eq. 23.
    for(vertex_descriptor v : vertices(tm))
    {
      const std::size_t i = ncc.vertex_index(v);
      put(target_signature, v, signature[Eigen::Index(i)]);
      put(target_normals, v, Vector_3(normals[i].x(), normals[i].y(), normals[i].z()));
    }
    reconstruct_from_normal_signature(
        tm, target_signature,
        parameters::combine(mesh_parameters, CGAL::parameters::vertex_normal_map(target_normals),
                            parameters::anchor_weight(anchor_weight)));
  }
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_DENOISING_H
