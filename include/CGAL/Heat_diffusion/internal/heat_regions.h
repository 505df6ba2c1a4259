// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The heat regions of the paper (eq. 15) and the kernel values on them, from which
// Anisotropic_heat_diffusion makes A_t.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_HEAT_REGIONS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_HEAT_REGIONS_H

#include <CGAL/Heat_diffusion/internal/Column_group_matrix.h>
#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/parallel_for.h>
#include <CGAL/Heat_diffusion/internal/progress.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

struct Heat_region_options
{
  double threshold;                 // tau(t): absolute, or relative to the peak (Columns::relative())
  std::size_t maximum_region_size;  // regions stop growing at this many vertices
  bool normalize_columns;           // the paper's A_t (columns sum to 1); else the kernel values are kept
  std::size_t group_size;           // the groups of sources when `group_begin` is empty
};

// Grows the heat region of every source j and fills column j of `matrix`: the kernel
// values h_t(j, i) on the region, divided by their sum if `options.normalize_columns`.
// `kernel` is a column evaluator (internal/kernel_columns.h); `order` is the order of
// the sources (results do not depend on it: each source writes its own column).
// `group_begin`, if not empty, is where groups of sources that share work start in
// `order`, with the end as last entry (the local kernel's clusters); else the groups
// are runs of `options.group_size` sources. A thread takes a group whole, and the
// matrix keeps the columns group by group (`Column_group_matrix`). Without the
// normalisation, `column_sums` and `peaks` receive each column's sum and h_t(j, j) (for
// the balancing); `statistics` (a `Heat_region_statistics`) the sizes of the regions.
// `progress` is told after each block of sources. The caller then calls
// `matrix.finish()` (once the memory that computed the columns is freed).
template <typename Columns, typename Statistics>
void build_heat_regions(const Columns& kernel, const Indexed_mesh& mesh, const std::vector<std::size_t>& order,
                        std::vector<std::size_t> group_begin, const Heat_region_options& options,
                        const Progress& progress, Column_group_matrix& matrix, Statistics& statistics,
                        Eigen::VectorXd& column_sums, Eigen::VectorXd& peaks)
{
  const bool balanced = !options.normalize_columns;
  const std::size_t n = mesh.number_of_vertices();
  if(group_begin.empty())
  {
    for(std::size_t first = 0; first < n; first += options.group_size)
      group_begin.push_back(first);
    group_begin.push_back(n);
  }
  struct Scratch
  {
    std::vector<std::size_t> mark;  // generation stamps: no clearing between sources
    std::size_t generation = 0;
    std::vector<std::size_t> queue;
    typename Columns::Workspace kernel_workspace;
    Column_group_matrix::Scratch group_places;  // for make_group()
  };
  // Memory (1.66M vertices, ~58 entries a column: 96M entries). The columns are
  // computed in blocks of sources, in parallel within a block; the thread that
  // computed a group's columns makes the group, and the block's groups are copied
  // (in parallel too) to A_t's arrays, once: A_t is never held twice. The per-column
  // vectors, the groups and the per-thread scratch are reused from block to block.
  // Blocks are small enough for the progress to move about every 1 % at that size.
  // (One small vector per column kept to the end would leave their memory in the
  // allocator's arenas: 1.5 GB at that size.)
  constexpr std::size_t block_size = 16384;
  matrix = Column_group_matrix(n);
  std::vector<std::vector<std::pair<std::size_t, double> > > columns((std::min)(block_size, n));
  std::vector<Column_group_matrix::Group> groups;
  Per_thread_scratch<Scratch> scratches([&] {
    return Scratch{std::vector<std::size_t>(n, 0), 0, {}, kernel.make_workspace(), matrix.make_scratch()};
  });
  statistics = Statistics();
  statistics.min_size = n;
  // of the kernel values H, for the balancing; the peaks h_t(j, j) are K's diagonal
  column_sums.resize(balanced ? Eigen::Index(n) : 0);
  peaks.resize(balanced ? Eigen::Index(n) : 0);
  std::size_t total = 0;
  progress.report(0., "the construction of the heat regions");
  std::size_t group = 0;  // the first group of the block
  for(std::size_t first = 0; first < n;)
  {
    // (a block ends with a group, so that no group is split between two blocks)
    std::size_t last = (std::min)(first + block_size, n), end_group = group;
    while(group_begin[end_group] < last)
      ++end_group;
    last = group_begin[end_group];
    const std::size_t count = last - first;
    if(columns.size() < count)
      columns.resize(count);
    if(groups.size() < end_group - group)
      groups.resize(end_group - group);
    auto compute_column = [&](std::size_t position, Scratch& s) {
      const std::size_t j = order[first + position];
      kernel.prepare(j, s.kernel_workspace);
      auto h = [&](std::size_t i) { return kernel(j, i, s.kernel_workspace); };
      ++s.generation;
      const double peak = h(j);
      const double tau = kernel.relative() ? options.threshold * peak : options.threshold;
      auto& column = columns[position];
      column.clear();
      column.emplace_back(j, peak);
      s.mark[j] = s.generation;
      s.queue.assign(1, j);
      for(std::size_t q = 0; q < s.queue.size() && column.size() < options.maximum_region_size; ++q)
      {
        const std::size_t i = s.queue[q];
        for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
        {
          const std::size_t u = mesh.fan[k];
          if(s.mark[u] == s.generation)
            continue;
          s.mark[u] = s.generation;
          const double value = h(u);
          if(value > tau && column.size() < options.maximum_region_size)
          {
            column.emplace_back(u, value);
            s.queue.push_back(u);
          }
        }
      }
      // A region whose source value is not positive (possible only for a badly
      // truncated kernel), or whose total is not finite (a kernel overflowing at an
      // extreme t), keeps its heat: a column of the identity, never NaN in A_t.
      double sum = 0;
      for(const auto& entry : column)
        sum += entry.second;
      // (normalised by make_group(); balanced: the kernel values are kept, and balanced
      // once every column is known)
      if(!(column.front().second > 0) || !(sum > 0) || !std::isfinite(sum))
      {
        column.assign(1, {j, 1.});
        sum = 1.;
      }
      if(balanced)
      {
        column_sums[Eigen::Index(j)] = sum;
        peaks[Eigen::Index(j)] = Column_group_matrix::stored_value(column.front().second, sum);
      }
    };
    parallel_for_with_scratch(
        end_group - group, scratches,
        [&](std::size_t g, Scratch& s) {
          const std::size_t begin = group_begin[group + g] - first, end = group_begin[group + g + 1] - first;
          for(std::size_t position = begin; position < end; ++position)
            compute_column(position, s);
          Column_group_matrix::make_group(columns.data() + begin, end - begin, s.group_places, groups[g],
                                          options.normalize_columns);
        },
        1);
    matrix.append(groups.data(), end_group - group, order.data() + first);
    for(std::size_t position = 0; position < count; ++position)
    {
      const std::size_t size = columns[position].size();
      total += size;
      statistics.min_size = (std::min)(statistics.min_size, size);
      statistics.max_size = (std::max)(statistics.max_size, size);
      statistics.collapsed_regions += size == 1 ? 1 : 0;
      statistics.capped_regions += size >= options.maximum_region_size ? 1 : 0;
    }
    group = end_group;
    progress.report(double(last) / double(n), "the construction of the heat regions");
    first = last;
  }
  statistics.mean_size = double(total) / double(n);
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_HEAT_REGIONS_H
