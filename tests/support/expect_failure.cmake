# cmake -DCOMMAND="prog;arg;..." -DEXPECT_REGEX=<regex> [-DENV="NAME=value;..."] -P expect_failure.cmake
# Passes only if COMMAND exits non-zero (not by a crash signal) AND its output matches
# EXPECT_REGEX. ctest's WILL_FAIL alone would also pass on a crash, and PASS_REGULAR_EXPRESSION
# alone ignores the exit status.
foreach(_kv ${ENV})  # optional environment for the command, e.g. -DENV=PSEUDOSHADOW_GLSL_DIR=/x
  string(REGEX MATCH "^[^=]+" _k "${_kv}")
  string(REGEX REPLACE "^[^=]+=" "" _v "${_kv}")
  set(ENV{${_k}} "${_v}")
endforeach()
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(rc EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit, got 0")
endif()
if(NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "expected an error exit, got: ${rc}")
endif()
if(NOT "${out}${err}" MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "output does not match \"${EXPECT_REGEX}\"")
endif()
