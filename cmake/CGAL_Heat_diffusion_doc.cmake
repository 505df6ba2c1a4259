# The user manual and reference (Doxygen): target `doc` and the CTest cases
# `doc_heat_diffusion`, which fails on any Doxygen warning (WARN_AS_ERROR =
# FAIL_ON_WARNINGS in doc/Heat_diffusion/Doxyfile.in), and
# `doc_heat_diffusion_in_browser`, which opens every page in headless Chromium, offline,
# and checks what a reader sees. Included by the top-level CMakeLists.txt.
find_package(Doxygen QUIET)
# The check of undocumented members reads Doxygen's XML with Python.
find_program(CGAL_HEAT_DIFFUSION_PYTHON NAMES python3 python)

set(CGAL_HEAT_DIFFUSION_SOURCE_DIR "${PROJECT_SOURCE_DIR}")
set(CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR "${PROJECT_BINARY_DIR}/doc/Heat_diffusion")
# MathJax goes with the manual (html/mathjax, see CGAL_Heat_diffusion_doc_mathjax.cmake),
# so that its formulas render without network access; without a MathJax 2 here, the
# manual loads MathJax from a web CDN.
find_path(CGAL_HEAT_DIFFUSION_MATHJAX_DIR MathJax.js
          PATHS /usr/share/javascript/mathjax /usr/share/mathjax
          DOC "MathJax 2, copied into the manual (Debian: libjs-mathjax)")
if(CGAL_HEAT_DIFFUSION_MATHJAX_DIR)
  set(CGAL_HEAT_DIFFUSION_MATHJAX_RELPATH "mathjax")
else()
  set(CGAL_HEAT_DIFFUSION_MATHJAX_RELPATH "https://cdn.jsdelivr.net/npm/mathjax@2")
  if(DOXYGEN_FOUND)
    message(STATUS "Heat_diffusion: MathJax not found (Debian: libjs-mathjax): "
                   "the manual's formulas will need the network")
  endif()
endif()
configure_file("${PROJECT_SOURCE_DIR}/doc/Heat_diffusion/Doxyfile.in"
               "${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}/Doxyfile" @ONLY)

if(DOXYGEN_FOUND)
  set(copy_mathjax "")
  if(CGAL_HEAT_DIFFUSION_MATHJAX_DIR)
    set(copy_mathjax COMMAND "${CMAKE_COMMAND}" "-DMATHJAX_DIR=${CGAL_HEAT_DIFFUSION_MATHJAX_DIR}"
                             "-DHTML_DIR=${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}/html"
                             -P "${CMAKE_CURRENT_LIST_DIR}/CGAL_Heat_diffusion_doc_mathjax.cmake")
  endif()
  add_custom_target(doc
    COMMAND "${DOXYGEN_EXECUTABLE}" "${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}/Doxyfile"
    ${copy_mathjax}
    COMMAND "${CMAKE_COMMAND}" -E echo
            "Manual: ${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}/html/index.html"
    WORKING_DIRECTORY "${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}"
    COMMENT "Building the Heat_diffusion manual and reference with Doxygen"
    VERBATIM)
  if(CGAL_HEAT_DIFFUSION_TESTING)
    # Runs doxygen (non-zero at the end of the run when it printed a warning), copies
    # MathJax beside the pages, then checks groups, examples, undocumented members and
    # the umbrella header (see the script).
    add_test(NAME doc_heat_diffusion
             COMMAND "${CMAKE_COMMAND}" "-DDOXYGEN=${DOXYGEN_EXECUTABLE}"
                     "-DDOXYFILE=${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}/Doxyfile"
                     "-DSOURCE_DIR=${PROJECT_SOURCE_DIR}"
                     "-DMATHJAX_DIR=${CGAL_HEAT_DIFFUSION_MATHJAX_DIR}"
                     "-DPYTHON=${CGAL_HEAT_DIFFUSION_PYTHON}"
                     -P "${CMAKE_CURRENT_LIST_DIR}/CGAL_Heat_diffusion_check_doc.cmake")
    # Also catches the warnings of a Doxygen that does not return an error. It builds
    # the pages that doc_heat_diffusion_in_browser opens (fixture).
    set_tests_properties(doc_heat_diffusion PROPERTIES
      FAIL_REGULAR_EXPRESSION "[Ww]arning:;[Ee]rror:"
      FIXTURES_SETUP heat_diffusion_doc_html
      RESOURCE_LOCK heat_diffusion_doc_html
      LABELS doc)

    # Every page of the manual opened in headless Chromium without network access: no
    # formula left as raw TeX, no broken image, no missing file, no JavaScript error
    # (see the script). A screenshot of the first page goes to the test's folder. The
    # script reports "skipped" (77) when Chromium is not installed: the manual was
    # then not looked at.
    find_package(Python3 COMPONENTS Interpreter QUIET)
    set(browser_test_dir "${PROJECT_BINARY_DIR}/test/doc_heat_diffusion_in_browser")
    if(Python3_Interpreter_FOUND)
      add_test(NAME doc_heat_diffusion_in_browser
               COMMAND "${Python3_EXECUTABLE}"
                       "${CMAKE_CURRENT_LIST_DIR}/CGAL_Heat_diffusion_check_doc_in_browser.py"
                       "${CGAL_HEAT_DIFFUSION_DOC_OUTPUT_DIR}/html" "${browser_test_dir}")
      set_tests_properties(doc_heat_diffusion_in_browser PROPERTIES
        FIXTURES_REQUIRED heat_diffusion_doc_html
        SKIP_RETURN_CODE 77
        TIMEOUT 300
        LABELS doc)
    else()
      add_test(NAME doc_heat_diffusion_in_browser
               COMMAND "${CMAKE_COMMAND}" -E echo "python3 not found: the manual was not checked in a browser")
      set_tests_properties(doc_heat_diffusion_in_browser PROPERTIES
        SKIP_REGULAR_EXPRESSION "python3 not found" LABELS doc)
    endif()
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
