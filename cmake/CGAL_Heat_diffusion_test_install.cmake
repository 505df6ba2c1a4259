# The CTest case install_heat_diffusion: installs the package from BINARY_DIR into a
# fresh prefix under WORK_DIR, then configures, builds and runs the consumer project
# CONSUMER_SOURCE_DIR with find_package(CGAL_Heat_diffusion) against that prefix only.
foreach(var BINARY_DIR CONSUMER_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "CGAL_Heat_diffusion_test_install.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()

set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/consumer_build")
file(REMOVE_RECURSE "${prefix}")
# Keep the consumer's build folder between runs (its object file): only the
# package configuration and headers are tested anew, and the build is incremental.
file(REMOVE "${consumer_build}/CMakeCache.txt")

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "install_heat_diffusion: ${name} failed (${result})")
  endif()
  message(STATUS "install_heat_diffusion: ${name}: ok")
endfunction()

run_step("cmake --install" "${CMAKE_COMMAND}" --install "${BINARY_DIR}" --prefix "${prefix}")

foreach(f include/CGAL/Heat_diffusion.h
          include/CGAL/Heat_diffusion/normal_controlled_coordinates.h
          include/CGAL/Heat_diffusion/internal
          share/CGAL_Heat_diffusion/cmake/CGAL_Heat_diffusionConfig.cmake
          share/CGAL_Heat_diffusion/cmake/CGAL_Heat_diffusionConfigVersion.cmake
          share/CGAL_Heat_diffusion/cmake/CGAL_Heat_diffusionTargets.cmake)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "install_heat_diffusion: ${prefix}/${f} was not installed")
  endif()
endforeach()

# The Python module, when it is built: installed under the prefix, and imported from
# there (not from the build tree) by the interpreter it was built for.
if(PYTHON)
  file(GLOB python_module "${prefix}/${PYTHON_MODULE_DIR}/cgal_heat_diffusion*")
  if(NOT python_module)
    message(FATAL_ERROR "install_heat_diffusion: the Python module was not installed into ${prefix}/${PYTHON_MODULE_DIR}")
  endif()
  run_step("import the installed Python module"
    "${CMAKE_COMMAND}" -E env "PYTHONPATH=${prefix}/${PYTHON_MODULE_DIR}" PYTHONDONTWRITEBYTECODE=1
    "${PYTHON}" -c "import os, sys, numpy as np, cgal_heat_diffusion as hd
assert os.path.realpath(hd.__file__).startswith(os.path.realpath(sys.argv[1])), hd.__file__
V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
assert np.all(np.isfinite(hd.normal_signature(V, F)))" "${prefix}")
endif()

set(generator_args "")
if(GENERATOR)
  set(generator_args -G "${GENERATOR}")
endif()
set(compiler_args "")
if(CXX_COMPILER)
  set(compiler_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif()
# The consumer must find the installed copy: the prefix is the only hint, and the
# package registry is not searched.
run_step("configure the consumer"
  "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE_DIR}" -B "${consumer_build}" ${generator_args} ${compiler_args}
  "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
  "-DCMAKE_PREFIX_PATH=${prefix}"
  "-DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF"
  "-DEXPECTED_PREFIX=${prefix}")
run_step("build the consumer" "${CMAKE_COMMAND}" --build "${consumer_build}" --config "${BUILD_TYPE}")

find_program(consumer heat_diffusion_consumer PATHS "${consumer_build}" "${consumer_build}/${BUILD_TYPE}" NO_DEFAULT_PATH)
if(NOT consumer)
  message(FATAL_ERROR "install_heat_diffusion: the consumer program was not built")
endif()
set(mesh_args "")
if(MESH AND EXISTS "${MESH}")
  set(mesh_args "${MESH}")
endif()
run_step("run the consumer" "${consumer}" ${mesh_args})
