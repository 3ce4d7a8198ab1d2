# cmake -DEXE=pseudoshadow -DSCENE=s.toml -DSESSION=session.txt -DOUT=dir -P console_session.cmake
# Replays a console session from a file on stdin: errors name their line and the session
# continues (exit 1 because a command failed), the image and the override file are written,
# and `render --overrides` reproduces the console's image exactly.
file(MAKE_DIRECTORY ${OUT})
file(READ ${SESSION} text)
string(REPLACE "OUT_DIR" "${OUT}" text "${text}")
file(WRITE ${OUT}/session.txt "${text}")
file(REMOVE ${OUT}/console.png ${OUT}/console.overrides.toml)
# Both sides pin the Gabor strategy: under "auto" the console (an open-ended session) bakes a
# tile while a one-frame `render` draws the exact per-pixel sum, which is less work for it
# (RendererOptions::expected_frames); the two then differ within the tile's error (<= 1 level).
# Pinned, the contract under test is exact: the saved overrides reproduce the console's image.
set(pin materials.table4_1_a.gabor_strategy="baked")
execute_process(COMMAND ${EXE} tune --console --scene ${SCENE} --set render.size=[64,64] --set ${pin}
  INPUT_FILE ${OUT}/session.txt RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "expected exit 1 (two commands failed), got ${rc}")
endif()
foreach(needle "<stdin>:5: --set materials.table4_1_a.lamda_max: unknown key; close matches: lambda_max"
               "<stdin>:6: unknown command 'rendr'" "shadow_pixels [0-9]+" "saved .*console.png")
  if(NOT "${out}${err}" MATCHES "${needle}")
    message(FATAL_ERROR "output lacks \"${needle}\"")
  endif()
endforeach()
if("${out}${err}" MATCHES "<stdin>:10")
  message(FATAL_ERROR "a command after quit ran")
endif()
file(READ ${OUT}/console.overrides.toml saved)
if(NOT saved MATCHES "materials.table4_1_a.lambda_min = 1.0\n")
  message(FATAL_ERROR "override file lacks the edit:\n${saved}")
endif()
execute_process(COMMAND ${EXE} render --scene ${SCENE} --set render.size=[64,64] --set ${pin}
  --overrides ${OUT}/console.overrides.toml --out ${OUT}/render.png -q RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render --overrides failed (${rc})")
endif()
execute_process(COMMAND ${EXE} compare ${OUT}/console.png ${OUT}/render.png --fail 0 RESULT_VARIABLE rc
  OUTPUT_VARIABLE cmp ERROR_VARIABLE cmp)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render --overrides differs from the console's image: ${cmp}")
endif()
