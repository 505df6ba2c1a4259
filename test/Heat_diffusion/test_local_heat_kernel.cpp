// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The local heat kernel (Heat_kernel_method::local): its columns against an
// independent reference -- Crank-Nicolson time stepping of B u' = -L u from
// u(0) = B^-1 e_j on the whole mesh, with a Rannacher start and Richardson
// extrapolation -- next to the truncated m = 150 spectral kernel and to the lumped-mass
// variant; then the heat regions, column sums and heat conservation of A_t built from
// it, and the API of the kernel choice. On CGAL's fandisk and armadillo.

#include <CGAL/Heat_diffusion/Anisotropic_heat_diffusion.h>
#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/internal/heat_operators.h>
#include <CGAL/Heat_diffusion/internal/local_heat_kernel.h>
#include <CGAL/Heat_diffusion/internal/sparse_cholesky.h>
#include <CGAL/Heat_diffusion/multiscale_features.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "kernel_accuracy.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace test_local_heat_kernel {

namespace HD = CGAL::Heat_diffusion;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef HD::Anisotropic_heat_diffusion<Mesh> Diffusion;
typedef Eigen::SparseMatrix<double> Sparse_matrix;

const std::vector<double> times = {0.5, 1., 2., 4.};
using kernel_accuracy::previous_tolerance;

// Columns of exp(-t B^-1 L) B^-1 for `sources` at every t of `times`, by Crank-Nicolson
// steps of size dt after four implicit Euler steps of dt / 2 (Rannacher's start, which
// damps the stiff modes of B^-1 e_j that Crank-Nicolson alone would keep ringing).
std::vector<Eigen::MatrixXd> time_stepping(const Sparse_matrix& L, const Sparse_matrix& B,
                                           const std::vector<std::size_t>& sources, double dt)
{
  HD::internal::Sparse_cholesky mass_solver, step_solver;
  HD::internal::factorize_or_throw(mass_solver, B, "B");
  const Sparse_matrix left = B + 0.5 * dt * L, right = B - 0.5 * dt * L;
  HD::internal::factorize_or_throw(step_solver, left, "B + dt/2 L");
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(L.rows(), Eigen::Index(sources.size()));
  for(std::size_t s = 0; s < sources.size(); ++s)
    unit(Eigen::Index(sources[s]), Eigen::Index(s)) = 1.;
  Eigen::MatrixXd u = mass_solver.solve(unit);
  std::vector<Eigen::MatrixXd> result;
  double t = 0;
  std::size_t step = 0;
  for(double target : times)
  {
    for(; t < target - 1e-9; ++step)
    {
      const bool euler = step < 4;  // (B + dt/2 L) is also implicit Euler's matrix for dt / 2
      u = step_solver.solve(euler ? Eigen::MatrixXd(B * u) : Eigen::MatrixXd(right * u));
      t += euler ? 0.5 * dt : dt;
    }
    result.push_back(u);
  }
  return result;
}

double relative_error(const Eigen::VectorXd& x, const Eigen::VectorXd& reference)
{
  return (x - reference).norm() / reference.norm();
}

typedef HD::internal::Local_heat_kernel Local_kernel;

Eigen::VectorXd local_column(const Local_kernel& kernel, std::size_t j, std::size_t n, Local_kernel::Workspace& workspace)
{
  kernel.compute_column(j, workspace);
  Eigen::VectorXd column = Eigen::VectorXd::Zero(Eigen::Index(n));
  for(std::uint32_t i : Local_kernel::patch(workspace))
    column[Eigen::Index(i)] = Local_kernel::value(workspace, i);
  return column;
}

