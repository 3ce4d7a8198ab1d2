# ps_run(NAME what COMMAND ... [WORKING_DIRECTORY d] [EXPECT_FAIL]): runs a command; a failure
# (or, with EXPECT_FAIL, a success) stops the test with the command, its output and what it meant.
function(ps_run)
  cmake_parse_arguments(R "EXPECT_FAIL" "NAME;WORKING_DIRECTORY;OUTPUT_VARIABLE" "COMMAND" ${ARGN})
  if(NOT R_WORKING_DIRECTORY)
    set(R_WORKING_DIRECTORY ${DIR})
  endif()
  execute_process(COMMAND ${R_COMMAND} WORKING_DIRECTORY ${R_WORKING_DIRECTORY}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(R_EXPECT_FAIL AND rc EQUAL 0)
    message(FATAL_ERROR "${R_NAME}: succeeded but must fail\n  ${R_COMMAND}\n${out}${err}")
  elseif(NOT R_EXPECT_FAIL AND NOT rc EQUAL 0)
    message(FATAL_ERROR "${R_NAME}: failed (${rc})\n  ${R_COMMAND}\n${out}${err}")
  endif()
  if(R_OUTPUT_VARIABLE)
    set(${R_OUTPUT_VARIABLE} "${out}${err}" PARENT_SCOPE)
  endif()
endfunction()

# The render every round trip compares: the default scene, small, with a --set, a probe pose and
# velocity and two frames, so overrides, the pose and the frame loop all reach the output.
set(PS_RENDER_ARGS render --size 64x64 --set materials.wood.lambda_min=0.4 --probe 2,0,7.5
    --velocity 0,150,0 --frames 2 --backend osmesa -q)
