# cmake -DEXE=pseudoshadow -DLUT=table.lut -DWORK=dir -P paths_are_the_users.cmake
# Where a relative path resolves (docs/scene-format.md "Relative paths"): a path written on the
# command line (--set) resolves against the working directory; a path written inside an override
# file or a scene file resolves against that file. Each case runs `render` with WORK as the
# working directory, so a path that resolved against the shipped scenes' directory (the default
# scene's base) or the working directory instead of the file would not be found.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/sub)
configure_file(${LUT} ${WORK}/my.lut COPYONLY)
configure_file(${LUT} ${WORK}/sub/side.lut COPYONLY)
file(WRITE ${WORK}/sub/o.overrides.toml "materials.wood.intensity_lut = \"side.lut\"\n")
file(WRITE ${WORK}/sub/scene.toml
     "[materials.wood]\nintensity_lut = \"side.lut\"\n\n[[surfaces]]\nmaterial = \"wood\"\n")

include(${CMAKE_CURRENT_LIST_DIR}/expect_render.cmake)

# --set: the working directory (issue: it was the default scene's directory).
expect_render(0 "" --set materials.wood.intensity_lut=my.lut)
expect_render(0 "" --set "materials.wood.intensity_lut=\"my.lut\"")
# Not found: the message names the file where the user stands.
expect_render(2 "--set materials.wood.intensity_lut: .*file not found: .*/paths_work/nope.lut"
              --set materials.wood.intensity_lut=nope.lut)
# A table beside the override file, the override file given from another directory.
expect_render(0 "" --overrides sub/o.overrides.toml)
# Beside the override file only: side.lut is not in the working directory.
expect_render(2 "file not found: .*/paths_work/side.lut" --set materials.wood.intensity_lut=side.lut)
# A scene's own path: against the scene file's directory, whatever the working directory.
expect_render(0 "" --scene sub/scene.toml)
