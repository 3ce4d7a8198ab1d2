# `maze summarize` through the CLI on what pilots leave (docs/maze.md, "Pilots, aborted sessions,
# duplicates"): one aborted session's folder exits 0 with a note per skipped plot and no PNG
# (not even an empty one) and "—" for its means; one complete session draws both plots; the same
# session given twice (a study folder and a copy of one of its logs) exits 2 naming both paths; a
# study folder is read as its participants' logs. Usage:
#   cmake -DCMD=pseudoshadow -DDATA=tests/maze/data -DDIR=out -P maze_summarize_check.cmake
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR}/study/P01 ${DIR}/study/P04 ${DIR}/study/P01/practice ${DIR}/backup)
file(COPY_FILE ${DATA}/p1_cues_on.jsonl ${DIR}/study/P01/session.jsonl)
file(COPY_FILE ${DATA}/p3_cues_on_cut.jsonl ${DIR}/study/P01/practice/session.jsonl)
file(COPY_FILE ${DATA}/p4_cues_on_quit.jsonl ${DIR}/study/P04/session.jsonl)
file(COPY_FILE ${DATA}/p1_cues_on.jsonl ${DIR}/backup/P01.jsonl)

function(summarize want_rc)
  execute_process(COMMAND ${CMD} maze summarize ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL want_rc)
    message(FATAL_ERROR "maze summarize ${ARGN}: exit ${rc}, expected ${want_rc}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

function(expect text pattern what)
  if(NOT text MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: expected /${pattern}/ in:\n${text}")
  endif()
endfunction()

# One aborted pilot, given as the participant's folder.
summarize(0 ${DIR}/study/P04 --out ${DIR}/aborted)
expect("${err}" "errors_by_room.png skipped: no session in the group means" "stderr")
expect("${err}" "time_per_trial.png skipped: no completed trials" "stderr")
expect("${err}" "cues_on session 1: N = 0, no mean" "stderr")
expect("${out}" "summarized 1 session \\(0 in the group means\\)" "stdout")
foreach(png errors_by_room.png time_per_trial.png errors_by_room.png.partial time_per_trial.png.partial)
  if(EXISTS ${DIR}/aborted/${png})
    message(FATAL_ERROR "${DIR}/aborted/${png}: written with nothing to draw")
  endif()
endforeach()
file(READ ${DIR}/aborted/summary.md md)
expect("${md}" "\\| cues_on \\| 1 \\| 0 \\(1\\) \\| 0 \\| — \\| — \\|" "summary.md")
if(md MATCHES "0\\.00 \\|")
  message(FATAL_ERROR "summary.md: a mean of nobody shown as 0.00:\n${md}")
endif()
file(STRINGS ${DIR}/aborted/groups.csv groups)
list(GET groups 1 row)
expect("${row}" "^cues_on,1,0,0,,," "groups.csv (empty cells for N = 0)")

# One complete session: both plots, neither empty.
summarize(0 ${DIR}/study/P01/session.jsonl --out ${DIR}/one)
foreach(png errors_by_room.png time_per_trial.png)
  file(SIZE ${DIR}/one/${png} size)
  if(size LESS 1000)
    message(FATAL_ERROR "${DIR}/one/${png}: ${size} bytes")
  endif()
endforeach()

# The same session twice: the study folder and a copy of P01's log kept elsewhere.
summarize(2 ${DIR}/study ${DIR}/backup/P01.jsonl --out ${DIR}/twice)
expect("${err}" "^pseudoshadow maze summarize: ${DIR}/study/P01/session.jsonl and ${DIR}/backup/P01.jsonl are the same session \\(participant P1, session 1" "stderr")
if(EXISTS ${DIR}/twice/summary.md)
  message(FATAL_ERROR "a refused summary wrote ${DIR}/twice/summary.md")
endif()

# The study folder: P01 and P04 (not P01's practice); the aborted P04 left out of the means.
summarize(0 ${DIR}/study --out ${DIR}/study_summary)
expect("${out}" "summarized 2 sessions \\(1 in the group means\\) in 1 group" "stdout")
file(STRINGS ${DIR}/study_summary/participants.csv people)
list(LENGTH people n)
if(NOT n EQUAL 3)
  message(FATAL_ERROR "participants.csv: expected P1 and P4, got:\n${people}")
endif()
