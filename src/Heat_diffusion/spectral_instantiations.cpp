// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The spectral path's heavy templates, instantiated once: the library
// CGAL::Heat_diffusion_compiled. Programs linked with it are compiled with
// CGAL_HEAT_DIFFUSION_EXTERN_TEMPLATES, which declares these instantiations `extern`,
// so that they do not compile the eigen solver and the coarse level's simplification
// themselves. They do not depend on the mesh type: one library serves every mesh.

#include <CGAL/Heat_diffusion/internal/coarse_level.h>
#include <CGAL/Heat_diffusion/internal/generalized_eigensolver.h>

namespace CGAL {
namespace Heat_diffusion {
namespace internal {

template Generalized_eigenpairs compute_smallest_generalized_eigenpairs<Eigen::SparseMatrix<double>>(
    const Eigen::SparseMatrix<double>&, const Eigen::SparseMatrix<double>&, Eigen::Index,
    const std::function<bool(double)>&, const Generalized_eigensolver_options&);
template Generalized_eigenpairs compute_smallest_generalized_eigenpairs<Eigen::SparseMatrix<double>>(
    const Eigen::SparseMatrix<double>&, const Eigen::SparseMatrix<double>&, Eigen::Index,
    const std::function<bool(double)>&);
template Coarse_level make_coarse_level<CGAL::Exact_predicates_inexact_constructions_kernel>(
    const Indexed_mesh&, std::size_t, const Progress&);

} // namespace internal
} // namespace Heat_diffusion
} // namespace CGAL
