# cmake -DCOMMAND="prog;arg;..." -DLOG=<events.jsonl> -P run_events_check.cmake
# `run` with no audio device: exits 0, prints exactly ONE warning line on stderr (the
# libraries' own complaints suppressed), and its --events log holds a contact_start.
set(ENV{ALSOFT_DRIVERS} alsa)  # with --audio-device ps-no-such-device: a device that cannot open
file(REMOVE "${LOG}")
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "expected exit 0, got ${rc}")
endif()
string(REPLACE ";" "," err_flat "${err}")  # a ";" would split the list below
string(REGEX MATCHALL "[^\n]+" err_lines "${err_flat}")
list(LENGTH err_lines n)
if(NOT n EQUAL 1 OR NOT err MATCHES "^warning: no audio device")
  message(FATAL_ERROR "expected one stderr line 'warning: no audio device ...', got ${n} lines")
endif()
file(STRINGS "${LOG}" events REGEX "\"event\":\"contact_start\"")
if(NOT events)
  message(FATAL_ERROR "${LOG}: no contact_start event")
endif()
