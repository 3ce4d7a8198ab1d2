# cmake -DCOMMAND="prog;arg;..." -DEXPECT_EXIT=<status> -DEXPECT_REGEX=<regex> [-DINPUT=file] -P expect_exit.cmake
# Passes only if COMMAND exits with exactly EXPECT_EXIT (a crash gives a non-number) and its
# stdout+stderr match EXPECT_REGEX: the exit status is part of the CLI's contract (0 ok,
# 1 runtime error, 2 usage error), so a message that is right under the wrong status fails.
if(INPUT)
  execute_process(COMMAND ${COMMAND} INPUT_FILE ${INPUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
else()
  execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
endif()
message("${out}${err}")
if(NOT "${rc}" STREQUAL "${EXPECT_EXIT}")
  message(FATAL_ERROR "expected exit status ${EXPECT_EXIT}, got ${rc}")
endif()
if(NOT "${out}${err}" MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "output does not match \"${EXPECT_REGEX}\"")
endif()
