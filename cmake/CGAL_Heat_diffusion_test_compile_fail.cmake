# The CTest cases that check a compile-time error: builds TARGET in BINARY_DIR and
# passes if the build fails with exactly the errors whose messages EXPECTED lists
# (one per error, separated by '|'), so that a wrong named parameter gives a message
# that names it, not pages of template errors.
# Usage: cmake -DBINARY_DIR=... -DTARGET=... -DEXPECTED=... -P CGAL_Heat_diffusion_test_compile_fail.cmake
foreach(var BINARY_DIR TARGET EXPECTED)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "CGAL_Heat_diffusion_test_compile_fail.cmake: ${var} is not set")
  endif()
endforeach()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BINARY_DIR}" --target "${TARGET}"
                OUTPUT_VARIABLE output ERROR_VARIABLE output RESULT_VARIABLE result)
if(result EQUAL 0)
  message(FATAL_ERROR "${TARGET}: compiled, but it must not:\n${output}")
endif()
string(REPLACE "|" ";" expected "${EXPECTED}")
set(missing 0)
foreach(message IN LISTS expected)
  string(FIND "${output}" "${message}" found)
  if(found EQUAL -1)
    message("${TARGET}: the compiler did not say: ${message}")
    math(EXPR missing "${missing} + 1")
  endif()
endforeach()
string(REGEX MATCHALL "error:" errors "${output}")
list(LENGTH errors error_count)
list(LENGTH expected expected_count)
if(missing GREATER 0 OR NOT error_count EQUAL expected_count)
  message(FATAL_ERROR "${TARGET}: ${error_count} error(s), expected the ${expected_count} above:\n${output}")
endif()
message("${TARGET}: failed to compile, as it must, with the ${expected_count} expected message(s)")
