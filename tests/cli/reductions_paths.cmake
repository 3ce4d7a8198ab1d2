# `render --reductions fragment` (the reductions as fragment shaders, the path a WebGL2 build
# has; docs/gl-stack.md, "Compute") must write the compute path's image and stats values: the
# same scene rendered both ways over several frames (the reductions feed the next frame's plane
# and the probe's displacement), the images compared with zero tolerance and the stats' reduced
# values as text. Zero, because both paths run the same row functions on the same texels
# (ReductionPathsGLTest checks every AOV too).
#   cmake -DEXE=... -DOUT=<dir> -P reductions_paths.cmake
foreach(_m compute fragment)
  execute_process(COMMAND "${EXE}" render --reductions ${_m} --size 192x144 --frames 4 --out "${OUT}/${_m}.png"
                          --stats "${OUT}/${_m}.json" -q RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "render --reductions ${_m} failed (${rc}): ${err}")
  endif()
  file(READ "${OUT}/${_m}.json" _stats)
  foreach(_key reference_normal displacement max_penetration probe_position shadow_pixels penetrating_pixels)
    string(JSON _v_${_m}_${_key} ERROR_VARIABLE _json_error GET "${_stats}" ${_key})
    if(_json_error)
      message(FATAL_ERROR "${OUT}/${_m}.json: no ${_key} (${_json_error})")
    endif()
  endforeach()
endforeach()
foreach(_key reference_normal displacement max_penetration probe_position shadow_pixels penetrating_pixels)
  if(NOT "${_v_compute_${_key}}" STREQUAL "${_v_fragment_${_key}}")
    message(FATAL_ERROR "stats ${_key}: compute ${_v_compute_${_key}}, fragment ${_v_fragment_${_key}}")
  endif()
endforeach()
if(_v_compute_shadow_pixels EQUAL 0)
  message(FATAL_ERROR "no pseudo-shadow in the frame: nothing was compared")
endif()
execute_process(COMMAND "${EXE}" compare "${OUT}/compute.png" "${OUT}/fragment.png" --fail 0
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the compute and fragment reductions' images differ")
endif()
# A misspelt path is a usage error that names the choices.
execute_process(COMMAND "${EXE}" render --reductions gpu --out "${OUT}/never.png" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "compute,fragment")
  message(FATAL_ERROR "--reductions gpu: exit ${rc}, expected 2 naming compute and fragment: ${err}")
endif()
