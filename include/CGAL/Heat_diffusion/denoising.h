// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Mesh denoising by anisotropic diffusion of the Normal Signature: paper, section 7, eq. 22-23.

#ifndef CGAL_HEAT_DIFFUSION_DENOISING_H
#define CGAL_HEAT_DIFFUSION_DENOISING_H

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/denoising_report.h>
#include <CGAL/Heat_diffusion/parameters.h>
#include <CGAL/Heat_diffusion/reconstruction.h>
#include <CGAL/Heat_diffusion/internal/Denoising/denoising_chain.h>
#include <CGAL/Heat_diffusion/internal/Denoising/self_intersection_repair.h>
#include <CGAL/Heat_diffusion/internal/Denoising/signature_normals.h>
#include <CGAL/Heat_diffusion/internal/errors.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/internal/named_params_helper.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <limits>
#include <optional>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {

// The named parameters denoising_method, normal_sigma and displacement_limit are in parameters.h.

/// \ingroup PkgHeatDiffusionApplications
/// Denoises the triangle mesh `tm` in place, keeping its connectivity. Two algorithms
/// are available (named parameter `denoising_method`).
///
/// <b>`Denoising_method::normal_filtering` (the default).</b> The paper's denoising
/// (section 7, eq. 22-23) diffuses the Normal Signature and reconstructs the vertices
/// from it; on a noisy mesh the diffused signature is too poor a target (see the user
/// manual), so the default diffuses the <em>normals</em> with the anisotropic edge weights
/// of eq. 10 instead, and fits the vertices to them. Every length it uses is local to a
/// vertex or a face, so that meshes of very uneven triangles are treated like even ones:
///  0. impulsive noise (a fraction of the vertices displaced far, the others clean) is
///     removed first, by an outlier test: the neighbours \f$ u_k \f$ of an interior vertex
///     \f$ v_i \f$ define, without it, a plane through their mean \f$ c_i \f$ with the normal
///     \f$ n_i \f$ of their polygon; \f$ h_i = n_i \cdot (v_i - c_i) \f$ is the height of
///     \f$ v_i \f$ above it, \f$ \rho_i \f$ the root mean square height of the \f$ u_k \f$
///     (how much the ring itself is folded), and \f$ r_i = h_i - p_i \f$ the residual, \f$ p_i \f$
///     the mean of the neighbours' own heights (a smooth surface's curvature cancels in it).
///     \f$ v_i \f$ is an outlier if \f$ |h_i| > 3 \rho_i \f$ (not a crease or a corner, which fold
///     the ring), \f$ |h_i| > 0.05\, e_i \f$ (\f$ e_i \f$ its mean edge length), \f$ r_i h_i > 0 \f$
///     and \f$ |r_i| > 4 s \f$, s the median of \f$ |r_j| \f$ over the vertices divided by
///     0.6745 (the scale of the clean majority); it is moved along \f$ n_i \f$ to the
///     height \f$ p_i \f$, so that it does not slide within the surface. The test runs up to
///     8 rounds, each moving every outlier found so far again. If the first round finds
///     fewer outliers than 1 % of the vertices (the tips and corners of a clean mesh, which
///     no local test tells from an impulse), the mesh is left as it is; otherwise what
///     follows runs on the result, as its input (noise that is both Gaussian and
///     impulsive needs both). Not with a user `normal_sigma`;
///  1. the noise level \f$ \hat\varepsilon \f$ is the median over interior vertices of the
///     distance of \f$ v_i \f$, along its area-weighted normal, from the mean of its
///     neighbours, divided by \f$ 0.6745 \sqrt{1 + 1/d_i} \f$ (\f$ d_i \f$ the degree): about
///     the standard deviation of Gaussian noise along the normals;
///  2. an iteration diffuses the face normals `number_of_steps` times,
///     \f$ n_f \leftarrow \sum_{g} a_g\, e^{-|n_f - n_g|^2/2\sigma_n^2}\, n_g \f$
///     (normalised) over f and the faces g sharing a vertex with f (\f$ a_g \f$ areas):
///     the weights of eq. 10 with normals in place of the NCC, which stop the diffusion
///     across creases; then moves the vertices so that the faces fit the diffused normals
///     (five Jacobi steps of \f$ v_i \leftarrow v_i + \frac{1}{|F_i|}\sum_{f \ni v_i} n_f n_f^T (c_f - v_i) \f$,
///     the vertex update of Sun et al. 2007);
///  3. with a width \f$ \sigma_f \f$ per face, the weight between f and g being
///     \f$ e^{-|n_f - n_g|^2/(\sigma_f^2 + \sigma_g^2)} \f$, the iterations run until the root
///     mean square displacement of the vertices reaches `displacement_limit`
///     \f$ \times\, \hat\varepsilon \f$. \f$ \sigma_f \f$ is \f$ \max(0.75\,\tau_f, 1.5\,\beta_f) \f$
///     clamped to [0.2, 0.45] (at 0.45 faces across a crease of 40 degrees or more weigh each
///     other less than a third): \f$ \tau_f = \hat\varepsilon \sqrt{\sum_i |e_i|^2} / (2 A_f) \f$ is the
///     tilt that the noise gives the normal of f (\f$ e_i \f$ its edges, \f$ A_f \f$ its area), and
///     \f$ \beta_f \f$ the area-weighted mean of \f$ |n_f - n_g| \f$ over the faces g sharing a
///     vertex with f on the input smoothed by the implicit cotangent flow for the time
///     \f$ 9 \bar e^2 \f$ (\f$ \bar e \f$ the mean edge length): how much the shape itself turns
///     there. Narrow widths keep the flat parts from leaking across creases; wider ones keep
///     the noise and the shape's curvature from being frozen into false creases;
///  4. if the result is then piecewise flat (its own noise level, measured as in 1, is
///     below 0.15 \f$ \hat\varepsilon \f$: CAD parts), the iterations go on, up to
///     `number_of_iterations` or until the vertices stop moving: flat parts and sharp
///     creases are the fixed point of the filter (not strips one face wide between two
///     creases, such as the rims of thin walls, which these iterations erode: see the
///     user manual);
///  5. otherwise the surface is curved: the range weights would freeze the noise into
///     false creases, so the input is filtered again with isotropic weights
///     (\f$ \sigma_n = \infty \f$) in small iterations (one Jacobi step of the vertex fit,
///     then a tangential relaxation \f$ v_i \leftarrow v_i + 0.1\,(I - n_i n_i^T)(\bar v_i - v_i) \f$,
///     \f$ \bar v_i \f$ the mean of the neighbours), until the root mean square displacement
///     from the input along the vertex normals reaches `displacement_limit` \f$ \times\,\hat\varepsilon_2 \f$,
///     the last iteration cut back to reach it exactly. \f$ \hat\varepsilon_2 = \sqrt{e_2(p)^2 - e_2(q)^2} \f$,
///     p the input and q the result of 3, where \f$ e_2 \f$ is the noise
///     level of second differences: the median over the vertices of the distance along the
///     normal of \f$ ((I - W)^2 p)_i \f$ from 0 (W the mean over the one-ring) divided by
///     \f$ 0.6745 \f$ and by the norm of row i of \f$ (I - W)^2 \f$; the curvature of a smooth
///     shape, which the estimate of 1 counts as noise, cancels in it to first order, and
///     the detail that it still counts, kept by 3, is subtracted (noise and detail add in
///     quadrature). Then, where \f$ \hat\varepsilon_2 \f$ is above 0.12 mean edge lengths, up to 30 more
///     tangential relaxations (their number ramps from 0 to 30 between 0.12 and 0.17 mean
///     edge lengths): noise in random directions moves the vertices within the surface too;
///  6. on a curved mesh of needle triangles the result is a smoothed copy of the input, or
///     this isotropic filtering starts from a smoothed fit instead of the input. A face's
///     normal moves by about the noise over its smallest altitude, so that on needles the
///     normals are mostly noise, which filtering normals cannot average out, and the noise
///     level of 1, measured along normals that tilt with the noise of thin fans, is about
///     half the true one. Let
///     \f$ P \f$ be the input smoothed by one implicit step of the cotangent mean curvature
///     flow (\f$ (M + tL)x = Mp \f$) of time \f$ t = \bar e^2 \f$ (\f$ \bar e \f$ the mean edge length),
///     \f$ a \f$ the median over the faces of \f$ P \f$ of 2 area / (longest edge)\f$^2 \f$ (0.87 for
///     an equilateral triangle) and \f$ \nu = \max(0, (0.5/a)^2 - 1) \f$. If \f$ \nu > 0 \f$, let
///     \f$ S \f$ be the input smoothed by the same flow for the time \f$ 2 \nu \hat\varepsilon'^2 \f$,
///     in 8 implicit steps of an eighth of it (the same smoothing of the shape, a far
///     stronger one of the noise's high frequencies)
///     (the cotangent operator does not depend on the shape of the triangles), where
///     \f$ \hat\varepsilon' \f$ is the noise level of 1 measured along the normals of \f$ P \f$.
///     Let \f$ W \f$ be the input smoothed by the same flow, in 8 steps, for the time at
///     which the neighbour correlation of its residual \f$ r = p - W \f$,
///     \f$ \sum_{ij} r_i \cdot r_j / \sum_{ij} (|r_i|^2 + |r_j|^2)/2 \f$ over the pairs of
///     neighbours, reaches 0.3: searched over \f$ 2^k \hat\varepsilon^2 \f$,
///     \f$ -8 \leq k \leq 8 \f$, from \f$ k = 0 \f$, and interpolated in log time between the
///     two times around the crossing. While the flow removes noise its residual is white
///     (a correlation near 0); once it removes shape, which is smooth, the residual turns
///     correlated. Where what the flow removes first, \f$ M^{-1} L p \f$ (the limit of
///     \f$ r / t \f$ as the time \f$ t \to 0 \f$), has a positive correlation (noise at or
///     below the roughness of a coarse tessellation, which the noise level reads as noise),
///     the threshold is that correlation plus 0.05, if it is less than 0.3. For
///     \f$ \nu \geq 1 \f$ the result is \f$ W \f$, or, where the time of \f$ S \f$ is the longer
///     and \f$ S \f$ does not shrink the shape (see below),
///     \f$ w S + (1 - w) W \f$: with \f$ f \f$ the fraction of the correlation at the stop of
///     \f$ W \f$ that the residual's components along the normals of \f$ W \f$ keep,
///     \f$ w = 1 \f$ for \f$ f \leq 1/3 \f$ (the correlation comes from the vertices' sliding
///     along the needles, which removes no shape), \f$ w = 0 \f$ for \f$ f \geq 1 \f$,
///     linear between. The result has each closed
///     component scaled about its centroid to the volume it encloses in the input (mean
///     curvature flow shrinks a closed surface; the volume rescaling of Desbrun et al.
///     1999). Where \f$ S \f$ is the longer and shrinks the shape, \f$ W \f$ is relinearised:
///     3 implicit steps, each with the operator \f$ L, M \f$ of the points it starts from
///     (the cotangent weights of noisy needles are themselves noise), stopped by the same
///     rule. If the flow fails, the filtering that follows is
///     the result alone. It fits the vertices in one sparse least-squares solve,
///     \f$ \min_x \sum_f a_f \sum_{ij \in f} (n_f \cdot (x_j - x_i))^2 + 0.01 \sum_i m_i |x_i - v_i|^2 \f$,
///     to the face normals \f$ n_f \f$ of \f$ S \f$; for \f$ \nu \geq 1 \f$ the isotropic filtering then runs from the fit
///     in iterations of 2 until the root mean square displacement from the input reaches
///     `displacement_limit` times \f$ \sqrt{1 - \rho^2}\,\hat\varepsilon' \f$, where
///     \f$ \rho\,\hat\varepsilon \f$ is the noise level of the result of 3 measured as in 1 (the
///     shape's own detail); for \f$ 0 < \nu < 1 \f$ the result is the blend, with weights
///     \f$ 1 - \nu \f$ and \f$ \nu \f$, of that of 5 and that of these iterations stopped at
///     \f$ \sqrt{1 - \rho^2}\,(\hat\varepsilon + \nu(\hat\varepsilon' - \hat\varepsilon)) \f$, both from the fit.
///     Meshes of reasonable triangles (\f$ a \geq 0.5 \f$) are filtered as in 5.
/// Steps 3 and 4, and in 6 the fit and the iterations of 2 from it, stop short of shrinking the shape:
/// removing noise moves the vertices both ways along the normals, eroding thin parts
/// moves them one way, so that each of these phases ends at the iterate before the one
/// whose mean displacement from the input along the input's vertex normals (weighted by
/// area) exceeds both 0.1 \f$ \hat\varepsilon \f$ and a quarter of the root mean square
/// displacement (the small iterations of 5 are bounded by their own stop), and the fit of 6
/// is scaled back to that bound. A smoothed copy \f$ S \f$ whose displacement exceeds both
/// is not used (meshes whose parts are a few faces thick, or whose needles span holes,
/// where the noise level of 1 also counts the shape).
/// Where the result of the filter (4, 5, or 6 without \f$ S \f$) changes the volume of a closed
/// component by more than 1 %, the filter has eroded the shape (the rims of thin walls,
/// strips one face wide between creases): the result is then \f$ W \f$ of 6, rescaled as
/// there. Not with a `displacement_limit` above 1.1, which asks for the displacement.
/// A `normal_sigma` given by the user replaces 3 to 6 by iterations with that width until
/// the displacement of 3. A mesh whose noise level is 0 is left unchanged, and so is a
/// mesh whose result of 3, measured as in 1, is as rough as the input (noise and the
/// shape's detail add in quadrature: the estimate of 1 then measured the shape alone,
/// as on clean CAD meshes where it reads rounding errors or the facets of a coarse
/// tessellation).
/// Where the result is that of the isotropic filtering of 5, or of 6 from the fit
/// (`Denoising_stage::curved`, `Denoising_stage::needle_fit`), half of the vertices' drift
/// within the surface is then undone: the fit and the relaxations slide the vertices along
/// the surface, which raised the vertex error of organic meshes above the noisy input's
/// where the noise was along the normals. With \f$ q_i \f$ the result, \f$ p_i \f$ the input
/// and \f$ t_i \f$ the component of \f$ p_i - q_i \f$ in the tangent plane of the result's
/// vertex normal, each vertex moves, in 3 rounds, to the point of its own one-ring of
/// faces closest to \f$ q_i + 0.5\, t_i \f$ (on its ring, it stays on the result's surface).
/// Not all of it: that would also put back the part of noise in random directions that
/// lies within the surface, which the relaxations removed. Where even half of it does
/// (strong noise in random directions), the restored triangles are uneven and tilt their
/// normals: the drift is undone only if the area-weighted mean over the faces f of the
/// mean \f$ |n_f - n_g| \f$ over the faces g sharing a vertex with f grows by at most 1 %.
/// Last, the faces of the result that intersect each other
/// (`Polygon_mesh_processing::self_intersections()`, with `geom_traits`) are untangled:
/// in rounds, the vertices of the intersecting faces are smoothed, by the gentlest of
/// these steps that removes at least a quarter of the intersecting pairs: one umbrella
/// step \f$ v_i \leftarrow v_i + 0.5\,(\bar v_i - v_i) \f$ of these vertices alone,
/// Taubin's pair of steps (0.5 then -0.53), the same two with one ring of neighbours
/// added (degenerate faces, which `self_intersections()` reports as intersecting
/// themselves, are not counted). The rounds end when no step does, or after 10. The
/// closed components are then scaled back to their volumes, unless that makes more faces
/// intersect (touching parts of an assembly). Noise in random directions folds
/// faces over within the surface (fandisk at 0.5 mean edge length: 479 pairs, 0 after two
/// rounds); walls closer to each other than the noise are separated only as far as these
/// steps allow. A mesh that the filter leaves unchanged keeps its own intersections.
///
/// <b>`Denoising_method::signature_diffusion`: the paper's pipeline.</b> Each of the
/// `number_of_iterations` iterations
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
/// `sigma` = 1 rather than the paper's 0.1: on a noisy mesh the NCC differ by the noise
/// across every edge, so with `sigma` = 0.1 all edge weights underflow and the eigen
/// solve does not converge. Two iterations with anchors of weight 0.7 were the best
/// compromise found on fandisk; more iterations, or weaker anchors, fold the mesh near
/// its corners.
///
/// Every position stays finite. The defaults were chosen by measurement on CGAL's
/// meshes (CAD parts with creases, CAD parts of needle triangles, organic shapes) with
/// Gaussian noise of 0.1 to 0.5 mean edge length along the normals and in random
/// directions (see the user manual for the table).
///
/// @tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// @tparam NamedParameters a sequence of named parameters
///
/// @param tm the mesh, denoised in place; its faces must be triangles
/// @param np an optional sequence of named parameters among those below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{denoising_method}
///     \cgalParamDescription{the algorithm (see above)}
///     \cgalParamType{`Denoising_method`}
///     \cgalParamDefault{`Denoising_method::normal_filtering`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the (largest) number of outer iterations; 0 leaves `tm` unchanged}
///     \cgalParamType{`unsigned int` (\cgal's own named parameter `CGAL::parameters::number_of_iterations`)}
///     \cgalParamDefault{`40` (normal filtering; on curved surfaces the displacement limit stops it before) or `2` (signature diffusion)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_steps}
///     \cgalParamDescription{normal filtering: the number of diffusion steps of the face normals per iteration; signature diffusion: the number k of diffusion steps of the signature per iteration}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{normal_sigma}
///     \cgalParamDescription{normal filtering only: the width \f$ \sigma_n \f$ of the normal weights, used for all iterations (see above); smaller keeps more creases, and more noise}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{chosen by the algorithm (a width per face from 0.2 to 0.45, see above, or infinite on curved surfaces)}
///   \cgalParamNEnd
///   \cgalParamNBegin{displacement_limit}
///     \cgalParamDescription{normal filtering only: the multiple of the estimated noise level that the root mean square displacement from the input (along the vertex normals in the isotropic filtering of curved surfaces) must reach to end the crease-preserving phase and the isotropic filtering (see above); `std::numeric_limits<double>::infinity()` runs all the iterations}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sigma}
///     \cgalParamDescription{signature diffusion only: the width of the edge weights of the heat kernel; values much smaller than the noise of the NCC make the eigen solve fail (see above)}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{time}
///     \cgalParamDescription{signature diffusion only: the time t of one diffusion step, on the mesh rescaled to area = number of vertices}
///     \cgalParamType{`double`, positive and finite}
///     \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_eigenpairs}
///     \cgalParamDescription{signature diffusion only: the number m of eigenpairs of the truncated heat kernel}
///     \cgalParamType{`std::size_t`, positive}
///     \cgalParamDefault{`150`}
///   \cgalParamNEnd
///   \cgalParamNBegin{kernel_method, operator_normalization, local_kernel_tolerance, coarse_vertex_count}
///     \cgalParamDescription{signature diffusion only: how the heat kernel of each iteration is evaluated and made into \f$ A_t \f$, and its coarse level (see `Anisotropic_heat_diffusion` and `Edge_weighted_heat_kernel`)}
///     \cgalParamDefault{`Heat_kernel_method::automatic` (local unless `number_of_eigenpairs` or `coarse_vertex_count` is given); `Operator_normalization::balanced`; `defaults::local_kernel_tolerance`; the automatic coarse level}
///   \cgalParamNEnd
///   \cgalParamNBegin{anchor_weight}
///     \cgalParamDescription{signature diffusion only: the weight of the positional anchors of the reconstruction (see `reconstruct_from_normal_signature()`): smaller moves the vertices further per iteration}
///     \cgalParamType{`double`, positive and finite}
///     \cgalParamDefault{`0.7`}
///   \cgalParamNEnd
///   \cgalParamNBegin{progress_callback}
///     \cgalParamDescription{normal filtering: called after each iteration with the fraction of `number_of_iterations` done; signature diffusion: called during each eigen solve (see `Edge_weighted_heat_kernel`). Returning `false` cancels with a `std::runtime_error`; normal filtering then leaves `tm` unchanged}
///     \cgalParamType{a callable `bool(double)`, stored in a `std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`; the denoised positions are written to it}
///     \cgalParamType{a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and `GeomTraits::Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_normal_rule}
///     \cgalParamDescription{how the vertex normals of the NCC are computed (a `vertex_normal_map` is not used: the normals change with the mesh)}
///     \cgalParamType{a model of `VertexNormalRule`}
///     \cgalParamDefault{`Area_weighted_vertex_normals()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in `[0, n)`, `n` the number of vertices in `vertices(tm)` (removed vertices of a `Surface_mesh` are not counted)}
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
/// \returns what the algorithm chose and did (`Denoising_report`): the noise level it
///   estimated, its iterations, the stage whose result it returned, the kernel it selected.
///
/// \throws std::invalid_argument if a parameter is out of its range (the message names
///   it), or on a mesh the package cannot process (see `Normal_controlled_coordinates`),
///   which a signature diffusion iteration can produce only from an already degenerate
///   input; `tm` is then left as the previous iteration wrote it.
/// \throws std::runtime_error if an eigen solve or a factorisation fails (signature
///   diffusion), or if the `progress_callback` cancels.
///
/// Complexity: normal filtering: the outlier test of 0 is linear in the size of `tm`
/// per round (at most 8), and copies the mesh's index once if it finds impulses; then
/// linear in the size of `tm` per iteration (parallel
/// with TBB), at most `number_of_iterations` iterations plus those of the isotropic
/// filtering on curved surfaces; two sparse Cholesky factorisations of n unknowns (the
/// smoothing of the widths of 3 and the smoothed copy \f$ P \f$), on meshes of needles one
/// more (\f$ S \f$), and for \f$ W \f$ (needles with \f$ \nu \geq 1 \f$, eroded thin walls) up
/// to 10 numerical factorisations of one symbolic analysis (relinearised: up to 30
/// factorisations), and for \f$ 0 < \nu < 1 \f$ a conjugate gradient solve of 3n unknowns;
/// undoing the drift is linear in the size of `tm`;
/// the untangling finds the intersecting faces of the whole mesh once (box intersection,
/// near-linear in n) and, if there are any, at most 4 times per round and once more after
/// the rounds among the faces near those that moved (see `benchmark_denoising` for times
/// measured against the published filters).
/// Signature diffusion: per iteration, one edge-weighted heat kernel (a sparse Cholesky
/// factorisation and a Lanczos iteration of \f$ O(n m^2) \f$ dense work: most of the time),
/// the operator \f$ A_t \f$ (linear in n), k sparse products and one sparse Cholesky
/// factorisation of the reconstruction (the user manual gives measured times).
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Denoising_report denoise_mesh(TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type GeomTraits;
  typedef typename GeomTraits::Vector_3 Vector_3;
  typedef typename GeomTraits::Point_3 Point_3;
  typedef typename CGAL::internal_np::Lookup_named_param_def<internal_np::vertex_normal_rule_t, NamedParameters,
                                                             Area_weighted_vertex_normals>::type Rule;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  // Every parameter is checked before the mesh is touched.
  const Denoising_method method =
      internal::parameter_value(np, internal_np::denoising_method, Denoising_method::normal_filtering);
  if(method != Denoising_method::normal_filtering && method != Denoising_method::signature_diffusion)
    internal::throw_invalid_input("denoise_mesh: unknown denoising_method");
  const bool filtering = method == Denoising_method::normal_filtering;
  const double iterations = double(internal::parameter_value(
      np, CGAL::internal_np::number_of_iterations,
      filtering ? defaults::denoising::normal_filtering_iterations : defaults::denoising::signature_diffusion_iterations));
  const double sigma = internal::parameter_value(np, internal_np::sigma, defaults::denoising::sigma);
  const double time = internal::parameter_value(np, internal_np::time, defaults::denoising::time);
  const double steps =
      double(internal::parameter_value(np, internal_np::number_of_steps, defaults::denoising::number_of_steps));
  const double eigenpairs =
      double(internal::parameter_value(np, internal_np::number_of_eigenpairs, defaults::number_of_eigenpairs));
  const double anchor_weight =
      internal::parameter_value(np, internal_np::anchor_weight, defaults::denoising::anchor_weight);
  const Heat_kernel_method kernel_method = internal::resolve_kernel_method(np, false);
  const Operator_normalization normalization =
      internal::parameter_value(np, internal_np::operator_normalization, Operator_normalization::balanced);
  const double kernel_tolerance =
      internal::parameter_value(np, internal_np::local_kernel_tolerance, defaults::local_kernel_tolerance);
  // Left to Edge_weighted_heat_kernel where not given (its automatic choice).
  const std::optional<long long> coarse_vertex_count =
      internal::is_given(np, internal_np::coarse_vertex_count)
          ? std::optional<long long>((long long)(internal::parameter_value(np, internal_np::coarse_vertex_count, 0)))
          : std::nullopt;
  const double user_normal_sigma = internal::parameter_value(np, internal_np::normal_sigma, 0.);
  const bool automatic_normal_sigma = !internal::is_given(np, internal_np::normal_sigma);
  const double displacement_limit =
      internal::parameter_value(np, internal_np::displacement_limit, defaults::denoising::displacement_limit);
  const std::function<bool(double)> progress =
      internal::parameter_value(np, internal_np::progress_callback, std::function<bool(double)>());
  if(!(iterations >= 0) || !std::isfinite(iterations))
    internal::throw_invalid_input("denoise_mesh: number_of_iterations must not be negative");
  internal::checked_sigma(sigma, "denoise_mesh");
  internal::checked_positive(time, "denoise_mesh", "time");
  if(!(steps >= 0) || !std::isfinite(steps))
    internal::throw_invalid_input("denoise_mesh: number_of_steps must not be negative");
  if(!(eigenpairs >= 1) || !std::isfinite(eigenpairs))
    internal::throw_invalid_input("denoise_mesh: number_of_eigenpairs must be positive");
  internal::checked_positive(anchor_weight, "denoise_mesh", "anchor_weight");
  internal::checked_kernel_tolerance(kernel_tolerance, "denoise_mesh");
  if(!automatic_normal_sigma)
    internal::checked_positive(user_normal_sigma, "denoise_mesh", "normal_sigma");
  if(!(displacement_limit > 0))
    internal::throw_invalid_input("denoise_mesh: displacement_limit must be positive");
  Denoising_report report;
  report.method = method;
  if(!filtering)
  {
    report.stage = Denoising_stage::signature_diffusion;
    report.kernel_method = kernel_method;
  }
  if(internal::number_of_listed_vertices(tm) == 0 || iterations < 1)
    return report;

  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, tm));
  // The user's numbering or the rank in vertices(tm), without gaps where a
  // Surface_mesh has removed vertices.
  const auto vim = internal::vertex_numbering(tm, np);
  const GeomTraits gt = choose_parameter<GeomTraits>(get_parameter(np, CGAL::internal_np::geom_traits));
  const Rule rule = choose_parameter<Rule>(get_parameter(np, internal_np::vertex_normal_rule));
  const auto mesh_parameters =
      parameters::combine(CGAL::parameters::vertex_point_map(vpm).vertex_index_map(vim).geom_traits(gt),
                          parameters::vertex_normal_rule(rule));

  if(filtering)
  {
    // All work in the normalised frame of the indexed mesh: every quantity is
    // invariant under rigid motions and uniform scaling.
    const Normal_controlled_coordinates<TriangleMesh, GeomTraits> ncc(tm, mesh_parameters);
    internal::Normal_filtering_options options;
    options.iterations = std::size_t(iterations);
    options.steps = std::size_t(steps);
    options.normal_sigma = automatic_normal_sigma ? 0. : user_normal_sigma;
    options.displacement_limit = displacement_limit;
    const internal::Indexed_mesh& indexed = ncc.indexed_mesh();
    std::vector<Eigen::Vector3d> points =
        internal::filter_normals(indexed, options, internal::Progress(progress), &report);
    auto write_back = [&](const std::vector<Eigen::Vector3d>& result) {
      for(vertex_descriptor v : vertices(tm))
      {
        const Eigen::Vector3d x = indexed.to_user_frame(result[ncc.vertex_index(v)]);
        if(x.allFinite())
          put(vpm, v, Point_3(x.x(), x.y(), x.z()));
      }
    };
    // A mesh that the filter leaves as it is (a clean one) keeps its own intersections.
    if(points == indexed.points)
    {
      report.stage = Denoising_stage::unchanged;
      write_back(points);
    }
    else
      internal::untangle_self_intersections(tm, vpm, gt, indexed,
                                            [&](vertex_descriptor v) { return ncc.vertex_index(v); }, write_back,
                                            points);
    return report;
  }

  // The paper's pipeline (Denoising_method::signature_diffusion).
  auto target_signature = get(CGAL::dynamic_vertex_property_t<double>(), tm);
  auto target_normals = get(CGAL::dynamic_vertex_property_t<Vector_3>(), tm);
  for(std::size_t iteration = 0; iteration < std::size_t(iterations); ++iteration)
  {
    // 1. The kernel of the current mesh, and its Normal Signature diffused.
    const Anisotropic_heat_diffusion<TriangleMesh, GeomTraits> diffusion(
        tm, parameters::combine(mesh_parameters, parameters::sigma(sigma), parameters::time(time),
                                parameters::number_of_eigenpairs(std::size_t(eigenpairs)),
                                parameters::kernel_method(kernel_method),
                                parameters::operator_normalization(normalization),
                                parameters::local_kernel_tolerance(kernel_tolerance),
                                parameters::coarse_vertex_count(coarse_vertex_count),
                                parameters::progress_callback(progress)));
    const Normal_controlled_coordinates<TriangleMesh, GeomTraits>& ncc = diffusion.normal_controlled_coordinates();
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
    report.iterations = iteration + 1;
  }
  return report;
}

} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_DENOISING_H
