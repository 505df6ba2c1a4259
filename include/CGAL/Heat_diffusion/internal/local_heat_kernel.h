// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The edge-weighted heat kernel without eigenpairs and without truncation of the
// spectrum: each column h_t(., j) = [exp(-t B^-1 L) B^-1] e_j is computed on a patch
// grown around v_j, by a rational approximation of the exponential whose shifted patch
// matrices are factorised once for a cluster of neighbouring sources.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_LOCAL_HEAT_KERNEL_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_LOCAL_HEAT_KERNEL_H

#include <CGAL/Heat_diffusion/parameter_defaults.h>
#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/multipole_block_substitution.h>
#include <CGAL/Heat_diffusion/internal/multipole_ldlt.h>
#include <CGAL/Heat_diffusion/internal/rational_exponential.h>
#include <CGAL/Heat_diffusion/internal/vector_clones.h>
#include <CGAL/Heat_diffusion/internal/vertex_clusters.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/OrderingMethods>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// How large the kernel's patches are: a source's ball has the radius
// radius_factor * sqrt(t ln(1 / tolerance)) (or the reach of B^-1 e_j, if larger), and
// the sources come in clusters of at most cluster_size whose columns share one patch and
// its factorisations. Smaller patches lose more columns to the heat balance, which are
// computed again on enlarged patches; larger clusters share a factorisation among more
// sources but make every column's substitutions longer.
struct Local_kernel_patch_rule
{
  double radius_factor;
  std::size_t cluster_size;
};

// Which mass matrix the local kernel uses. `consistent` is the FEM mass matrix B of
// eq. 11, the operator of the spectral kernel; `lumped` replaces it by its row sums
// M = diag(B 1). Lumping changes the kernel by 2 to 37 % for t in [0.5, 4] on CGAL's
// meshes (8 to 32 % at t = 1; see the user manual), far more than the tolerance, so
// the package uses `consistent`; `lumped` is kept to measure that difference.
enum class Local_kernel_mass { consistent, lumped };

