// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The local heat kernel's factorisation: the complex symmetric LDL^T factorisations of
// the shifted patch matrices t L_P + z_k B_P, one per pole z_k of the rational
// exponential, with one ordering and one symbolic analysis for all poles. The
// substitutions that solve with them are in multipole_block_substitution.h.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_MULTIPOLE_LDLT_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_MULTIPOLE_LDLT_H

#include <CGAL/Heat_diffusion/internal/rational_exponential.h>
#include <CGAL/Heat_diffusion/internal/vector_clones.h>

#include <Eigen/Core>
#include <Eigen/OrderingMethods>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The factorisations of P (t L_P + z_k B_P) P^T for the poles z_k of a
// Rational_exponential (the workspace's `exponential`) on a patch P, sharing one ordering and one symbolic analysis,
// and the workspace of the solutions of the right-hand sides -a_k e_s of a cluster's
// sources s. The caller fills the patch matrices of the workspace, then calls
// analyse() and factorise(), then Multipole_block_substitution's place_sources() and
// forward_substitution(); its solve_row() then completes the back substitution of a
// row (and of the rows it needs) where a column is read, into `columns`. The workspace
// is reused from patch to patch.
class Multipole_ldlt
{
public:
  static constexpr std::size_t maximum_number_of_poles = Rational_exponential::maximum_number_of_poles;
  // The block columns that the back substitution solves together, a pass (summed up in
  // registers: one vector of sixteen floats, or two of eight), and the multiple to which
  // a block row is rounded up. (Sixteen single-precision lanes fill an AVX-512 register;
  // passes of eight were measured slower.)
  static constexpr std::size_t lanes_per_pass = 16;

  struct Workspace
  {
    // the number p of rows: the patch's vertices
    std::size_t size() const { return patch_heat.size(); }
    // the rational approximation whose poles are factorised (set by the caller)
    const Rational_exponential* exponential = nullptr;
    std::size_t number_of_poles() const { return exponential->number_of_poles; }

    // the patch matrices, full symmetric pattern in compressed columns (extracted by the caller)
    std::vector<int> column_begin, row;
    std::vector<double> stiffness_value, mass_value, patch_heat;  // L_P, B_P, B_P 1

    // ordering and LDL^T
    std::vector<int> permutation, inverse_permutation;  // new -> old, old -> new
    std::vector<int> parent, factor_begin, factor_count, flag, pattern, factor_row;
    std::vector<double> factor_real, factor_imag, diagonal_real, diagonal_imag, y_real, y_imag;
    std::vector<double> diagonal_scale;  // 1 / |d|^2
    Eigen::SparseMatrix<double, Eigen::ColMajor, int> ordering_pattern;
    // the right-hand sides, then the solutions: p rows of (pole, source), split complex;
    // a row holds `stride` block columns, the sources rounded up to lanes_per_pass (the
    // extra columns stay zero)
    std::vector<float> block_real, block_imag;
    std::size_t stride = 0;
    std::vector<float> substitution_factor_real, substitution_factor_imag;  // the factor, rounded to float
    // The sources in the blocks: ordered by the postorder of their rows in the
    // elimination tree, so that the sources in the subtree of row j are the consecutive
    // block columns [source_begin[j], source_end[j]): the forward solutions are zero
    // outside them (an empty range: the row stays zero).
    std::vector<std::uint32_t> block_column;  // per source of the cluster
    std::vector<std::uint32_t> source_begin, source_end;
    Eigen::VectorXi tree_parent, postorder;  // (place_sources())
    std::vector<std::pair<int, std::uint32_t> > source_rank;
    // by the back substitution, per pass of lanes_per_pass block columns: pass * p + row
    std::vector<unsigned char> row_is_solved;
    std::vector<int> ancestors;  // the rows solve_row() solves next, for one pass
    std::vector<double> heat_forward_real, heat_forward_imag;  // L_k^-1 B_P 1, rows of poles

    // p x c, the cluster's columns on its patch (the solved rows), in block column order
    Eigen::MatrixXd columns;
  };

