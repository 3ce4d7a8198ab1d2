# A broken shader edit must name file:line: copy glsl/ to OUT, break the line of FILE holding
# NEEDLE (which is line LINE), render
# with PSEUDOSHADOW_GLSL_DIR=OUT and expect a non-zero exit and "FILE:LINE:" in the message.
#   cmake -DEXE=... -DSRC=<glsl dir> -DOUT=<dir> -DFILE=lib/x.glsl -DNEEDLE=text -DLINE=N -P shader_error.cmake
file(REMOVE_RECURSE "${OUT}")
file(COPY "${SRC}/" DESTINATION "${OUT}")
file(READ "${OUT}/${FILE}" _text)
string(FIND "${_text}" "${NEEDLE}" _at)
if(_at LESS 0)
  message(FATAL_ERROR "${FILE} no longer contains \"${NEEDLE}\": update the test")
endif()
string(REPLACE "${NEEDLE}" "${NEEDLE} this_is_not_glsl;" _text "${_text}")
file(WRITE "${OUT}/${FILE}" "${_text}")
set(ENV{PSEUDOSHADOW_GLSL_DIR} "${OUT}")
execute_process(COMMAND "${EXE}" render --size 32x32 --out "${OUT}/x.png" -q
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(rc EQUAL 0 OR NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "expected an error exit, got: ${rc}")
endif()
if(NOT "${err}" MATCHES "${FILE}:${LINE}:")
  message(FATAL_ERROR "the message does not name ${FILE}:${LINE}:")
endif()