// Columns of the heat kernel H_t = exp(-t B^-1 L) B^-1 of the pencil (L, B), without
// eigenpairs and without truncating the spectrum.
//
// Locality. On the surface rescaled to area = n, the column of v_j decays like a
// Gaussian of the distance to v_j: for t = 1 it is above 1e-4 of its peak on a few
// hundred vertices only, whatever the size of the mesh. The column is computed on a
// patch P around v_j with a zero (absorbing) condition outside, containing the ball of
// the metric of diffusion_length() whose radius grows with sqrt(t ln(1/tolerance)).
// The heat lost through the border of the patch measures the truncation: the exact
// column carries the total heat 1^T B h = 1, so |1 - 1^T B_P h_P| is checked against
// the tolerance. The columns that fail (on armadillo subdivided twice, at t = 1: 707 of
// 416k, in 609 of its 3417 clusters, at the default tolerance; 28 in 27 of 4511 at
// 1e-4) are computed again on patches enlarged around those sources alone, until each
// passes.
//
// Rational approximation. With r(x) = sum_k Re(a_k / (-x - z_k)) ~ exp(-x)
// (Rational_exponential: two poles, uniform error 1.26e-4 on [0, inf), or three, 1.5e-6;
// exponential_for() chooses by the tolerance),
//   h_P = r(t B_P^-1 L_P) B_P^-1 e_j = - sum_k Re( a_k (t L_P + z_k B_P)^-1 e_j ):
// two or three complex symmetric sparse solves per column, no iteration, no convergence
// test.
// t L_P + z_k B_P has a definite imaginary part (Im z_k B_P), so its LDL^T
// factorisation without pivoting exists and is stable; it is computed in complex
// arithmetic by a simplicial up-looking LDL^T (after Davis's LDL) with an AMD ordering.
//
// Clusters. The sources are partitioned into compact clusters of about
// patch_rule_for(tolerance).cluster_size vertices (clustered_order()); one patch, the
// union of the balls of its sources, serves the whole cluster: one ordering, one
// symbolic analysis and one numeric factorisation per pole per cluster, and the
// cluster's columns solved together as a block (contiguous rows, vectorised). A workspace keeps the last cluster's columns, so the sources should
// come cluster after cluster (source_order()). A column depends only on its
// cluster, never on the order of the calls or on the thread: sequential and parallel
// runs give identical results.
//
// Solving where the columns are read. A heat region needs the column on a fraction of
// the patch, near its source. The forward substitution of a unit right-hand side fills
// in only the source's ancestors in the elimination tree; with the sources ordered by
// the postorder of their rows, the sources below a row are consecutive block columns,
// and each row updates only those (a fraction of the full block's work). The back substitution of a row needs only its ancestors: value() solves a
// row, and the ancestors not solved yet, when it is first read, in the lanes_per_pass
// block columns of the source's pass (the sources next to each other in the postorder):
// the rows read are a part of the patch, late in the elimination order, and a pass
// solves them for its columns only. The heat balance needs no column in full: with
// M_k = L_k D_k L_k^T (complex symmetric), 1^T B_P h_s = sum_k Re(u_k^T D_k^-1 y_ks),
// where u_k = L_k^-1 B_P 1 is computed with the factor and y_ks = L_k^-1 (-a_k e_s) is
// the forward solution.
//
// Precision. The factorisation is computed in double precision, the substitutions in
// single precision, from a copy of the factor: the block of a cluster (p rows of the
// poles and c sources, complex) then takes half the memory (1.4 MB on armadillo
// subdivided to 416k vertices at t = 1, within a core's L2 cache of 2 MB), and a vector
// register holds twice the lanes. The matrices are well conditioned (|t lambda + z_k| >=
// 2.68 with three poles, 1.95 with two, for the eigenvalues lambda >= 0 of the pencil) and
// the poles' terms cancel little (|a_k / z_k| <= 3.23, 1.95), so the rounding stays small:
// with three poles a column of A_t differs from the one of double-precision substitutions
// by at most 2.8e-6 (relative L2, armadillo subdivided to 104k vertices, t = 0.5 to 4), and
// a heat balance by at most 4.9e-7 (104k and 416k), which bounds the tolerances that the
// heat balance can check; and the substitutions are faster (benchmark_local_kernel).
//
// Cost per cluster of c sources: a patch of p ~ (sqrt(c) + radius)^2 vertices, one
// complex factorisation of it per pole, and c complex forward and back substitutions per
// pole on part of the factor; p grows like t and like log(1 / tolerance). Linear in n
// for fixed t.
class Local_heat_kernel
{
public:
  typedef Eigen::SparseMatrix<double> Sparse_matrix;

  // The relative accuracy aimed at by default: heat lost through the patch border,
  // relative to the column's heat (the package's default; see defaults::local_kernel_tolerance).
  static constexpr double default_tolerance = defaults::local_kernel_tolerance;

  static constexpr std::uint32_t not_in_patch = (std::numeric_limits<std::uint32_t>::max)();
  static constexpr std::size_t no_cluster = (std::numeric_limits<std::size_t>::max)();

  // Everything a cluster needs, allocated once per thread and reused: the arrays of
  // size n are stamped with a generation instead of being cleared for every patch.
  struct Workspace : Multipole_ldlt::Workspace
  {
    std::vector<std::uint32_t> stamp;  // == generation: the vertex was reached for this patch
    std::vector<std::uint32_t> local;  // its row in the patch (or not_in_patch)
    std::vector<double> distance;      // tentative Dijkstra distance
    std::uint32_t generation = 0;

    std::vector<std::uint32_t> patch;  // global indices of the patch
    std::vector<std::pair<double, std::uint32_t> > heap;
    std::vector<std::uint32_t> source_rows;  // the cluster's sources' rows in the patch

    // the last cluster, and the kernel that computed it
    const void* owner = nullptr;
    std::size_t cluster = no_cluster;
    bool whole_component = false;
    std::vector<double> deficits;   // |1 - 1^T B_P h| of each, per block column
    std::size_t source_position = 0;  // the column of the last compute_column()

    // The sources of the cluster whose columns lost more heat than the tolerance through
    // the border of the cluster's patch: their columns come from larger patches around
    // them alone, computed in `enlarged`. Per source of the cluster, its column there
    // (or not_in_patch).
    std::vector<std::size_t> enlarged_sources;
    std::vector<std::uint32_t> enlarged_position;
    std::unique_ptr<Workspace> enlarged;
    bool reads_enlarged = false;  // the last column is in `enlarged`

