// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// What denoise_mesh() chose and did: its algorithm, the noise level it estimated, the
// stage whose result it returned, the kernel it selected.

#ifndef CGAL_HEAT_DIFFUSION_DENOISING_REPORT_H
#define CGAL_HEAT_DIFFUSION_DENOISING_REPORT_H

#include <CGAL/Heat_diffusion/heat_kernel_method.h>

#include <cstddef>

namespace CGAL {
namespace Heat_diffusion {

/// \ingroup PkgHeatDiffusionApplications
/// The algorithm of `denoise_mesh()` (its named parameter `denoising_method`).
enum class Denoising_method
{
  /// The default: anisotropic diffusion of the face normals, whose edge weights
  /// are those of eq. 10 with the normals in place of the NCC, alternated with
  /// vertex updates that fit the faces to the diffused normals; the noise level, the
  /// weights and the stop adapt to the mesh (see `denoise_mesh()`).
  normal_filtering,
  /// The paper's pipeline (eq. 22-23): the Normal Signature diffused with the
  /// edge-weighted heat kernel, the normals updated, the vertices reconstructed by
  /// `reconstruct_from_normal_signature()`.
  signature_diffusion
};

/// \ingroup PkgHeatDiffusionApplications
/// The stage of `denoise_mesh()` whose result it returned (the numbers are those of its
/// description).
enum class Denoising_stage
{
  /// No noise was measured (1), or what was measured is the shape's own roughness
  /// (a clean mesh), or the filter left every vertex where it was: the mesh is returned
  /// unchanged.
  unchanged,
  /// The iterations with the user's `normal_sigma`.
  user_normal_sigma,
  /// The crease-preserving filter, run on to its fixed point on a piecewise flat surface (4).
  piecewise_flat,
  /// The isotropic filtering of a curved surface (5).
  curved,
  /// A curved mesh of needle triangles: the smoothed copy of the input, or its blend with
  /// the cotangent flow W (6).
  needle_copy,
  /// A curved mesh of needle triangles: the isotropic filtering from the fit to the
  /// smoothed copy, or its blend with that of 5 (6).
  needle_fit,
  /// The filter eroded a closed part by more than 1 % of its volume: the input smoothed by
  /// the cotangent flow W, rescaled to its volume.
  cotangent_flow,
  /// `Denoising_method::signature_diffusion`.
  signature_diffusion,
  /// Impulsive noise: the outliers that the test of step 0 found were moved back along
  /// their rings' normals, and the filters that followed left the result as it was.
  impulses
};

/// \ingroup PkgHeatDiffusionApplications
/// What `denoise_mesh()` chose where its defaults adapt to the mesh, and what it did:
/// the values a front end reports next to the parameters its user gave.
struct Denoising_report
{
  /// The algorithm that ran.
  Denoising_method method = Denoising_method::normal_filtering;
  /// Normal filtering: the estimated noise level (step 1 of `denoise_mesh()`), in mean
  /// edge lengths of the input; 0 where none was measured, and for signature diffusion.
  double noise_level = 0;
  /// The iterations done: normal filtering, the diffusion and fit iterations of all its
  /// phases; signature diffusion, the outer iterations.
  std::size_t iterations = 0;
  /// The stage whose result was returned.
  Denoising_stage stage = Denoising_stage::unchanged;
  /// Normal filtering: the number of vertices that the outlier test (step 0 of
  /// `denoise_mesh()`) moved back; 0 where it found no impulsive noise.
  std::size_t impulses = 0;
  /// Signature diffusion: the kernel that `Heat_kernel_method::automatic` (or the user)
  /// selected. Normal filtering builds no heat kernel: `Heat_kernel_method::automatic`.
  Heat_kernel_method kernel_method = Heat_kernel_method::automatic;
};

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_DENOISING_REPORT_H
