# The CTest case subdirectory_heat_diffusion: configures and builds the project
# CONSUMER_SOURCE_DIR, which adds the package (SOURCE_DIR) with add_subdirectory(),
# and checks that the package behaves as a sub-project should:
#   - it leaves the parent's cache alone: no BUILD_TESTING (ON would build the
#     package's tests, OFF would switch off those of a parent that includes CTest
#     later), no build type (the consumer is configured without one);
#   - it adds no tool, example, test, benchmark, manual or mesh data to the parent's
#     build tree: only the target CGAL::Heat_diffusion (the consumer builds and runs;
#     the optional library CGAL::Heat_diffusion_compiled is not built unless linked);
#   - in a parent that includes CTest, before or after adding the package, the
#     parent's test is the only one.
# Usage: cmake -DSOURCE_DIR=... -DCONSUMER_SOURCE_DIR=... -DWORK_DIR=... [-DGENERATOR=...]
#        [-DCXX_COMPILER=...] -P CGAL_Heat_diffusion_test_subdirectory.cmake
foreach(var SOURCE_DIR CONSUMER_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "CGAL_Heat_diffusion_test_subdirectory.cmake: ${var} is not set")
  endif()
endforeach()

set(generator_args "")
if(GENERATOR)
  set(generator_args -G "${GENERATOR}")
endif()
set(compiler_args "")
if(CXX_COMPILER)
  set(compiler_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "subdirectory_heat_diffusion: ${name} failed (${result})")
  endif()
  message(STATUS "subdirectory_heat_diffusion: ${name}: ok")
endfunction()

set(problems "")
macro(problem text)
  message("subdirectory_heat_diffusion: error: ${text}")
  list(APPEND problems "${text}")
endmacro()

# 1. A parent without CTest and without a build type. Its object file is kept between
#    runs; the configuration is redone from scratch.
set(build "${WORK_DIR}/plain")
file(REMOVE "${build}/CMakeCache.txt")
file(REMOVE_RECURSE "${build}/heat_diffusion" "${build}/data")
run_step("configure the consumer"
  "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE_DIR}" -B "${build}" ${generator_args} ${compiler_args}
  "-DHEAT_DIFFUSION_SOURCE_DIR=${SOURCE_DIR}")

file(STRINGS "${build}/CMakeCache.txt" cache_build_testing REGEX "^BUILD_TESTING:")
if(cache_build_testing)
  problem("the parent's cache has ${cache_build_testing}, but the parent does not use CTest")
endif()
file(STRINGS "${build}/CMakeCache.txt" cache_build_type REGEX "^CMAKE_BUILD_TYPE:")
if(cache_build_type AND NOT cache_build_type MATCHES "=$")
  problem("the parent's cache has ${cache_build_type}, but the parent set no build type")
endif()

# The binary folders of the package's parts exist only if they were added.
foreach(part tools examples test benchmark doc data)
  if(EXISTS "${build}/heat_diffusion/${part}")
    problem("the package added ${part}/ to the parent's build tree (${build}/heat_diffusion/${part})")
  endif()
endforeach()
if(EXISTS "${build}/data")
  problem("the package unpacked mesh data into the parent's build tree (${build}/data)")
endif()

execute_process(COMMAND "${CMAKE_CTEST_COMMAND}" -N WORKING_DIRECTORY "${build}"
                OUTPUT_VARIABLE ctest_list RESULT_VARIABLE ctest_result)
if(ctest_list MATCHES "Total Tests: ([0-9]+)" AND NOT CMAKE_MATCH_1 EQUAL 0)
  problem("the parent has no test, but ctest lists ${CMAKE_MATCH_1}:\n${ctest_list}")
endif()

if(problems)
  list(LENGTH problems count)
  message(FATAL_ERROR "subdirectory_heat_diffusion: ${count} problem(s) after configuring")
endif()

# Builds everything the parent's build builds: the consumer only.
run_step("build the consumer" "${CMAKE_COMMAND}" --build "${build}")
file(GLOB_RECURSE built_programs LIST_DIRECTORIES false
     "${build}/heat_diffusion" "${build}/*_example" "${build}/test_*" "${build}/benchmark_*"
     "${build}/*Heat_diffusion_compiled.a")
foreach(f IN LISTS built_programs)
  if(NOT IS_DIRECTORY "${f}" AND NOT f MATCHES "\\.(cmake|txt|make|o|d|marks|includecache|internal|json)$")
    problem("the parent's build made a program of the package: ${f}")
  endif()
endforeach()
find_program(consumer subdirectory_consumer PATHS "${build}" "${build}/Debug" NO_DEFAULT_PATH NO_CACHE)
if(NOT consumer)
  message(FATAL_ERROR "subdirectory_heat_diffusion: the consumer program was not built")
endif()
run_step("run the consumer" "${consumer}")

# 2. A parent that includes CTest, before or after adding the package: its own test
#    is the only one, and is there (configured only).
foreach(when BEFORE AFTER)
  set(build "${WORK_DIR}/ctest_${when}")
  file(REMOVE_RECURSE "${build}")
  run_step("configure the consumer with CTest ${when} the package"
    "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE_DIR}" -B "${build}" ${generator_args} ${compiler_args}
    "-DHEAT_DIFFUSION_SOURCE_DIR=${SOURCE_DIR}" -DCONSUMER_USES_CTEST=${when})
  execute_process(COMMAND "${CMAKE_CTEST_COMMAND}" -N WORKING_DIRECTORY "${build}" OUTPUT_VARIABLE ctest_list)
  if(NOT ctest_list MATCHES "Total Tests: 1\n" OR NOT ctest_list MATCHES "subdirectory_consumer")
    problem("with CTest ${when} the package, the parent has one test, subdirectory_consumer, but ctest lists:\n${ctest_list}")
  endif()
  if(EXISTS "${build}/data")
    problem("the package unpacked mesh data into the parent's build tree (${build}/data)")
  endif()
endforeach()

if(problems)
  list(LENGTH problems count)
  message(FATAL_ERROR "subdirectory_heat_diffusion: ${count} problem(s)")
endif()
message("subdirectory_heat_diffusion: the package added only CGAL::Heat_diffusion")