    // How many times this workspace's patch was enlarged (0 for a cluster's patch);
    // enlargements() tells it for the last column.
    std::size_t enlargements = 0;
  };

  Local_heat_kernel(const Indexed_mesh& mesh, const Sparse_matrix& stiffness, const Sparse_matrix& mass,
                    double time, double tolerance = default_tolerance,
                    Local_kernel_mass mass_kind = Local_kernel_mass::consistent)
    : mesh_(mesh), stiffness_(stiffness), mass_(mass), time_(time), tolerance_(tolerance), mass_kind_(mass_kind),
      exponential_(&exponential_for(tolerance))
  {
    const Local_kernel_patch_rule rule = patch_rule_for(tolerance);
    const std::size_t n = mesh.number_of_vertices();
    // (the patch matrices are read from the one pattern)
    CGAL_precondition(stiffness.rows() == Eigen::Index(n) && have_the_same_pattern(stiffness, mass));
    lumped_mass_.assign(n, 0.);
    for(Eigen::Index j = 0; j < mass.outerSize(); ++j)
      for(Sparse_matrix::InnerIterator it(mass, j); it; ++it)
        lumped_mass_[std::size_t(it.row())] += it.value();
    // The column beyond distance r holds about exp(-r^2 / (6 t)) of its heat (unit
    // weights, in the metric of diffusion_length()). At small t the part B^-1 e_j, which
    // decays like (2 - sqrt 3)^r, can reach farther, and it crosses the creases that a
    // small sigma closes to L: no heat flows there, so the heat balance cannot see it.
    const double log_tolerance = std::log(1. / tolerance);
    const double reach_in_edges = log_tolerance / std::log(2. + std::sqrt(3.));
    initial_radius_ = (std::max)(rule.radius_factor * std::sqrt(time * log_tolerance), reach_in_edges);
    // The edge lengths of diffusion_length() along the fans (the graph of L), for
    // Dijkstra, at most initial_radius_ / reach_in_edges: where the triangles are large,
    // a ball of that radius still spans the reach of B^-1 e_j in edges. (Uncapped, long
    // edges make patches too small in edges: many more clusters lose too much heat and
    // are computed again on enlarged patches.)
    // (Computed where Dijkstra needs them, not stored: an array along the fans would
    // take 8 bytes per halfedge, for a square root per edge of a patch.)
    longest_edge_ = initial_radius_ / reach_in_edges;
    std::vector<std::size_t> begin;
    cluster_order_ = clustered_order(mesh, rule.cluster_size, &begin);
    cluster_begin_.assign(begin.begin(), begin.end());
    cluster_of_.assign(n, 0);
    position_in_cluster_.assign(n, 0);
    for(std::size_t c = 0; c + 1 < begin.size(); ++c)
      for(std::size_t a = begin[c]; a < begin[c + 1]; ++a)
      {
        cluster_of_[cluster_order_[a]] = std::uint32_t(c);
        position_in_cluster_[cluster_order_[a]] = std::uint32_t(a - begin[c]);
      }
  }

  // Whether `a` and `b` are compressed, of the same size and with the same pattern (the
  // one-ring pattern of assemble_heat_operators()).
  static bool have_the_same_pattern(const Sparse_matrix& a, const Sparse_matrix& b)
  {
    if(!a.isCompressed() || !b.isCompressed() || a.rows() != b.rows() || a.cols() != b.cols() ||
       a.nonZeros() != b.nonZeros())
      return false;
    return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
           std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
  }

  double time() const { return time_; }
  // The sources in the order the kernel works best: its clusters one after the other,
  // so that consecutive sources share their patch factorisations.
  const std::vector<std::size_t>& source_order() const { return cluster_order_; }
  // Where each cluster starts in source_order(), and its end.
  const std::vector<std::size_t>& cluster_begin() const { return cluster_begin_; }
  double tolerance() const { return tolerance_; }
  // The rational approximation of the exponential that the kernel uses.
  const Rational_exponential& exponential() const { return *exponential_; }

