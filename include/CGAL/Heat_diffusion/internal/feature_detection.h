// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The strict 2-ring extrema of a field (paper, section 7), by vertex index.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_FEATURE_DETECTION_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_FEATURE_DETECTION_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/errors.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The one-rings of a mesh by vertex index, in compressed rows: the neighbours of
// vertex i are neighbours[begin[i] .. begin[i+1]).
struct Vertex_adjacency
{
  std::vector<std::size_t> begin;
  std::vector<std::size_t> neighbours;
};

// From the edges, so that vertices of any valence, on boundaries or not, get all
// their neighbours.
template <typename TriangleMesh, typename IndexOf>
Vertex_adjacency make_vertex_adjacency(const TriangleMesh& tm, std::size_t n, const IndexOf& index_of)
{
  Vertex_adjacency adjacency;
  adjacency.begin.assign(n + 1, 0);
  for(auto e : edges(tm))
  {
    ++adjacency.begin[index_of(source(e, tm)) + 1];
    ++adjacency.begin[index_of(target(e, tm)) + 1];
  }
  for(std::size_t i = 0; i < n; ++i)
    adjacency.begin[i + 1] += adjacency.begin[i];
  adjacency.neighbours.resize(adjacency.begin[n]);
  std::vector<std::size_t> fill(adjacency.begin.begin(), adjacency.begin.end() - 1);
  for(auto e : edges(tm))
  {
    const std::size_t a = index_of(source(e, tm)), b = index_of(target(e, tm));
    adjacency.neighbours[fill[a]++] = b;
    adjacency.neighbours[fill[b]++] = a;
  }
  return adjacency;
}

inline Vertex_adjacency make_vertex_adjacency(const Indexed_mesh& mesh)
{
  return Vertex_adjacency{mesh.fan_begin, mesh.fan};
}

inline double checked_feature_threshold(double c, const char* function)
{
  if(!(c >= 0. && c <= 1.))
  {
    std::ostringstream os;
    os << function << ": feature_threshold must be in [0, 1], not " << c;
    throw_invalid_input(os.str());
  }
  return c;
}

// The criterion of the paper (section 7), which states the convex case; the concave
// one is its mirror:
// i is convex if F(i) > F(j) for every j != i of its 2-ring and F(i) > c max F,
// concave if F(i) < F(j) for every such j and F(i) < c min F. The 2-ring is visited
// as the one-ring and the one-rings of its vertices; i itself, met there again, is
// skipped (some vertices are visited twice, which changes no strict comparison).
// Indices come out in increasing order.
inline void detect_features(const Vertex_adjacency& adjacency, const Eigen::VectorXd& field, double c,
                            std::vector<std::size_t>& convex, std::vector<std::size_t>& concave)
{
  const std::size_t n = std::size_t(field.size());
  if(n == 0)
    return;
  const double convex_threshold = c * field.maxCoeff();
  const double concave_threshold = c * field.minCoeff();
  for(std::size_t i = 0; i < n; ++i)
  {
    const double value = field[Eigen::Index(i)];
    bool is_maximum = value > convex_threshold;
    bool is_minimum = value < concave_threshold;
    auto compare = [&](std::size_t u) {
      const double other = field[Eigen::Index(u)];
      is_maximum = is_maximum && value > other;
      is_minimum = is_minimum && value < other;
    };
    for(std::size_t a = adjacency.begin[i]; a < adjacency.begin[i + 1] && (is_maximum || is_minimum); ++a)
    {
      const std::size_t j = adjacency.neighbours[a];
      compare(j);
      for(std::size_t b = adjacency.begin[j]; b < adjacency.begin[j + 1]; ++b)
        if(adjacency.neighbours[b] != i)
          compare(adjacency.neighbours[b]);
    }
    if(is_maximum)
      convex.push_back(i);
    if(is_minimum)
      concave.push_back(i);
  }
}

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_FEATURE_DETECTION_H
