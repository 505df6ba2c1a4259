// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The local heat kernel's block substitutions: the unit right-hand sides of a cluster
// of sources placed in blocks ordered along the elimination tree, their forward
// substitution with the factors of Multipole_ldlt for all poles at once, and the back
// substitution of a row and the rows it needs, done where a column is read.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_MULTIPOLE_BLOCK_SUBSTITUTION_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_MULTIPOLE_BLOCK_SUBSTITUTION_H

#include <CGAL/Heat_diffusion/internal/multipole_ldlt.h>
#include <CGAL/Heat_diffusion/internal/rational_exponential.h>
#include <CGAL/Heat_diffusion/internal/vector_clones.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The substitutions with the factors of Multipole_ldlt::factorise(), on the blocks of
// the workspace: place_sources(), then forward_substitution(), then solve_row() for
// each row where a column is read.
class Multipole_block_substitution
{
public:
  typedef Multipole_ldlt::Workspace Workspace;
  static constexpr std::size_t lanes_per_pass = Multipole_ldlt::lanes_per_pass;

#ifdef CGAL_HEAT_DIFFUSION_VECTOR_EXTENSIONS
  // b -= l a, complex, over `count` lanes (a multiple of the vector's width). Always
  // inlined, so that it is compiled for the clone that calls it.
  template <typename Vector>
  __attribute__((always_inline)) static inline void subtract_product_in_vectors(float* br, float* bi, float lr,
                                                                                float li, const float* ar,
                                                                                const float* ai, std::size_t count)
  {
    constexpr std::size_t width = sizeof(Vector) / sizeof(float);
    for(std::size_t s = 0; s < count; s += width)
    {
      Vector xr, xi, yr, yi;
      load_vector(xr, ar + s);
      load_vector(xi, ai + s);
      load_vector(yr, br + s);
      load_vector(yi, bi + s);
      yr -= lr * xr - li * xi;
      yi -= lr * xi + li * xr;
      store_vector(br + s, yr);
      store_vector(bi + s, yi);
    }
  }
#endif

  // Forward substitution X_k <- L_k^-1 X_k for the c right-hand sides of all poles.
  // With unit right-hand sides, the solution of a source is not zero only on the
  // source's ancestors in the elimination tree: row j updates only the block columns
  // of the sources in its subtree, and the rows without any are skipped. (Over the whole
  // passes that hold those columns, in vectors: the other columns of such a row are
  // zeros, cleared by place_sources(), and the updates they give change nothing.)
  CGAL_HEAT_DIFFUSION_VECTOR_CLONES
  static void forward_substitution(Workspace& w)
  {
    constexpr std::size_t S = lanes_per_pass;
    const std::size_t K = w.number_of_poles(), p = w.size(), stride = w.stride;
#ifdef CGAL_HEAT_DIFFUSION_VECTOR_EXTENSIONS
    const bool sixteens = vector_registers_of_512_bits(), eights = vector_registers_of_256_bits();
#endif
    for(std::size_t j = 0; j < p; ++j)
    {
      if(w.source_begin[j] >= w.source_end[j])
        continue;
      const std::size_t begin = w.source_begin[j] / S * S, end = (w.source_end[j] + S - 1) / S * S;
      const std::size_t q1 = std::size_t(w.factor_begin[j + 1]);
      for(std::size_t q = std::size_t(w.factor_begin[j]); q < q1; ++q)
      {
        const std::size_t i = std::size_t(w.factor_row[q]);
        for(std::size_t m = 0; m < K; ++m)
        {
          const float lr = w.substitution_factor_real[q * K + m], li = w.substitution_factor_imag[q * K + m];
          const float* ar = w.block_real.data() + (j * K + m) * stride;
          const float* ai = w.block_imag.data() + (j * K + m) * stride;
          float* br = w.block_real.data() + (i * K + m) * stride;
          float* bi = w.block_imag.data() + (i * K + m) * stride;
#ifdef CGAL_HEAT_DIFFUSION_VECTOR_EXTENSIONS
          if(sixteens)
            subtract_product_in_vectors<Sixteen_floats>(br + begin, bi + begin, lr, li, ar + begin, ai + begin,
                                                        end - begin);
          else if(eights)
            subtract_product_in_vectors<Eight_floats>(br + begin, bi + begin, lr, li, ar + begin, ai + begin,
                                                      end - begin);
          else
#endif
            for(std::size_t s = begin; s < end; ++s)
            {
              br[s] -= lr * ar[s] - li * ai[s];
              bi[s] -= lr * ai[s] + li * ar[s];
            }
        }
      }
    }
  }

#ifdef CGAL_HEAT_DIFFUSION_VECTOR_EXTENSIONS
  // Row j of pole m in back_substitution(), in the block columns [offset, offset + lanes)
  // (whole passes), with 1 / d_j = gr + i gi: a pass at a time, summed up in registers
  // over the factor column and written once, in lanes_per_pass / width vectors of `width`
  // floats (faster than the plain loops in the same clones, which the compiler
  // vectorises less well). Always inlined, so that it is compiled for the clone of
  // back_substitution() that calls it.
  template <typename Vector>
  __attribute__((always_inline)) static inline void back_substitute_in_vectors(Workspace& w, std::size_t j,
                                                                               std::size_t m, std::size_t offset,
                                                                               std::size_t lanes, float gr,
                                                                               float gi, bool zero)
  {
    constexpr std::size_t width = sizeof(Vector) / sizeof(float);
    constexpr std::size_t V = lanes_per_pass / width;
    static_assert(V * width == lanes_per_pass, "a pass is a whole number of vectors");
    const std::size_t K = w.number_of_poles(), stride = w.stride;
    float* ar = w.block_real.data() + (j * K + m) * stride + offset;
    float* ai = w.block_imag.data() + (j * K + m) * stride + offset;
    const std::size_t q0 = std::size_t(w.factor_begin[j]), q1 = std::size_t(w.factor_begin[j + 1]);
    for(std::size_t o = 0; o < lanes; o += lanes_per_pass)
    {
      Vector xr[V], xi[V], yr, yi;
      for(std::size_t v = 0; v < V; ++v)
        if(zero)
          xr[v] = xi[v] = Vector{};
        else
        {
          load_vector(yr, ar + o + width * v);
          load_vector(yi, ai + o + width * v);
          xr[v] = gr * yr - gi * yi;
          xi[v] = gr * yi + gi * yr;
        }
      for(std::size_t q = q0; q < q1; ++q)
      {
        const std::size_t i = std::size_t(w.factor_row[q]);
        const float lr = w.substitution_factor_real[q * K + m], li = w.substitution_factor_imag[q * K + m];
        const float* br = w.block_real.data() + (i * K + m) * stride + offset + o;
        const float* bi = w.block_imag.data() + (i * K + m) * stride + offset + o;
        for(std::size_t v = 0; v < V; ++v)
        {
          load_vector(yr, br + width * v);
          load_vector(yi, bi + width * v);
          xr[v] -= lr * yr - li * yi;
          xi[v] -= lr * yi + li * yr;
        }
      }
      for(std::size_t v = 0; v < V; ++v)
      {
        store_vector(ar + o + width * v, xr[v]);
        store_vector(ai + o + width * v, xi[v]);
      }
    }
  }
#endif

