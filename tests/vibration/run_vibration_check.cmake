# cmake -DCOMMAND="prog;arg;..." -P run_vibration_check.cmake
# `run --vibration-out sound` on OpenAL Soft's null device (mixes in real time, plays nothing)
# with the scripted stroke: exits 0 and its summary's vibration line names the device and the
# measured latency of the ticks it sent.
set(ENV{ALSOFT_DRIVERS} null)
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "expected exit 0, got ${rc}")
endif()
if(NOT out MATCHES "vibration: sound on 'No Output'; [1-9][0-9]* ticks; latency tick -> sample out of OpenAL ms p50 [0-9.]+ p99 [0-9.]+ max [0-9.]+ \\([1-9][0-9]* ticks measured\\)")
  message(FATAL_ERROR "no vibration line with measured latency in run's summary")
endif()
