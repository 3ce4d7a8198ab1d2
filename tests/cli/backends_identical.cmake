# EGL and OSMesa must render byte-identical images (docs/gl-stack.md): render the same scene on
# both and compare with zero tolerance. That is a property of llvmpipe behind both; where EGL
# drives a GPU the images may legitimately differ, and the test reports SKIPPED (the test's
# SKIP_REGULAR_EXPRESSION) after reading the renderer from --stats.
#   cmake -DEXE=... -DOUT=<dir> [-DSCENE=file] -P backends_identical.cmake
set(_scene_args)
if(SCENE)
  set(_scene_args --scene "${SCENE}")
endif()
foreach(_b egl osmesa)
  execute_process(COMMAND "${EXE}" render ${_scene_args} --backend ${_b} --size 128x128 --frames 2
                          --out "${OUT}/${_b}.png" --stats "${OUT}/${_b}.json" -q RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "render on ${_b} failed (${rc})")
  endif()
  file(READ "${OUT}/${_b}.json" _stats)
  string(JSON _renderer ERROR_VARIABLE _json_error GET "${_stats}" gl_renderer)
  if(_json_error)
    message(FATAL_ERROR "${OUT}/${_b}.json: no gl_renderer (${_json_error})")
  endif()
  if(NOT _renderer MATCHES "llvmpipe")
    message("SKIPPED: byte parity is a property of llvmpipe; ${_b} renders with ${_renderer}")
    return()
  endif()
endforeach()
execute_process(COMMAND "${EXE}" compare "${OUT}/egl.png" "${OUT}/osmesa.png" --fail 0
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "EGL and OSMesa images differ")
endif()
