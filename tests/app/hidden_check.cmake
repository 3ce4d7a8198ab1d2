# cmake -DCMD=<pseudoshadow> -DSCENE=<materials_demo.toml> -DINDEX=<hidden surface> -DDIR=<dir> -P hidden_check.cmake
# A hidden object (visible = false) draws no pixel: the scene renders to the same bytes with
# the hidden sphere where it is and moved 10 m away. The control: made visible, moving it does
# change the image (so the comparison can fail). That it is felt is tests/world's
# GodObjectTest (a hidden sphere deflects the proxy).
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
function(render out)
  execute_process(COMMAND ${CMD} render --scene ${SCENE} --size 96x96 --out ${DIR}/${out}.png -q ${ARGN}
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "render ${out}: exit ${rc}: ${err}")
  endif()
  file(SHA256 ${DIR}/${out}.png h)
  set(${out} ${h} PARENT_SCOPE)
endfunction()
set(away --set "surfaces.${INDEX}.center=[0,0,-10000]")
set(shown --set "surfaces.${INDEX}.visible=true")
render(hidden)
render(hidden_away ${away})
render(shown_here ${shown})
render(shown_away ${shown} ${away})
if(NOT hidden STREQUAL hidden_away)
  message(FATAL_ERROR "moving the hidden sphere changed the image: it is drawn")
endif()
if(shown_here STREQUAL shown_away)
  message(FATAL_ERROR "control: moving the sphere when visible did not change the image (the check cannot fail)")
endif()
