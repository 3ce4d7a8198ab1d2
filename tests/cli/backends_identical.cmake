# EGL and OSMesa must render byte-identical images (docs/gl-stack.md): render the same scene on
# both and compare with zero tolerance.
#   cmake -DEXE=... -DOUT=<dir> [-DSCENE=file] -P backends_identical.cmake
set(_scene_args)
if(SCENE)
  set(_scene_args --scene "${SCENE}")
endif()
foreach(_b egl osmesa)
  execute_process(COMMAND "${EXE}" render ${_scene_args} --backend ${_b} --size 128x128 --frames 2
                          --out "${OUT}/${_b}.png" -q RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "render on ${_b} failed (${rc})")
  endif()
endforeach()
execute_process(COMMAND "${EXE}" compare "${OUT}/egl.png" "${OUT}/osmesa.png" --fail 0
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "EGL and OSMesa images differ")
endif()
