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

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

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

#endif // CGAL_HEAT_DIFFUSION_TEST_SUPPORT_H
