// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The applications of the paper's section 7 on CGAL's meshes: multi-scale feature
// detection (invariance, noise, convexity, orientation, kernels, the HKS baseline)
// and the hierarchical decomposition with its shape filters.
//
// Diffusion parameters of the feature tests: sigma = 1, m = 150, t = 1, the paper's
// Fig. 6 setting. With these no heat region of fandisk collapses (min size 47, see
// the manual's table), so every vertex diffuses; with sigma = 0.1 the truncated
// kernel collapses 2161 regions, and a collapsed vertex keeps its own heat, which
// makes spurious extrema that say nothing about the detector.

#include <CGAL/Heat_diffusion/decomposition.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/bounding_box.h>

#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>

namespace test_applications {

namespace HD = CGAL::Heat_diffusion;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef HD::Anisotropic_heat_diffusion<Mesh> Diffusion;
typedef HD::Features_at_scale<Vertex> Features;

const std::vector<std::size_t> scales = {0, 10, 40};
const double c = 0.8;
// A comparison of field values closer than this, relative to max |F|, is a near-tie:
// rounding (of the eigen solve above all) may decide it either way.
const double tie_tolerance = 1e-9;

auto feature_parameters()
{
  return HD::parameters::combine(HD::parameters::sigma(1.), HD::parameters::number_of_eigenpairs(150),
                                 HD::parameters::time(1.));
}

template <typename TriangleMesh>
Eigen::VectorXd normal_signature(const HD::Anisotropic_heat_diffusion<TriangleMesh>& diffusion)
{
  const auto& kernel = diffusion.heat_kernel();
  Eigen::VectorXd f(Eigen::Index(kernel.number_of_vertices()));
  for(auto v : vertices(kernel.normal_controlled_coordinates().mesh()))
    f[Eigen::Index(kernel.vertex_index(v))] = kernel.normal_controlled_coordinates().normal_signature(v);
  return f;
}

// Per vertex: +1 robustly convex, -1 robustly concave, 0 robustly neither, and 2 if
// the verdict hangs on a near-tie: a comparison of the criterion decided by less than
// tie_tolerance max|F| (evaluated with every comparison shifted against and in
// favour of the vertex, the two verdicts differ).
std::vector<int> robust_verdicts(const Eigen::VectorXd& f, const std::vector<std::set<std::size_t> >& rings)
{
  const double eps = tie_tolerance * f.cwiseAbs().maxCoeff();
  const double hi = c * f.maxCoeff(), lo = c * f.minCoeff();
  std::vector<int> verdict(std::size_t(f.size()), 0);
  for(std::size_t i = 0; i < verdict.size(); ++i)
  {
    const double x = f[Eigen::Index(i)];
    bool max_sure = x > hi + eps, max_possible = x > hi - eps;
    bool min_sure = x < lo - eps, min_possible = x < lo + eps;
    for(std::size_t j : rings[i])
    {
      const double y = f[Eigen::Index(j)];
      max_sure = max_sure && x > y + eps;
      max_possible = max_possible && x > y - eps;
      min_sure = min_sure && x < y - eps;
      min_possible = min_possible && x < y + eps;
    }
    if(max_sure != max_possible || min_sure != min_possible)
      verdict[i] = 2;
    else
      verdict[i] = max_sure ? 1 : (min_sure ? -1 : 0);
  }
  return verdict;
}

std::vector<int> verdicts_of(const Features& features, std::size_t n)
{
  std::vector<int> verdict(n, 0);
  for(Vertex v : features.convex)
    verdict[v.idx()] = 1;
  for(Vertex v : features.concave)
    verdict[v.idx()] = -1;
  return verdict;
}

// Compares `features` of a transformed mesh with the robust verdicts of the reference:
// every disagreement must sit at a near-tie. Returns the number of near-ties.
std::size_t compare_with_reference(const std::vector<int>& reference, const Features& features,
                                   const std::string& what, int sign = 1)
{
  const std::vector<int> got = verdicts_of(features, reference.size());
  std::size_t ties = 0, disagreements = 0, tie_disagreements = 0;
  for(std::size_t i = 0; i < reference.size(); ++i)
  {
    if(reference[i] == 2)
    {
      ++ties;
      tie_disagreements += got[i] != 0 ? 1 : 0;
    }
    else if(sign * reference[i] != got[i])
      ++disagreements;
  }
  std::cout << "  " << what << ": " << features.convex.size() << " convex, " << features.concave.size()
            << " concave; near-ties " << ties << " (" << tie_disagreements << " detected there), other disagreements "
            << disagreements << std::endl;
  CHECK_MESSAGE(disagreements == 0, what << ": " << disagreements << " vertices differ away from near-ties");
  return ties;
}

std::size_t count(const std::vector<int>& verdict, int value)
{
  return std::size_t(std::count(verdict.begin(), verdict.end(), value));
}

// Features are the same vertex sets after rigid motions and uniform scaling
// (NCC, NS and the kernel on the surface rescaled to area = n are invariant), and
// reversing the orientation (NS -> -NS) swaps convex and concave.
void check_invariance()
{
  const Mesh mesh = test_support::load<Mesh>("fandisk.off");
  const auto rings = test_support::two_rings(mesh);
  const Diffusion reference(mesh, feature_parameters());
  const Eigen::VectorXd ns = normal_signature(reference);
  const std::vector<Eigen::VectorXd> reference_fields = reference.diffuse(ns, scales);
  std::vector<std::vector<int> > reference_verdicts;
  std::cout << "fandisk, sigma 1, m 150, t 1, c 0.8:" << std::endl;
  for(std::size_t s = 0; s < scales.size(); ++s)
  {
    reference_verdicts.push_back(robust_verdicts(reference_fields[s], rings));
    std::cout << "  k = " << scales[s] << ": " << count(reference_verdicts[s], 1) << " convex, "
              << count(reference_verdicts[s], -1) << " concave, " << count(reference_verdicts[s], 2)
              << " near-ties (relative " << tie_tolerance << ")" << std::endl;
  }

  // The function on the reference itself agrees with the robust verdicts: this checks
  // the detector against the independent (std::set based) 2-ring of the test.
  Mesh reference_mesh = mesh;
  auto reference_ns = reference_mesh.add_property_map<Vertex, double>("v:ns", 0.).first;
  HD::compute_normal_signature(reference_mesh, reference_ns);
  const Diffusion again(reference_mesh, feature_parameters());
  const auto own = HD::detect_multiscale_features(again, reference_ns, scales);
  for(std::size_t s = 0; s < scales.size(); ++s)
  {
    CHECK(own[s].number_of_steps == scales[s]);
    compare_with_reference(reference_verdicts[s], own[s], "reference k = " + std::to_string(scales[s]));
  }

  // Rigid motion: a rotation about a skew axis and a translation.
  const double angle = 0.7;
  Eigen::Vector3d axis(1., 2., -0.5);
  axis.normalize();
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
  struct Transform
  {
    std::string name;
    std::function<K::Point_3(const K::Point_3&)> map;
  };
  const std::vector<Transform> transforms = {
      {"rigid motion",
       [&](const K::Point_3& p) {
         const Eigen::Vector3d x = rotation * Eigen::Vector3d(p.x(), p.y(), p.z()) + Eigen::Vector3d(3., -7., 11.);
         return K::Point_3(x.x(), x.y(), x.z());
       }},
      {"scale 1e-3", [](const K::Point_3& p) { return K::Point_3(1e-3 * p.x(), 1e-3 * p.y(), 1e-3 * p.z()); }},
      {"scale 1e3", [](const K::Point_3& p) { return K::Point_3(1e3 * p.x(), 1e3 * p.y(), 1e3 * p.z()); }}};
  std::size_t total_ties = 0;
  for(const Transform& transform : transforms)
  {
    Mesh moved = mesh;
    for(Vertex v : moved.vertices())
      moved.point(v) = transform.map(mesh.point(v));
    auto moved_ns = moved.add_property_map<Vertex, double>("v:ns", 0.).first;
    HD::compute_normal_signature(moved, moved_ns);
    const Diffusion diffusion(moved, feature_parameters());
    const auto features = HD::detect_multiscale_features(diffusion, moved_ns, scales,
                                                         HD::parameters::feature_threshold(c));
    const std::vector<Eigen::VectorXd> fields = diffusion.diffuse(normal_signature(diffusion), scales);
    for(std::size_t s = 0; s < scales.size(); ++s)
    {
      const double difference = (fields[s] - reference_fields[s]).cwiseAbs().maxCoeff() /
                                reference_fields[s].cwiseAbs().maxCoeff();
      std::cout << "  " << transform.name << ", k = " << scales[s] << ": max |F - F_ref| / max |F_ref| = "
                << difference << std::endl;
      total_ties += compare_with_reference(reference_verdicts[s], features[s],
                                           transform.name + " k = " + std::to_string(scales[s]));
    }
  }
  std::cout << "  near-ties over the 3 transforms x 3 scales: " << total_ties << std::endl;

  // Reversed orientation: NS changes sign, convex and concave swap.
  Mesh reversed = mesh;
  PMP::reverse_face_orientations(reversed);
  auto reversed_ns = reversed.add_property_map<Vertex, double>("v:ns", 0.).first;
  HD::compute_normal_signature(reversed, reversed_ns);
  const Diffusion reversed_diffusion(reversed, feature_parameters());
  const auto swapped = HD::detect_multiscale_features(reversed_diffusion, reversed_ns, scales);
  for(std::size_t s = 0; s < scales.size(); ++s)
    compare_with_reference(reference_verdicts[s], swapped[s], "reversed k = " + std::to_string(scales[s]), -1);
}

// With 0.1 mean-edge-length noise along the normals, the clean features at k = 10
// are re-detected, with their type, within their 2-ring. Three noise seeds; the
// paper's c = 0.8 keeps few features, so c = 0.5 and 0.2 are measured as well. With
// the default (local) kernel: the truncated spectral kernel at t = 1 re-detects far
// fewer (benchmark_features, table 2), and is not what a user gets by default.
void check_noise_robustness()
{
  const Mesh clean = test_support::load<Mesh>("fandisk.off");
  const auto rings = test_support::two_rings(clean);
  auto features_at_10 = [](const Mesh& input, double threshold) {
    Mesh mesh = input;
    auto ns = mesh.add_property_map<Vertex, double>("v:ns", 0.).first;
    HD::compute_normal_signature(mesh, ns);
    const Diffusion diffusion(mesh, HD::parameters::combine(HD::parameters::sigma(1.), HD::parameters::time(1.)));
    CHECK(diffusion.kernel_method() == HD::Heat_kernel_method::local);
    return HD::detect_multiscale_features(diffusion, ns, {10}, HD::parameters::feature_threshold(threshold)).front();
  };
  for(double threshold : {0.8, 0.5, 0.2})
  {
    const Features reference = features_at_10(clean, threshold);
    const std::size_t clean_total = reference.convex.size() + reference.concave.size();
    std::size_t hits = 0, noisy_total = 0;
    for(unsigned seed : {1u, 2u, 3u})
    {
      Mesh noisy = clean;
      test_support::add_normal_noise(noisy, 0.1, seed);
      const Features found = features_at_10(noisy, threshold);
      noisy_total += found.convex.size() + found.concave.size();
      hits += test_support::count_found_nearby(reference.convex, found.convex, rings) +
              test_support::count_found_nearby(reference.concave, found.concave, rings);
    }
    const double fraction = double(hits) / double(3 * clean_total);
    std::cout << "noise 0.1 mean edge length, k = 10, c = " << threshold << ": " << clean_total
              << " clean features (" << reference.convex.size() << " convex), " << double(noisy_total) / 3
              << " noisy ones on average, " << 100 * fraction << " % re-detected within their 2-ring (3 seeds)"
              << std::endl;
    CHECK(clean_total > 0);
    CHECK_MESSAGE(fraction >= 0.8, "c = " << threshold << ": only " << 100 * fraction
                                          << " % of the clean features re-detected");
  }
}

// A convex mesh (checked with exact predicates: larger_sphere.off is, sphere966.off
// is not, it has 768 reflex halfedges) has no concave features at any scale, and
// reversed, no convex ones: the sign conventions hold end to end.
void check_convex_mesh()
{
  const Mesh sphere = test_support::load<Mesh>("larger_sphere.off");
  bool convex = true;
  for(auto h : sphere.halfedges())
  {
    if(sphere.is_border(h) || sphere.is_border(sphere.opposite(h)))
      continue;
    // the apex across the edge lies on the inner side of the face of h (or on it)
    const Vertex apex = sphere.target(sphere.next(sphere.opposite(h)));
    const auto o = CGAL::orientation(sphere.point(sphere.source(h)), sphere.point(sphere.target(h)),
                                     sphere.point(sphere.target(sphere.next(h))), sphere.point(apex));
    convex = convex && o != CGAL::POSITIVE;
  }
  CHECK_MESSAGE(convex, "larger_sphere.off is expected to be convex");
  for(bool reverse : {false, true})
  {
    Mesh mesh = sphere;
    if(reverse)
      PMP::reverse_face_orientations(mesh);
    auto ns = mesh.add_property_map<Vertex, double>("v:ns", 0.).first;
    HD::compute_normal_signature(mesh, ns);
    const Diffusion diffusion(mesh, feature_parameters());
    for(const Features& f : HD::detect_multiscale_features(diffusion, ns, scales))
    {
      std::cout << "larger_sphere" << (reverse ? " reversed" : "") << ", k = " << f.number_of_steps << ": "
                << f.convex.size() << " convex, " << f.concave.size() << " concave" << std::endl;
      CHECK_MESSAGE((reverse ? f.convex : f.concave).empty(), "a convex mesh has features of the wrong type");
      CHECK((reverse ? f.concave : f.convex).size() > 0);
    }
  }
}

// The other kernels give the same features (the numerical work is in double).
template <typename OtherKernel>
void check_kernel(const std::string& name)
{
  typedef CGAL::Surface_mesh<typename OtherKernel::Point_3> Other_mesh;
  typedef typename Other_mesh::Vertex_index Other_vertex;
  const Mesh mesh = test_support::load<Mesh>("fandisk.off");
  const auto rings = test_support::two_rings(mesh);
  // Copied by hand: copy_face_graph() does not keep the vertex order.
  Other_mesh other;
  for(Vertex v : mesh.vertices())
    other.add_vertex(typename OtherKernel::Point_3(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()));
  for(auto f : mesh.faces())
  {
    std::vector<Other_vertex> corners;
    for(Vertex v : vertices_around_face(mesh.halfedge(f), mesh))
      corners.push_back(Other_vertex(v.idx()));
    other.add_face(corners);
  }
  const Diffusion reference(mesh, feature_parameters());
  const std::vector<Eigen::VectorXd> fields = reference.diffuse(normal_signature(reference), scales);
  auto ns = other.template add_property_map<Other_vertex, double>("v:ns", 0.).first;
  HD::compute_normal_signature(other, ns);
  const HD::Anisotropic_heat_diffusion<Other_mesh> diffusion(other, feature_parameters());
  const auto features = HD::detect_multiscale_features(diffusion, ns, scales);
  for(std::size_t s = 0; s < scales.size(); ++s)
  {
    Features converted;
    for(Other_vertex v : features[s].convex)
      converted.convex.push_back(Vertex(v.idx()));
    for(Other_vertex v : features[s].concave)
      converted.concave.push_back(Vertex(v.idx()));
    compare_with_reference(robust_verdicts(fields[s], rings), converted, name + " k = " + std::to_string(scales[s]));
  }
}

// The single-scale free function: k = 0 needs no kernel; k > 0 builds one from the
// named parameters and agrees with the class-based overload; the HKS maxima baseline.
void check_free_function_and_hks()
{
  Mesh mesh = test_support::load<Mesh>("fandisk.off");
  auto ns = mesh.add_property_map<Vertex, double>("v:ns", 0.).first;
  HD::compute_normal_signature(mesh, ns);
  const Diffusion diffusion(mesh, feature_parameters());
  const auto both = HD::detect_multiscale_features(diffusion, ns, {0, 10});
  for(std::size_t k : {0, 10})
  {
    std::vector<Vertex> convex, concave;
    HD::detect_multiscale_features(mesh, ns, std::back_inserter(convex), std::back_inserter(concave),
                                   HD::parameters::combine(feature_parameters(), HD::parameters::number_of_steps(k)));
    const Features& expected = both[k == 0 ? 0 : 1];
    CHECK_MESSAGE(convex == expected.convex && concave == expected.concave,
                  "the free function at k = " << k << " differs from the class-based overload");
  }

  // HKS maxima (the paper's Fig. 7 baseline), on the isotropic kernel. The paper's
  // point: they cannot be told convex from concave, while the NS features can.
  const HD::Edge_weighted_heat_kernel<Mesh> isotropic(
      mesh, HD::parameters::combine(HD::parameters::sigma(std::numeric_limits<double>::infinity()),
                                    HD::parameters::number_of_eigenpairs(150)));
  auto hks = mesh.add_property_map<Vertex, double>("v:hks", 0.).first;
  const double t = 20.;  // above 4 ln 10 / lambda_150, where the truncated kernel is accurate
  std::cout << "HKS: t = " << t << ", 4 ln 10 / lambda_m = " << 4 * std::log(10.) / isotropic.eigenvalues().maxCoeff()
            << std::endl;
  for(Vertex v : mesh.vertices())
    hks[v] = isotropic.heat_kernel_signature(v, t);
  std::vector<Vertex> maxima, minima;
  HD::detect_multiscale_features(mesh, hks, std::back_inserter(maxima), std::back_inserter(minima));
  std::size_t on_convex = 0, on_concave = 0;
  for(Vertex v : maxima)
    (ns[v] > 0 ? on_convex : on_concave) += 1;
  std::size_t ns_convex_wrong = 0, ns_concave_wrong = 0;
  for(Vertex v : both[1].convex)
    ns_convex_wrong += ns[v] > 0 ? 0 : 1;
  for(Vertex v : both[1].concave)
    ns_concave_wrong += ns[v] < 0 ? 0 : 1;
  std::cout << "HKS maxima: " << maxima.size() << " (" << on_convex << " at convex vertices, " << on_concave
            << " at concave ones), minima " << minima.size() << "; NS features at k = 10 on the wrong side: "
            << ns_convex_wrong << " convex, " << ns_concave_wrong << " concave" << std::endl;
  CHECK(!maxima.empty());
  CHECK_MESSAGE(minima.empty(), "the HKS is positive: no feature below c min HKS");
}

void check_invalid_input()
{
  Mesh mesh = test_support::load<Mesh>("elephant.off");
  auto field = mesh.add_property_map<Vertex, double>("v:f", 0.).first;
  HD::compute_normal_signature(mesh, field);
  std::vector<Vertex> out;
  auto detect = [&](const auto& np) {
    HD::detect_multiscale_features(mesh, field, std::back_inserter(out), std::back_inserter(out), np);
  };
  CHECK_THROWS(detect(HD::parameters::feature_threshold(1.5)), std::invalid_argument, "feature_threshold must be in [0, 1]");
  CHECK_THROWS(detect(HD::parameters::feature_threshold(-0.1)), std::invalid_argument, "not -0.1");
  CHECK_THROWS(detect(HD::parameters::feature_threshold(std::nan(""))), std::invalid_argument, "feature_threshold");
  field[Vertex(17)] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS(detect(HD::parameters::feature_threshold(0.8)), std::invalid_argument,
               "detect_multiscale_features: the field value at vertex 17 is nan, not a finite number");
  CHECK_THROWS(detect(HD::parameters::number_of_steps(3)), std::invalid_argument, "vertex 17");
  field[Vertex(17)] = 0.;
  CHECK(out.empty());

  const Diffusion diffusion(mesh, HD::parameters::number_of_eigenpairs(20));
  std::vector<Mesh::Property_map<Vertex, double> > bands = {mesh.add_property_map<Vertex, double>("v:d1", 0.).first};
  auto residual = mesh.add_property_map<Vertex, double>("v:r", 0.).first;
  CHECK_THROWS(HD::decompose_field(diffusion, field, bands, residual, HD::parameters::steps_per_level(0)),
               std::invalid_argument, "steps_per_level must be a positive integer");
  CHECK_THROWS(HD::synthesize_field(mesh, bands, residual, std::vector<double>{1., 2.}, residual),
               std::invalid_argument, "2 weights for 1 detail bands");
  CHECK_THROWS(HD::synthesize_field(mesh, bands, residual, std::vector<double>{std::nan("")}, residual),
               std::invalid_argument, "weight 0 is nan");
  field[Vertex(3)] = std::numeric_limits<double>::infinity();
  CHECK_THROWS(HD::decompose_field(diffusion, field, bands, residual), std::invalid_argument,
               "decompose_field: the field value at vertex 3 is inf");
}

double variance(const Eigen::VectorXd& x)
{
  return (x.array() - x.mean()).square().mean();
}

template <typename TriangleMesh>
Eigen::VectorXd normal_signature_of(const TriangleMesh& mesh)
{
  const HD::Normal_controlled_coordinates<TriangleMesh> ncc(mesh);
  Eigen::VectorXd s(Eigen::Index(num_vertices(mesh)));
  for(auto v : vertices(mesh))
    s[Eigen::Index(ncc.vertex_index(v))] = ncc.normal_signature(v);
  return s;
}

// Eq. 24-26 on real meshes: zero-sum bands, exact re-synthesis, the identity filter,
// and the variance of the NS under the paper's smoothing and enhancement filters.
void check_decomposition(const std::string& name, double sigma, std::size_t steps_per_level,
                         HD::Heat_kernel_method method = HD::Heat_kernel_method::spectral)
{
  Mesh mesh = test_support::load<Mesh>(name);
  auto ns = mesh.add_property_map<Vertex, double>("v:ns", 0.).first;
  HD::compute_normal_signature(mesh, ns);
  std::cout << "-- decomposition of " << name << ", "
            << (method == HD::Heat_kernel_method::local ? "local" : "spectral") << " kernel" << std::endl;
  const auto np = HD::parameters::combine(HD::parameters::sigma(sigma), HD::parameters::number_of_eigenpairs(150),
                                          HD::parameters::steps_per_level(steps_per_level),
                                          HD::parameters::kernel_method(method));
  const Diffusion diffusion(mesh, np);
  std::vector<Mesh::Property_map<Vertex, double> > bands;
  for(int j = 1; j <= 3; ++j)
    bands.push_back(mesh.add_property_map<Vertex, double>("v:d" + std::to_string(j), 0.).first);
  auto residual = mesh.add_property_map<Vertex, double>("v:residual", 0.).first;
  HD::decompose_field(diffusion, ns, bands, residual, np);

  double absolute_sum = 0;
  for(Vertex v : mesh.vertices())
    absolute_sum += std::abs(ns[v]);
  double worst_band_sum = 0, worst_telescope = 0;
  std::ostringstream band_norms;
  for(const auto& band : bands)
  {
    double sum = 0, norm = 0;
    for(Vertex v : mesh.vertices())
    {
      sum += band[v];
      norm += band[v] * band[v];
    }
    worst_band_sum = (std::max)(worst_band_sum, std::abs(sum) / absolute_sum);
    band_norms << " " << std::sqrt(norm);
  }
  for(Vertex v : mesh.vertices())
  {
    double total = residual[v];
    for(const auto& band : bands)
      total += band[v];
    worst_telescope = (std::max)(worst_telescope, std::abs(total - ns[v]));
  }
  worst_telescope /= absolute_sum / double(mesh.number_of_vertices());
  std::cout << name << " sigma " << sigma << ", 3 levels of " << steps_per_level << " steps: band L2 norms"
            << band_norms.str() << "; max |sum D^j| / sum |S| = " << worst_band_sum
            << ", max |sum_j D^j + S^3 - S| / mean |S| = " << worst_telescope << std::endl;
  CHECK_MESSAGE(worst_band_sum <= 1e-12, name << ": a band sums to " << worst_band_sum << " of sum |S|");
  CHECK_MESSAGE(worst_telescope <= 1e-12, name << ": bands + residual differ from S by " << worst_telescope);

  // synthesize_field with weights 1 gives S back; with weights 0 the residual.
  auto synthesized = mesh.add_property_map<Vertex, double>("v:synthesized", 0.).first;
  HD::synthesize_field(mesh, bands, residual, std::vector<double>{1., 1., 1.}, synthesized);
  double worst = 0;
  for(Vertex v : mesh.vertices())
    worst = (std::max)(worst, std::abs(synthesized[v] - ns[v]));
  CHECK_MESSAGE(worst <= 1e-12 * absolute_sum / double(mesh.number_of_vertices()), "synthesis error " << worst);
  HD::synthesize_field(mesh, bands, residual, std::vector<double>{0., 0., 0.}, synthesized);
  worst = 0;
  for(Vertex v : mesh.vertices())
    worst = (std::max)(worst, std::abs(synthesized[v] - residual[v]));
  CHECK(worst == 0);

  // The free function on the mesh agrees with the class-based overload.
  std::vector<Mesh::Property_map<Vertex, double> > bands2;
  for(int j = 1; j <= 3; ++j)
    bands2.push_back(mesh.add_property_map<Vertex, double>("v:e" + std::to_string(j), 0.).first);
  auto residual2 = mesh.add_property_map<Vertex, double>("v:residual2", 0.).first;
  HD::decompose_field(mesh, ns, bands2, residual2, np);
  worst = 0;
  for(Vertex v : mesh.vertices())
    for(std::size_t j = 0; j < 3; ++j)
      worst = (std::max)(worst, std::abs(bands2[j][v] - bands[j][v]));
  CHECK_MESSAGE(worst == 0, "decompose_field(tm, ...) differs from the class-based overload by " << worst);

  // Shape filters (Fig. 10), with the default sigma = 0.1 and anchor weight 1; with
  // sigma = 0.5 for the record (see the manual: larger sigma and smaller anchor
  // weights let the reconstruction's own smoothing win over the enhancement).
  const Eigen::VectorXd s0 = normal_signature_of(mesh);
  const auto box = CGAL::bounding_box(mesh.points().begin(), mesh.points().end());
  const double diagonal = std::sqrt(CGAL::to_double(CGAL::squared_distance(box.min(), box.max())));
  struct Filter
  {
    std::string name;
    std::vector<double> weights;
  };
  for(double filter_sigma : {0.1, 0.5})
  {
    double identity_error = 0, smoothed_variance = 0, enhanced_variance = 0;
    for(const Filter& filter : {Filter{"identity", {1., 1., 1.}}, Filter{"smoothing", {0., 0., 1.}},
                                Filter{"enhancement", {1., 3., 3.}}})
    {
      Mesh edited = mesh;
      HD::filter_shape(edited, filter.weights,
                       HD::parameters::combine(HD::parameters::sigma(filter_sigma),
                                               HD::parameters::steps_per_level(steps_per_level),
                                               HD::parameters::kernel_method(method)));
      double moved = 0;
      for(Vertex v : mesh.vertices())
        moved = (std::max)(moved, std::sqrt(CGAL::to_double(CGAL::squared_distance(mesh.point(v), edited.point(v)))));
      const double var = variance(normal_signature_of(edited));
      std::cout << "  filter_shape sigma " << filter_sigma << " " << filter.name << ": max vertex displacement "
                << moved / diagonal << " of the diagonal; NS variance " << var << " (input " << variance(s0)
                << ", ratio " << var / variance(s0) << ")" << std::endl;
      if(filter.name == "identity")
        identity_error = moved / diagonal;
      else if(filter.name == "smoothing")
        smoothed_variance = var;
      else
        enhanced_variance = var;
    }
    CHECK_MESSAGE(identity_error <= 1e-12, name << ": weights (1, 1, 1) moved a vertex by " << identity_error);
    if(filter_sigma == 0.1)
    {
      CHECK_MESSAGE(smoothed_variance < variance(s0), name << ": smoothing did not decrease the NS variance");
      CHECK_MESSAGE(enhanced_variance > variance(s0), name << ": enhancement did not increase the NS variance");
    }
  }
}

// Shape filtering with the defaults (the paper's Fig. 10), on an organic mesh and on CAD:
// the enhancement reaches at least half of the change of the NS variance that its
// target asks for and moves some vertex by at least 0.5 % of the bounding-box diagonal,
// the smoothing lowers the NS variance, and neither creates a self-intersection.
void check_shape_filter_defaults()
{
  for(const char* name : {"armadillo.off", "fandisk.off"})
  {
    const Mesh mesh = test_support::load<Mesh>(name);
    CHECK_MESSAGE(!CGAL::Polygon_mesh_processing::does_self_intersect(mesh), name << " self-intersects");
    const Eigen::VectorXd s0 = normal_signature_of(mesh);
    const double v0 = variance(s0);
    // the enhancement's target: the NS re-synthesised as filter_shape() does, with its
    // defaults (the diffusion's, and 2 steps per level)
    double target_variance = 0;
    {
      Mesh copy = mesh;
      auto ns = copy.add_property_map<Vertex, double>("v:ns", 0.).first;
      HD::compute_normal_signature(copy, ns);
      const Diffusion diffusion(copy);
      std::vector<Mesh::Property_map<Vertex, double> > bands;
      for(int j = 1; j <= 3; ++j)
        bands.push_back(copy.add_property_map<Vertex, double>("v:d" + std::to_string(j), 0.).first);
      auto residual = copy.add_property_map<Vertex, double>("v:residual", 0.).first;
      HD::decompose_field(diffusion, ns, bands, residual, HD::parameters::steps_per_level(2));
      HD::synthesize_field(copy, bands, residual, std::vector<double>{1., 3., 3.}, residual);
      Eigen::VectorXd target(s0.size());
      for(Vertex v : copy.vertices())
        target[Eigen::Index(diffusion.vertex_index(v))] = residual[v];
      target_variance = variance(target);
    }
    const auto box = CGAL::bounding_box(mesh.points().begin(), mesh.points().end());
    const double diagonal = std::sqrt(CGAL::to_double(CGAL::squared_distance(box.min(), box.max())));
    Mesh enhanced = mesh, smoothed = mesh;
    HD::filter_shape(enhanced, std::vector<double>{1., 3., 3.});
    HD::filter_shape(smoothed, std::vector<double>{0., 0., 1.});
    if(std::string(name) == "fandisk.off")
    {
      // the defaults are those the tool's enhance states and passes explicitly
      Mesh explicit_defaults = mesh;
      HD::filter_shape(explicit_defaults, std::vector<double>{1., 3., 3.},
                       HD::parameters::combine(HD::parameters::steps_per_level(2), HD::parameters::anchor_weight(0.03)));
      bool same = true;
      for(Vertex v : mesh.vertices())
        same = same && explicit_defaults.point(v) == enhanced.point(v);
      CHECK_MESSAGE(same, name << ": filter_shape's defaults are not 2 steps per level and anchor weight 0.03");
    }
    double moved = 0;
    for(Vertex v : mesh.vertices())
      moved = (std::max)(moved, std::sqrt(CGAL::to_double(CGAL::squared_distance(mesh.point(v), enhanced.point(v)))));
    const double enhanced_variance = variance(normal_signature_of(enhanced));
    const double smoothed_variance = variance(normal_signature_of(smoothed));
    const double reach = (enhanced_variance - v0) / (target_variance - v0);
    std::cout << name << ", filter_shape with the defaults: enhancement (1, 3, 3): NS variance " << enhanced_variance / v0
              << " times the input's (target " << target_variance / v0 << ", reached " << reach
              << " of the change), largest displacement " << moved / diagonal << " of the diagonal; smoothing (0, 0, 1): "
              << smoothed_variance / v0 << " times" << std::endl;
    CHECK_MESSAGE(target_variance > v0, name << ": the enhancement's target does not raise the NS variance");
    CHECK_MESSAGE(reach >= 0.5, name << ": the enhancement reaches " << reach << " of its target's variance change");
    CHECK_MESSAGE(moved >= 0.005 * diagonal, name << ": the enhancement moves no vertex by 0.5 % of the diagonal ("
                                                  << moved / diagonal << ")");
    CHECK_MESSAGE(smoothed_variance < v0, name << ": the smoothing does not lower the NS variance");
    CHECK_MESSAGE(!CGAL::Polygon_mesh_processing::does_self_intersect(enhanced),
                  name << ": the enhancement created a self-intersection");
    CHECK_MESSAGE(!CGAL::Polygon_mesh_processing::does_self_intersect(smoothed),
                  name << ": the smoothing created a self-intersection");
  }
}

// The applications take a diffusion built with either kernel: the local one has no
// eigenpairs, so they must not ask for them. With the local kernel's untruncated
// columns the features differ from the truncated spectral kernel's (the manual's
// comparison); here: they exist, are consistent with the field, and the free function
// agrees with the class.
void check_local_kernel_features()
{
  Mesh mesh = test_support::load<Mesh>("elephant.off");
  auto ns = mesh.add_property_map<Vertex, double>("v:ns", 0.).first;
  HD::compute_normal_signature(mesh, ns);
  const auto np = HD::parameters::combine(HD::parameters::sigma(1.), HD::parameters::time(1.),
                                          HD::parameters::kernel_method(HD::Heat_kernel_method::local));
  const Diffusion diffusion(mesh, np);
  CHECK(diffusion.kernel_method() == HD::Heat_kernel_method::local);
  const auto features = HD::detect_multiscale_features(diffusion, ns, scales);
  CHECK(features.size() == scales.size());
  const Eigen::VectorXd f0 = normal_signature_of(mesh);
  const std::vector<Eigen::VectorXd> fields = diffusion.diffuse(f0, scales);
  const auto rings = test_support::two_rings(mesh);
  for(std::size_t s = 0; s < scales.size(); ++s)
  {
    // Every reported convex feature is a 2-ring maximum of the diffused field, every
    // concave one a 2-ring minimum.
    auto value = [&](std::size_t vertex) { return fields[s][Eigen::Index(diffusion.vertex_index(Vertex(vertex)))]; };
    std::size_t wrong = 0;
    for(Vertex v : features[s].convex)
      for(std::size_t u : rings[v.idx()])
        wrong += value(u) > value(v.idx()) ? 1 : 0;
    for(Vertex v : features[s].concave)
      for(std::size_t u : rings[v.idx()])
        wrong += value(u) < value(v.idx()) ? 1 : 0;
    std::cout << "local kernel, elephant, k = " << scales[s] << ": " << features[s].convex.size() << " convex, "
              << features[s].concave.size() << " concave features" << std::endl;
    CHECK_MESSAGE(!features[s].convex.empty(), "local kernel: no convex feature at k = " << scales[s]);
    CHECK_MESSAGE(wrong == 0, "local kernel: " << wrong << " features are not 2-ring extrema at k = " << scales[s]);
  }
  // Diffusion removes extrema: the coarsest scale has fewer features than the input.
  CHECK(!features[0].concave.empty());
  CHECK(features[2].convex.size() + features[2].concave.size() <
        features[0].convex.size() + features[0].concave.size());
  std::vector<Vertex> convex, concave;
  HD::detect_multiscale_features(mesh, ns, std::back_inserter(convex), std::back_inserter(concave),
                                 HD::parameters::combine(np, HD::parameters::number_of_steps(10)));
  CHECK_MESSAGE(convex == features[1].convex && concave == features[1].concave,
                "the free function with the local kernel differs from the class-based overload");
}

// The applications' progress_callback. On a built diffusion, decompose_field() and
// detect_multiscale_features() report each step, forward to 1, and a callback that
// returns false cancels them. The free functions and filter_shape() fill the bar with
// the construction; the products after it report 1, and cancelling there throws too
// (so that Python's Ctrl-C stops them).
void check_applications_report_progress()
{
  Mesh mesh = test_support::load<Mesh>("elephant.off");
  auto ns = mesh.add_property_map<Vertex, double>("v:ns", 0.).first;
  HD::compute_normal_signature(mesh, ns);
  std::vector<Mesh::Property_map<Vertex, double> > bands;
  for(int j = 1; j <= 3; ++j)
    bands.push_back(mesh.add_property_map<Vertex, double>("v:d" + std::to_string(j), 0.).first);
  auto residual = mesh.add_property_map<Vertex, double>("v:residual", 0.).first;
  std::vector<double> fractions;
  const auto recorder = HD::parameters::progress_callback([&](double f) {
    fractions.push_back(f);
    return true;
  });
  // A callback that cancels at its call number `last` (from 0).
  std::size_t calls = 0;
  const auto cancel_at = [&calls](std::size_t last) {
    calls = 0;
    return HD::parameters::progress_callback([&calls, last](double) { return calls++ < last; });
  };
  const auto forward_to_one = [&fractions](std::size_t count) {
    return fractions.size() == count && std::is_sorted(fractions.begin(), fractions.end()) && fractions.back() == 1.;
  };
  const auto steps = HD::parameters::steps_per_level(4);

  const Diffusion diffusion(mesh);
  HD::decompose_field(diffusion, ns, bands, residual, HD::parameters::combine(steps, recorder));
  CHECK_MESSAGE(forward_to_one(12), "decompose_field: " << fractions.size() << " reports for 3 levels of 4 steps");
  CHECK_THROWS(HD::decompose_field(diffusion, ns, bands, residual, HD::parameters::combine(steps, cancel_at(5))),
               std::runtime_error, "the diffusion cancelled");
  fractions.clear();
  HD::detect_multiscale_features(diffusion, ns, {7, 0, 3}, recorder);
  CHECK_MESSAGE(forward_to_one(7), "detect_multiscale_features: " << fractions.size() << " reports for 7 steps");
  CHECK_THROWS(HD::detect_multiscale_features(diffusion, ns, {7}, cancel_at(2)), std::runtime_error,
               "the diffusion cancelled");

  // The free functions: the construction's reports, then one report of 1 per product.
  fractions.clear();
  HD::decompose_field(mesh, ns, bands, residual, HD::parameters::combine(steps, recorder));
  const std::size_t construction = fractions.size() - 12;
  CHECK(construction >= 2 && std::is_sorted(fractions.begin(), fractions.end()) && fractions[construction] == 1.);
  CHECK_THROWS(HD::decompose_field(mesh, ns, bands, residual, HD::parameters::combine(steps, cancel_at(construction + 5))),
               std::runtime_error, "the diffusion cancelled");
  std::vector<Vertex> convex, concave;
  CHECK_THROWS(HD::detect_multiscale_features(mesh, ns, std::back_inserter(convex), std::back_inserter(concave),
                                              HD::parameters::combine(HD::parameters::number_of_steps(7),
                                                                      cancel_at(construction + 2))),
               std::runtime_error, "the diffusion cancelled");
  Mesh filtered = mesh;
  fractions.clear();
  HD::filter_shape(filtered, std::vector<double>{1., 3., 3.}, HD::parameters::combine(steps, recorder));
  CHECK(fractions.size() == construction + 12 && std::is_sorted(fractions.begin(), fractions.end()));
  filtered = mesh;
  CHECK_THROWS(HD::filter_shape(filtered, std::vector<double>{1., 3., 3.},
                                HD::parameters::combine(steps, cancel_at(construction + 5))),
               std::runtime_error, "the diffusion cancelled");
}

void run()
{
  check_invariance();
  check_noise_robustness();
  check_convex_mesh();
  check_kernel<CGAL::Simple_cartesian<double> >("Simple_cartesian<double>");
  check_kernel<CGAL::Exact_predicates_exact_constructions_kernel>("EPECK");
  check_free_function_and_hks();
  check_invalid_input();
  check_decomposition("fandisk.off", 0.5, 5);
  check_decomposition("elephant.off", 0.5, 5);
  check_decomposition("elephant.off", 0.5, 5, HD::Heat_kernel_method::local);
  check_local_kernel_features();
  check_applications_report_progress();
  check_shape_filter_defaults();
}

const test_support::Suite_registration registration("test_applications", &run);

} // namespace test_applications
