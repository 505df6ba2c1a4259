// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The default algorithm of denoise_mesh() (Denoising_method::normal_filtering):
// anisotropic diffusion of the face normals alternated with vertex updates, a noise
// estimate and the rules that choose the normal weights and when to stop. Everything
// is measured in lengths local to each vertex and face, so that meshes whose edge
// lengths vary wildly (CAD exports of needle triangles) are treated like even ones.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NORMAL_FILTERING_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NORMAL_FILTERING_H

#include <CGAL/Heat_diffusion/denoising_report.h>
#include <CGAL/Heat_diffusion/internal/Denoising/face_adjacency.h>
#include <CGAL/Heat_diffusion/internal/Denoising/needle_surface_fit.h>
#include <CGAL/Heat_diffusion/internal/Denoising/noise_level.h>
#include <CGAL/Heat_diffusion/internal/Denoising/normal_fit.h>
#include <CGAL/Heat_diffusion/internal/Denoising/normal_widths.h>
#include <CGAL/Heat_diffusion/internal/Denoising/shrinkage_stop.h>
#include <CGAL/Heat_diffusion/internal/Denoising/volume_preservation.h>
#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/parallel_for.h>
#include <CGAL/Heat_diffusion/internal/progress.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// Tangential relaxation: every interior vertex moves by `weight` times the component
// of (mean of its neighbours - v_i) in its tangent plane. It changes the shape only to
// second order; it undoes the part of the noise that moved the vertices within the
// surface, which the fit to the normals (along the normals) cannot. `scratch` is
// scratch space.
inline void relax_tangentially(const Indexed_mesh& mesh, const Face_adjacency& adjacency, double weight,
                               std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector3d>& scratch,
                               std::vector<Eigen::Vector3d>& normals)
{
  area_weighted_normals(mesh, adjacency, points, normals);
  scratch = points;
  parallel_for(points.size(), [&](std::size_t i) {
    const std::size_t degree = mesh.degree(i);
    const double length = normals[i].norm();
    if(degree < 3 || !mesh.fan_is_closed[i] || !(length > 0))
      return;
    const Eigen::Vector3d normal = normals[i] / length;
    const Eigen::Vector3d move = fan_mean(mesh, scratch, i) - scratch[i];
    points[i] = scratch[i] + weight * (move - normal * normal.dot(move));
  });
}

// One step of the anisotropic diffusion of the face normals:
// n_f <- normalise(sum_{g in {f} u R(f)} a_g exp(-|n_f - n_g|^2 / (sigma_f^2 + sigma_g^2)) n_g),
// R(f) the faces sharing a vertex with f: the edge weights of eq. 10 with the normals
// in place of the NCC, with a width sigma_f per face (`widths`, see
// crease_preserving_widths(); equal widths give the weight exp(-|n_f - n_g|^2 / 2 sigma^2)
// of eq. 10). No spatial weight: R(f) is already the smallest neighbourhood, and a width
// in units of a global length would weigh the neighbours of small and large faces
// differently. Empty `widths` diffuse isotropically (sigma = infinity). `next` is
// scratch space.
inline void diffuse_face_normals(const Face_adjacency& adjacency, const std::vector<double>& areas,
                                 const std::vector<double>& widths, std::vector<Eigen::Vector3d>& normals,
                                 std::vector<Eigen::Vector3d>& next)
{
  const std::size_t m = normals.size();
  next.resize(m);
  const bool isotropic = widths.empty();
  parallel_for(m, [&](std::size_t f) {
    Eigen::Vector3d sum = areas[f] * normals[f];
    for(std::size_t k = adjacency.face_faces_begin[f]; k < adjacency.face_faces_begin[f + 1]; ++k)
    {
      const std::size_t g = adjacency.face_faces[k];
      const double weight = isotropic ? 1.
                                      : std::exp(-(normals[f] - normals[g]).squaredNorm() /
                                                 (widths[f] * widths[f] + widths[g] * widths[g]));
      sum += areas[g] * weight * normals[g];
    }
    const double length = sum.norm();
    next[f] = length > 0 && std::isfinite(length) ? Eigen::Vector3d(sum / length) : normals[f];
  });
  normals.swap(next);
}

