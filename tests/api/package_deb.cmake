# api.package_deb (tests/api/CMakeLists.txt). Inputs: BUILD, CLI, PYTHON, DIR.
include(${CMAKE_CURRENT_LIST_DIR}/run_checked.cmake)
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})

ps_run(NAME "cpack" COMMAND cpack -G DEB -B ${DIR}/pkg WORKING_DIRECTORY ${BUILD})
file(GLOB deb ${DIR}/pkg/*.deb)
list(LENGTH deb n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "cpack made ${n} .deb files in ${DIR}/pkg, expected one")
endif()
file(SIZE ${deb} bytes)
message(STATUS "package: ${deb} (${bytes} bytes)")

# Dependencies: found by dpkg-shlibdeps from the binaries, plus the GL the binaries only dlopen.
ps_run(NAME "read Depends" COMMAND dpkg-deb -f ${deb} Depends OUTPUT_VARIABLE depends)
foreach(pkg libegl1 libosmesa6 libpng16-16 libassimp5 libgl1-mesa-dri libegl-mesa0)
  if(NOT depends MATCHES "(^|, )${pkg}( |,|$|\n)")
    message(FATAL_ERROR "the package does not depend on ${pkg}: Depends: ${depends}")
  endif()
endforeach()

ps_run(NAME "unpack" COMMAND dpkg-deb -x ${deb} ${DIR}/unpacked)
set(bin ${DIR}/unpacked/usr/bin/pseudoshadow)
set(no_env ${CMAKE_COMMAND} -E env --unset=PSEUDOSHADOW_GLSL_DIR --unset=PYTHONPATH)
ps_run(NAME "the unpacked binary renders"
  COMMAND ${no_env} ${bin} ${PS_RENDER_ARGS} --out ${DIR}/deb.png --aov distance=${DIR}/deb_d.exr)
ps_run(NAME "the build's CLI renders"
  COMMAND ${CLI} ${PS_RENDER_ARGS} --out ${DIR}/cli.png --aov distance=${DIR}/cli_d.exr)
ps_run(NAME "the unpacked binary's image equals the build's"
  COMMAND ${CLI} compare ${DIR}/cli.png ${DIR}/deb.png --fail 0 --failpercent 0)
# A shipped scene with an include (the material library) and textures, from the unpacked copy.
ps_run(NAME "the unpacked binary renders an unpacked scene with an include and textures"
  COMMAND ${no_env} ${bin} render --scene ${DIR}/unpacked/usr/share/pseudoshadow/scenes/materials_demo.toml
          --size 64x64 --backend osmesa -q --out ${DIR}/materials_demo.png)
# The distance AOV is NaN outside the shadow; the Python reader compares it with NaN == NaN.
ps_run(NAME "the unpacked Python module imports from the unpacked root and renders"
  COMMAND ${CMAKE_COMMAND} -E env --unset=PSEUDOSHADOW_GLSL_DIR
          PYTHONPATH=${DIR}/unpacked/usr/lib/python3/dist-packages
          ${PYTHON} -c "import sys, numpy as np, pseudoshadow as p
assert p.__file__.startswith(sys.argv[1]), p.__file__
a, b = p.read_image(sys.argv[2]), p.read_image(sys.argv[3])
assert np.array_equal(a, b, equal_nan=True), 'distance AOVs differ'
f = p.Renderer(backend='osmesa', set={'render.size': [32, 32]}).render()
assert f.color.shape == (32, 32, 3) and f.stats['shadow_pixels'] > 0, f.stats
print('python', p.__file__)" ${DIR}/unpacked ${DIR}/cli_d.exr ${DIR}/deb_d.exr
  OUTPUT_VARIABLE said)
message(STATUS "${said}")

# Without its own shaders the unpacked binary must fail, naming what to do; reading the
# checkout's instead would pass every check above and break once the checkout is gone.
file(RENAME ${DIR}/unpacked/usr/share/pseudoshadow/glsl ${DIR}/unpacked/usr/share/pseudoshadow/glsl.moved)
ps_run(NAME "the unpacked binary without its shaders" EXPECT_FAIL
  COMMAND ${no_env} ${bin} ${PS_RENDER_ARGS} --out ${DIR}/none.png OUTPUT_VARIABLE said)
if(NOT said MATCHES "no shader directory.*PSEUDOSHADOW_GLSL_DIR")
  message(FATAL_ERROR "the unpacked binary without shaders said: ${said}")
endif()
