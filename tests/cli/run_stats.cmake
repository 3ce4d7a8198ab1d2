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
# The window bakes the Gabor tile between frames (docs/architecture.md, "When tiles bake"): its
# first frame is drawn before the tile is ready, whatever the machine's speed.
foreach(field first_frame_ms gabor_bake_ms gabor_bake_progress frames_before_tiles)
  string(JSON value ERROR_VARIABLE missing GET "${json}" ${field})
  if(missing)
    message(FATAL_ERROR "stats lack \"${field}\":\n${json}")
  endif()
endforeach()
string(JSON first GET "${json}" first_frame_ms)
string(JSON ready_type TYPE "${json}" gabor_tiles_ready_ms)
string(JSON before GET "${json}" frames_before_tiles)
if(before LESS 1)
  message(FATAL_ERROR "the window drew no frame before its Gabor tile was ready:\n${json}")
endif()
if(ready_type STREQUAL "NUMBER")
  string(JSON ready GET "${json}" gabor_tiles_ready_ms)
  if(NOT first LESS ready)
    message(FATAL_ERROR "first frame at ${first} ms, not before the tile (ready at ${ready} ms)")
  endif()
endif()
