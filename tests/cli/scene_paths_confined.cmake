# cmake -DEXE=pseudoshadow -DLUT=table.lut -DWORK=dir -P scene_paths_confined.cmake
# A shared scene cannot make `render` read the user's other files (docs/scene-format.md, "Files a
# scene may read"): a table outside the scene's folder is refused with the --allow-path that
# would admit it, before the file is read; with that --allow-path it renders; a file that is not
# a table is quoted only in part; the same file named with --set is the user's and is read.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/shared ${WORK}/private)
configure_file(${LUT} ${WORK}/private/curve.lut COPYONLY)
file(WRITE ${WORK}/private/passwd "root:x:0:0:PRIVATE-REST-OF-LINE\n")
file(WRITE ${WORK}/shared/scene.toml
     "[materials.wood]\nintensity_lut = \"../private/curve.lut\"\n\n[[surfaces]]\nmaterial = \"wood\"\n")
file(WRITE ${WORK}/shared/leak.toml
     "[materials.wood]\nintensity_lut = \"${WORK}/private/passwd\"\n\n[[surfaces]]\nmaterial = \"wood\"\n")

set(FORBID "PRIVATE-REST")  # the private file's rest of line
include(${CMAKE_CURRENT_LIST_DIR}/expect_render.cmake)

expect_render(1 "shared/scene.toml:2: 'intensity_lut' names '.*/private/curve.lut', outside the scene's folder.*--allow-path .*/private"
              --scene shared/scene.toml)
expect_render(0 "" --scene shared/scene.toml --allow-path private)
expect_render(1 "outside the scene's folder" --scene shared/leak.toml)
expect_render(1 "got 'root:x:0:0:PRIVA\\.\\.\\.'" --scene shared/leak.toml --allow-path private)
expect_render(0 "" --set materials.wood.intensity_lut=private/curve.lut)

# `tune --sweep` validates every cell before rendering: with the scene's own --allow-path (the
# validation once ignored it and refused a sweep the render would have allowed).
function(expect_sweep status regex)
  execute_process(COMMAND ${EXE} tune --scene shared/scene.toml --sweep "materials.wood.albedo=[0.5,0.5,0.5],[0.9,0.9,0.9]"
                          --size 16x16 --out sheet.png ${ARGN}
                  WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("tune --sweep ${ARGN} -> ${rc}: ${out}${err}")
  if(NOT "${rc}" STREQUAL "${status}" OR NOT "${out}${err}" MATCHES "${regex}")
    message(FATAL_ERROR "tune --sweep ${ARGN}: expected exit status ${status} and output matching \"${regex}\"")
  endif()
endfunction()
expect_sweep(1 "outside the scene's folder.*--allow-path .*/private")
expect_sweep(0 "" --allow-path private)