  // The approximation with the fewest poles (each a complex factorisation per patch
  // and a complex solve per column) whose error is at most a quarter of `tolerance`.
  // The approximation's error enters the heat balance (r(0) is not exactly 1), so that a
  // tolerance near it could never be met (with two poles at 1e-4 every patch grows to
  // the whole mesh); a quarter leaves the balance to the patch border.
  static const Rational_exponential& exponential_for(double tolerance)
  {
    const Rational_exponential& two = two_pole_exponential();
    return two.maximum_error <= 0.25 * tolerance ? two : three_pole_exponential();
  }

  // The patch rule at `tolerance`, with the approximation of exponential_for(): where
  // the patches' savings and the columns computed again balance best, measured in the
  // single-thread CPU time of building A_t (armadillo subdivided once, t = 0.5 to 4,
  // sigma 0.1; the user manual has the figures). With two poles (the default tolerance) the radius factor 2.4 and
  // clusters of 128; with three (tolerances below 5e-4) 2.6 and 96, the package's
  // earlier rule, kept so that local_kernel_tolerance(1e-4) computes what it did. (At
  // the default tolerance the radius is the reach of B^-1 e_j below t = 0.46.)
  static Local_kernel_patch_rule patch_rule_for(double tolerance)
  {
    return exponential_for(tolerance).number_of_poles == 2 ? Local_kernel_patch_rule{2.4, 128}
                                                            : Local_kernel_patch_rule{2.6, 96};
  }

  Workspace make_workspace() const
  {
    Workspace w;
    const std::size_t n = mesh_.number_of_vertices();
    w.stamp.assign(n, 0);
    w.local.assign(n, not_in_patch);
    w.distance.assign(n, 0.);
    return w;
  }

  // Computes h_t(i, j) for i in a patch around j. Afterwards `value(w, i)` is h_t(i, j)
  // (0 outside the patch), and patch(w) lists the patch.
  void compute_column(std::size_t j, Workspace& w) const
  {
    const std::size_t c = cluster_of_[j];
    if(w.cluster != c || w.owner != this)
    {
      w.owner = this;
      w.cluster = c;
      const std::size_t* sources = cluster_order_.data() + cluster_begin_[c];
      const std::size_t count = cluster_begin_[c + 1] - cluster_begin_[c];
      compute_cluster(sources, count, initial_radius_, w);
      // The columns that fail the heat balance: again on patches enlarged around their
      // sources alone, until all pass or the patch is the whole component.
      w.enlarged_sources.clear();
      w.enlarged_position.assign(count, not_in_patch);
      if(!w.whole_component)
        for(std::size_t s = 0; s < count; ++s)
          if(w.deficits[w.block_column[s]] > tolerance_)
          {
            w.enlarged_position[s] = std::uint32_t(w.enlarged_sources.size());
            w.enlarged_sources.push_back(sources[s]);
          }
      if(!w.enlarged_sources.empty())
      {
        if(!w.enlarged)
          w.enlarged = std::make_unique<Workspace>(make_workspace());
        Workspace& e = *w.enlarged;
        double radius = initial_radius_;
        e.enlargements = 0;
        do
        {
          radius *= 1.25;
          ++e.enlargements;
          compute_cluster(w.enlarged_sources.data(), w.enlarged_sources.size(), radius, e);
        } while(!e.whole_component && *std::max_element(e.deficits.begin(), e.deficits.end()) > tolerance_);
      }
    }
    const std::uint32_t position = position_in_cluster_[j];
    w.reads_enlarged = w.enlarged_position[position] != not_in_patch;
    if(w.reads_enlarged)
      w.enlarged->source_position = w.enlarged_position[position];
    else
      w.source_position = position;
  }

  static double value(Workspace& w, std::size_t i)
  {
    Workspace& v = w.reads_enlarged ? *w.enlarged : w;
    if(v.stamp[i] != v.generation || v.local[i] == not_in_patch)
      return 0.;
    const int row = v.inverse_permutation[v.local[i]];
    const std::size_t column = v.block_column[v.source_position], pass = column / lanes_per_pass;
    if(!v.row_is_solved[pass * v.patch.size() + std::size_t(row)])
      Multipole_block_substitution::solve_row(v, row, pass);
    return v.columns(Eigen::Index(v.local[i]), Eigen::Index(column));
  }

