// Copyright (c) 2026 The CGAL Heat_diffusion developers.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Shared by the test programs: checks that count failures instead of aborting (so
// one run reports every failing property) and CGAL's meshes; with mesh_measures.h,
// which the benchmarks share, the noise and the measures.

#ifndef CGAL_HEAT_DIFFUSION_TEST_SUPPORT_H
#define CGAL_HEAT_DIFFUSION_TEST_SUPPORT_H

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include "mesh_measures.h"

#include <Eigen/Sparse>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

namespace test_support {

inline int& failures()
{
  static int count = 0;
  return count;
}
inline int& checks()
{
  static int count = 0;
  return count;
}

inline void check(bool condition, const std::string& what, const char* file, int line)
{
  ++checks();
  if(!condition)
  {
    ++failures();
    std::cerr << file << ":" << line << ": FAILED: " << what << std::endl;
  }
}

// The closing line CTest users see; the exit code tells CTest.
inline int report(const std::string& suite)
{
  std::cout << suite << ": " << (checks() - failures()) << " passed, " << failures() << " failed" << std::endl;
  return failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// Whether the suite is built with the sanitizers (scripts/sanitize_and_fuzz.sh), where
// it runs some 10 times slower (ASan at -O1). There the suites leave out the comparisons
// with test-only baselines and the checks that a smaller mesh runs through the same code
// (armadillo); the release suite runs every case.
#ifdef CGAL_HEAT_DIFFUSION_TEST_UNDER_SANITIZERS
constexpr bool under_sanitizers = true;
#else
constexpr bool under_sanitizers = false;
#endif

inline std::string data_path(const std::string& name)
{
  return std::string(CGAL_HEAT_DIFFUSION_DATA_DIR) + "/" + name;
}

template <typename Mesh>
Mesh load(const std::string& name)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(data_path(name), mesh) || num_faces(mesh) == 0)
    throw std::runtime_error("cannot read the test mesh " + data_path(name));
  return mesh;
}

// Several suites are compiled into one test program (test/Heat_diffusion/CMakeLists.txt:
// CGAL's and the package's templates are then compiled once for all of them), and CTest
// runs each suite in its own process: `program suite`. A suite registers its entry point
// under its name with a namespace-scope `const test_support::Suite_registration`;
// run_suite() reports its checks under that name.
typedef void (*Suite_entry)();

inline std::map<std::string, Suite_entry>& suites()
{
  static std::map<std::string, Suite_entry> registered;
  return registered;
}

struct Suite_registration
{
  Suite_registration(const std::string& name, Suite_entry entry)
  {
    // (two suites of one name: the program would run one of them under both)
    if(!suites().emplace(name, entry).second)
    {
      std::cerr << "two test suites are named " << name << std::endl;
      std::abort();
    }
  }
};

// The test program's main(): runs the suite named by its one argument, then reports.
inline int run_suite(int argc, char** argv)
{
  const auto found = argc == 2 ? suites().find(argv[1]) : suites().end();
  if(found == suites().end())
  {
    std::cerr << "usage: " << (argc > 0 ? argv[0] : "test program") << " SUITE, where SUITE is one of:";
    for(const auto& suite : suites())
      std::cerr << " " << suite.first;
    std::cerr << std::endl;
    return 2;
  }
  found->second();
  return report(found->first);
}

} // namespace test_support

#define CHECK(condition) test_support::check((condition), #condition, __FILE__, __LINE__)
#define CHECK_MESSAGE(condition, message)                                                   \
  do                                                                                        \
  {                                                                                         \
    std::ostringstream check_stream__;                                                      \
    check_stream__ << #condition << " -- " << message;                                      \
    test_support::check((condition), check_stream__.str(), __FILE__, __LINE__);            \
  } while(false)

