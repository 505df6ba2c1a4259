// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Compact clusters of neighbouring vertices, one after the other.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_CLUSTERS_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_CLUSTERS_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The vertices partitioned into compact clusters of at most `cluster_size` vertices:
// seeds taken in breadth-first order, each cluster grown breadth first from its seed
// through the vertices not yet taken. Returns the clusters one after the other, and
// in `begin` (if given) where each starts (with the end as last entry).
inline std::vector<std::size_t> clustered_order(const Indexed_mesh& mesh, std::size_t cluster_size,
                                                std::vector<std::size_t>* begin = nullptr)
{
  const std::size_t n = mesh.number_of_vertices();
  // breadth-first order of the whole mesh, one component after the other
  std::vector<std::size_t> bfs;
  bfs.reserve(n);
  std::vector<unsigned char> seen(n, 0);
  for(std::size_t s = 0; s < n; ++s)
  {
    if(seen[s])
      continue;
    seen[s] = 1;
    std::size_t q = bfs.size();
    bfs.push_back(s);
    for(; q < bfs.size(); ++q)
    {
      const std::size_t i = bfs[q];
      for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1]; ++k)
        if(!seen[mesh.fan[k]])
        {
          seen[mesh.fan[k]] = 1;
          bfs.push_back(mesh.fan[k]);
        }
    }
  }
  std::vector<std::size_t> order;
  order.reserve(n);
  if(begin != nullptr)
    begin->clear();
  std::vector<unsigned char> taken(n, 0);
  std::vector<std::size_t> touched;
  std::fill(seen.begin(), seen.end(), 0);
  for(std::size_t seed : bfs)
  {
    if(taken[seed])
      continue;
    if(begin != nullptr)
      begin->push_back(order.size());
    const std::size_t first = order.size();
    taken[seed] = 1;
    order.push_back(seed);
    for(std::size_t q = first; q < order.size() && order.size() - first < cluster_size; ++q)
    {
      const std::size_t i = order[q];
      for(std::size_t k = mesh.fan_begin[i]; k < mesh.fan_begin[i + 1] && order.size() - first < cluster_size; ++k)
        if(!taken[mesh.fan[k]])
        {
          taken[mesh.fan[k]] = 1;
          order.push_back(mesh.fan[k]);
        }
    }
  }
  if(begin != nullptr)
    begin->push_back(order.size());
  return order;
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_CLUSTERS_H
