# `replay --vibration` twice on the scripted stroke: both exit 0, both WAVs are byte-identical,
# and the WAV is as long as the replay (1.6 s at 48 kHz, 16-bit mono: 76801 samples, 153602
# bytes of data after libsndfile's 44-byte header).
file(MAKE_DIRECTORY ${OUT})
foreach(run a b)
  execute_process(COMMAND ${PS} replay --log trajectory:${LOG} --out ${OUT}/${run} --fps 5
                          --set render.size=[64,64] --vibration ${OUT}/${run}/vibration.wav -q
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "replay --vibration (${run}) exited ${rc}: ${err}")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/a/vibration.wav ${OUT}/b/vibration.wav
                RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "two replays gave different vibration WAVs")
endif()
file(SIZE ${OUT}/a/vibration.wav size)
if(NOT size EQUAL 153646)
  message(FATAL_ERROR "vibration.wav is ${size} bytes, expected 153646 (44 + 2 * 76801)")
endif()
