# Installation: `cmake --install build --prefix P` installs the public headers
# (include/CGAL/Heat_diffusion, internal/ included), the manual when it was built
# (share/doc/CGAL_Heat_diffusion/html), the Python module when it is built
# (python/Heat_diffusion/CMakeLists.txt) and the CMake package config, so
# that a separate project can use
#   find_package(CGAL_Heat_diffusion)
#   target_link_libraries(my_program PRIVATE CGAL::Heat_diffusion)
# with CMAKE_PREFIX_PATH=P. The CTest case install_heat_diffusion proves it with the
# consumer project test/Heat_diffusion/install_consumer/. Included by the top-level
# CMakeLists.txt, after the target Heat_diffusion is defined.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(CGAL_HEAT_DIFFUSION_INSTALL_CMAKEDIR "${CMAKE_INSTALL_DATADIR}/CGAL_Heat_diffusion/cmake"
    CACHE STRING "Where the CMake package config of CGAL Heat_diffusion is installed (relative to the prefix)")

install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/CGAL/Heat_diffusion"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/CGAL"
        FILES_MATCHING PATTERN "*.h")
# The umbrella header, which includes the whole public API.
install(FILES "${PROJECT_SOURCE_DIR}/include/CGAL/Heat_diffusion.h"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/CGAL")

# The manual, if built (target doc, or the CTest case doc_heat_diffusion): its pages
# carry MathJax in html/mathjax, so that the installed copy renders its formulas
# offline, on any machine it is copied to.
install(DIRECTORY "${PROJECT_BINARY_DIR}/doc/Heat_diffusion/html/"
        DESTINATION "${CMAKE_INSTALL_DOCDIR}/html"
        OPTIONAL COMPONENT doc)

install(TARGETS Heat_diffusion EXPORT CGAL_Heat_diffusionTargets)
install(EXPORT CGAL_Heat_diffusionTargets
        NAMESPACE CGAL::
        DESTINATION "${CGAL_HEAT_DIFFUSION_INSTALL_CMAKEDIR}")

# What the package was configured with, for find_dependency() in the config.
set(CGAL_HEAT_DIFFUSION_CONFIG_WITH_TBB OFF)
if(CGAL_HEAT_DIFFUSION_WITH_TBB AND TARGET CGAL::TBB_support)
  set(CGAL_HEAT_DIFFUSION_CONFIG_WITH_TBB ON)
endif()
set(CGAL_HEAT_DIFFUSION_CONFIG_WITH_CHOLMOD OFF)
if(CGAL_HEAT_DIFFUSION_WITH_CHOLMOD AND CHOLMOD_INCLUDE_DIR AND CHOLMOD_LIBRARY)
  set(CGAL_HEAT_DIFFUSION_CONFIG_WITH_CHOLMOD ON)
endif()

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/CGAL_Heat_diffusionConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/cmake/CGAL_Heat_diffusionConfig.cmake"
  INSTALL_DESTINATION "${CGAL_HEAT_DIFFUSION_INSTALL_CMAKEDIR}"
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR)
# Header-only: the version file does not check the architecture.
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/cmake/CGAL_Heat_diffusionConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion
  ARCH_INDEPENDENT)
install(FILES "${PROJECT_BINARY_DIR}/cmake/CGAL_Heat_diffusionConfig.cmake"
              "${PROJECT_BINARY_DIR}/cmake/CGAL_Heat_diffusionConfigVersion.cmake"
        DESTINATION "${CGAL_HEAT_DIFFUSION_INSTALL_CMAKEDIR}")

# The CTest case: install into a temporary prefix, configure, build and run the
# consumer project against the installed copy (not this source tree).
if(CGAL_HEAT_DIFFUSION_TESTING)
  add_test(NAME install_heat_diffusion
           COMMAND "${CMAKE_COMMAND}"
                   "-DBINARY_DIR=${PROJECT_BINARY_DIR}"
                   "-DCONSUMER_SOURCE_DIR=${PROJECT_SOURCE_DIR}/test/Heat_diffusion/install_consumer"
                   "-DWORK_DIR=${PROJECT_BINARY_DIR}/test/install_heat_diffusion"
                   "-DBUILD_TYPE=$<IF:$<CONFIG:>,${CMAKE_BUILD_TYPE},$<CONFIG>>"
                   "-DGENERATOR=${CMAKE_GENERATOR}"
                   "-DCXX_COMPILER=${CMAKE_CXX_COMPILER}"
                   "-DMESH=${CGAL_HEAT_DIFFUSION_DATA_DIR}/fandisk.off"
                   "-DPYTHON=$<$<BOOL:${CGAL_HEAT_DIFFUSION_BUILD_PYTHON}>:${Python3_EXECUTABLE}>"
                   "-DPYTHON_MODULE_DIR=${CGAL_HEAT_DIFFUSION_INSTALL_PYTHONDIR}"
                   -P "${CMAKE_CURRENT_LIST_DIR}/CGAL_Heat_diffusion_test_install.cmake")
  # Not while doc_heat_diffusion rewrites the manual's pages, which it installs.
  set_tests_properties(install_heat_diffusion PROPERTIES LABELS install TIMEOUT 900
                       RESOURCE_LOCK heat_diffusion_doc_html)
endif()