  // The patch of the last column (global indices).
  static const std::vector<std::uint32_t>& patch(const Workspace& w)
  {
    return w.reads_enlarged ? w.enlarged->patch : w.patch;
  }

  // The enlargements the patch of the last column needed (for statistics and tests).
  static std::size_t enlargements(const Workspace& w)
  {
    return w.reads_enlarged ? w.enlarged->enlargements : 0;
  }

private:
  static constexpr std::size_t lanes_per_pass = Multipole_ldlt::lanes_per_pass;

  // Length of the edge ik in the metric in which the kernel spreads like a Gaussian:
  // a random walk with rates w_ik / m_i moves about sqrt(m / w) per unit time. The
  // patch ignores the weights (w = 1): with a small sigma, B still couples the
  // vertices that L separates, and heat crosses sharp creases through the mass matrix.
  double diffusion_length(std::size_t i, std::size_t k) const
  {
    return std::sqrt(0.5 * (lumped_mass_[i] + lumped_mass_[k]));
  }

  // The length of the edge ik for the patches' Dijkstra (see the constructor).
  double edge_length(std::size_t i, std::size_t k) const { return (std::min)(diffusion_length(i, k), longest_edge_); }

  void next_generation(Workspace& w) const
  {
    if(++w.generation == 0)  // wrapped around: the stamps would lie
    {
      std::fill(w.stamp.begin(), w.stamp.end(), 0u);
      w.generation = 1;
    }
  }

  // The patch: the vertices at distance <= radius from one of the sources (Dijkstra
  // over the mesh edges, the graph of L), in the order they are reached. Returns true
  // iff no vertex of their component is left outside.
  bool grow_patch(const std::size_t* sources, std::size_t count, double radius, Workspace& w) const
  {
    next_generation(w);
    w.patch.clear();
    w.heap.clear();
    auto reach = [&](std::size_t i, double d) {
      if(w.stamp[i] != w.generation)
      {
        w.stamp[i] = w.generation;
        w.local[i] = not_in_patch;
        w.distance[i] = d;
      }
      else if(d < w.distance[i])
        w.distance[i] = d;
      else
        return;
      w.heap.emplace_back(-d, std::uint32_t(i));
      std::push_heap(w.heap.begin(), w.heap.end());
    };
    for(std::size_t s = 0; s < count; ++s)
      reach(sources[s], 0.);
    while(!w.heap.empty())
    {
      const double d = -w.heap.front().first;
      const std::size_t i = w.heap.front().second;
      if(d > radius && w.local[i] == not_in_patch)
        break;
      std::pop_heap(w.heap.begin(), w.heap.end());
      w.heap.pop_back();
      if(w.local[i] != not_in_patch || d > w.distance[i])
        continue;  // a stale entry
      w.local[i] = std::uint32_t(w.patch.size());
      w.patch.push_back(std::uint32_t(i));
      for(std::size_t q = mesh_.fan_begin[i]; q < mesh_.fan_begin[i + 1]; ++q)
      {
        const std::size_t k = mesh_.fan[q];
        if(w.stamp[k] != w.generation || w.local[k] == not_in_patch)
          reach(k, d + edge_length(i, k));
      }
    }
    return w.heap.empty();
  }

  bool in_patch(const Workspace& w, std::size_t k) const
  {
    return w.stamp[k] == w.generation && w.local[k] != not_in_patch;
  }

  // L_P and B_P (a zero condition outside), on their common pattern, and the patch
  // heat weights B_P 1.
  void extract_patch_matrices(Workspace& w) const
  {
    const std::size_t p = w.patch.size();
    w.column_begin.assign(1, 0);
    w.row.clear();
    w.stiffness_value.clear();
    w.mass_value.clear();
    w.patch_heat.assign(p, 0.);
    const bool lumped = mass_kind_ == Local_kernel_mass::lumped;
    const auto* column_start = stiffness_.outerIndexPtr();
    const auto* rows = stiffness_.innerIndexPtr();
    for(std::size_t a = 0; a < p; ++a)
    {
      const std::size_t global = w.patch[a];
      for(auto q = column_start[global]; q < column_start[global + 1]; ++q)
      {
        const std::size_t r = std::size_t(rows[q]);
        if(!in_patch(w, r))
          continue;
        const double bv = !lumped ? mass_.valuePtr()[q] : r == global ? lumped_mass_[global] : 0.;
        w.row.push_back(int(w.local[r]));
        w.stiffness_value.push_back(stiffness_.valuePtr()[q]);
        w.mass_value.push_back(bv);
        w.patch_heat[a] += bv;  // B_P symmetric: column sums are row sums
      }
      w.column_begin.push_back(int(w.row.size()));
    }
  }