// The heat balance that decides the patches, |1 - 1_P^T B_P h_P| <= tolerance on the
// patch P of the column, on the full columns (all the patch solved, not only where a
// heat region reads it) of every 16th source and of the first 50 whose patches were
// enlarged. Returns the number of columns on enlarged patches.
std::size_t check_heat_balance(const Local_kernel& kernel, const Sparse_matrix& B, const std::string& label)
{
  const std::size_t n = std::size_t(B.rows());
  auto workspace = kernel.make_workspace();
  std::size_t enlarged = 0, checked = 0;
  double worst = 0;
  for(std::size_t position = 0; position < n; ++position)
  {
    const std::size_t j = kernel.source_order()[position];
    kernel.compute_column(j, workspace);
    const bool is_enlarged = Local_kernel::enlargements(workspace) > 0;
    enlarged += is_enlarged ? 1 : 0;
    if(position % 16 != 0 && !(is_enlarged && enlarged <= 50))
      continue;
    const bool whole_mesh = Local_kernel::patch(workspace).size() == n;
    const Eigen::VectorXd heat = B * local_column(kernel, j, n, workspace);  // zero outside P
    double patch_heat = 0;
    for(std::uint32_t i : Local_kernel::patch(workspace))
      patch_heat += heat[Eigen::Index(i)];
    const double deficit = std::abs(1. - patch_heat);
    if(!whole_mesh)
      worst = (std::max)(worst, deficit);
    ++checked;
  }
  std::cout << label << ", t = " << kernel.time() << ": heat balance of " << checked << " full columns, worst "
            << worst << "; " << enlarged << " of " << n << " columns on enlarged patches" << std::endl;
  CHECK_MESSAGE(worst <= kernel.tolerance() * (1. + 1e-6), label << ", t = " << kernel.time() << ": heat lost " << worst);
  return enlarged;
}

// The rational approximation behind the local kernel: r(x) ~ exp(-x) uniformly on
// [0, inf) (up to 1e6, and its limit 0 at infinity); and the clusters of sources: a
// partition of the vertices into compact groups.
void check_rational_approximation_and_clusters()
{
  for(const HD::internal::Rational_exponential* r :
      {&HD::internal::three_pole_exponential(), &HD::internal::two_pole_exponential()})
  {
    double worst = 0;
    for(int e = -8000; e <= 6000; ++e)
    {
      const double x = e == -8000 ? 0. : std::pow(10., e / 1000.);
      worst = (std::max)(worst, std::abs((*r)(x) - std::exp(-x)));
    }
    std::cout << "rational approximation of exp(-x) with " << r->number_of_poles
              << " poles on [0, 1e6]: max error " << worst << " (stated " << r->maximum_error << ")" << std::endl;
    // the stated error, which chooses the approximation, is the measured one
    CHECK_MESSAGE(worst <= r->maximum_error * 1.02 && worst >= r->maximum_error * 0.9,
                  r->number_of_poles << " poles: rational approximation error " << worst);
    CHECK(std::abs((*r)(1e12)) < 1e-11);
  }

  const Mesh mesh = test_support::load<Mesh>("fandisk.off");
  const HD::Normal_controlled_coordinates<Mesh> ncc(mesh);
  const HD::internal::Indexed_mesh& indexed = ncc.indexed_mesh();
  std::vector<std::size_t> begin;
  const std::vector<std::size_t> order = HD::internal::clustered_order(indexed, 32, &begin);
  std::vector<std::size_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  bool permutation = sorted.size() == indexed.number_of_vertices();
  for(std::size_t i = 0; permutation && i < sorted.size(); ++i)
    permutation = sorted[i] == i;
  CHECK_MESSAGE(permutation, "clustered_order is not a permutation of the vertices");
  CHECK(begin.front() == 0 && begin.back() == order.size());
  std::size_t largest = 0;
  for(std::size_t c = 0; c + 1 < begin.size(); ++c)
    largest = (std::max)(largest, begin[c + 1] - begin[c]);
  CHECK_MESSAGE(largest <= 32, "cluster of " << largest << " vertices");
  std::cout << "fandisk: " << begin.size() - 1 << " clusters of at most 32 vertices, mean "
            << double(order.size()) / double(begin.size() - 1) << std::endl;
}

