# api.install_consumer (tests/api/CMakeLists.txt). Inputs: BUILD, SOURCE, CLI, DIR, LAUNCHER.
include(${CMAKE_CURRENT_LIST_DIR}/run_checked.cmake)
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})

ps_run(NAME "install" COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${DIR}/prefix)
set(_launcher "")
if(LAUNCHER)
  set(_launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
ps_run(NAME "configure the example consumer against the install"
  COMMAND ${CMAKE_COMMAND} -S ${SOURCE}/examples/consumer -B ${DIR}/consumer
          -DCMAKE_PREFIX_PATH=${DIR}/prefix -DCMAKE_BUILD_TYPE=Release ${_launcher})
ps_run(NAME "build the example consumer" COMMAND ${CMAKE_COMMAND} --build ${DIR}/consumer)
ps_run(NAME "run the example consumer" COMMAND ${DIR}/consumer/consumer ${DIR}/consumer.ppm osmesa
       OUTPUT_VARIABLE said)
if(NOT said MATCHES "64x64 on osmesa: [1-9][0-9]* shadow pixels")
  message(FATAL_ERROR "the consumer rendered no shadow: ${said}")
endif()

# An error thrown inside libpseudoshadow.so is caught by its type in the consumer, with the
# CLI's message (the exception's type information crosses the library boundary).
ps_run(NAME "the example consumer on a missing scene" EXPECT_FAIL
  COMMAND ${DIR}/consumer/consumer ${DIR}/none.ppm osmesa no/such/scene.toml OUTPUT_VARIABLE failed)
if(NOT failed STREQUAL "consumer: no/such/scene.toml: cannot open scene file: no such file\n")
  message(FATAL_ERROR "the consumer on a missing scene said: '${failed}'")
endif()

# The same frame from the build tree's CLI: equal in every byte.
ps_run(NAME "CLI render" COMMAND ${CLI} ${PS_RENDER_ARGS} --out ${DIR}/cli.png)
ps_run(NAME "the consumer's frame equals the CLI's"
  COMMAND ${CLI} compare ${DIR}/cli.png ${DIR}/consumer.ppm --fail 0 --failpercent 0)
message(STATUS "consumer: ${said}")
