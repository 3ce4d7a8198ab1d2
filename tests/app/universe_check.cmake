# cmake -DCMD=<pseudoshadow> -DSCENE=<panel.toml> -DTRAJ=<universe_to_weight.traj> -DDIR=<dir> -P universe_check.cmake
# A replay of the press on the control panel: one button_fired naming weight.toml, then the
# switch to it; the last frame is Weight's (it differs from the first, the panel's); the button
# pictures were made in the cache ($PSEUDOSHADOW_CACHE_DIR) and a second replay reuses them
# (same files, same times) and gives the same frames.
file(REMOVE_RECURSE "${DIR}" "$ENV{PSEUDOSHADOW_CACHE_DIR}")  # a cold cache: the first replay makes the pictures
file(MAKE_DIRECTORY "${DIR}")
foreach(run a b)
  execute_process(COMMAND ${CMD} replay --scene ${SCENE} --log ${TRAJ} --out ${DIR}/${run} --fps 10
                          --set render.size=[64,64] -q
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "replay ${run}: exit ${rc}: ${err}")
  endif()
  file(GLOB pictures_${run} "$ENV{PSEUDOSHADOW_CACHE_DIR}/pictures/*_128.png")  # not Field's floor map
  set(stamps_${run} "")
  foreach(p IN LISTS pictures_${run})
    file(TIMESTAMP ${p} t "%s")
    list(APPEND stamps_${run} ${t})
  endforeach()
endforeach()
list(LENGTH pictures_a n)
if(NOT n EQUAL 4)
  message(FATAL_ERROR "expected the 4 worlds' pictures in the cache, found ${n}: ${pictures_a}")
endif()
if(NOT "${pictures_a}${stamps_a}" STREQUAL "${pictures_b}${stamps_b}")
  message(FATAL_ERROR "the second replay made its pictures again instead of reusing the cache")
endif()
file(READ "${DIR}/a/events.jsonl" log)
message("${log}")
if(NOT log MATCHES "\"event\":\"button_fired\"[^\n]*\"label\":\"scene:weight.toml\"")
  message(FATAL_ERROR "no button_fired for the Weight button")
endif()
if(NOT log MATCHES "\"event\":\"scene_switched\"[^\n]*\"label\":\"weight.toml\"")
  message(FATAL_ERROR "no switch to weight.toml")
endif()
file(SHA256 "${DIR}/a/frame_00000.png" first)
file(SHA256 "${DIR}/a/frame_00010.png" last)
file(SHA256 "${DIR}/b/frame_00010.png" last_b)
if(first STREQUAL last)
  message(FATAL_ERROR "the last frame is still the panel")
endif()
if(NOT last STREQUAL last_b)
  message(FATAL_ERROR "two replays gave different frames")
endif()
