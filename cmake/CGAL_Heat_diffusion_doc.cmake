# The user manual and reference (Doxygen): target `doc` and the CTest case
# `doc_heat_diffusion`, which fails on any Doxygen warning (WARN_AS_ERROR =
# FAIL_ON_WARNINGS in doc/Heat_diffusion/Doxyfile.in). Included by the top-level
# CMakeLists.txt.
find_package(Doxygen QUIET)
# The check of undocumented members reads Doxygen's XML with Python.
find_program(CGAL_HEAT_DIFFUSION_PYTHON NAMES python3 python)

set(CGAL_HEAT_DIFFUSION_SOURCE_DIR "${PROJECT_SOURCE_DIR}")
set(CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR "${PROJECT_BINARY_DIR}/doc/Heat_diffusion")
configure_file("${PROJECT_SOURCE_DIR}/doc/Heat_diffusion/Doxyfile.in"
               "${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}/Doxyfile" @ONLY)

if(DOXYGEN_FOUND)
  add_custom_target(doc
    COMMAND "${DOXYGEN_EXECUTABLE}" "${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}/Doxyfile"
    COMMAND "${CMAKE_COMMAND}" -E echo
            "Manual: ${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}/html/index.html"
    WORKING_DIRECTORY "${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}"
    COMMENT "Building the Heat_diffusion manual and reference with Doxygen"
    VERBATIM)
  if(CGAL_HEAT_DIFFUSION_TESTING)
    # Runs doxygen (non-zero at the end of the run when it printed a warning), then
    # checks groups and examples (see the script).
    add_test(NAME doc_heat_diffusion
             COMMAND "${CMAKE_COMMAND}" "-DDOXYGEN=${DOXYGEN_EXECUTABLE}"
                     "-DDOXYFILE=${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}/Doxyfile"
                     "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
                     "-DPYTHON=${CGAL_HEAT_DIFFUSION_PYTHON}"
                     -P "${CMAKE_CURRENT_LIST_DIR}/CGAL_Heat_diffusion_check_doc.cmake")
    # Also catches the warnings of a Doxygen that does not return an error.
    set_tests_properties(doc_heat_diffusion PROPERTIES
      FAIL_REGULAR_EXPRESSION "[Ww]arning:;[Ee]rror:"
      LABELS doc)
  endif()
else()
  message(STATUS "Heat_diffusion: doxygen not found, no `doc` target (Debian: doxygen)")
  add_custom_target(doc
    COMMAND "${CMAKE_COMMAND}" -E echo "doxygen not found (Debian: apt-get install doxygen)"
    COMMAND "${CMAKE_COMMAND}" -E false
    VERBATIM)
  if(CGAL_HEAT_DIFFUSION_TESTING)
    # Reported as "Skipped" by CTest, not passed: the reference was not checked.
    add_test(NAME doc_heat_diffusion
             COMMAND "${CMAKE_COMMAND}" -E echo "doxygen not found (Debian: doxygen): reference not checked")
    set_tests_properties(doc_heat_diffusion PROPERTIES SKIP_REGULAR_EXPRESSION "doxygen not found" LABELS doc)
  endif()
endif()
