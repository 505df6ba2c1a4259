# The CTest case doc_heat_diffusion: builds the manual and reference with Doxygen,
# which fails on any warning (WARN_AS_ERROR = FAIL_ON_WARNINGS), then checks what
# Doxygen does not warn about:
#   - every `\ingroup G` of the manual and the public headers names a `\defgroup G`
#     (Doxygen silently drops the free functions of an unknown group);
#   - every `\cgalExample{F}` names a file of examples/;
#   - every example of examples/Heat_diffusion/ is quoted by the manual (\cgalExample);
#   - every public class and member of include/CGAL/ is documented: Doxygen drops an
#     undocumented one from the reference without a warning (HIDE_UNDOC_MEMBERS), so a
#     second run with EXTRACT_ALL writes the XML of everything, which
#     CGAL_Heat_diffusion_undocumented.py (PYTHON) reads;
#   - the umbrella header CGAL/Heat_diffusion.h includes every public header, and
#     nothing of internal/.
# With MATHJAX_DIR set (not empty), MathJax is copied beside the pages after the first
# run, as the target `doc` does (CGAL_Heat_diffusion_doc_mathjax.cmake).
# Usage: cmake -DDOXYGEN=... -DDOXYFILE=... -DSOURCE_DIR=... -DPYTHON=... [-DMATHJAX_DIR=...]
#              -P CGAL_Heat_diffusion_check_doc.cmake
foreach(var DOXYGEN DOXYFILE SOURCE_DIR PYTHON)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "CGAL_Heat_diffusion_check_doc.cmake: ${var} is not set")
  endif()
endforeach()

get_filename_component(doc_output_dir "${DOXYFILE}" DIRECTORY)
execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}"
                WORKING_DIRECTORY "${doc_output_dir}"
                RESULT_VARIABLE doxygen_result)
set(problems 0)
if(NOT doxygen_result EQUAL 0)
  message("error: doxygen failed (${doxygen_result}): see the warnings above")
  math(EXPR problems "${problems} + 1")
endif()
if(MATHJAX_DIR)
  set(HTML_DIR "${doc_output_dir}/html")
  include("${CMAKE_CURRENT_LIST_DIR}/CGAL_Heat_diffusion_doc_mathjax.cmake")
endif()

file(GLOB doc_files "${SOURCE_DIR}/doc/Heat_diffusion/*.txt" "${SOURCE_DIR}/doc/Heat_diffusion/Concepts/*.h")
file(GLOB header_files "${SOURCE_DIR}/include/CGAL/Heat_diffusion/*.h")
set(defined_groups "")
set(used_groups "")
set(quoted_examples "")
foreach(f IN LISTS doc_files header_files)
  file(STRINGS "${f}" lines REGEX "[\\@](defgroup|ingroup|cgalExample)")
  foreach(line IN LISTS lines)
    if(line MATCHES "[\\@]defgroup[ \t]+([A-Za-z0-9_]+)")
      list(APPEND defined_groups "${CMAKE_MATCH_1}")
    endif()
    if(line MATCHES "[\\@]ingroup[ \t]+([A-Za-z0-9_]+)")
      list(APPEND used_groups "${CMAKE_MATCH_1}|${f}")
    endif()
    if(line MATCHES "[\\@]cgalExample{([^}]+)}")
      list(APPEND quoted_examples "${CMAKE_MATCH_1}")
      if(NOT EXISTS "${SOURCE_DIR}/examples/${CMAKE_MATCH_1}")
        message("${f}: warning: \\cgalExample{${CMAKE_MATCH_1}}: no such file in examples/")
        math(EXPR problems "${problems} + 1")
      endif()
    endif()
  endforeach()
endforeach()

foreach(use IN LISTS used_groups)
  string(REPLACE "|" ";" use "${use}")
  list(GET use 0 group)
  list(GET use 1 file)
  list(FIND defined_groups "${group}" found)
  if(found EQUAL -1)
    message("${file}: warning: \\ingroup ${group}: the group is not defined "
            "(add a \\defgroup to doc/Heat_diffusion/PackageDescription.txt)")
    math(EXPR problems "${problems} + 1")
  endif()
endforeach()

file(GLOB examples RELATIVE "${SOURCE_DIR}/examples" "${SOURCE_DIR}/examples/Heat_diffusion/*.cpp")
foreach(example IN LISTS examples)
  list(FIND quoted_examples "${example}" found)
  if(found EQUAL -1)
    message("${SOURCE_DIR}/examples/${example}: warning: the manual does not quote this example "
            "(add \\cgalExample{${example}} to doc/Heat_diffusion/Heat_diffusion.txt)")
    math(EXPR problems "${problems} + 1")
  endif()
endforeach()

# Everything public is documented.
set(all_doxyfile "${doc_output_dir}/Doxyfile_extract_all")
file(WRITE "${all_doxyfile}" "@INCLUDE = \"${DOXYFILE}\"
EXTRACT_ALL = YES
HIDE_UNDOC_MEMBERS = NO
HIDE_UNDOC_CLASSES = NO
GENERATE_HTML = NO
GENERATE_XML = YES
XML_OUTPUT = xml_extract_all
GENERATE_TAGFILE =
WARNINGS = NO
WARN_AS_ERROR = NO
")
file(REMOVE_RECURSE "${doc_output_dir}/xml_extract_all")
execute_process(COMMAND "${DOXYGEN}" "${all_doxyfile}" WORKING_DIRECTORY "${doc_output_dir}"
                RESULT_VARIABLE doxygen_result)
if(NOT doxygen_result EQUAL 0)
  message("error: doxygen (EXTRACT_ALL) failed (${doxygen_result})")
  math(EXPR problems "${problems} + 1")
endif()
execute_process(COMMAND "${PYTHON}" "${CMAKE_CURRENT_LIST_DIR}/CGAL_Heat_diffusion_undocumented.py"
                        "${doc_output_dir}/xml_extract_all" "${SOURCE_DIR}/include"
                RESULT_VARIABLE undocumented_result)
if(NOT undocumented_result EQUAL 0)
  message("error: public classes or members without documentation (see above)")
  math(EXPR problems "${problems} + 1")
endif()

# The umbrella header includes the public headers, and only them.
set(umbrella "${SOURCE_DIR}/include/CGAL/Heat_diffusion.h")
if(NOT EXISTS "${umbrella}")
  message("${umbrella}: warning: the umbrella header is missing")
  math(EXPR problems "${problems} + 1")
else()
  file(STRINGS "${umbrella}" umbrella_includes REGEX "^#include <CGAL/Heat_diffusion/")
  foreach(header IN LISTS header_files)
    get_filename_component(header_name "${header}" NAME)
    list(FIND umbrella_includes "#include <CGAL/Heat_diffusion/${header_name}>" found)
    if(found EQUAL -1)
      message("${umbrella}: warning: does not include the public header CGAL/Heat_diffusion/${header_name}")
      math(EXPR problems "${problems} + 1")
    endif()
  endforeach()
  foreach(line IN LISTS umbrella_includes)
    if(line MATCHES "/internal/")
      message("${umbrella}: warning: includes an internal header: ${line}")
      math(EXPR problems "${problems} + 1")
    endif()
  endforeach()
endif()

if(problems GREATER 0)
  message(FATAL_ERROR "doc_heat_diffusion: ${problems} problem(s)")
endif()
message("doc_heat_diffusion: no warning; manual in ${doc_output_dir}/html/index.html")
