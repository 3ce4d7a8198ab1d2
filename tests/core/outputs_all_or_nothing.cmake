# A failed command leaves nothing behind (docs/errors.md), as a user meets it:
#
#   cmake -DEXE=<pseudoshadow> -DDIR=<scratch dir> -P outputs_all_or_nothing.cmake
#
# 1. `render --out w/ok.png --aov intensity=w/i.exr --stats f.txt/s.json`, where f.txt is a
#    regular FILE (a read-only directory would not stop root, and CI runs as root): exit 1, the
#    message names s.json, and neither ok.png nor i.exr exists (nor w/, which the command would
#    have created).
# 2. An output that fails only when written, after the render (an AOV with an extension no
#    encoder knows): exit 1 and the image written before it is not published either.
# 3. `--out DIR/missing/deeper/x.png`: exit 1 naming DIR/missing, which is not created.
cmake_minimum_required(VERSION 3.25)
foreach(_var EXE DIR)
  if(NOT DEFINED ${_var})
    message(FATAL_ERROR "outputs_all_or_nothing.cmake: -D${_var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
file(WRITE "${DIR}/f.txt" "a regular file, so f.txt/s.json cannot be written\n")

# Runs pseudoshadow render with ARGN; expects exit 1 and output matching `regex`.
function(expect_render_failure regex)
  execute_process(COMMAND "${EXE}" render --size 16x16 --frames 1 -q ${ARGN}
                  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
  message("exit ${_rc}: ${_out}")
  if(NOT _rc STREQUAL "1")
    message(FATAL_ERROR "expected exit 1, got ${_rc}")
  endif()
  if(NOT _out MATCHES "${regex}")
    message(FATAL_ERROR "output does not match \"${regex}\"")
  endif()
endfunction()

function(expect_absent)
  foreach(_p ${ARGN})
    if(EXISTS "${_p}")
      message(FATAL_ERROR "a failed command left ${_p} behind")
    endif()
  endforeach()
endfunction()

# 1. caught before the render
expect_render_failure("s\\.json: cannot write: .*f\\.txt is not a directory"
  --out "${DIR}/w/ok.png" --aov "intensity=${DIR}/w/i.exr" --stats "${DIR}/f.txt/s.json")
expect_absent("${DIR}/w/ok.png" "${DIR}/w/i.exr" "${DIR}/w")

# 2. caught after the render, while writing: ok.png was already staged
expect_render_failure("i\\.unknownformat"
  --out "${DIR}/w/ok.png" --aov "intensity=${DIR}/w/i.unknownformat")
expect_absent("${DIR}/w/ok.png" "${DIR}/w")

# 3. only the last directory is created
expect_render_failure("cannot create directory .*missing/deeper: .*missing does not exist"
  --out "${DIR}/missing/deeper/x.png")
expect_absent("${DIR}/missing")

# Nothing but the file we made ourselves: no temp files either.
file(GLOB _left RELATIVE "${DIR}" LIST_DIRECTORIES true "${DIR}/*" "${DIR}/.*")
if(NOT _left STREQUAL "f.txt")
  message(FATAL_ERROR "expected only f.txt in ${DIR}, found: ${_left}")
endif()
message("all three failures left nothing behind")