  // The columns of `count` sources on the union of their balls of `radius`, solved up
  // to the back substitution, which value() completes row by row where the columns
  // are read: the heat regions need a fraction of the patch, and the rows they need
  // are near the sources, late in the elimination order. Sets w.deficits and
  // w.whole_component.
  void compute_cluster(const std::size_t* sources, std::size_t count, double radius, Workspace& w) const
  {
    const std::size_t K = exponential_->number_of_poles;
    w.exponential = exponential_;
    w.whole_component = grow_patch(sources, count, radius, w);
    extract_patch_matrices(w);
    Multipole_ldlt::analyse(w);
    const std::size_t p = w.patch.size(), c = count;
    w.columns.resize(Eigen::Index(p), Eigen::Index(c));
    // (the rows are cleared by place_sources() or where the back substitution reaches them)
    w.stride = (c + lanes_per_pass - 1) / lanes_per_pass * lanes_per_pass;
    w.block_real.resize(K * p * w.stride);
    w.block_imag.resize(K * p * w.stride);
    w.row_is_solved.assign(w.stride / lanes_per_pass * p, 0);
    Multipole_ldlt::factorise(w, time_);
    w.substitution_factor_real.assign(w.factor_real.begin(), w.factor_real.end());
    w.substitution_factor_imag.assign(w.factor_imag.begin(), w.factor_imag.end());
    // right-hand sides -a_k e_j, then h = sum_k Re((t L + z_k B)^-1 (-a_k e_j))
    w.source_rows.resize(c);
    for(std::size_t s = 0; s < c; ++s)
      w.source_rows[s] = w.local[sources[s]];
    Multipole_block_substitution::place_sources(w.source_rows.data(), c, w);
    Multipole_block_substitution::forward_substitution(w);
    // The heat balance, 1 - 1^T B_P h_s = 1 - sum_k Re(u_k^T D_k^-1 y_ks) (see above),
    // over the rows where the forward solutions y_ks are not zero.
    w.deficits.assign(c, 1.);
    for(std::size_t j = 0; j < p; ++j)
    {
      const std::size_t begin = w.source_begin[j], end = w.source_end[j];
      if(begin >= end)
        continue;
      for(std::size_t m = 0; m < K; ++m)
      {
        const double er = w.diagonal_real[j * K + m], ei = w.diagonal_imag[j * K + m];
        const double ur = w.heat_forward_real[j * K + m], ui = w.heat_forward_imag[j * K + m];
        const double scale = w.diagonal_scale[j * K + m];
        const double gr = (ur * er + ui * ei) * scale, gi = (ui * er - ur * ei) * scale;  // u_j / d_j
        const float* yr = w.block_real.data() + (j * K + m) * w.stride;
        const float* yi = w.block_imag.data() + (j * K + m) * w.stride;
        for(std::size_t s = begin; s < end; ++s)
          w.deficits[s] -= gr * yr[s] - gi * yi[s];
      }
    }
    for(double& deficit : w.deficits)
      deficit = std::abs(deficit);
  }

  const Indexed_mesh& mesh_;
  const Sparse_matrix& stiffness_;
  const Sparse_matrix& mass_;
  double time_;
  double tolerance_;
  Local_kernel_mass mass_kind_;
  const Rational_exponential* exponential_;
  std::vector<double> lumped_mass_;
  double initial_radius_ = 0;
  double longest_edge_ = 0;  // the cap of edge_length()
  std::vector<std::size_t> cluster_order_, cluster_begin_;
  std::vector<std::uint32_t> cluster_of_, position_in_cluster_;
};

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_LOCAL_HEAT_KERNEL_H
