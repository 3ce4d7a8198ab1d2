# expect_render(STATUS REGEX ARGS...): runs `EXE render --size 16 --out out.png -q ARGS` in WORK
# and fails unless it exits STATUS and its output matches REGEX; output matching FORBID (when
# the including script sets it) fails too. Included by the path tests.
function(expect_render status regex)
  execute_process(COMMAND ${EXE} render --size 16 --out out.png -q ${ARGN}
                  WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("render ${ARGN} -> ${rc}: ${out}${err}")
  if(NOT "${rc}" STREQUAL "${status}")
    message(FATAL_ERROR "render ${ARGN}: expected exit status ${status}, got ${rc}")
  endif()
  if(NOT "${out}${err}" MATCHES "${regex}")
    message(FATAL_ERROR "render ${ARGN}: output does not match \"${regex}\"")
  endif()
  if(DEFINED FORBID AND "${out}${err}" MATCHES "${FORBID}")
    message(FATAL_ERROR "render ${ARGN}: the output matches \"${FORBID}\", which it must not quote")
  endif()
endfunction()
