# cmake -DCMD=<pseudoshadow> -DCSV=<bench.csv> -DDIR=<scratch dir> -P plot_only.cmake
# `bench --plot-only` as a user meets it: with a bench.csv from an earlier run in the directory
# it exits 0 and writes both plots (fresh files: any from before are removed first); without a
# bench.csv it exits 1 with one line naming the file; a damaged row is named by file:line.
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})

execute_process(COMMAND ${CMD} bench --plot-only --out-dir ${DIR} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 1 OR NOT err MATCHES "^pseudoshadow bench: [^\n]*/bench.csv: cannot read")
  message(FATAL_ERROR "no bench.csv: expected exit 1 and 'bench.csv: cannot read', got ${rc}: ${err}")
endif()

file(READ ${CSV} text)
string(REPLACE "depth_map,128,34.49" "depth_map,128,fast" bad "${text}")
if(bad STREQUAL text)
  message(FATAL_ERROR "the damaged-row check found no depth_map,128 row to damage in ${CSV}")
endif()
file(WRITE ${DIR}/bench.csv "${bad}")
execute_process(COMMAND ${CMD} bench --plot-only --out-dir ${DIR} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 1 OR NOT err MATCHES "bench.csv:[0-9]+: bad frame_ms value")
  message(FATAL_ERROR "damaged row: expected exit 1 and 'bench.csv:N: bad frame_ms value', got ${rc}: ${err}")
endif()

configure_file(${CSV} ${DIR}/bench.csv COPYONLY)
execute_process(COMMAND ${CMD} bench --plot-only --out-dir ${DIR} RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "expected exit 0, got ${rc}: ${err}")
endif()
foreach(png bench.png bench_ratios.png)
  if(NOT EXISTS ${DIR}/${png})
    message(FATAL_ERROR "${png} was not written")
  endif()
  file(READ ${DIR}/${png} magic LIMIT 8 HEX)
  if(NOT magic STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "${png} is not a PNG (starts with ${magic})")
  endif()
endforeach()
