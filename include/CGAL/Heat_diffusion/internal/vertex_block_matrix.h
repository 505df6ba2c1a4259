// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Sparse matrices over the vertices of a mesh that couple each vertex with itself and
// its one-ring neighbours (the heat operators, the cotangent stiffness matrix of the
// denoising flow, the system of its normal fit), written in place in Eigen's
// compressed columns, without the triplets and their sort.

#ifndef CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_BLOCK_MATRIX_H
#define CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_BLOCK_MATRIX_H

#include <CGAL/Heat_diffusion/internal/Indexed_mesh.h>
#include <CGAL/Heat_diffusion/internal/parallel_for.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

// The pattern of such a matrix: column i lists vertex i and its neighbours in increasing
// order, each once (two edges between the same vertices add up, as they would in a sum
// of triplets).
struct One_ring_pattern
{
  explicit One_ring_pattern(const Indexed_mesh& mesh)
  {
    const std::size_t n = mesh.number_of_vertices();
    // Each column sorted in a slot of degree + 1 places (in parallel, the same rows on
    // any number of threads), then the slots packed in place.
    std::vector<std::size_t> sizes(n);
    rows.resize(mesh.fan.size() + n);
    parallel_for(n, [&](std::size_t i) {
      const auto first = rows.begin() + std::ptrdiff_t(mesh.fan_begin[i] + i);
      *first = i;
      const auto last = std::copy(mesh.fan.begin() + std::ptrdiff_t(mesh.fan_begin[i]),
                                  mesh.fan.begin() + std::ptrdiff_t(mesh.fan_begin[i + 1]), first + 1);
      std::sort(first, last);
      sizes[i] = std::size_t(std::unique(first, last) - first);
    });
    begin.assign(n + 1, 0);
    for(std::size_t i = 0; i < n; ++i)
    {
      begin[i + 1] = begin[i] + sizes[i];
      const auto first = rows.begin() + std::ptrdiff_t(mesh.fan_begin[i] + i);  // at or after begin[i]
      std::copy(first, first + std::ptrdiff_t(sizes[i]), rows.begin() + std::ptrdiff_t(begin[i]));
    }
    rows.resize(begin[n]);
  }

  // The place of row i among the rows of column j (i is j or one of its neighbours).
  std::size_t place(std::size_t i, std::size_t j) const
  {
    const std::size_t* first = rows.data() + begin[j];
    const std::size_t k = std::size_t(std::lower_bound(first, rows.data() + begin[j + 1], i) - first);
    CGAL_assertion(begin[j] + k < begin[j + 1] && first[k] == i);
    return k;
  }

  std::vector<std::size_t> begin;  // column j: rows[begin[j] .. begin[j+1])
  std::vector<std::size_t> rows;
};

// The number of entries of a matrix, checked against the index type of Eigen's sparse
// matrices.
inline Eigen::Index checked_number_of_entries(std::size_t entries)
{
  if(entries > std::size_t((std::numeric_limits<Eigen::SparseMatrix<double>::StorageIndex>::max)()))
    throw std::length_error("CGAL::Heat_diffusion: the mesh has too many edges for the sparse matrices' index type");
  return Eigen::Index(entries);
}

// A matrix of BlockSize x BlockSize blocks on the one-ring pattern, every block stored
// (zero until something is added to it), so that a block is found among degree + 1
// rows and no list of triplets is built and sorted (the normal fit's 3 x 3 blocks took
// 108 triplets per face). Contributions to an entry are summed in the order they are
// added, as setFromTriplets() sums the duplicates in the order of its list.
template <int BlockSize>
class Vertex_block_matrix
{
public:
  explicit Vertex_block_matrix(const Indexed_mesh& mesh) : pattern_(mesh)
  {
    typedef Eigen::SparseMatrix<double>::StorageIndex Storage_index;
    const std::size_t n = mesh.number_of_vertices();
    const Eigen::Index entries = checked_number_of_entries(std::size_t(BlockSize) * BlockSize * pattern_.rows.size());
    const Eigen::Index size = Eigen::Index(BlockSize * n);
    matrix_.resize(size, size);
    matrix_.resizeNonZeros(entries);
    Storage_index* outer = matrix_.outerIndexPtr();
    Storage_index* inner = matrix_.innerIndexPtr();
    for(std::size_t j = 0; j < n; ++j)
    {
      const std::size_t height = BlockSize * (pattern_.begin[j + 1] - pattern_.begin[j]);
      for(int c = 0; c < BlockSize; ++c)
      {
        const std::size_t first = BlockSize * BlockSize * pattern_.begin[j] + c * height;
        outer[BlockSize * j + c] = Storage_index(first);
        for(std::size_t k = pattern_.begin[j]; k < pattern_.begin[j + 1]; ++k)
          for(int r = 0; r < BlockSize; ++r)
            inner[first + BlockSize * (k - pattern_.begin[j]) + r] = Storage_index(BlockSize * pattern_.rows[k] + r);
      }
    }
    outer[size] = Storage_index(entries);
    set_zero();
  }

  // The place among the matrix's values of the entry (r, c) of the block of rows of
  // vertex i and columns of vertex j, a neighbour of i or i itself.
  std::size_t place(std::size_t i, std::size_t j, int r = 0, int c = 0) const
  {
    return std::size_t(matrix_.outerIndexPtr()[BlockSize * j + c]) + BlockSize * pattern_.place(i, j) + r;
  }

  // That entry.
  double& at(std::size_t i, std::size_t j, int r = 0, int c = 0) { return matrix_.valuePtr()[place(i, j, r, c)]; }

  // Every value 0, the pattern kept (to write new values in place).
  void set_zero() { std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.); }

  // Adds `block` (BlockSize x BlockSize) to the block of rows of vertex i and columns of
  // vertex j, a neighbour of i or i itself.
  template <typename Block>
  void add(std::size_t i, std::size_t j, const Block& block)
  {
    const std::size_t k = pattern_.place(i, j);
    double* values = matrix_.valuePtr();
    const auto* outer = matrix_.outerIndexPtr();
    for(int c = 0; c < BlockSize; ++c)
      for(int r = 0; r < BlockSize; ++r)
        values[outer[BlockSize * j + c] + BlockSize * k + r] += block(r, c);
  }

  Eigen::SparseMatrix<double>& matrix() { return matrix_; }
  const Eigen::SparseMatrix<double>& matrix() const { return matrix_; }

private:
  One_ring_pattern pattern_;
  Eigen::SparseMatrix<double> matrix_;
};

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL

#endif // CGAL_HEAT_DIFFUSION_INTERNAL_VERTEX_BLOCK_MATRIX_H
