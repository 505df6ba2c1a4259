// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_COLUMN_GROUP_MATRIX_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_COLUMN_GROUP_MATRIX_H

#include <CGAL/Heat_diffusion/internal/parallel_for.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// A sparse n x n matrix made of groups of columns, computed group by group (A_t: the
// columns of a cluster of sources of the local kernel, or of a run of sources of the
// spectral one), and kept as it is computed: per group, its columns, whose entries
// name the group's rows (the rows its columns touch) by their place among them. A
// product y = A x first sums every group row, column after column of the group, then
// every row y_i over its group rows in the order of the groups: the same bits on any
// number of threads, since the groups are a fixed partition of the columns.
//
// Why not one compressed-row matrix: its rows are only known once every column is,
// so the columns would be kept (all of them) and then scattered into it: the matrix
// held twice, and scattered writes with their page faults. Here a group is written
// once, next to where it was computed, which lowers the peak memory by about a third
// on large meshes. The price is in the product: a row lies in about 3 groups, so a
// step is somewhat slower than in compressed rows (benchmark_local_kernel).
//
// An entry names its row by its place among its group's rows: a group has a few
// hundred rows, so that place takes 16 bits in a block whose groups all have at most
// 65536 rows (two bytes an entry less than a 32-bit row), and 32 bits in the other
// blocks (very large heat regions).
//
// An entry's value is kept in single precision, relative to a scale per column kept
// in double precision: the value of entry (i, j) is value * column_scale[j]. The
// float's relative rounding, 6e-8, is far below the kernels' own errors (the local
// kernel's columns are accurate to 1e-4 at best; the truncated spectral kernel is coarser still), and an
// entry takes six bytes instead of ten: 40 % less memory for the matrix, and less
// traffic for its products. The products and the operators made from the matrix are
// in double precision on the rounded values, so that what they promise exactly (a
// column of A_t summing to 1, symmetry, rows of the balanced A_t summing to 1) holds to
// double rounding. A column's values are stored divided by their sum, in (0, 1]: no
// float overflow or underflow whatever the kernel's scale.
class Column_group_matrix
{
public:
  typedef int Index;  // Eigen's default storage index: what operator_matrix() returns
  typedef Eigen::SparseMatrix<double, Eigen::ColMajor, Index> Sparse_matrix;

  // One group as the thread that computed its columns makes it.
  struct Group
  {
    std::vector<Index> rows;          // the rows its columns touch, in the order first touched
    std::vector<Index> column_begin;  // per column, where its entries start; the end last
    std::vector<Index> entry_row;     // per entry, its row's place in `rows`
    std::vector<float> values;        // per entry, its value / its column's scale
    std::vector<double> column_scale;
  };

  // Per thread, for make_group(): the place of each row of the matrix among the group's
  // rows (-1 between calls).
  struct Scratch
  {
    std::vector<Index> place;
  };

  Column_group_matrix() = default;
  explicit Column_group_matrix(std::size_t n) : n_(n) {}

  Scratch make_scratch() const { return Scratch{std::vector<Index>(n_, -1)}; }

  // The value that the matrix keeps for `value` in a column of values summing to
  // `column_sum` (> 0), with `normalize` false (see make_group()).
  static double stored_value(double value, double column_sum)
  {
    return double(float(value / column_sum)) * column_sum;
  }

  // Writes to `out` the group of the `count` columns `columns[k]`, each a list of
  // (row, value) whose values sum to a positive finite number. With `normalize`, each
  // column is divided by the sum of its stored values: its entries sum to 1 to
  // rounding.
  template <typename Column>
  static void make_group(const Column* columns, std::size_t count, Scratch& s, Group& out, bool normalize = false)
  {
    out.rows.clear();
    out.column_begin.assign(1, 0);
    out.entry_row.clear();
    out.values.clear();
    out.column_scale.clear();
    for(std::size_t k = 0; k < count; ++k)
    {
      double sum = 0;
      for(const auto& entry : columns[k])
        sum += entry.second;
      CGAL_precondition(sum > 0 && std::isfinite(sum));
      double stored_sum = 0;
      for(const auto& entry : columns[k])
      {
        Index& place = s.place[entry.first];
        if(place < 0)
        {
          place = Index(out.rows.size());
          out.rows.push_back(Index(entry.first));
        }
        out.entry_row.push_back(place);
        out.values.push_back(float(entry.second / sum));
        stored_sum += double(out.values.back());
      }
      out.column_scale.push_back(normalize ? 1. / stored_sum : sum);
      out.column_begin.push_back(Index(out.values.size()));
    }
    for(Index row : out.rows)
      s.place[std::size_t(row)] = -1;
  }

