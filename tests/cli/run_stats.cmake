# cmake -DXVFB=xvfb-run -DEXE=pseudoshadow -DTRAJ=stroke.traj -DOUT=dir -P run_stats.cmake
# `run` shares render's --size and --stats: a scripted window session of 3 frames at 64x48
# exits 0 and writes the last frame's stats as JSON (the same fields as `render --stats`).
file(REMOVE ${OUT}/run_stats.json)
execute_process(COMMAND ${XVFB} -a ${EXE} run --device trajectory:${TRAJ} --frames 3 --size 64x48
                        --stats ${OUT}/run_stats.json -q
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "expected exit 0, got ${rc}")
endif()
file(READ ${OUT}/run_stats.json json)
foreach(field backend gl_renderer max_penetration timings_ms)
  if(NOT json MATCHES "\"${field}\"")
    message(FATAL_ERROR "stats lack \"${field}\":\n${json}")
  endif()
endforeach()