  // A fill-reducing ordering (AMD) of the patch pattern, and the symbolic LDL^T:
  // elimination tree and column counts of the factor.
  static void analyse(Workspace& w)
  {
    const int p = int(w.size());
    // (AMD reads the pattern only, and overwrites it)
    Eigen::SparseMatrix<double, Eigen::ColMajor, int>& pattern = w.ordering_pattern;
    pattern.resize(p, p);
    pattern.resizeNonZeros(int(w.row.size()));
    std::copy(w.column_begin.begin(), w.column_begin.end(), pattern.outerIndexPtr());
    std::copy(w.row.begin(), w.row.end(), pattern.innerIndexPtr());
    std::fill(pattern.valuePtr(), pattern.valuePtr() + w.row.size(), 1.);
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> ordering;
    Eigen::internal::minimum_degree_ordering(pattern, ordering);
    w.permutation.assign(ordering.indices().data(), ordering.indices().data() + p);
    w.inverse_permutation.resize(std::size_t(p));
    for(int k = 0; k < p; ++k)
      w.inverse_permutation[std::size_t(w.permutation[std::size_t(k)])] = k;

    w.parent.assign(std::size_t(p), -1);
    w.flag.assign(std::size_t(p), -1);
    w.factor_count.assign(std::size_t(p), 0);
    for(int k = 0; k < p; ++k)
    {
      w.flag[std::size_t(k)] = k;
      const int a = w.permutation[std::size_t(k)];
      for(int q = w.column_begin[std::size_t(a)]; q < w.column_begin[std::size_t(a) + 1]; ++q)
      {
        int i = w.inverse_permutation[std::size_t(w.row[std::size_t(q)])];
        if(i >= k)
          continue;
        for(; w.flag[std::size_t(i)] != k; i = w.parent[std::size_t(i)])
        {
          if(w.parent[std::size_t(i)] == -1)
            w.parent[std::size_t(i)] = k;
          ++w.factor_count[std::size_t(i)];
          w.flag[std::size_t(i)] = k;
        }
      }
    }
    w.factor_begin.assign(std::size_t(p) + 1, 0);
    for(int k = 0; k < p; ++k)
      w.factor_begin[std::size_t(k) + 1] = w.factor_begin[std::size_t(k)] + w.factor_count[std::size_t(k)];
  }


