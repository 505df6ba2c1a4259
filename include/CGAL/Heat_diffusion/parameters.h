// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Named parameters of the Heat_diffusion package.

#ifndef CGAL_HEAT_DIFFUSION_PARAMETERS_H
#define CGAL_HEAT_DIFFUSION_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <type_traits>

namespace CGAL {
namespace Heat_diffusion {

/// \cond SKIP_IN_MANUAL
namespace internal_np {

// CGAL 5.5 cannot be taught new `.member()` parameters from outside CGAL, but its
// lookup (`get_parameter`) is generic in the tag type: a package-owned enum works
// as a tag as long as the pack is built with `Named_function_parameters`.
enum sigma_t { sigma };
enum diffusion_time_t { time };
enum number_of_eigenpairs_t { number_of_eigenpairs };
enum number_of_steps_t { number_of_steps };
enum anchor_weight_t { anchor_weight };
enum vertex_normal_rule_t { vertex_normal_rule };
enum scale_invariant_kernel_t { scale_invariant_kernel };
enum kernel_method_t { kernel_method };
enum operator_normalization_t { operator_normalization };
enum progress_callback_t { progress_callback };
enum feature_threshold_t { feature_threshold };
enum steps_per_level_t { steps_per_level };
enum coarse_vertex_count_t { coarse_vertex_count };

} // namespace internal_np
/// \endcond

/// \ingroup PkgHeatDiffusionRef
/// Named parameters of the package. They return `CGAL::Named_function_parameters`,
/// so CGAL's own parameters can be chained after them:
/// `CGAL::Heat_diffusion::parameters::sigma(0.1).vertex_point_map(vpm)`.
/// To put CGAL's parameters first, use `combine()`.
namespace parameters {

/// \cond SKIP_IN_MANUAL
using CGAL::parameters::default_values;
using CGAL::parameters::Default_named_parameters;
using CGAL::parameters::get_parameter;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::is_default_parameter;

#define CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(TAG, NAME)                       \
  template <typename T>                                                      \
  CGAL::Named_function_parameters<T, internal_np::TAG> NAME(const T& value) \
  {                                                                          \
    return CGAL::Named_function_parameters<T, internal_np::TAG>(value);     \
  }
/// \endcond

/// Edge-weight width `sigma` of \f$ w_{ij} = \exp(-|\delta_i-\delta_j|^2/\sigma^2) \f$ (paper, eq. 10).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(sigma_t, sigma)
/// Diffusion time `t` of one step, measured on the mesh rescaled to total area = vertex count.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(diffusion_time_t, time)
/// Number `m` of generalized eigenpairs of the truncated spectral kernel (paper, eq. 20).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(number_of_eigenpairs_t, number_of_eigenpairs)
/// Number `k` of diffusion steps \f$ F^k = A_t^k F^0 \f$ (paper, eq. 19).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(number_of_steps_t, number_of_steps)
/// Weight of the positional anchors of the least-squares reconstruction (paper, eq. 23).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(anchor_weight_t, anchor_weight)
/// Rule that computes vertex normals, a model of `VertexNormalRule`.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(vertex_normal_rule_t, vertex_normal_rule)

/// `true` for the scale-invariant kernel of eq. 14 instead of eq. 13.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(scale_invariant_kernel_t, scale_invariant_kernel)
/// How `Anisotropic_heat_diffusion` evaluates the heat kernel, a `Heat_kernel_method`.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(kernel_method_t, kernel_method)
/// How `Anisotropic_heat_diffusion` makes \f$ A_t \f$ from the kernel, an `Operator_normalization`.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(operator_normalization_t, operator_normalization)
/// A callable `bool(double fraction_done)` called on the calling thread during long
/// computations (the eigenpairs and the coarse level, the heat regions, denoising);
/// returning `false` cancels them with an exception.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(progress_callback_t, progress_callback)

/// The threshold c of the feature criterion \f$ F^k(i) > c \max F^k \f$ (paper, section 7).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(feature_threshold_t, feature_threshold)
/// Number of diffusion steps that make one level of a hierarchical decomposition (paper, eq. 24).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(steps_per_level_t, steps_per_level)

/// Vertex count of the coarse level on which the eigenpairs are computed (paper,
/// eq. 21); 0 computes them on the mesh itself. See `Edge_weighted_heat_kernel`.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(coarse_vertex_count_t, coarse_vertex_count)

#undef CGAL_HEAT_DIFFUSION_NAMED_PARAMETER

/// \cond SKIP_IN_MANUAL
namespace internal {

// Rebuilds the chain `np` on top of `base`, innermost parameter first, so that both
// packs can be searched by one `get_parameter`. A parameter present in both packs
// is taken from `np` (it is found first).
template <typename Base>
const Base& rebase(const CGAL::Named_function_parameters<bool, CGAL::internal_np::all_default_t>&,
                   const Base& base)
{
  return base;
}

template <typename T, typename Tag, typename Base>
auto rebase(const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& np,
            const Base& base)
{
  return CGAL::Named_function_parameters<T, Tag, Base>(CGAL::internal_np::get_reference(np.v), base);
}

template <typename T, typename Tag, typename Inner, typename Base>
auto rebase(const CGAL::Named_function_parameters<T, Tag, Inner>& np, const Base& base)
{
  auto inner = rebase(static_cast<const Inner&>(np), base);
  return CGAL::Named_function_parameters<T, Tag, decltype(inner)>(CGAL::internal_np::get_reference(np.v),
                                                                  inner);
}

} // namespace internal
/// \endcond

/// \ingroup PkgHeatDiffusionRef
/// Merges named parameter packs, so that this package's parameters and CGAL's own
/// can be given in any order:
/// `combine(CGAL::parameters::vertex_point_map(vpm), parameters::sigma(0.1))`.
/// The result can be passed to this package's functions and to CGAL's (which
/// ignore the tags they do not know). When a parameter appears in several packs,
/// the value of the last pack wins.
template <typename NP>
const NP& combine(const NP& np)
{
  return np;
}

template <typename NP1, typename NP2, typename... NPs>
auto combine(const NP1& np1, const NP2& np2, const NPs&... rest)
{
  return combine(internal::rebase(np2, np1), rest...);
}

} // namespace parameters
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_PARAMETERS_H