// Vertex update for given face normals (Sun et al. 2007): Jacobi steps of the fit
// of each face's plane to its target normal,
// v_i <- v_i + (1/|F_i|) sum_{f in F_i} n_f n_f^T (c_f - v_i).
// `centroids` must be the face centroids of `points` on entry (they are overwritten:
// each step needs those of its own points); `next` is scratch space.
inline void fit_vertices_to_normals(const Indexed_mesh& mesh, const Face_adjacency& adjacency,
                                    const std::vector<Eigen::Vector3d>& face_normals, std::size_t steps,
                                    std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector3d>& centroids,
                                    std::vector<Eigen::Vector3d>& next)
{
  const std::size_t n = points.size();
  next.resize(n);
  for(std::size_t step = 0; step < steps; ++step)
  {
    if(step > 0)
      for(std::size_t f = 0; f < mesh.triangles.size(); ++f)
      {
        const auto& t = mesh.triangles[f];
        centroids[f] = (points[t[0]] + points[t[1]] + points[t[2]]) / 3.;
      }
    parallel_for(n, [&](std::size_t i) {
      Eigen::Vector3d move = Eigen::Vector3d::Zero();
      const std::size_t begin = adjacency.vertex_faces_begin[i], end = adjacency.vertex_faces_begin[i + 1];
      for(std::size_t k = begin; k < end; ++k)
      {
        const std::size_t f = adjacency.vertex_faces[k];
        move += face_normals[f] * face_normals[f].dot(centroids[f] - points[i]);
      }
      next[i] = end > begin ? Eigen::Vector3d(points[i] + move / double(end - begin)) : points[i];
    });
    points.swap(next);
  }
}

struct Normal_filtering_options
{
  std::size_t iterations = 40;
  std::size_t steps = 1;
  double normal_sigma = 0;  // 0: chosen by the algorithm
  double displacement_limit = 1.;
};

// A surface that the crease-preserving filter makes flat to within this fraction of the
// noise level is taken for piecewise flat (CAD parts: 0.02 to 0.14 of it on CGAL's
// fandisk and anchor_dense with 0.1 to 0.5 mean edge length of noise, but 0.16 on
// anchor_dense at 0.5 in random directions); curved surfaces keep more (elephant: 0.16
// to 0.53, armadillo 0.16 to 0.35 up to 0.3 noise; the needle-triangle blade), which the
// filter would only turn into false creases. The test is close on some meshes (see the
// user manual: elephant at 0.5 noise, ALSTOM_TEST4 at 0.3).
constexpr double piecewise_flat_roughness = 0.15;

// The isotropic filtering of a curved surface (see filter_normals) in small iterations:
// one Jacobi step of the vertex fit instead of five, then a tangential relaxation of
// this weight (relax_tangentially). Five steps move the vertices by about 0.7 of the
// noise level per iteration, too coarse for the stop (elephant at 0.1 noise: 6.96, 8.01
// and 9.02 degrees after the first three); the relaxation removes the noise within the
// surface (noise in random directions). Larger weights flatten the detail and erode
// the thin walls of CAD parts (turbine at 0.1 noise: 8.09 degrees with 0.1, 8.47 with
// 0.2, 8.84 with 0.3).
constexpr std::size_t curved_fit_steps = 1;
constexpr double curved_tangential_weight = 0.1;

// After the small iterations, tangential relaxations (of curved_tangential_weight) in a
// number that ramps from 0 to 30 as the noise level of second differences goes from
// 0.12 to 0.17 mean edge lengths. Noise in random directions displaces the vertices
// within the surface too, and from about that level on the relaxations of the small
// iterations leave most of it: measured with the benchmark's seeds, 30 more relaxations
// took elephant at 0.5 noise in random directions from 14.1 to 10.3 degrees (new
// self-intersections 131 to 6), bunny from 14.2 to 7.64 (4488 to 0) and armadillo from
// 17.4 to 12.5 (2340 to 217), with the volume unchanged. At low noise they cost more than
// they gain (elephant at 0.1 along the normals: 7.00 to 7.41 with 30): the relaxation
// also moves a clean but irregular mesh. Noise in random directions reads lower on this
// scale (only its component along the normals counts): 0.07 mean edge lengths on
// elephant at 0.1, 0.15 at 0.3, 0.22 at 0.5; along the normals 0.11, 0.26 and 0.36.
inline std::size_t final_relaxation_steps(double noise_in_mean_edges)
{
  const double ramp = (std::max)(0., (std::min)(1., (noise_in_mean_edges - 0.12) / 0.05));
  return std::size_t(std::lround(30. * ramp));
}

