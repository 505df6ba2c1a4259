// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The spectral kernel on point sets: the vertices of CGAL's fandisk taken as points, with
// the mesh's normals. Its A_t against the local kernel's where the truncation is small,
// its eigenvalues against the mesh's, the balanced operator's guarantees, the automatic
// choice of the kernel, and the parameters it refuses.

#include <CGAL/Heat_diffusion/Edge_weighted_heat_kernel.h>
#include <CGAL/Heat_diffusion/normal_controlled_coordinates.h>
#include <CGAL/Heat_diffusion/point_set_anisotropic_heat_diffusion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Surface_mesh.h>

#include "mesh_vertices_as_points.h"
#include "test_support.h"

#include <Eigen/Core>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace test_point_set_spectral_kernel {

namespace HD = CGAL::Heat_diffusion;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef Epick::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Point_set_3<Point> Point_set;
typedef HD::Point_set_anisotropic_heat_diffusion<Point_set> Diffusion;

constexpr unsigned int k = 8;

void run()
{
  try
  {
    const Mesh mesh = test_support::load<Mesh>("fandisk.off");
    const HD::Normal_controlled_coordinates<Mesh> mesh_ncc(mesh);
    const Point_set points = test_support::mesh_vertices_as_points(mesh, mesh_ncc);
    const std::size_t n = points.size();

    // Where the truncation is small (sigma = 1, t = 16, m = 300: t is above 4 ln 10 /
    // lambda_m), the spectral A_t is the local one's.
    const auto options = HD::parameters::sigma(1.).time(16.);
    const Diffusion local(points, k, options);
    const Diffusion spectral(points, k, options.number_of_eigenpairs(300));
    CHECK(local.kernel_method() == HD::Heat_kernel_method::local && local.eigenvalues().size() == 0);
    CHECK(spectral.kernel_method() == HD::Heat_kernel_method::spectral);
    CHECK(spectral.eigenvalues().size() == 300 && spectral.eigenvalues().minCoeff() >= 0.);
    const double lambda_m = spectral.eigenvalues()[299];
    CHECK_MESSAGE(16. * lambda_m > 4. * std::log(10.), "t lambda_m = " << 16. * lambda_m);
    Eigen::VectorXd ns(static_cast<Eigen::Index>(n));
    for(std::size_t i = 0; i < n; ++i)
      ns[Eigen::Index(i)] = local.normal_controlled_coordinates().normal_signature(i);
    const Eigen::VectorXd a = local.diffuse(ns, 10), b = spectral.diffuse(ns, 10);
    const double difference = (a - b).norm() / (a - ns).norm();
    std::cout << "fandisk points, sigma 1, t 16, m 300: t lambda_m " << 16. * lambda_m
              << ", F^10 spectral against local " << difference << " of what the steps change" << std::endl;
    // (measured: 1.0e-5; the local kernel's own tolerance allows far more)
    CHECK_MESSAGE(difference <= 1e-3, "F^10 of the spectral kernel is " << difference << " from the local one's");

    // the balanced operator's guarantees, as on meshes
    const Eigen::SparseMatrix<double>& A = spectral.operator_matrix();
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(Eigen::Index(n));
    const double rows = ((A * ones).array() - 1.).abs().maxCoeff();
    const double columns = ((A.transpose() * ones).array() - 1.).abs().maxCoeff();
    CHECK_MESSAGE(rows <= 1e-12 && columns <= 1e-12, "row sums off by " << rows << ", column sums by " << columns);
    const Eigen::VectorXd constant = spectral.diffuse(3. * ones, 100);
    CHECK(((constant.array() - 3.).abs() <= 1e-12).all());
    CHECK(std::abs(b.sum() - ns.sum()) <= 1e-12 * ns.cwiseAbs().sum());

    // The points' eigenvalues against the mesh's (the same sigma). The fans are the
    // one-rings at 58 % of fandisk's vertices, and their union has more edges than the
    // mesh: the points' L is stiffer, and eigenvalues 2 to 20 differ from the mesh's by
    // up to 18 % (measured; 22 % when the fans could mix the two sides of a crease).
    const HD::Edge_weighted_heat_kernel<Mesh> mesh_kernel(mesh, HD::parameters::sigma(1.).number_of_eigenpairs(20));
    double worst = 0;
    for(Eigen::Index i = 1; i < 20; ++i)
    {
      worst = (std::max)(worst, std::abs(spectral.eigenvalues()[i] / mesh_kernel.eigenvalues()[i] - 1.));
    }
    std::cout << "fandisk, eigenvalues 2 to 20 of the points against the mesh's: largest relative difference "
              << worst << std::endl;
    CHECK_MESSAGE(worst <= 0.3, "the points' eigenvalues differ from the mesh's by up to " << worst);

    // the scale-invariant kernel (eq. 14) selects the spectral kernel by itself
    const Diffusion invariant(points, k, HD::parameters::scale_invariant_kernel(true).number_of_eigenpairs(50));
    CHECK(invariant.kernel_method() == HD::Heat_kernel_method::spectral);
    CHECK(invariant.diffuse(ns, 5).allFinite());

    CHECK_THROWS(Diffusion(points, k, HD::parameters::coarse_vertex_count(500)), std::invalid_argument,
                 "coarse_vertex_count simplifies a mesh");
    CHECK_THROWS(Diffusion(points, k, HD::parameters::number_of_eigenpairs(0)), std::invalid_argument,
                 "number_of_eigenpairs must be positive");
    CHECK_THROWS(Diffusion(points, k,
                           HD::parameters::kernel_method(HD::Heat_kernel_method::local).scale_invariant_kernel(true)),
                 std::invalid_argument, "needs the eigenvalues");
  }
  catch(const std::exception& e)
  {
    std::cerr << "unexpected exception: " << e.what() << std::endl;
    test_support::check(false, "no unexpected exception", __FILE__, __LINE__);
  }
}

const test_support::Suite_registration registration("test_point_set_spectral_kernel", &run);

} // namespace test_point_set_spectral_kernel
