# A planned study through the CLI: `maze plan`, a scripted participant for a plan row, that row
# run with `maze --plan`; the study folder refuses a participant's session or a seed used again
# (unless --force); a trajectory written for another seed is warned about.
#   cmake -DCMD=pseudoshadow -DMAZE=maze.toml -DDIR=out -P maze_plan_check.cmake
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR}/study)
function(expect want_rc pattern)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL want_rc OR NOT "${out}${err}" MATCHES "${pattern}")
    message(FATAL_ERROR "${ARGN}\nexit ${rc} (want ${want_rc}), output:\n${out}${err}\nwanted: ${pattern}")
  endif()
endfunction()
expect(0 "plan: 4 participants, 8 rows \\(2 sessions each\\)" ${CMD} maze plan --participants 4 --conditions on,off --out ${DIR}/plan.csv)
file(STRINGS ${DIR}/plan.csv plan)
list(GET plan 5 p03)  # header, P01 x2, P02 x2, then P03 session 1
if(NOT p03 MATCHES "^P03,1,cues_on,103,([a-z_ ]+),")
  message(FATAL_ERROR "plan row: ${p03}")
endif()
set(first_order ${CMAKE_MATCH_1})
expect(0 "" ${CMD} maze script --maze ${MAZE} --plan ${DIR}/plan.csv --participant P03 --out ${DIR}/p03.traj)
expect(0 "P03 after 1 pass \\(criterion\\)" ${CMD} maze --maze ${MAZE} --plan ${DIR}/plan.csv --participant P03
       --device trajectory:${DIR}/p03.traj --out ${DIR}/study/P03)
file(STRINGS ${DIR}/study/P03/session.jsonl log)
list(GET log 0 start)
list(GET log 1 pass1)
string(REPLACE " " "\",\"" quoted "${first_order}")
if(NOT start MATCHES "\"condition\":\"cues_on\"" OR NOT start MATCHES "\"seed\":103" OR NOT pass1 MATCHES "\"order\":\\[\"none\",\"${quoted}\"\\]")
  message(FATAL_ERROR "the plan row is not what ran:\n${start}\n${pass1}\nwanted order ${first_order}")
endif()
expect(1 "seed 103 is already P03's" ${CMD} maze --maze ${MAZE} --participant X --seed 103 --cues on
       --device trajectory:${DIR}/p03.traj --out ${DIR}/study/X)
expect(1 "participant P03 already has session 1" ${CMD} maze --maze ${MAZE} --plan ${DIR}/plan.csv --participant P03
       --device trajectory:${DIR}/p03.traj --out ${DIR}/study/P03b)
if(EXISTS ${DIR}/study/X OR EXISTS ${DIR}/study/P03b)
  message(FATAL_ERROR "a refused session left a directory")
endif()
expect(0 "P03 after 1 pass" ${CMD} maze --maze ${MAZE} --plan ${DIR}/plan.csv --participant P03
       --device trajectory:${DIR}/p03.traj --out ${DIR}/study/P03b --force)
expect(0 "warning: trajectory:.*p03.traj was written for --seed 103, this session has --seed 9" ${CMD} maze --maze ${MAZE}
       --participant Y --seed 9 --cues on --device trajectory:${DIR}/p03.traj --out ${DIR}/study/Y)