  // Diagonal scaling and back substitution X_k <- L_k^-T D_k^-1 X_k of the rows listed
  // in w.ancestors, from the last to the first, in the block columns of the passes
  // [first_pass, last_pass): each row needs its rows in the pattern of its factor column,
  // which are among its ancestors in the elimination tree and so already solved in those
  // passes. Then the passes' columns of the cluster on those rows: sum_k Re X_k.
  CGAL_HEAT_DIFFUSION_VECTOR_CLONES
  static void back_substitution(Workspace& w, std::size_t first_pass, std::size_t last_pass)
  {
    constexpr std::size_t S = lanes_per_pass;
    const std::size_t K = w.number_of_poles(), stride = w.stride, p = w.size();
#ifdef CGAL_HEAT_DIFFUSION_VECTOR_EXTENSIONS
    const bool sixteens = vector_registers_of_512_bits(), eights = vector_registers_of_256_bits();
#endif
    for(std::size_t position = w.ancestors.size(); position-- > 0;)
    {
      const std::size_t j = std::size_t(w.ancestors[position]);
      const bool zero = w.source_begin[j] >= w.source_end[j];  // no source below it
      for(std::size_t m = 0; m < K; ++m)
      {
        const double er = w.diagonal_real[j * K + m], ei = w.diagonal_imag[j * K + m];
        const double scale = w.diagonal_scale[j * K + m];
        const float gr = float(er * scale), gi = float(-ei * scale);  // 1 / d_j
        const std::size_t lanes = (last_pass - first_pass) * S;
#ifdef CGAL_HEAT_DIFFUSION_VECTOR_EXTENSIONS
        if(sixteens)
          back_substitute_in_vectors<Sixteen_floats>(w, j, m, first_pass * S, lanes, gr, gi, zero);
        else if(eights)
          back_substitute_in_vectors<Eight_floats>(w, j, m, first_pass * S, lanes, gr, gi, zero);
        else
#endif
        {
          // the passes in row j, and in row i
          float* ar = w.block_real.data() + (j * K + m) * stride + first_pass * S;
          float* ai = w.block_imag.data() + (j * K + m) * stride + first_pass * S;
          auto pass_of = [&](const std::vector<float>& block, std::size_t i) {
            return block.data() + (i * K + m) * stride + first_pass * S;
          };
          const std::size_t q0 = std::size_t(w.factor_begin[j]), q1 = std::size_t(w.factor_begin[j + 1]);
          if(zero)
          {
            std::fill_n(ar, lanes, 0.f);
            std::fill_n(ai, lanes, 0.f);
          }
          else
            for(std::size_t s = 0; s < lanes; ++s)
            {
              const float vr = ar[s], vi = ai[s];
              ar[s] = gr * vr - gi * vi;
              ai[s] = gr * vi + gi * vr;
            }
          for(std::size_t q = q0; q < q1; ++q)
          {
            const std::size_t i = std::size_t(w.factor_row[q]);
            const float lr = w.substitution_factor_real[q * K + m], li = w.substitution_factor_imag[q * K + m];
            const float* br = pass_of(w.block_real, i);
            const float* bi = pass_of(w.block_imag, i);
            for(std::size_t s = 0; s < lanes; ++s)
            {
              ar[s] -= lr * br[s] - li * bi[s];
              ai[s] -= lr * bi[s] + li * br[s];
            }
          }
        }
      }
      const Eigen::Index a = Eigen::Index(w.permutation[j]);
      const std::size_t last = (std::min)(last_pass * S, std::size_t(w.columns.cols()));
      for(std::size_t s = first_pass * S; s < last; ++s)
      {
        double sum = 0.;
        for(std::size_t m = 0; m < K; ++m)
          sum += w.block_real[(j * K + m) * stride + s];
        w.columns(a, Eigen::Index(s)) = sum;
      }
      for(std::size_t pass = first_pass; pass < last_pass; ++pass)
        w.row_is_solved[pass * p + j] = 1;
    }
  }

