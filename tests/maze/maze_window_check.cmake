# `pseudoshadow maze --window` under Xvfb with a scripted participant played in real time: the
# window session reaches the criterion and writes the same kind of log as the headless one.
#   cmake -DCMD=pseudoshadow -DXVFB=xvfb-run -DMAZE=maze.toml -DDIR=out -P maze_window_check.cmake
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
execute_process(COMMAND ${CMD} maze script --maze ${MAZE} --seed 7 --speed 300 --out ${DIR}/fast.traj RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "maze script failed")
endif()
execute_process(COMMAND ${XVFB} -a ${CMD} maze --maze ${MAZE} --participant W --seed 7 --cues off
                        --device trajectory:${DIR}/fast.traj --window --out ${DIR}/w
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "W after 1 pass \\(criterion\\)")
  message(FATAL_ERROR "window session: exit ${rc}\n${out}\n${err}")
endif()
file(STRINGS ${DIR}/w/session.jsonl lines)
list(GET lines -1 last)
if(NOT last MATCHES "\"type\":\"session_end\",\"reason\":\"criterion\",\"passes\":1,\"trials_to_criterion\":1")
  message(FATAL_ERROR "last log line: ${last}")
endif()
if(NOT EXISTS ${DIR}/w/device.log)
  message(FATAL_ERROR "no device stream ${DIR}/w/device.log")
endif()