// The heat region of v_j (eq. 15, as the user manual defines it): grown breadth first from v_j through the vertices
// where the column is above tau(t).
std::size_t region_size(const HD::internal::Indexed_mesh& mesh, std::size_t j, const Eigen::VectorXd& column, double t)
{
  const double tau = 0.01 / (1. + t);
  std::vector<unsigned char> seen(mesh.number_of_vertices(), 0);
  std::vector<std::size_t> queue(1, j);
  seen[j] = 1;
  for(std::size_t q = 0; q < queue.size(); ++q)
    for(std::size_t k = mesh.fan_begin[queue[q]]; k < mesh.fan_begin[queue[q] + 1]; ++k)
    {
      const std::size_t u = mesh.fan[k];
      if(!seen[u] && column[Eigen::Index(u)] > tau)
        queue.push_back(u);
      seen[u] = 1;
    }
  return queue.size();
}

void check_columns(const std::string& name, double sigma)
{
  const Mesh mesh = test_support::load<Mesh>(name);
  const std::string label = name + " sigma " + std::to_string(sigma).substr(0, 3);
  const HD::Edge_weighted_heat_kernel<Mesh> spectral(
      mesh, HD::parameters::combine(HD::parameters::sigma(sigma), HD::parameters::number_of_eigenpairs(150)));
  const HD::internal::Indexed_mesh& indexed = spectral.normal_controlled_coordinates().indexed_mesh();
  const Sparse_matrix& L = spectral.stiffness_matrix();
  const Sparse_matrix& B = spectral.mass_matrix();
  const std::size_t n = indexed.number_of_vertices();
  std::vector<std::size_t> sources;
  for(std::size_t s = 0; s < 5; ++s)
    sources.push_back((s * 7919 + 13) % n);

  // The reference, and a bound on its own error: Richardson's extrapolation of the runs
  // with dt and dt / 2 against the dt / 2 run.
  const double dt = 0.0125;
  const std::vector<Eigen::MatrixXd> coarse = time_stepping(L, B, sources, dt);
  const std::vector<Eigen::MatrixXd> fine = time_stepping(L, B, sources, dt / 2);

  std::size_t enlarged_columns = 0;
  for(std::size_t ti = 0; ti < times.size(); ++ti)
    for(const double tolerance : {previous_tolerance, HD::defaults::local_kernel_tolerance})
    {
      const double t = times[ti];
      const Eigen::MatrixXd reference = (4. * fine[ti] - coarse[ti]) / 3.;
      const HD::internal::Local_heat_kernel local(indexed, L, B, t, tolerance);
      const HD::internal::Local_heat_kernel lumped(indexed, L, B, t, tolerance,
                                                   HD::internal::Local_kernel_mass::lumped);
      const std::string case_label = label + ", t = " + std::to_string(t).substr(0, 3) + ", tolerance " +
                                     std::to_string(tolerance).substr(0, 6) + " (" +
                                     std::to_string(local.exponential().number_of_poles) + " poles)";
      auto workspace = local.make_workspace();
      double reference_error = 0, local_error = 0, lumped_error = 0, truncated_error = 0, truncated_min = 1e300;
      std::size_t patch_min = n, patch_max = 0, enlargements_max = 0, exact_region_min = n, exact_region_max = 0;
      std::size_t region_mismatch = 0;
      for(std::size_t s = 0; s < sources.size(); ++s)
      {
        const std::size_t j = sources[s];
        const Eigen::VectorXd exact = reference.col(Eigen::Index(s));
        reference_error = (std::max)(reference_error, relative_error(fine[ti].col(Eigen::Index(s)), exact));
        local_error = (std::max)(local_error, relative_error(local_column(local, j, n, workspace), exact));
        patch_min = (std::min)(patch_min, Local_kernel::patch(workspace).size());
        patch_max = (std::max)(patch_max, Local_kernel::patch(workspace).size());
        enlargements_max = (std::max)(enlargements_max, Local_kernel::enlargements(workspace));
        lumped_error = (std::max)(lumped_error, relative_error(local_column(lumped, j, n, workspace), exact));
        Eigen::VectorXd truncated(static_cast<Eigen::Index>(n));
        for(std::size_t i = 0; i < n; ++i)
          truncated[Eigen::Index(i)] = spectral.kernel(i, j, t);
        const double e = relative_error(truncated, exact);
        truncated_error = (std::max)(truncated_error, e);
        truncated_min = (std::min)(truncated_min, e);
        // the heat region of the local column is that of the exact one (up to the
        // vertices whose values are within the column's error of the threshold)
        const std::size_t region = region_size(indexed, j, exact, t);
        const std::size_t local_region = region_size(indexed, j, local_column(local, j, n, workspace), t);
        region_mismatch = (std::max)(region_mismatch, std::size_t(std::abs(double(region) - double(local_region))));
        exact_region_min = (std::min)(exact_region_min, region);
        exact_region_max = (std::max)(exact_region_max, region);
      }
      // a column depends on its cluster only, not on what the workspace computed before
      // (the parallel construction of A_t relies on it): bit-identical in a fresh one
      for(std::size_t s = 0; s < sources.size(); ++s)
      {
        const Eigen::VectorXd reused = local_column(local, sources[s], n, workspace);
        auto fresh_workspace = local.make_workspace();
        const Eigen::VectorXd fresh = local_column(local, sources[s], n, fresh_workspace);
        CHECK_MESSAGE((reused - fresh).cwiseAbs().maxCoeff() == 0,
                      case_label << ": column " << sources[s] << " depends on the workspace's history");
      }
      enlarged_columns += check_heat_balance(local, B, label);
      std::cout << case_label << ": column error, local " << local_error << ", lumped mass " << lumped_error
                << ", truncated m = 150 " << truncated_min << " .. " << truncated_error
                << " (reference error <= " << reference_error << "); patches " << patch_min << " .. " << patch_max
                << " vertices, patch enlargements <= " << enlargements_max << ", exact heat regions "
                << exact_region_min << " .. " << exact_region_max << std::endl;
      CHECK_MESSAGE(reference_error <= 1e-4, case_label << ": the reference is off by " << reference_error);
      // Three poles and the earlier default: the column within 1e-3 of the exact one
      // (measured at most 9.8e-5). Two poles and the default tolerance: the two-pole
      // approximation's own error on the column (at most 7.0e-3, measured with patches
      // of radius factor 2.6, whose truncation is far below the tolerance) plus the
      // truncation the tolerance allows (the patch rule of that tolerance uses it: at
      // most 1.40e-2 in all, fandisk at t = 4), so within 7e-3 + tolerance; and a
      // region may then differ by two vertices (measured: two at t = 4, one below).
      const bool previous = tolerance == previous_tolerance;
      CHECK_MESSAGE(local_error <= (previous ? 1e-3 : 7e-3 + tolerance),
                    case_label << ": local kernel error " << local_error);
      CHECK_MESSAGE(region_mismatch <= (previous ? 1u : 2u), case_label << ": heat regions differ by " << region_mismatch);
      // the measurements behind the documented choices: lumping the mass and truncating
      // the spectrum each cost far more than the local kernel's error (lumping at least
      // 1.4 times the default's on fandisk with sigma 1 at t = 4, where the kernel
      // barely sees the creases; 26 times with sigma 0.1)
      CHECK_MESSAGE(lumped_error > (previous ? 10 : 1.2) * local_error, case_label << ": lumped " << lumped_error);
      if(t <= 1.)
        CHECK_MESSAGE(truncated_min > (previous ? 100 : 50) * local_error,
                      case_label << ": truncated " << truncated_min);
    }
  // The enlargement of the patches, exercised on every mesh: at the tolerances above few
  // columns need it (armadillo's patch metric is capped where the triangles are large);
  // at 1e-5 some do. (Not tighter: the heat balance is
  // computed from single-precision substitutions, whose rounding reaches 5e-7.)
  const HD::internal::Local_heat_kernel tight(indexed, L, B, 1., 1e-5);
  enlarged_columns += check_heat_balance(tight, B, label);
  CHECK_MESSAGE(enlarged_columns > 0, label << ": no column needed an enlarged patch");
}

