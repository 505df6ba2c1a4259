// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Named parameters of the Heat_diffusion package.

#ifndef CGAL_HEAT_DIFFUSION_PARAMETERS_H
#define CGAL_HEAT_DIFFUSION_PARAMETERS_H

#include <CGAL/Heat_diffusion/parameter_defaults.h>

#include <CGAL/Named_function_parameters.h>

#include <optional>
#include <type_traits>

namespace CGAL {
namespace Heat_diffusion {

/// \cond SKIP_IN_MANUAL
enum class Heat_kernel_method;      // heat_kernel_method.h
enum class Operator_normalization;  // operator_normalization.h
enum class Denoising_method;        // denoising.h

namespace internal_np {

// CGAL 5.5 cannot be taught new `.member()` parameters from outside CGAL, but its
// lookup (`get_parameter`) is generic in the tag type. The package's tags are all
// instances of one template, so that one partial specialisation of
// CGAL::Named_function_parameters (below) gives every pack that ends with one of them
// the package's members as well as CGAL's: packs stay CGAL::Named_function_parameters
// (not a derived class, which PMP's overload resolution would treat differently).
template <int N>
struct Parameter_tag
{
};

// The package's parameters: X(number, name, condition on the value type K, what the
// value must be). The condition is checked by a static_assert that names the parameter.
#define CGAL_HEAT_DIFFUSION_PARAMETER_LIST(X)                                                            \
  X(1, sigma, is_number<K>, "a number")                                                                   \
  X(2, time, is_number<K>, "a number")                                                                    \
  X(3, number_of_eigenpairs, is_count<K>, "an integer")                                                   \
  X(4, number_of_steps, is_count<K>, "an integer (a floating-point count would be truncated)")            \
  X(5, anchor_weight, is_number<K>, "a number")                                                           \
  X(6, vertex_normal_rule, std::is_class<K>::value, "a model of VertexNormalRule")                        \
  X(7, scale_invariant_kernel, (std::is_same<K, bool>::value), "a bool")                                  \
  X(8, kernel_method, (std::is_same<K, Heat_kernel_method>::value), "a CGAL::Heat_diffusion::Heat_kernel_method") \
  X(9, progress_callback, (std::is_invocable_r<bool, const K&, double>::value), "callable as bool(double)") \
  X(10, feature_threshold, is_number<K>, "a number")                                                      \
  X(11, steps_per_level, is_count<K>, "an integer (a floating-point count would be truncated)")           \
  X(12, coarse_vertex_count, is_count<K>, "an integer")                                                   \
  X(13, denoising_method, (std::is_same<K, Denoising_method>::value), "a CGAL::Heat_diffusion::Denoising_method") \
  X(14, normal_sigma, is_number<K>, "a number")                                                           \
  X(15, displacement_limit, is_number<K>, "a number")                                                     \
  X(16, operator_normalization, (std::is_same<K, Operator_normalization>::value),                         \
    "a CGAL::Heat_diffusion::Operator_normalization")                                                     \
  X(17, local_kernel_tolerance, is_number<K>, "a number")

template <typename K>
constexpr bool is_number = std::is_arithmetic<K>::value && !std::is_same<K, bool>::value;
template <typename K>
constexpr bool is_count = std::is_integral<K>::value && !std::is_same<K, bool>::value;

// The type of a value, or of the value a std::optional may hold (an empty optional is
// a parameter that was not given: see parameters::sigma()).
template <typename V>
struct Given_value
{
  typedef V type;
};
template <typename V>
struct Given_value<std::optional<V> >
{
  typedef V type;
};

// check_sigma<V>(), ...: the static_assert on the value type K of each parameter.
#define CGAL_HEAT_DIFFUSION_CHECK(N, NAME, CONDITION, WHAT)                                            \
  template <typename V>                                                                               \
  constexpr void check_##NAME()                                                                       \
  {                                                                                                   \
    typedef typename Given_value<V>::type K;                                                          \
    static_assert(CONDITION, "CGAL::Heat_diffusion::parameters::" #NAME ": the value must be " WHAT); \
  }
CGAL_HEAT_DIFFUSION_PARAMETER_LIST(CGAL_HEAT_DIFFUSION_CHECK)
#undef CGAL_HEAT_DIFFUSION_CHECK

// The tags: sigma_t, time_t, ... and their values sigma, time, ...
#define CGAL_HEAT_DIFFUSION_TAG(N, NAME, CONDITION, WHAT) \
  typedef Parameter_tag<N> NAME##_t;                      \
  inline constexpr NAME##_t NAME{};
CGAL_HEAT_DIFFUSION_PARAMETER_LIST(CGAL_HEAT_DIFFUSION_TAG)
#undef CGAL_HEAT_DIFFUSION_TAG
// The historical name of the tag of `time`.
typedef time_t diffusion_time_t;

// A no-op entry that the members for CGAL's own parameters put at the end of the
// pack, so that the result keeps the package's members; nothing looks it up.
typedef Parameter_tag<0> chain_t;

} // namespace internal_np
/// \endcond

} // namespace Heat_diffusion

/// \cond SKIP_IN_MANUAL
// The packs that end with a parameter of the package: CGAL's members, each of which
// returns a pack that again ends with one of the package's entries, and the package's
// members. Everything else is as in CGAL's primary template.
template <typename T, int N, typename Base>
struct Named_function_parameters<T, Heat_diffusion::internal_np::Parameter_tag<N>, Base>
  : internal_np::Named_params_impl<T, Heat_diffusion::internal_np::Parameter_tag<N>, Base>
{
  typedef internal_np::Named_params_impl<T, Heat_diffusion::internal_np::Parameter_tag<N>, Base> base;
  typedef Named_function_parameters<T, Heat_diffusion::internal_np::Parameter_tag<N>, Base> self;

  Named_function_parameters() : base(T()) {}
  Named_function_parameters(const T& v) : base(v) {}
  Named_function_parameters(const T& v, const Base& b) : base(v, b) {}

#define CGAL_add_named_parameter(X, Y, Z)                                                              \
  template <typename K>                                                                               \
  Named_function_parameters<bool, Heat_diffusion::internal_np::chain_t,                               \
                            Named_function_parameters<K, internal_np::X, self> >                      \
  Z(const K& k) const                                                                                 \
  {                                                                                                   \
    return {false, Named_function_parameters<K, internal_np::X, self>(k, *this)};                     \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_HEAT_DIFFUSION_MEMBER(NUMBER, NAME, CONDITION, WHAT)                                       \
  template <typename K>                                                                               \
  Named_function_parameters<K, Heat_diffusion::internal_np::NAME##_t, self> NAME(const K& k) const     \
  {                                                                                                   \
    Heat_diffusion::internal_np::check_##NAME<K>();                                                   \
    return {k, *this};                                                                                \
  }
  CGAL_HEAT_DIFFUSION_PARAMETER_LIST(CGAL_HEAT_DIFFUSION_MEMBER)
#undef CGAL_HEAT_DIFFUSION_MEMBER
};
/// \endcond

namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionRef
/// Named parameters of the package. They chain with each other and with CGAL's own
/// parameters in any order, as long as the chain starts in this namespace:
/// `CGAL::Heat_diffusion::parameters::sigma(0.1).time(2.).vertex_point_map(vpm).number_of_steps(3)`,
/// or `CGAL::Heat_diffusion::parameters::vertex_point_map(vpm).sigma(0.1)`: this namespace
/// also offers every parameter of `CGAL::parameters`. A chain that starts in
/// `CGAL::parameters` cannot take the package's parameters
/// (`CGAL::parameters::vertex_point_map(vpm).sigma(0.1)` does not compile: CGAL 5.5's
/// packs cannot be given new members); `combine()` merges such packs. The packs are
/// `CGAL::Named_function_parameters`, which CGAL's functions accept (they ignore the
/// package's parameters). A value of the wrong type, such as `number_of_steps(2.7)`,
/// is a compile-time error that names the parameter.
///
/// Every parameter of this namespace may also be given as a `std::optional` of its
/// value type: an empty optional is the same as leaving the parameter out, so that a
/// program that knows only at run time which parameters its user set (a command-line
/// tool, a language binding) passes one pack of one type and gets, for the rest,
/// exactly the function's own defaults, adaptive ones included:
/// `parameters::sigma(std::optional<double>()).time(std::optional<double>(2.))` is `parameters::time(2.)`.
namespace parameters {

/// \cond SKIP_IN_MANUAL
using CGAL::parameters::default_values;
using CGAL::parameters::Default_named_parameters;
using CGAL::parameters::get_parameter;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::is_default_parameter;

#define CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(NAME)                                                        \
  template <typename K>                                                                                 \
  CGAL::Named_function_parameters<K, internal_np::NAME##_t> NAME(const K& value)                        \
  {                                                                                                     \
    internal_np::check_##NAME<K>();                                                                     \
    return CGAL::Named_function_parameters<K, internal_np::NAME##_t>(value);                            \
  }

// CGAL's parameters, starting a chain that takes the package's parameters too.
#define CGAL_add_named_parameter(X, Y, Z)                                                                \
  template <typename K>                                                                                 \
  auto Z(const K& value)                                                                                \
  {                                                                                                     \
    return CGAL::Named_function_parameters<bool, internal_np::chain_t,                                  \
                                           CGAL::Named_function_parameters<K, CGAL::internal_np::X> >(  \
        false, CGAL::Named_function_parameters<K, CGAL::internal_np::X>(value));                        \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
/// \endcond

/// Edge-weight width `sigma` of \f$ w_{ij} = \exp(-|\delta_i-\delta_j|^2/\sigma^2) \f$ (paper, eq. 10).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(sigma)
/// Diffusion time `t` of one step, measured on the mesh rescaled to total area = vertex count.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(time)
/// Number `m` of generalized eigenpairs of the truncated spectral kernel (paper, eq. 20).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(number_of_eigenpairs)
/// Number `k` of diffusion steps \f$ F^k = A_t^k F^0 \f$ (paper, eq. 19).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(number_of_steps)
/// Weight of the positional anchors of the least-squares reconstruction (paper, eq. 23).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(anchor_weight)
/// Rule that computes vertex normals, a model of `VertexNormalRule`.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(vertex_normal_rule)

/// `true` for the scale-invariant kernel of eq. 14 instead of eq. 13.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(scale_invariant_kernel)
/// How `Anisotropic_heat_diffusion` evaluates the heat kernel, a `Heat_kernel_method`.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(kernel_method)
/// How `Anisotropic_heat_diffusion` makes \f$ A_t \f$ from the kernel, an `Operator_normalization`.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(operator_normalization)
/// The accuracy of the local heat kernel (`Heat_kernel_method::local`): the heat that a
/// column may lose through the border of the patch it is computed on, relative to its
/// heat, which also chooses the rational approximation of the exponential (the one with
/// the fewest poles whose error is at most a quarter of it). See `defaults::local_kernel_tolerance`.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(local_kernel_tolerance)
/// A callable `bool(double fraction_done)` called on the calling thread during long
/// computations (the eigenpairs and the coarse level, the heat regions, denoising);
/// returning `false` cancels them with an exception.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(progress_callback)

/// The threshold c of the feature criterion \f$ F^k(i) > c \max F^k \f$ (paper, section 7).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(feature_threshold)
/// Number of diffusion steps that make one level of a hierarchical decomposition (paper, eq. 24).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(steps_per_level)

/// Vertex count of the coarse level on which the eigenpairs are computed (paper,
/// eq. 21); 0 computes them on the mesh itself. See `Edge_weighted_heat_kernel`.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(coarse_vertex_count)

/// The algorithm of `denoise_mesh()`, a `Denoising_method`.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(denoising_method)
/// The width \f$ \sigma_n \f$ of the normal weights \f$ \exp(-|n_f - n_g|^2 / 2\sigma_n^2) \f$ of
/// `denoise_mesh()` (`Denoising_method::normal_filtering`).
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(normal_sigma)
/// The bound on the root mean square displacement of `denoise_mesh()`
/// (`Denoising_method::normal_filtering`), in multiples of the estimated noise level.
CGAL_HEAT_DIFFUSION_NAMED_PARAMETER(displacement_limit)

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
/// One pack: `np` itself (the end of the recursion of `combine()`).
template <typename NP>
const NP& combine(const NP& np)
{
  return np;
}

/// \ingroup PkgHeatDiffusionRef
/// Merges named parameter packs, so that this package's parameters and CGAL's own
/// can be given in any order:
/// `combine(CGAL::parameters::vertex_point_map(vpm), parameters::sigma(0.1))`.
/// The result can be passed to this package's functions and to CGAL's (which
/// ignore the tags they do not know). When a parameter appears in several packs,
/// the value of the last pack wins.
template <typename NP1, typename NP2, typename... NPs>
auto combine(const NP1& np1, const NP2& np2, const NPs&... rest)
{
  return combine(internal::rebase(np2, np1), rest...);
}

} // namespace parameters

/// \cond SKIP_IN_MANUAL
namespace internal {

template <typename V>
constexpr bool is_optional = false;
template <typename V>
constexpr bool is_optional<std::optional<V> > = true;

// Whether `np` gives the parameter `tag`: it is in the pack, and not as an empty
// std::optional. The functions whose default is not a value (an automatic choice)
// decide with this at run time.
template <typename NamedParameters, typename Tag>
bool is_given(const NamedParameters& np, Tag tag)
{
  if constexpr(parameters::is_default_parameter<NamedParameters, Tag>::value)
    return false;
  else
  {
    const auto& value = parameters::get_parameter(np, tag);
    if constexpr(is_optional<std::decay_t<decltype(value)> >)
      return value.has_value();
    else
      return true;
  }
}

// The value of the parameter `tag` in `np`, or `default_value` where it is not given
// (is_given()): parameters::choose_parameter() that also opens a std::optional. An empty
// std::optional<T> gives T(default_value): a default that T cannot hold (a negative one
// for an unsigned T) is for the caller to read with is_given() instead.
template <typename NamedParameters, typename Tag, typename Default>
auto parameter_value(const NamedParameters& np, Tag tag, const Default& default_value)
{
  if constexpr(parameters::is_default_parameter<NamedParameters, Tag>::value)
    return default_value;
  else
  {
    const auto& value = parameters::get_parameter(np, tag);
    typedef std::decay_t<decltype(value)> Value;
    if constexpr(is_optional<Value>)  // in the type of the value given, as when it is given plainly
    {
      typedef typename Value::value_type Result;
      return value ? Result(*value) : Result(default_value);
    }
    else
      return Value(value);
  }
}

} // namespace internal
/// \endcond

} // namespace Heat_diffusion
} // namespace CGAL

#undef CGAL_HEAT_DIFFUSION_PARAMETER_LIST

#endif // CGAL_HEAT_DIFFUSION_PARAMETERS_H
