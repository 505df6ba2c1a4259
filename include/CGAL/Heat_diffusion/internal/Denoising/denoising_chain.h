// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The default algorithm of denoise_mesh() (Denoising_method::normal_filtering) as a
// chain: the outlier test (impulse_removal.h), the normal filter (normal_filtering.h),
// and the vertices put back where they were along the surface (tangential_drift.h). The
// untangling of self-intersections, which needs the user's mesh, follows in denoising.h.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_DENOISING_CHAIN_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_DENOISING_CHAIN_H

#include <CGAL/Heat_diffusion/denoising_report.h>
#include <CGAL/Heat_diffusion/internal/Denoising/face_adjacency.h>
#include <CGAL/Heat_diffusion/internal/Denoising/impulse_removal.h>
#include <CGAL/Heat_diffusion/internal/Denoising/normal_filtering.h>
#include <CGAL/Heat_diffusion/internal/Denoising/tangential_drift.h>
#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/progress.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The default algorithm: the outlier test (remove_impulses()), then the normal filter
// (filter_normals_of_input()) on its result, which is then the filter's input (its noise level, displacements and
// shrinkage are measured from there). The filter alone leaves impulses: its noise level,
// a median, reads the clean majority (fandisk, impulses of 1 mean edge length on a fifth
// of the vertices: 18.8 degrees, the noisy input 20.2). The filter still runs after the
// test, for noise that is also Gaussian (fandisk, 0.1 everywhere and impulses of 0.5 on
// a tenth: the test alone 13.2, the filter alone 2.01, both 1.80). A user normal_sigma
// runs the filter alone, as asked. Last, on curved surfaces, half of the vertices'
// drift within the surface is undone (undo_tangential_drift()).
inline std::vector<Eigen::Vector3d> filter_normals(const Indexed_mesh& mesh, const Normal_filtering_options& options,
                                                   const Progress& reporter, Denoising_report* report = nullptr)
{
  std::vector<Eigen::Vector3d> cleaned = mesh.points;
  const std::size_t impulses =
      options.normal_sigma > 0 || options.iterations == 0 ? 0 : remove_impulses(mesh, cleaned);
  Indexed_mesh cleaned_mesh;
  if(impulses > 0)
  {
    cleaned_mesh = mesh;
    cleaned_mesh.points.swap(cleaned);
  }
  const Indexed_mesh& input = impulses > 0 ? cleaned_mesh : mesh;
  Denoising_report own_report;
  Denoising_report* chain_report = report ? report : &own_report;
  std::vector<Eigen::Vector3d> points = filter_normals_of_input(input, options, reporter, chain_report);
  // Where the isotropic filtering of a curved surface ran (5 and 6 of denoise_mesh()):
  // its fit to the normals and its relaxations slide the vertices within the surface.
  // Not on the piecewise flat path, whose fit pulls the vertices onto the creases (fandisk
  // at 0.3 along the normals: 2.71 to 3.13 degrees with the drift undone in full), nor on
  // the smoothed copies of needle meshes and the cotangent flow, whose vertices moved
  // along the needles by more than their rings (anchor at 0.1: 12.6 to 15.0 degrees with
  // half the drift undone, cheese at 0.3 in random directions 21.2 to 40.4, and the RMS
  // error still above the noisy input's).
  const Denoising_stage stage = chain_report->stage;
  if(stage == Denoising_stage::curved || stage == Denoising_stage::needle_fit)
    undo_tangential_drift(input, make_face_adjacency(input), input.points, points);
  if(report && impulses > 0)
  {
    report->impulses = impulses;
    if(report->stage == Denoising_stage::unchanged)
      report->stage = Denoising_stage::impulses;
  }
  return points;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_DENOISING_CHAIN_H