// Checks that `statement` throws `Exception` whose message contains `fragment`.
#define CHECK_THROWS(statement, Exception, fragment)                                         \
  do                                                                                        \
  {                                                                                         \
    bool thrown__ = false;                                                                  \
    std::string message__;                                                                  \
    try                                                                                     \
    {                                                                                       \
      statement;                                                                            \
    }                                                                                       \
    catch(const Exception& e)                                                               \
    {                                                                                       \
      thrown__ = true;                                                                      \
      message__ = e.what();                                                                 \
    }                                                                                       \
    CHECK_MESSAGE(thrown__ && message__.find(fragment) != std::string::npos,                \
                  "expected " #Exception " containing '" << fragment << "', got '" << message__ << "'"); \
  } while(false)

namespace test_support {

// The product of the diffusion steps (A_t kept by groups of columns,
// internal::Column_group_matrix) against operator_matrix() (compressed columns, each
// column's rows increasing): the same up to rounding, and the same bits on one thread
// as on all of them.
template <typename Diffusion>
void check_diffusion_product(const Diffusion& diffusion, const Eigen::VectorXd& f, const std::string& label)
{
  const Eigen::SparseMatrix<double>& A = diffusion.operator_matrix();
  bool sorted = A.isCompressed();
  for(Eigen::Index j = 0; sorted && j < A.outerSize(); ++j)
    for(Eigen::Index q = A.outerIndexPtr()[j] + 1; sorted && q < A.outerIndexPtr()[j + 1]; ++q)
      sorted = A.innerIndexPtr()[q - 1] < A.innerIndexPtr()[q];
  CHECK_MESSAGE(sorted, label << ": a column of operator_matrix() whose rows are not increasing");
  const Eigen::VectorXd product = A * f;
  const double error = (diffusion.diffuse(f, 1) - product).cwiseAbs().maxCoeff() / f.cwiseAbs().maxCoeff();
  std::cout << label << ": diffuse(f, 1) against operator_matrix() f: " << error << std::endl;
  CHECK_MESSAGE(error <= 1e-13, label << ": diffuse(f, 1) differs from operator_matrix() f by " << error);
#ifdef CGAL_LINKED_WITH_TBB
  const Eigen::VectorXd parallel = diffusion.diffuse(f, 10);
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  CHECK_MESSAGE(diffusion.diffuse(f, 10) == parallel, label << ": F^10 on one thread differs from F^10 on all");
#endif
}

// The properties of the balanced operator (Operator_normalization::balanced) that a
// user checks first: A_t nonnegative, symmetric in pattern and values, every row and
// every column summing to 1; over 1000 steps a constant field stays constant, the
// vertex sum of `f` is conserved, every F^k stays within [min F^0, max F^0], and
// diffusion commutes with adding a constant.
template <typename Diffusion>
void check_balanced_operator(const Diffusion& diffusion, const Eigen::VectorXd& f, const std::string& label)
{
  const Eigen::SparseMatrix<double>& A = diffusion.operator_matrix();
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(A.rows());
  const Eigen::VectorXd row_sums = A * ones, column_sums = A.transpose() * ones;
  const double row_error = (row_sums.array() - 1.).abs().maxCoeff();
  const double column_error = (column_sums.array() - 1.).abs().maxCoeff();
  const Eigen::SparseMatrix<double> transposed = A.transpose();
  const Eigen::SparseMatrix<double> difference = A - transposed;
  double asymmetry = 0;  // relative to the entry, and pattern: an entry without its mirror is a whole entry
  for(Eigen::Index j = 0; j < difference.outerSize(); ++j)
    for(Eigen::SparseMatrix<double>::InnerIterator it(difference, j); it; ++it)
      asymmetry = (std::max)(asymmetry, std::abs(it.value()) /
                                            (std::max)(std::abs(A.coeff(it.row(), j)), std::abs(A.coeff(j, it.row()))));
  std::cout << label << ": balanced A_t, " << diffusion.balancing_iterations() << " balancing iterations, max |row sum - 1| "
            << row_error << ", max |column sum - 1| " << column_error << ", asymmetry " << asymmetry << std::endl;
  CHECK_MESSAGE(row_error <= 1e-13, label << ": max |row sum - 1| = " << row_error);
  CHECK_MESSAGE(column_error <= 1e-13, label << ": max |column sum - 1| = " << column_error);
  CHECK_MESSAGE(A.coeffs().minCoeff() >= 0, label << ": negative entry in A_t");
  CHECK_MESSAGE(asymmetry <= 1e-14, label << ": A_t not symmetric (relative difference " << asymmetry << ")");

  const std::vector<std::size_t> steps = {1, 10, 100, 1000};
  const std::vector<Eigen::VectorXd> constant = diffusion.diffuse(Eigen::VectorXd(7.5 * ones), steps);
  const std::vector<Eigen::VectorXd> fields = diffusion.diffuse(f, steps);
  const double c = 10. * f.cwiseAbs().maxCoeff();
  const std::vector<Eigen::VectorXd> shifted = diffusion.diffuse(Eigen::VectorXd(f.array() + c), steps);
  const double scale = f.cwiseAbs().sum(), range = f.maxCoeff() - f.minCoeff();
  double constant_error = 0, drift = 0, overshoot = 0, shift_error = 0;
  for(std::size_t s = 0; s < steps.size(); ++s)
  {
    constant_error = (std::max)(constant_error, (constant[s].array() / 7.5 - 1.).abs().maxCoeff());
    drift = (std::max)(drift, std::abs(fields[s].sum() - f.sum()) / scale);
    overshoot = (std::max)(overshoot, (std::max)(fields[s].maxCoeff() - f.maxCoeff(), f.minCoeff() - fields[s].minCoeff()));
    shift_error = (std::max)(shift_error, (shifted[s].array() - c - fields[s].array()).abs().maxCoeff() / c);
  }
  std::cout << label << ": over 1000 steps, constant field off by " << constant_error << ", heat drift " << drift
            << ", beyond the initial range by " << overshoot / range << " of it, diffuse(f + c) - c off by "
            << shift_error << " of c" << std::endl;
  CHECK_MESSAGE(constant_error <= 1e-12, label << ": a constant field changes by " << constant_error << " (relative)");
  CHECK_MESSAGE(drift <= 1e-12, label << ": relative heat drift " << drift << " over 1000 steps");
  CHECK_MESSAGE(overshoot <= 1e-13 * range, label << ": F^k leaves [min F^0, max F^0] by " << overshoot);
  CHECK_MESSAGE(shift_error <= 1e-12, label << ": diffuse(f + c) - c differs from diffuse(f) by " << shift_error << " c");
}

} // namespace test_support

#endif // CGAL_HEAT_DIFFUSION_TEST_SUPPORT_H