// Runs the filter on `points` (the normalised frame of `mesh`), starting from the input
// positions. Without a user normal_sigma:
//  1. the crease-preserving filter, with a width per face adapted to the noise and to
//     the shape's bending (crease_preserving_widths()), runs until the vertices have
//     moved, in root mean square, `displacement_limit` times the noise level of the input;
//  2. if the result is piecewise flat (its own noise level is below
//     piecewise_flat_roughness times that of the input), the filter goes on for all the
//     iterations: flat parts and creases between wide flat parts are its fixed point, so
//     more iterations sharpen them. Not so a strip one face wide between two creases
//     (the rims and chamfers of thin-walled parts): its faces have fewer neighbours in
//     their own plane than across the creases, whose small weights (0.007 each at 90
//     degrees) then win, and every iteration tilts the strip further into its walls.
//     Measured on CGAL's turbine (2603 of its 18460 faces have their three vertices on
//     creases of 40 degrees or more), with noise of only 0.02 mean edge length and
//     this path: those faces go from 4.3 to 56 degrees of MAD over the 40 iterations
//     and the volume shrinks by 17 %; with the clean normals put back on them after
//     each diffusion, 0.3 noise ends at 3.6 degrees and -1.0 %. Unsolved (see the
//     user manual);
//  3. otherwise the surface is curved, and the normals are diffused isotropically from
//     the input (the range weights would freeze the noise into false creases) in small
//     iterations with a tangential relaxation, until the displacement along the
//     normals reaches the noise level of second differences less (in quadrature) its
//     level on the result of 1, which keeps the shape's detail, then relaxed
//     tangentially where that noise level is large (final_relaxation_steps()). On a
//     mesh of needles (needle factor nu > 0, see needle_reference_aspect) the result is
//     a smoothed copy rescaled to the input's volume for nu >= 1; for 0 < nu < 1 the
//     filter starts from the fit to the needle copy instead of the input, and the small
//     iterations are blended with coarse ones, stopped on the whole displacement with
//     the noise level measured along the smoothed normals.
// 1, 2, the fit and the coarse iterations of 3 end before they shrink the shape (see
// shrinkage_bound), and a needle copy that shrinks it is not used. With a user
// normal_sigma, that width is used until the displacement limit.
// A mesh without measurable noise is left unchanged, and so is a curved one whose
// roughness after 1 is as large as its noise estimate (the estimate was all shape).
// `report`, if given, receives the noise level, the iterations and the stage returned.
inline std::vector<Eigen::Vector3d> filter_normals_of_input(const Indexed_mesh& mesh,
                                                            const Normal_filtering_options& options,
                                                            const Progress& reporter, Denoising_report* report)
{
  const std::size_t n = mesh.number_of_vertices();
  const Face_adjacency adjacency = make_face_adjacency(mesh);
  const double noise = plane_fit_noise_level(mesh, adjacency, mesh.points);
  std::vector<Eigen::Vector3d> points = mesh.points;
  std::size_t done = 0;
  auto record = [&](Denoising_stage stage) {
    if(report)
    {
      report->method = Denoising_method::normal_filtering;
      report->noise_level = std::isfinite(noise) && noise > 0 ? noise / mean_edge_length(mesh) : 0.;
      report->iterations = done;
      report->stage = stage;
    }
  };
  if(!(noise > 0) || !std::isfinite(noise) || options.iterations == 0)
  {
    record(Denoising_stage::unchanged);
    return points;
  }

  std::vector<Eigen::Vector3d> face_normals, centroids, face_scratch, vertex_scratch;
  std::vector<double> areas;
  auto displacement_of = [&](const std::vector<Eigen::Vector3d>& moved) {
    double squares = 0;
    for(std::size_t i = 0; i < n; ++i)
      squares += (moved[i] - mesh.points[i]).squaredNorm();
    return std::sqrt(squares / double(n));
  };
  auto displacement = [&]() { return displacement_of(points); };
  // One iteration; returns the root mean square move of the vertices.
  auto iterate = [&](const std::vector<double>& widths, std::size_t fit_steps = 5, double tangential_weight = 0) {
    const std::vector<Eigen::Vector3d> before = points;
    face_geometry(mesh, points, face_normals, areas, centroids);
    for(std::size_t step = 0; step < options.steps; ++step)
      diffuse_face_normals(adjacency, areas, widths, face_normals, face_scratch);
    fit_vertices_to_normals(mesh, adjacency, face_normals, fit_steps, points, centroids, vertex_scratch);
    if(tangential_weight > 0)
      relax_tangentially(mesh, adjacency, tangential_weight, points, vertex_scratch, face_scratch);
    ++done;
    reporter.report((std::min)(1., double(done) / double(options.iterations)), "denoise_mesh");
    double squares = 0;
    for(std::size_t i = 0; i < n; ++i)
      squares += (points[i] - before[i]).squaredNorm();
    return std::sqrt(squares / double(n));
  };
  // The magnitude of the mean displacement of `moved` along the input's normals if it is
  // shrinking the shape (see shrinkage_bound), else 0.
  std::vector<Eigen::Vector3d> input_normals;
  area_weighted_normals(mesh, adjacency, mesh.points, input_normals);
  auto shrinkage_of = [&](const std::vector<Eigen::Vector3d>& moved) {
    const double mean = std::abs(mean_normal_displacement(mesh.points, moved, input_normals));
    return mean > shrinkage_bound * noise && mean >= systematic_fraction * displacement_of(moved) ? mean : 0.;
  };
  auto shrinkage = [&]() { return shrinkage_of(points); };
  std::vector<Eigen::Vector3d> previous;
  // One iteration, undone if it shrinks the shape: then returns false. `move` receives
  // the root mean square move of the iteration.
  auto iterate_unless_shrinking = [&](const std::vector<double>& widths, double& move) {
    previous = points;
    move = iterate(widths);
    if(shrinkage() == 0)
      return true;
    points.swap(previous);
    return false;
  };
  // Iterations until the displacement limit; `guarded`: and before the shape shrinks.
  auto run_to_limit = [&](const std::vector<double>& widths, double limit, bool guarded) {
    double move = 0;
    for(std::size_t it = 0; it < options.iterations; ++it)
    {
      if(!guarded)
        iterate(widths);
      else if(!iterate_unless_shrinking(widths, move))
        break;
      if(displacement() >= limit)
        break;
    }
  };

  if(options.normal_sigma > 0)
  {
    run_to_limit(std::vector<double>(mesh.triangles.size(), options.normal_sigma), options.displacement_limit * noise,
                 false);
    record(Denoising_stage::user_normal_sigma);
    return points;
  }
  // The cotangent flow of the input: one symbolic factorisation for all its smoothings.
  Cotangent_flow flow(mesh, mesh.points);
  // The result of a normal filter in `points`, or instead, where the filter has eroded
  // the shape (see volume_tolerance), the input smoothed by the cotangent flow until
  // what it removes is no longer white noise (smooth_until_residual_is_correlated()),
  // rescaled to the input's volume (unless the flow fails). Records `stage`, or the flow.
  auto unless_eroded = [&](Denoising_stage stage) {
    std::vector<Eigen::Vector3d> smoothed;
    double time = 0;
    if(options.displacement_limit <= erosion_check_limit &&
       largest_volume_change(mesh, mesh.points, points) > volume_tolerance &&
       smooth_until_residual_is_correlated(mesh, noise, flow, smoothed, time))
    {
      restore_component_volumes(mesh, mesh.points, smoothed);
      points.swap(smoothed);
      stage = Denoising_stage::cotangent_flow;
    }
    record(stage);
  };
  const std::vector<double> widths = crease_preserving_widths(mesh, adjacency, noise, flow);
  run_to_limit(widths, options.displacement_limit * noise, true);
  const std::size_t first_phase = done;
  const double roughness = plane_fit_noise_level(mesh, adjacency, points);
  // A mesh of needles (needle factor 1 or more, see needle_reference_aspect) is not
  // taken for piecewise flat: its normals are mostly noise, and the crease-preserving
  // phase cuts a curved mesh of needles into false facets that pass the test (blade at
  // 0.1 noise: a roughness of 0.068 of the noise level; b9_mesh 0.05 to 0.14, nu 1.05 to
  // 2.1). Measured with the benchmark's seeds: blade clean and at 0.1 along the normals
  // 2.57 and 8.86 degrees on the piecewise flat path, 1.44 and 5.30 on the needle path;
  // b9_mesh clean and at 0.1 to 0.5 both ways 28.0 and 28.9 to 41.1 against 21.3 and
  // 20.1 to 32.1.
  const Needle_measure needles = measure_needles(mesh, adjacency, flow);
  const double needle_factor = needles.factor;
  if(roughness < piecewise_flat_roughness * noise && needle_factor < 1)
  {
    double move = 0;
    for(std::size_t it = first_phase; it < options.iterations; ++it)
      if(!iterate_unless_shrinking(widths, move) || move < 1e-4 * noise)  // shrinking, or converged
        break;
    unless_eroded(Denoising_stage::piecewise_flat);
    return points;
  }
  // The noise level of the coarse iterations' stop (meshes of needles), without the
  // shape's own detail. The estimate of the input
  // measures the noise and the detail of a curved shape together (a smooth surface gives
  // a multiple of its curvature times the squared edge length: 0.15 mean edge length on
  // the clean elephant, 0.11 on armadillo, against 0.003 on fandisk), so that at low noise
  // the isotropic filtering ran until it had moved the vertices by the noise plus the
  // detail, and flattened the detail (elephant at 0.1 noise: the estimate reads 0.17 mean
  // edge length, and each isotropic iteration after the first raised the MAD). The
  // roughness left by the crease-preserving phase is that detail (the filter has removed
  // the noise and kept the shape: the premise of the piecewise flat test above); noise
  // and detail are independent and add in quadrature, so the noise alone is
  // sqrt(1 - rho^2) times the estimate, rho = roughness / noise. On piecewise flat
  // parts this path is not taken.
  const double rho = roughness / noise;
  const double detail_free = std::sqrt((std::max)(0., 1. - rho * rho));
  // A roughness as large as the estimate (rho >= 1) leaves no noise at all: the estimate
  // measured the shape alone, and the input is returned unchanged. Clean meshes whose
  // estimate reads rounding errors or the facets of a coarse tessellation as noise end
  // here (CGAL's fandisk, anchor_dense, rotor_small: rho 1.05, 1e11 and 1.12; the filters
  // below moved them by the second-difference level or the needle fit, up to 16 degrees
  // of MAD on rotor_small), while noise keeps rho below 0.6 on the benchmark's twelve
  // meshes from 0.1 mean edge length on, and below 0.87 on eight of them at 0.02.
  if(detail_free == 0)
  {
    record(Denoising_stage::unchanged);
    return mesh.points;
  }
  // The same subtraction for the noise level of second differences (the stop of the
  // small iterations below): the level of the crease-preserving phase's result is the
  // detail that this estimate counts. (Measured here: the curved path below starts
  // again from the input.)
  const double detail_of_second_differences = second_difference_noise_level(mesh, adjacency, points);
  points = mesh.points;
  const double curved_noise =
      needles.noise > 0 ? noise + (std::min)(1., needle_factor) * (needles.noise - noise) : noise;
  // On a mesh of needles with nu >= 1 the result is a smoothed copy of the input
  // (smooth_needle_mesh()); if the flow fails, or for 0 < nu < 1, the vertices fitted to
  // the normals of the needle copy, anchored to the input, and the filter below.
  if(needle_factor >= 1 &&
     smooth_needle_mesh(mesh, adjacency, noise, needles, flow,
                        [&](const std::vector<Eigen::Vector3d>& copy) { return shrinkage_of(copy) > 0; }, points))
  {
    record(Denoising_stage::needle_copy);
    return points;
  }
  if(std::vector<Eigen::Vector3d> copy; needle_copy(needles, flow, copy))
  {
    std::vector<Eigen::Vector3d> copy_normals, copy_centroids, fitted;
    std::vector<double> copy_areas;
    face_geometry(mesh, copy, copy_normals, copy_areas, copy_centroids);
    if(fit_vertices_to_normals_least_squares(mesh, copy_normals, mesh.points, needle_fit_anchor_weight, fitted))
      points.swap(fitted);
  }
  // The fit of a mesh of needles to a smoothed copy shrinks the shape too: it is scaled
  // back where it does (see shrinkage_bound). The mean displacement is linear in the
  // scale, and its fraction of the root mean square displacement does not depend on it.
  if(const double mean = shrinkage(); mean > 0)
    for(std::size_t i = 0; i < n; ++i)
      points[i] = mesh.points[i] + (shrinkage_bound * noise / mean) * (points[i] - mesh.points[i]);
  const std::vector<double> isotropic;  // no range weights
  // On a mesh of needles (needle factor 1 or more) the coarse iterations below, with
  // the stop on the whole displacement: on blade at 0.3 noise the small iterations give
  // 11.2 degrees instead of 9.71. Between 0 and 1 the two results are blended.
  const double needle_weight = (std::min)(1., needle_factor);
  std::vector<Eigen::Vector3d> small_steps;
  if(needle_weight < 1)
  {
    // Small iterations (curved_fit_steps, curved_tangential_weight) until the root mean
    // square displacement from the input along the vertex normals reaches the limit,
    // the last iteration cut back so that it reaches it exactly (the displacement is
    // linear along the segment, to first order). The noise level is that of second
    // differences, which counts less of the shape's detail as noise (elephant at 0.1
    // noise: 1.10 times the noise, against 1.67 for plane_fit_noise_level), less the
    // detail that it still counts, in quadrature: its level on the result of the
    // crease-preserving phase. (Not the detail-free factor of the other estimate, which
    // would take most of the noise level away on bunny at 0.1 noise in random
    // directions, rho = 0.64: 3.14 degrees instead of 1.97.) Without that subtraction
    // the stop moved a mesh with little noise by its detail: elephant with 0.02 mean
    // edge length of noise went from 2.38 degrees of MAD to 4.76, the clean elephant to
    // 4.32. Only the displacement along the normals is compared with a noise measured
    // along them: the relaxation's moves within the surface are not noise removed along
    // the normals.
    const double input_level = second_difference_noise_level(mesh, adjacency, mesh.points);
    const double detail_ratio = input_level > 0 ? detail_of_second_differences / input_level : 1.;
    const double curved_noise_level = input_level * std::sqrt((std::max)(0., 1. - detail_ratio * detail_ratio));
    const double limit = options.displacement_limit * curved_noise_level;
    std::vector<Eigen::Vector3d> normals;
    auto normal_displacement = [&]() {
      area_weighted_normals(mesh, adjacency, points, normals);
      double squares = 0;
      for(std::size_t i = 0; i < n; ++i)
      {
        const double length = normals[i].norm();
        if(length > 0)
        {
          const double d = normals[i].dot(points[i] - mesh.points[i]) / length;
          squares += d * d;
        }
      }
      return std::sqrt(squares / double(n));
    };
    const std::vector<Eigen::Vector3d> start = points;
    double moved = normal_displacement();
    for(std::size_t it = 0; it < options.iterations && moved < limit; ++it)
    {
      previous = points;
      iterate(isotropic, curved_fit_steps, curved_tangential_weight);
      const double next = normal_displacement();
      if(next >= limit)
      {
        const double t = next > moved ? (std::max)(0., (std::min)(1., (limit - moved) / (next - moved))) : 1.;
        for(std::size_t i = 0; i < n; ++i)
          points[i] = previous[i] + t * (points[i] - previous[i]);
      }
      moved = next;
    }
    // Noise in random directions also moves the vertices within the surface, by more
    // than the small iterations' relaxation undoes once the noise is large: relax more.
    const std::size_t relaxations = final_relaxation_steps(curved_noise_level / mean_edge_length(mesh));
    for(std::size_t k = 0; k < relaxations; ++k)
      relax_tangentially(mesh, adjacency, curved_tangential_weight, points, previous, normals);
    if(needle_weight == 0)
    {
      unless_eroded(Denoising_stage::curved);
      return points;
    }
    small_steps.swap(points);
    points = start;
  }
  run_to_limit(isotropic, options.displacement_limit * detail_free * curved_noise, true);
  if(!small_steps.empty())
    for(std::size_t i = 0; i < n; ++i)
      points[i] = needle_weight * points[i] + (1. - needle_weight) * small_steps[i];
  unless_eroded(Denoising_stage::needle_fit);
  return points;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_DENOISING_NORMAL_FILTERING_H