  // Appends `count` groups as one block (copied in parallel); `sources` lists the
  // column index of each of their columns, in order.
  // \throws std::length_error if the matrix gets more entries than Index holds.
  void append(const Group* groups, std::size_t count, const std::size_t* sources)
  {
    Block block;
    block.first_group_row = group_row_target_.size();
    block.group_column_begin.assign(count + 1, 0);
    block.group_row_begin.assign(count + 1, 0);
    std::vector<std::size_t> entry_offset(count + 1, 0);
    for(std::size_t g = 0; g < count; ++g)
    {
      block.group_column_begin[g + 1] = block.group_column_begin[g] + Index(groups[g].column_begin.size() - 1);
      block.group_row_begin[g + 1] = block.group_row_begin[g] + Index(groups[g].rows.size());
      entry_offset[g + 1] = entry_offset[g] + groups[g].values.size();
    }
    const std::size_t columns = std::size_t(block.group_column_begin[count]), entries = entry_offset[count];
    entries_ += entries;
    if(entries_ > std::size_t((std::numeric_limits<Index>::max)()))
      throw std::length_error("CGAL::Heat_diffusion::Anisotropic_heat_diffusion: A_t has more entries than its "
                              "index type holds; use a smaller time t");
    // (new[] leaves the arrays uninitialised: their pages are first written by the
    // parallel copies, not by one thread filling them with zeros)
    block.column_index.assign(sources, sources + columns);
    block.column_scale.resize(columns);
    block.column_begin.reset(new Index[columns + 1]);
    bool narrow = true;
    for(std::size_t g = 0; g < count; ++g)
      narrow = narrow && groups[g].rows.size() <= std::size_t(1) << 16;
    if(narrow)
      block.narrow_entry_row.reset(new Narrow_row[entries]);
    else
      block.wide_entry_row.reset(new Index[entries]);
    block.values.reset(new float[entries]);
    block.column_begin[columns] = Index(entries);
    group_row_target_.resize(block.first_group_row + std::size_t(block.group_row_begin[count]));
    parallel_for(count, [&](std::size_t g) {
      const Group& group = groups[g];
      const Index first_row = block.group_row_begin[g], first_column = block.group_column_begin[g];
      std::copy(group.rows.begin(), group.rows.end(),
                group_row_target_.begin() + std::ptrdiff_t(block.first_group_row) + first_row);
      for(std::size_t c = 0; c + 1 < group.column_begin.size(); ++c)
        block.column_begin[std::size_t(first_column) + c] = Index(entry_offset[g]) + group.column_begin[c];
      std::copy(group.column_scale.begin(), group.column_scale.end(),
                block.column_scale.begin() + std::ptrdiff_t(first_column));
      if(narrow)
        std::transform(group.entry_row.begin(), group.entry_row.end(),
                       block.narrow_entry_row.get() + entry_offset[g], [](Index r) { return Narrow_row(r); });
      else
        std::copy(group.entry_row.begin(), group.entry_row.end(), block.wide_entry_row.get() + entry_offset[g]);
      std::copy(group.values.begin(), group.values.end(), block.values.get() + entry_offset[g]);
    }, 1);
    blocks_.push_back(std::move(block));
  }

  // Once every group is appended: the group rows of every row, in the order of the
  // groups. (Counted and placed in parallel over `parts` ranges of group rows, each
  // from where the ranges before it end in each row: the order is the same whatever
  // the number of ranges.)
  void finish()
  {
    const std::size_t total = group_row_target_.size();
    const std::size_t parts = (std::max)(std::size_t(1), (std::min)(total, number_of_parallel_parts()));
    auto range_of = [&](std::size_t part) { return std::make_pair(total * part / parts, total * (part + 1) / parts); };
    std::vector<std::vector<Index> > next(parts);  // per range and row
    parallel_for(parts, [&](std::size_t part) {
      next[part].assign(n_, 0);
      const std::pair<std::size_t, std::size_t> range = range_of(part);
      for(std::size_t v = range.first; v < range.second; ++v)
        ++next[part][std::size_t(group_row_target_[v])];
    }, 1);
    row_begin_.assign(n_ + 1, 0);
    Index position = 0;
    for(std::size_t i = 0; i < n_; ++i)
    {
      row_begin_[i] = position;
      for(std::size_t part = 0; part < parts; ++part)
        position += std::exchange(next[part][i], position);
    }
    row_begin_[n_] = position;
    row_group_rows_.resize(total);
    parallel_for(parts, [&](std::size_t part) {
      const std::pair<std::size_t, std::size_t> range = range_of(part);
      for(std::size_t v = range.first; v < range.second; ++v)
        row_group_rows_[std::size_t(next[part][std::size_t(group_row_target_[v])]++)] = Index(v);
    }, 1);
  }

