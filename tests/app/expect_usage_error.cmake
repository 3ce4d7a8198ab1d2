# Runs `CMD bench --no-such-option` and requires exit status 2 and a message naming it.
execute_process(COMMAND ${CMD} bench --no-such-option RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "expected exit status 2, got ${rc}")
endif()
if(NOT err MATCHES "unknown option '--no-such-option'")
  message(FATAL_ERROR "unexpected message: ${err}")
endif()