  // Numeric LDL^T of P (t L_P + z_k B_P) P^T for the poles z_k together (they share the
  // symbolic analysis: one traversal), complex symmetric (no conjugation). Entry q of
  // the factor of pole k is factor_real / factor_imag[q * number_of_poles() + k].
  CGAL_HEAT_DIFFUSION_VECTOR_CLONES static void factorise(Workspace& w, double t)
  {
    const std::size_t K = w.number_of_poles();
    // y's rows hold the poles and unused lanes up to four, so that a row is one vector
    static_assert(maximum_number_of_poles <= 4, "one vector of four per row of y");
    constexpr std::size_t Y = 4;
#ifdef CGAL_HEAT_DIFFUSION_VECTOR_EXTENSIONS
    const bool vectors = vector_registers_of_256_bits();
#endif
    const int p = int(w.size());
    const std::size_t nnz = std::size_t(w.factor_begin[std::size_t(p)]);
    w.factor_row.resize(nnz);
    // (and spare values, read with the last entry's or row's poles by a vector of four)
    w.factor_real.resize(nnz * K + Y - K);
    w.factor_imag.resize(nnz * K + Y - K);
    w.diagonal_real.resize(std::size_t(p) * K + Y - K);
    w.diagonal_imag.resize(std::size_t(p) * K + Y - K);
    w.diagonal_scale.resize(std::size_t(p) * K + Y - K);
    w.y_real.assign(std::size_t(p) * Y, 0.);
    w.y_imag.assign(std::size_t(p) * Y, 0.);
    w.heat_forward_real.resize(std::size_t(p) * K + Y - K);
    w.heat_forward_imag.resize(std::size_t(p) * K + Y - K);
    w.pattern.resize(std::size_t(p));
    std::fill(w.factor_count.begin(), w.factor_count.end(), 0);
    std::fill(w.flag.begin(), w.flag.end(), -1);  // no stale marks of the symbolic analysis
    const std::array<Exponential_pole, maximum_number_of_poles>& poles = w.exponential->poles;
    double* yr = w.y_real.data();
    double* yi = w.y_imag.data();
    for(int k = 0; k < p; ++k)
    {
      // scatter column k of the permuted upper triangle into y, and find the pattern
      // of row k of the factor (the reach in the elimination tree)
      int top = p;
      w.flag[std::size_t(k)] = k;
      const int a = w.permutation[std::size_t(k)];
      for(int q = w.column_begin[std::size_t(a)]; q < w.column_begin[std::size_t(a) + 1]; ++q)
      {
        int i = w.inverse_permutation[std::size_t(w.row[std::size_t(q)])];
        if(i > k)
          continue;
        const double l = t * w.stiffness_value[std::size_t(q)], b = w.mass_value[std::size_t(q)];
        for(std::size_t m = 0; m < K; ++m)
        {
          yr[std::size_t(i) * Y + m] += l + poles[m].pole_real * b;
          yi[std::size_t(i) * Y + m] += poles[m].pole_imag * b;
        }
        int length = 0;
        for(; w.flag[std::size_t(i)] != k; i = w.parent[std::size_t(i)])
        {
          w.pattern[std::size_t(length++)] = i;
          w.flag[std::size_t(i)] = k;
        }
        while(length > 0)
          w.pattern[std::size_t(--top)] = w.pattern[std::size_t(--length)];
      }
      // (copies, then clears: one loop doing both is miscompiled by g++ 12 at -O2,
      // whose loop distribution into memcpy / memset loses the imaginary parts)
      std::array<double, maximum_number_of_poles> dr, di;
      std::copy(yr + std::size_t(k) * Y, yr + std::size_t(k) * Y + K, dr.begin());
      std::copy(yi + std::size_t(k) * Y, yi + std::size_t(k) * Y + K, di.begin());
      std::fill(yr + std::size_t(k) * Y, yr + std::size_t(k) * Y + K, 0.);
      std::fill(yi + std::size_t(k) * Y, yi + std::size_t(k) * Y + K, 0.);
      double* ur = w.heat_forward_real.data() + std::size_t(k) * K;
      double* ui = w.heat_forward_imag.data() + std::size_t(k) * K;
      std::fill(ur, ur + K, w.patch_heat[std::size_t(a)]);
      std::fill(ui, ui + K, 0.);
#ifdef CGAL_HEAT_DIFFUSION_VECTOR_EXTENSIONS
      if(vectors)
      {
        // all poles at once, in vectors of four: the lanes past the poles are zeros in
        // y's rows, and read the next entry or a spare value elsewhere (and are dropped)
        Four_doubles dkr{0., 0., 0., 0.}, dki{0., 0., 0., 0.}, ukr, uki{0., 0., 0., 0.};
        for(std::size_t m = 0; m < K; ++m)
        {
          dkr[m] = dr[m];
          dki[m] = di[m];
        }
        ukr = Four_doubles{1., 1., 1., 1.} * w.patch_heat[std::size_t(a)];
        for(; top < p; ++top)
        {
          const std::size_t i = std::size_t(w.pattern[std::size_t(top)]);
          Four_doubles xr, xi;
          load_vector(xr, yr + i * Y);
          load_vector(xi, yi + i * Y);
          std::fill(yr + i * Y, yr + i * Y + Y, 0.);
          std::fill(yi + i * Y, yi + i * Y + Y, 0.);
          const std::size_t q0 = std::size_t(w.factor_begin[i]), q1 = q0 + std::size_t(w.factor_count[i]);
          for(std::size_t q = q0; q < q1; ++q)
          {
            double* zr = yr + std::size_t(w.factor_row[q]) * Y;
            double* zi = yi + std::size_t(w.factor_row[q]) * Y;
            Four_doubles fr, fi, gr, gi;
            load_vector(fr, w.factor_real.data() + q * K);
            load_vector(fi, w.factor_imag.data() + q * K);
            load_vector(gr, zr);
            load_vector(gi, zi);
            gr -= fr * xr - fi * xi;
            gi -= fr * xi + fi * xr;
            store_vector(zr, gr);
            store_vector(zi, gi);
          }
          w.factor_row[q1] = k;
          // l_ki = y_i / d_i
          Four_doubles er, ei, scale, uir, uii;
          load_vector(er, w.diagonal_real.data() + i * K);
          load_vector(ei, w.diagonal_imag.data() + i * K);
          load_vector(scale, w.diagonal_scale.data() + i * K);
          const Four_doubles lr = (xr * er + xi * ei) * scale, li = (xi * er - xr * ei) * scale;
          dkr -= lr * xr - li * xi;
          dki -= lr * xi + li * xr;
          std::memcpy(w.factor_real.data() + q1 * K, &lr, K * sizeof(double));
          std::memcpy(w.factor_imag.data() + q1 * K, &li, K * sizeof(double));
          load_vector(uir, w.heat_forward_real.data() + i * K);
          load_vector(uii, w.heat_forward_imag.data() + i * K);
          ukr -= lr * uir - li * uii;
          uki -= lr * uii + li * uir;
          ++w.factor_count[i];
        }
        for(std::size_t m = 0; m < K; ++m)
        {
          dr[m] = dkr[m];
          di[m] = dki[m];
          ur[m] = ukr[m];
          ui[m] = uki[m];
        }
      }
      else
#endif
        for(; top < p; ++top)
        {
          const std::size_t i = std::size_t(w.pattern[std::size_t(top)]);
          std::array<double, maximum_number_of_poles> vr, vi;
          std::copy(yr + i * Y, yr + i * Y + K, vr.begin());
          std::copy(yi + i * Y, yi + i * Y + K, vi.begin());
          std::fill(yr + i * Y, yr + i * Y + K, 0.);
          std::fill(yi + i * Y, yi + i * Y + K, 0.);
          const std::size_t q0 = std::size_t(w.factor_begin[i]), q1 = q0 + std::size_t(w.factor_count[i]);
          for(std::size_t q = q0; q < q1; ++q)
          {
            const std::size_t r = std::size_t(w.factor_row[q]);
            const double* fr = w.factor_real.data() + q * K;
            const double* fi = w.factor_imag.data() + q * K;
            for(std::size_t m = 0; m < K; ++m)
            {
              yr[r * Y + m] -= fr[m] * vr[m] - fi[m] * vi[m];
              yi[r * Y + m] -= fr[m] * vi[m] + fi[m] * vr[m];
            }
          }
          w.factor_row[q1] = k;
          for(std::size_t m = 0; m < K; ++m)
          {
            // l_ki = y_i / d_i
            const double er = w.diagonal_real[i * K + m], ei = w.diagonal_imag[i * K + m];
            const double scale = w.diagonal_scale[i * K + m];
            const double lr = (vr[m] * er + vi[m] * ei) * scale, li = (vi[m] * er - vr[m] * ei) * scale;
            dr[m] -= lr * vr[m] - li * vi[m];
            di[m] -= lr * vi[m] + li * vr[m];
            w.factor_real[q1 * K + m] = lr;
            w.factor_imag[q1 * K + m] = li;
            const double uir = w.heat_forward_real[i * K + m], uii = w.heat_forward_imag[i * K + m];
            ur[m] -= lr * uir - li * uii;
            ui[m] -= lr * uii + li * uir;
          }
          ++w.factor_count[i];
        }
      for(std::size_t m = 0; m < K; ++m)
      {
        if(!(dr[m] * dr[m] + di[m] * di[m] > 0) || !std::isfinite(dr[m]) || !std::isfinite(di[m]))
          throw std::runtime_error("CGAL::Heat_diffusion: the factorisation of a local heat kernel matrix failed");
        w.diagonal_real[std::size_t(k) * K + m] = dr[m];
        w.diagonal_imag[std::size_t(k) * K + m] = di[m];
        w.diagonal_scale[std::size_t(k) * K + m] = 1. / (dr[m] * dr[m] + di[m] * di[m]);
      }
    }
  }
};

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_MULTIPOLE_LDLT_H