// A_t from the local kernel: heat regions of stable sizes, columns summing to 1,
// heat conserved over 1000 steps.
void check_diffusion(const std::string& name, double sigma)
{
  const Mesh mesh = test_support::load<Mesh>(name);
  const std::string label = name + " sigma " + std::to_string(sigma).substr(0, 3);
  const Diffusion diffusion(mesh, HD::parameters::combine(HD::parameters::sigma(sigma), HD::parameters::time(1.),
                                                          HD::parameters::kernel_method(HD::Heat_kernel_method::local)));
  CHECK(diffusion.kernel_method() == HD::Heat_kernel_method::local);
  const auto& A = diffusion.operator_matrix();
  const Eigen::VectorXd column_sums = Eigen::RowVectorXd::Ones(A.rows()) * A;
  const double column_error = (column_sums.array() - 1.).abs().maxCoeff();
  CHECK_MESSAGE(column_error <= 1e-13, label << ": max |column sum - 1| = " << column_error);
  CHECK_MESSAGE(A.coeffs().minCoeff() > 0, label << ": non-positive entry in A_t " << A.coeffs().minCoeff());
  const auto& stats = diffusion.region_statistics();
  std::cout << label << ": local kernel heat regions (t = 1) min " << stats.min_size << " mean " << stats.mean_size
            << " max " << stats.max_size << ", collapsed " << stats.collapsed_regions << std::endl;
  CHECK_MESSAGE(stats.capped_regions == 0, label << ": " << stats.capped_regions << " capped regions");
  // Stable sizes: with sigma = 1 no region is more than 4 times the mean or less than
  // a tenth of it. With sigma = 0.1 the sizes follow the weights, as they must: across
  // fandisk's sharp creases they fall to 1e-11 and below, and some vertices keep their
  // heat (check_columns() compares the regions with those of the exact kernel).
  CHECK_MESSAGE(double(stats.max_size) <= 4 * stats.mean_size,
                label << ": region sizes up to " << stats.max_size << ", mean " << stats.mean_size);
  if(sigma >= 1.)
  {
    CHECK_MESSAGE(double(stats.min_size) >= 0.1 * stats.mean_size,
                  label << ": region sizes from " << stats.min_size << ", mean " << stats.mean_size);
    CHECK_MESSAGE(stats.collapsed_regions == 0, label << ": " << stats.collapsed_regions << " collapsed regions");
  }

  Eigen::VectorXd f0(static_cast<Eigen::Index>(diffusion.number_of_vertices()));
  for(Vertex v : mesh.vertices())
    f0[Eigen::Index(diffusion.vertex_index(v))] = diffusion.normal_controlled_coordinates().normal_signature(v);
  const std::vector<std::size_t> steps = {0, 1, 10, 100, 1000};
  const std::vector<Eigen::VectorXd> fields = diffusion.diffuse(f0, steps);
  const double scale = f0.cwiseAbs().sum();
  double drift = 0;
  for(std::size_t s = 0; s < steps.size(); ++s)
    drift = (std::max)(drift, std::abs(fields[s].sum() - f0.sum()) / scale);
  std::cout << label << ": relative heat drift over 1000 steps " << drift << std::endl;
  CHECK_MESSAGE(drift <= 1e-12, label << ": relative heat drift " << drift);
  CHECK(fields[2].maxCoeff() - fields[2].minCoeff() < fields[0].maxCoeff() - fields[0].minCoeff());
  test_support::check_diffusion_product(diffusion, f0, label);
}

