# cmake -DCMD=<pseudoshadow> -DSCENE=<roman.toml> -DTRAJ=<roman_crossing.traj> -DDIR=<dir> -P replay_crossing_check.cmake
# A replay of the stroke across the Roman surface's double line (docs/fourd.md): the event log
# has exactly one sheet_crossing, in front (+1), on the double line (x = 20 mm), between the
# contact start and end; the WAV is written; and with fourd_local_model = "nearest" the proxy
# cannot pass through (the other sheet stops it), so no crossing is logged.
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
foreach(model continuity nearest)
  execute_process(COMMAND ${CMD} replay --scene ${SCENE} --log ${TRAJ} --out ${DIR}/${model} --fps 10
                          --set render.size=[64,64] --set "surfaces.0.fourd_local_model=\"${model}\""
                          --audio ${DIR}/${model}.wav -q
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "replay (${model}): exit ${rc}: ${err}")
  endif()
  file(READ "${DIR}/${model}/events.jsonl" log_${model})
  string(REGEX MATCHALL "\"event\":\"sheet_crossing\"[^\n]*" crossings_${model} "${log_${model}}")
endforeach()
message("${log_continuity}")
list(LENGTH crossings_continuity n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "continuity: expected one sheet_crossing, found ${n}")
endif()
if(NOT crossings_continuity MATCHES "\"value\":1,\"pos\":\\[(19\\.[5-9]|20\\.[0-4])")
  message(FATAL_ERROR "continuity: the crossing should be in front (+1) at x = 20 mm: ${crossings_continuity}")
endif()
if(NOT log_continuity MATCHES "contact_start.*sheet_crossing.*contact_end")
  message(FATAL_ERROR "continuity: the crossing should come between contact start and end")
endif()
file(SIZE "${DIR}/continuity.wav" bytes)
if(bytes LESS 48000)  # 1.8 s at 48 kHz, 16 bit: ~170 kB
  message(FATAL_ERROR "continuity.wav: ${bytes} bytes, expected the whole replay's track")
endif()
list(LENGTH crossings_nearest m)
if(NOT m EQUAL 0)
  message(FATAL_ERROR "nearest: expected no crossing (the other sheet stops the proxy), found ${m}")
endif()
