# One golden scene rendered on Mesa's surfaceless platform and on an EGL device (Mesa's software
# device: --gpu software), which must give byte-identical images: both are llvmpipe behind
# another EGL display, so any byte of difference is a bug in how the display is opened.
#
#   cmake -DEXE=<pseudoshadow> -DSCENE=<scene file> -DSIZE=128x128 -DFRAMES=2 -DNAME=<case>
#         -DOUT_DIR=<dir> [-DEXTRA_ARGS=<args>] -P run_device_identical.cmake
#
# Reports SKIPPED (CTest's SKIP_REGULAR_EXPRESSION) where EGL offers no software device.
cmake_minimum_required(VERSION 3.25)

foreach(_var EXE SCENE SIZE FRAMES NAME OUT_DIR)
  if(NOT DEFINED ${_var} OR "${${_var}}" STREQUAL "")
    message(FATAL_ERROR "run_device_identical.cmake: -D${_var}=... is required")
  endif()
endforeach()

# A cold picture cache (one per case, prepare/button_pictures.h): a button's picture cached by
# an older build would stand in for this build's render of it, and a golden regenerated over a
# warm cache would hold an older renderer's pictures (seen: universe_panel).
if(DEFINED ENV{PSEUDOSHADOW_CACHE_DIR} AND NOT "$ENV{PSEUDOSHADOW_CACHE_DIR}" STREQUAL "")
  file(REMOVE_RECURSE "$ENV{PSEUDOSHADOW_CACHE_DIR}")
endif()
execute_process(COMMAND "${EXE}" render --gpu list RESULT_VARIABLE _rc OUTPUT_VARIABLE _list ERROR_VARIABLE _list)
if(NOT _rc STREQUAL "0" OR NOT _list MATCHES " software ")
  message("SKIPPED: no software EGL device: ${_list}")
  return()
endif()

set(_extra "${EXTRA_ARGS}")
if(NOT "${EXTRA_ARGS}" MATCHES ";")
  separate_arguments(_extra UNIX_COMMAND "${EXTRA_ARGS}")
endif()
file(MAKE_DIRECTORY "${OUT_DIR}")
set(_images "")
foreach(_display surfaceless software)
  set(_gpu "")
  if(_display STREQUAL "software")
    set(_gpu --gpu software)
  endif()
  set(_image "${OUT_DIR}/${NAME}.${_display}.png")
  file(REMOVE "${_image}")
  set(_cmd "${EXE}" render --scene "${SCENE}" --backend egl ${_gpu} --size "${SIZE}" --frames "${FRAMES}"
      --out "${_image}" -q ${_extra})
  execute_process(COMMAND ${_cmd} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
  if(NOT _rc STREQUAL "0" OR NOT EXISTS "${_image}")
    list(JOIN _cmd " " _text)
    message(NOTICE "render failed (exit ${_rc})\n  command: ${_text}\n${_out}")
    message(FATAL_ERROR "device ${NAME}: FAILED")
  endif()
  list(APPEND _images "${_image}")
endforeach()

execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files ${_images} RESULT_VARIABLE _same)
if(NOT _same STREQUAL "0")
  execute_process(COMMAND "${EXE}" compare ${_images} --fail 0 OUTPUT_VARIABLE _cmp ERROR_VARIABLE _cmp)
  message(NOTICE "device ${NAME}: the software EGL device's image differs from the surfaceless one: ${_cmp}\n  ${_images}")
  message(FATAL_ERROR "device ${NAME}: FAILED")
endif()
file(REMOVE ${_images})
message("device ${NAME}: byte-identical on the software EGL device and the surfaceless platform")