  // Solves row j of the factorised system (permuted order) in the block columns of
  // `pass`, and the rows it needs there: its ancestors not solved yet in that pass. (A
  // solved row's ancestors are all solved.)
  static void solve_row(Workspace& w, int j, std::size_t pass)
  {
    const unsigned char* solved = w.row_is_solved.data() + pass * w.size();
    w.ancestors.clear();
    for(; j != -1 && !solved[std::size_t(j)]; j = w.parent[std::size_t(j)])
      w.ancestors.push_back(j);
    // (the plain loops solve all the passes at once: they are faster over whole rows)
#ifdef CGAL_HEAT_DIFFUSION_VECTOR_EXTENSIONS
    if(vector_registers_of_256_bits())
      back_substitution(w, pass, pass + 1);
    else
#endif
      back_substitution(w, 0, w.stride / lanes_per_pass);
  }

  // Orders the c sources (their rows in the patch, before the ordering) by the postorder
  // of their rows in the elimination tree
  // (w.block_column), and finds the block columns [source_begin[j], source_end[j]) of
  // the sources in the subtree of each row j; clears the rows where that is not empty,
  // the rows the forward substitution writes, and writes the right-hand sides
  // -a_k e_s.
  static void place_sources(const std::uint32_t* source_rows, std::size_t c, Workspace& w)
  {
    const std::size_t K = w.number_of_poles(), stride = w.stride;
    const int p = int(w.size());
    // the postorder of the elimination forest (Eigen's, whose roots hang from a root p)
    w.tree_parent.resize(p);
    for(int j = 0; j < p; ++j)
      w.tree_parent[j] = w.parent[std::size_t(j)] == -1 ? p : w.parent[std::size_t(j)];
    Eigen::internal::treePostorder(p, w.tree_parent, w.postorder);
    w.source_rank.resize(c);  // (postorder of the source's row, the source)
    for(std::size_t s = 0; s < c; ++s)
      w.source_rank[s] = {w.postorder[std::size_t(w.inverse_permutation[source_rows[s]])], std::uint32_t(s)};
    std::sort(w.source_rank.begin(), w.source_rank.end());
    const auto& poles = w.exponential->poles;
    w.block_column.resize(c);
    w.source_begin.assign(std::size_t(p), 0);
    w.source_end.assign(std::size_t(p), 0);
    for(std::size_t column = 0; column < c; ++column)
    {
      const std::size_t s = w.source_rank[column].second;
      const int row = w.inverse_permutation[source_rows[s]];
      w.block_column[s] = std::uint32_t(column);
      // (columns come in increasing order: the first visit of a row gives its begin)
      for(int j = row; j != -1; j = w.parent[std::size_t(j)])
      {
        if(w.source_end[std::size_t(j)] == 0)
        {
          w.source_begin[std::size_t(j)] = std::uint32_t(column);
          std::fill_n(w.block_real.data() + std::size_t(j) * K * stride, K * stride, 0.f);
          std::fill_n(w.block_imag.data() + std::size_t(j) * K * stride, K * stride, 0.f);
        }
        w.source_end[std::size_t(j)] = std::uint32_t(column + 1);
      }
      for(std::size_t m = 0; m < K; ++m)
      {
        w.block_real[(std::size_t(row) * K + m) * stride + column] = float(-poles[m].residue_real);
        w.block_imag[(std::size_t(row) * K + m) * stride + column] = float(-poles[m].residue_imag);
      }
    }
  }
};

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_MULTIPOLE_BLOCK_SUBSTITUTION_H