  std::size_t number_of_group_rows() const { return group_row_target_.size(); }

  // y = A x; `partial` (number_of_group_rows()) receives the sums of the group rows.
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y, Eigen::VectorXd& partial) const
  {
    CGAL_precondition(row_group_rows_.size() == group_row_target_.size());
    for(const Block& block : blocks_)
      with_arrays(block, [&](const auto& arrays) {
        parallel_for(block.group_row_begin.size() - 1, [&](std::size_t g) {
          // the group's rows
          double* const sums = partial.data() + block.first_group_row + std::size_t(block.group_row_begin[g]);
          std::fill(sums, sums + (block.group_row_begin[g + 1] - block.group_row_begin[g]), 0.);
          for(Index c = block.group_column_begin[g]; c < block.group_column_begin[g + 1]; ++c)
          {
            const double xj = x[Eigen::Index(arrays.column_index[c])] * arrays.column_scale[c];
            for(Index q = arrays.column_begin[c]; q < arrays.column_begin[c + 1]; ++q)
              sums[arrays.entry_row[q]] += double(arrays.values[q]) * xj;
          }
        }, 1);
      });
    parallel_for(n_, [&](std::size_t i) { y[Eigen::Index(i)] = sum_of_group_rows(i, partial); });
  }

  // y = D ((A + A^T) / 2) D x + diag(c) x, with D = diag(scaling) and c = `correction`
  // (empty for none): the balanced operator made of a kernel matrix A. One pass over
  // the entries, so about the memory traffic of multiply(): each column both scatters
  // into its group rows (A D x) and gathers from them (A^T D x), from the values of D x
  // copied per group row into `gathered` (number_of_group_rows(), as `partial`). The
  // same bits on any number of threads, as multiply(). `x` and `y` must differ.
  void multiply_symmetric_part(const Eigen::VectorXd& x, Eigen::VectorXd& y, const Eigen::VectorXd& scaling,
                               const Eigen::VectorXd& correction, Eigen::VectorXd& partial,
                               Eigen::VectorXd& gathered) const
  {
    CGAL_precondition(row_group_rows_.size() == group_row_target_.size() && &x != &y);
    for(const Block& block : blocks_)
      with_arrays(block, [&](const auto& arrays) {
        parallel_for(block.group_row_begin.size() - 1, [&](std::size_t g) {
          // the group's rows
          const std::size_t first = block.first_group_row + std::size_t(block.group_row_begin[g]);
          const std::size_t rows = std::size_t(block.group_row_begin[g + 1] - block.group_row_begin[g]);
          double* const sums = partial.data() + first;
          double* const scaled = gathered.data() + first;
          const Index* const targets = group_row_target_.data() + first;
          for(std::size_t r = 0; r < rows; ++r)
          {
            const Eigen::Index i = Eigen::Index(targets[r]);
            sums[r] = 0;
            scaled[r] = scaling[i] * x[i];
          }
          for(Index c = block.group_column_begin[g]; c < block.group_column_begin[g + 1]; ++c)
          {
            const Eigen::Index j = Eigen::Index(arrays.column_index[c]);
            const double scale = arrays.column_scale[c], xj = scaling[j] * x[j] * scale;
            double transposed = 0;
            for(Index q = arrays.column_begin[c]; q < arrays.column_begin[c + 1]; ++q)
            {
              const double value = double(arrays.values[q]);
              sums[arrays.entry_row[q]] += value * xj;
              transposed += value * scaled[arrays.entry_row[q]];
            }
            y[j] = transposed * scale;
          }
        }, 1);
      });
    const bool corrected = correction.size() > 0;
    parallel_for(n_, [&](std::size_t i) {
      const Eigen::Index k = Eigen::Index(i);
      y[k] = scaling[k] * (0.5 * (sum_of_group_rows(i, partial) + y[k])) + (corrected ? correction[k] * x[k] : 0.);
    });
  }

  // The matrix in compressed columns, each column's rows increasing.
  Sparse_matrix column_major() const
  {
    Sparse_matrix matrix{Eigen::Index(n_), Eigen::Index(n_)};
    matrix.resizeNonZeros(Eigen::Index(entries_));
    Index* outer = matrix.outerIndexPtr();
    std::fill(outer, outer + n_ + 1, 0);
    for(const Block& block : blocks_)
      for(std::size_t c = 0; c < block.column_index.size(); ++c)
        outer[std::size_t(block.column_index[c]) + 1] = block.column_begin[c + 1] - block.column_begin[c];
    for(std::size_t j = 0; j < n_; ++j)
      outer[j + 1] += outer[j];
    std::vector<std::pair<Index, double> > column;
    for(const Block& block : blocks_)
      with_arrays(block, [&](const auto& arrays) {
        for(std::size_t g = 0; g + 1 < block.group_column_begin.size(); ++g)
        {
          const Index* const targets =
              group_row_target_.data() + block.first_group_row + std::size_t(block.group_row_begin[g]);
          for(Index c = block.group_column_begin[g]; c < block.group_column_begin[g + 1]; ++c)
          {
            // (in the order the group first touched the rows)
            column.clear();
            for(Index q = arrays.column_begin[c]; q < arrays.column_begin[c + 1]; ++q)
              column.emplace_back(targets[arrays.entry_row[q]], double(arrays.values[q]) * arrays.column_scale[c]);
            std::sort(column.begin(), column.end());
            const std::size_t first = std::size_t(outer[std::size_t(arrays.column_index[c])]);
            for(std::size_t k = 0; k < column.size(); ++k)
            {
              matrix.innerIndexPtr()[first + k] = column[k].first;
              matrix.valuePtr()[first + k] = column[k].second;
            }
          }
        }
      });
    return matrix;
  }