// The accuracy budget of the local kernel's default tolerance: A_t (balanced) from the
// default kernel against A_t from the reference kernel (tolerance 2e-6, three poles),
// next to what the heat regions leave out of each kernel column (13 to 14 % of its heat on
// these meshes). The kernel's error on A_t must stay a small fraction of that truncation,
// which defines A_t: its mean at most a fiftieth of the truncation's mean, its 99th
// percentile about the tolerance; F^10 of the Normal Signature within 1e-3 of what the 10
// steps change; the features at k = 10 the same. The earlier default (1e-4, three poles)
// stays within 1e-5 of the reference.
void check_operator_accuracy(const std::string& name)
{
  const Mesh mesh = test_support::load<Mesh>(name);
  const auto local = HD::parameters::kernel_method(HD::Heat_kernel_method::local);
  const Diffusion reference(mesh, local.local_kernel_tolerance(kernel_accuracy::reference_tolerance));
  const Diffusion reference_columns(mesh, local.local_kernel_tolerance(kernel_accuracy::reference_tolerance)
                                              .operator_normalization(HD::Operator_normalization::columns));
  const kernel_accuracy::Summary truncation = kernel_accuracy::heat_outside_regions(reference_columns);
  const Diffusion by_default(mesh, local);
  const Diffusion previous(mesh, local.local_kernel_tolerance(previous_tolerance));
  const kernel_accuracy::Summary error =
      kernel_accuracy::column_distances(by_default.operator_matrix(), reference.operator_matrix());
  const kernel_accuracy::Summary previous_error =
      kernel_accuracy::column_distances(previous.operator_matrix(), reference.operator_matrix());

  std::map<Vertex, double> signature;
  Eigen::VectorXd f0(Eigen::Index(reference.number_of_vertices()));
  for(Vertex v : mesh.vertices())
  {
    signature[v] = reference.normal_controlled_coordinates().normal_signature(v);
    f0[Eigen::Index(reference.vertex_index(v))] = signature[v];
  }
  const Eigen::VectorXd f10_reference = reference.diffuse(f0, 10), f10 = by_default.diffuse(f0, 10);
  const double field_error = (f10 - f10_reference).norm() / (f10_reference - f0).norm();
  const auto features = [&](const Diffusion& diffusion) {
    const auto found = HD::detect_multiscale_features(diffusion, boost::make_assoc_property_map(signature), {10});
    return std::make_pair(found[0].convex, found[0].concave);
  };
  const auto reference_features = features(reference);

  std::cout << name << ": heat outside the regions, mean " << truncation.mean << " (largest " << truncation.largest
            << "); A_t column distance to the reference at the default tolerance: mean " << error.mean
            << ", 99th percentile " << error.percentile_99 << ", largest " << error.largest
            << "; at 1e-4: mean " << previous_error.mean << ", largest " << previous_error.largest
            << "; F^10 of the NS " << field_error << std::endl;
  CHECK_MESSAGE(error.mean <= 0.02 * truncation.mean, name << ": mean A_t error " << error.mean);
  CHECK_MESSAGE(error.percentile_99 <= 1.5 * HD::defaults::local_kernel_tolerance,
                name << ": 99th percentile " << error.percentile_99);
  CHECK_MESSAGE(previous_error.mean <= 1e-5, name << ": mean A_t error at 1e-4 " << previous_error.mean);
  CHECK_MESSAGE(field_error <= 1e-3, name << ": F^10 error " << field_error);
  CHECK_MESSAGE(features(by_default) == reference_features, name << ": the features at k = 10 differ");
  CHECK(!reference_features.first.empty());
  // the truncation is what the comparison is against: far more than the kernel's error
  CHECK_MESSAGE(truncation.mean > 0.05, name << ": heat outside the regions " << truncation.mean);
}

