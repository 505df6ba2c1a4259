// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The default values of the package's named parameters, in one place: the functions
// read them, and so do front ends that must show a default (the tool's --help, the
// Python module's docstrings) without keeping a copy that could drift.

#ifndef CGAL_HEAT_DIFFUSION_PARAMETER_DEFAULTS_H
#define CGAL_HEAT_DIFFUSION_PARAMETER_DEFAULTS_H

#include <array>
#include <cstddef>
#include <limits>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionRef
/// The default values of the named parameters, where a function uses a fixed value.
/// Parameters whose default adapts to the mesh (the kernel of `Heat_kernel_method::automatic`,
/// the coarse level of `Edge_weighted_heat_kernel`, the normal widths of `denoise_mesh()`)
/// have no constant here: a front end that wants the library's choice leaves them out,
/// or passes an empty `std::optional` (see `parameters`).
namespace defaults {

/// `sigma` of `Anisotropic_heat_diffusion` and `Edge_weighted_heat_kernel`: the width of the edge weights of eq. 10.
inline constexpr double sigma = 0.1;
/// `time` of `Anisotropic_heat_diffusion`: t of one diffusion step.
inline constexpr double time = 1.;
/// `number_of_eigenpairs` of the spectral kernel (`Edge_weighted_heat_kernel`).
inline constexpr std::size_t number_of_eigenpairs = 150;
/// `number_of_steps` of `anisotropic_heat_diffusion()`.
inline constexpr std::size_t number_of_steps = 1;
/// `local_kernel_tolerance` of `Anisotropic_heat_diffusion`: the local kernel's accuracy,
/// chosen from the error that the heat regions' truncation of its columns already makes
/// (see the user manual). 1e-4, with three poles, was the package's earlier default.
inline constexpr double local_kernel_tolerance = 1e-2;
/// `feature_threshold` of `detect_features()` and `detect_multiscale_features()` (the paper's c).
inline constexpr double feature_threshold = 0.8;
/// The scales k at which the paper shows features and diffused fields (section 7), which
/// the tool and the Python module use when the caller gives none.
inline constexpr std::array<std::size_t, 3> feature_scales = {0, 10, 40};
/// The neighbour count k of the point-set classes and functions
/// (`Point_set_normal_controlled_coordinates`, `Point_set_anisotropic_heat_diffusion`),
/// which take it as an argument: the tool and the Python module use it when the caller
/// gives none (chosen by measurement: see the user manual's section on point sets).
inline constexpr unsigned int number_of_neighbors = 8;
/// `steps_per_level` of `decompose_field()`.
inline constexpr std::size_t decomposition_steps_per_level = 5;
/// `steps_per_level` of `filter_shape()`.
inline constexpr std::size_t shape_filter_steps_per_level = 2;
/// `anchor_weight` of `filter_shape()`.
inline constexpr double shape_filter_anchor_weight = 0.03;
/// `anchor_weight` of `reconstruct_from_normal_signature()`.
inline constexpr double reconstruction_anchor_weight = 1.;

/// The defaults of the heat kernel signature (`Edge_weighted_heat_kernel::heat_kernel_signature()`)
/// as Sun, Ovsjanikov and Guibas define it, which the tool's `hks` and the Python
/// module's `heat_kernel_signature()` compute when not told otherwise.
namespace heat_kernel_signature {
/// `sigma`: infinite, the plain (isotropic) Laplacian of the classical signature.
inline constexpr double sigma = std::numeric_limits<double>::infinity();
/// The time t of the signature, on the mesh rescaled to area = vertex count.
inline constexpr double time = 20.;
} // namespace heat_kernel_signature

/// The number of detail bands that the tool's `decompose` and the Python module's
/// `decompose()` make when not told (`decompose_field()` makes as many as it is given maps).
inline constexpr std::size_t detail_levels = 3;
/// The band weights of the tool's `enhance` when not told (`filter_shape()` takes them as
/// an argument): the details of the first band kept, those of the next two tripled.
inline constexpr std::array<double, 3> enhancement_weights = {1., 3., 3.};

/// The defaults of `denoise_mesh()`.
namespace denoising {
/// `number_of_iterations` with `Denoising_method::normal_filtering` (the displacement limit usually stops it first).
inline constexpr unsigned int normal_filtering_iterations = 40;
/// `number_of_iterations` with `Denoising_method::signature_diffusion`.
inline constexpr unsigned int signature_diffusion_iterations = 2;
/// `number_of_steps`: normal diffusion steps, or signature diffusion steps, per iteration.
inline constexpr std::size_t number_of_steps = 1;
/// `displacement_limit` (normal filtering), in multiples of the estimated noise level.
inline constexpr double displacement_limit = 1.;
/// `sigma` (signature diffusion): wider than `defaults::sigma`, see `denoise_mesh()`.
inline constexpr double sigma = 1.;
/// `time` (signature diffusion).
inline constexpr double time = 1.;
/// `anchor_weight` (signature diffusion).
inline constexpr double anchor_weight = 0.7;
} // namespace denoising

/// The defaults of `denoise_point_set()`, measured with `benchmark_point_set_denoising`.
namespace point_set_denoising {
/// The neighbour count k, which `denoise_point_set()` takes as an argument: the tool and
/// the Python module use it when the caller gives none. Wider than the fans'
/// `defaults::number_of_neighbors`: the planes fitted to the neighbours must average
/// over a few noise deviations (the user manual's section on point-set denoising).
inline constexpr unsigned int number_of_neighbors = 24;
/// `number_of_iterations` (the displacement limit usually stops them first).
inline constexpr unsigned int iterations = 40;
/// `number_of_steps`: normal filtering steps per iteration.
inline constexpr std::size_t number_of_steps = 1;
/// `displacement_limit`, in multiples of the estimated noise level.
inline constexpr double displacement_limit = 1.;
} // namespace point_set_denoising

} // namespace defaults
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_PARAMETER_DEFAULTS_H