private:
  // Row i of A x: the sums of its group rows, in the order of the groups.
  double sum_of_group_rows(std::size_t i, const Eigen::VectorXd& partial) const
  {
    double sum = 0;
    for(Index q = row_begin_[i]; q < row_begin_[i + 1]; ++q)
      sum += partial[row_group_rows_[std::size_t(q)]];
    return sum;
  }

  typedef std::uint16_t Narrow_row;

  // Groups appended together. Group g has the columns [group_column_begin[g],
  // group_column_begin[g + 1]) and the group rows first_group_row + [group_row_begin[g],
  // group_row_begin[g + 1]) of the whole matrix; an entry's row is its place among its
  // group's rows, in narrow_entry_row or else in wide_entry_row (see above). (The large
  // arrays are shared by copies: the matrix does not change once built.)
  struct Block
  {
    std::size_t first_group_row = 0;
    std::vector<Index> group_column_begin, group_row_begin;
    std::vector<Index> column_index;   // per column, its index in the matrix
    std::vector<double> column_scale;  // per column (see above)
    std::shared_ptr<Index[]> column_begin;
    std::shared_ptr<Narrow_row[]> narrow_entry_row;
    std::shared_ptr<Index[]> wide_entry_row;
    std::shared_ptr<float[]> values;
  };

  // A block's arrays as raw pointers, for the products: the loads of the arrays'
  // addresses stay out of the loops.
  template <typename Row>
  struct Block_arrays
  {
    Block_arrays(const Block& block, const Row* rows)
      : column_index(block.column_index.data()), column_scale(block.column_scale.data()),
        column_begin(block.column_begin.get()), entry_row(rows), values(block.values.get())
    {}
    const Index* const column_index;
    const double* const column_scale;
    const Index* const column_begin;
    const Row* const entry_row;
    const float* const values;
  };

  // Calls f(Block_arrays) with the block's rows, narrow or wide.
  template <typename F>
  static void with_arrays(const Block& block, F f)
  {
    if(block.narrow_entry_row)
      f(Block_arrays<Narrow_row>(block, block.narrow_entry_row.get()));
    else
      f(Block_arrays<Index>(block, block.wide_entry_row.get()));
  }

  std::size_t n_ = 0, entries_ = 0;
  std::vector<Block> blocks_;
  std::vector<Index> group_row_target_;  // per group row, its row of the matrix
  std::vector<Index> row_begin_;         // per row, where its group rows start in row_group_rows_
  std::vector<Index> row_group_rows_;    // the group rows of each row, in the order of the groups
};

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_COLUMN_GROUP_MATRIX_H