// The kernel choice through the API: defaults, accessors, rejections, the free function.
void check_interface()
{
  const Mesh mesh = test_support::load<Mesh>("sphere966.off");
  const auto local = HD::parameters::kernel_method(HD::Heat_kernel_method::local);
  const Diffusion by_default(mesh, HD::parameters::number_of_eigenpairs(10));
  CHECK(by_default.kernel_method() == HD::Heat_kernel_method::spectral);
  CHECK(by_default.heat_kernel().number_of_eigenpairs() == 10);
  const Diffusion diffusion(mesh, local);
  CHECK(diffusion.number_of_vertices() == mesh.number_of_vertices());
  CHECK_THROWS(diffusion.heat_kernel(), std::logic_error, "no spectral heat kernel");
  CHECK_THROWS(Diffusion(mesh, HD::parameters::combine(local, HD::parameters::scale_invariant_kernel(true))),
               std::invalid_argument, "needs the eigenvalues");
  CHECK_THROWS(Diffusion(mesh, HD::parameters::combine(local, HD::parameters::sigma(0.))), std::invalid_argument,
               "sigma must be positive");
  CHECK_THROWS(Diffusion(mesh, HD::parameters::combine(local, HD::parameters::time(-1.))), std::invalid_argument,
               "time must be positive");
  CHECK_THROWS(Diffusion(mesh, HD::parameters::combine(local, HD::parameters::time(std::numeric_limits<double>::infinity()))),
               std::invalid_argument, "time must be positive");
  for(double tolerance : {0., 1., -1e-3, std::numeric_limits<double>::quiet_NaN(), HUGE_VAL})
    CHECK_THROWS(Diffusion(mesh, HD::parameters::combine(local, HD::parameters::local_kernel_tolerance(tolerance))),
                 std::invalid_argument, "local_kernel_tolerance must be in (0, 1)");
  // the tolerance chooses the approximation: two poles where the heat balance can
  // still check the tolerance, three below
  CHECK(Local_kernel::exponential_for(HD::defaults::local_kernel_tolerance).number_of_poles == 2);
  CHECK(Local_kernel::exponential_for(previous_tolerance).number_of_poles == 3);
  CHECK(Local_kernel::exponential_for(5.04e-4).number_of_poles == 2);
  CHECK(Local_kernel::exponential_for(5.03e-4).number_of_poles == 3);
  // checked with the spectral kernel too, which ignores it
  CHECK_THROWS(Diffusion(mesh, HD::parameters::number_of_eigenpairs(10).local_kernel_tolerance(2.)),
               std::invalid_argument, "local_kernel_tolerance must be in (0, 1)");

  // the free function with the local method equals the class
  std::map<Vertex, double> in, out, out2;
  for(Vertex v : mesh.vertices())
    in[v] = mesh.point(v).x();
  HD::anisotropic_heat_diffusion(mesh, boost::make_assoc_property_map(in), boost::make_assoc_property_map(out),
                                 HD::parameters::combine(local, HD::parameters::number_of_steps(3)));
  diffusion.diffuse(boost::make_assoc_property_map(in), boost::make_assoc_property_map(out2), 3);
  double worst = 0;
  for(Vertex v : mesh.vertices())
    worst = (std::max)(worst, std::abs(out[v] - out2[v]));
  CHECK_MESSAGE(worst == 0, "free function vs class: " << worst);

  // the local and spectral A_t agree where the truncated kernel is accurate: a small
  // mesh with every eigenpair (m = n), at t = 1: at the earlier default tolerance within
  // 1e-3, at the default within 1e-2 (the two-pole approximation's error on the columns)
  const Diffusion full(mesh, HD::parameters::combine(HD::parameters::number_of_eigenpairs(mesh.number_of_vertices()),
                                                     HD::parameters::sigma(1.)));
  for(const double tolerance : {previous_tolerance, HD::defaults::local_kernel_tolerance})
  {
    const Diffusion full_local(mesh, HD::parameters::combine(local, HD::parameters::sigma(1.),
                                                             HD::parameters::local_kernel_tolerance(tolerance)));
    const Sparse_matrix difference = full.operator_matrix() - full_local.operator_matrix();
    const double operator_difference = difference.norm() / full.operator_matrix().norm();
    std::cout << "sphere966: A_t local (tolerance " << tolerance << ") vs all " << mesh.number_of_vertices()
              << " eigenpairs, relative difference " << operator_difference << std::endl;
    CHECK_MESSAGE(operator_difference <= (tolerance == previous_tolerance ? 1e-3 : 1e-2),
                  "A_t local vs full spectral: " << operator_difference);
  }
}

void run()
{
  try
  {
    check_rational_approximation_and_clusters();
    check_columns("fandisk.off", 1.);
    check_columns("fandisk.off", 0.1);
    check_columns("armadillo.off", 1.);
    check_diffusion("fandisk.off", 1.);
    check_diffusion("fandisk.off", 0.1);
    check_diffusion("armadillo.off", 1.);
    check_operator_accuracy("fandisk.off");
    check_operator_accuracy("armadillo.off");
    check_interface();
  }
  catch(const std::exception& e)
  {
    std::cerr << "unexpected exception: " << e.what() << std::endl;
    test_support::check(false, "no unexpected exception", __FILE__, __LINE__);
  }
}

const test_support::Suite_registration registration("test_local_heat_kernel", &run);

} // namespace test_local_heat_kernel
