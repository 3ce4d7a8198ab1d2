# One golden-image case, run by CTest as a script:
#
#   cmake -DEXE=<pseudoshadow> -DSCENE=<scene file> -DBACKEND=egl|osmesa -DSIZE=128x128 -DFRAMES=2
#         -DGOLDEN=<golden_images/x.png> -DOUT_DIR=<dir> [-DFAIL=<T>] [-DFAILPERCENT=<P>]
#         [-DHARDFAIL=<H>] [-DEXTRA_ARGS=<args>] -P run_golden.cmake
#
# Every golden in golden_images/ is a render with --frames 2 (tests/golden/CMakeLists.txt and
# tests/maze/CMakeLists.txt pass -DFRAMES=2); a render with another frame count differs from it
# (the default scene's own 1 frame: 7.34 % of the pixels, up to 81 levels). The case's exact
# render and compare commands are printed first (and again with any failure), so a person can
# reproduce the golden by hand (docs/testing.md, "Golden images").
#
# 1. renders the scene to OUT_DIR/<name>.actual.png (<name> = GOLDEN's file name minus extension);
# 2. UPDATE_GOLDEN=1 in the environment: copies the actual image over GOLDEN (only if its pixels
#    differ: another PNG encoder or compression level gives other bytes for the same pixels, so
#    rewriting identical goldens would only churn git) and passes. Goldens change in their own
#    commit, saying why;
# 3. otherwise compares GOLDEN (A) with the actual image (B) through `${EXE} compare`. Pass: the
#    actual and diff images are deleted. Fail: both are kept and named in the message.
# FAIL (max channel difference of a passing pixel, [0,1] scale), FAILPERCENT (allowed % of
# failing pixels) and HARDFAIL (no pixel may differ by more, whatever FAILPERCENT allows) default
# to compare's own defaults (1/255, 0, no cap) when not given. EXTRA_ARGS is a
# CMake list ("--seed;3") or, without semicolons, a shell-style string ("--seed 3").
cmake_minimum_required(VERSION 3.25)

foreach(_var EXE SCENE BACKEND SIZE FRAMES GOLDEN OUT_DIR)
  if(NOT DEFINED ${_var} OR "${${_var}}" STREQUAL "")
    message(FATAL_ERROR "run_golden.cmake: -D${_var}=... is required")
  endif()
endforeach()

get_filename_component(_name "${GOLDEN}" NAME_WLE)

# Prints the details verbatim (FATAL_ERROR text is re-wrapped by CMake, which mangles logs and
# paths) and the commands that reproduce the case, then fails the test with a short line. Takes
# ONE quoted argument: ARGN would split the text at its semicolons.
function(golden_fail text)
  message(NOTICE "${text}\n${_reproduce}")
  message(FATAL_ERROR "golden ${_name}: FAILED")
endfunction()

# A command list as one line a POSIX shell runs as is: an argument with other characters than
# these is single-quoted ('[0,0,5]' would otherwise be a glob).
function(shell_line out_var)
  set(_words "")
  foreach(_arg IN LISTS ARGN)
    if(_arg MATCHES "^[A-Za-z0-9_./=,:@%+-]+$")
      list(APPEND _words "${_arg}")
    else()
      string(REPLACE "'" "'\\''" _arg "${_arg}")
      list(APPEND _words "'${_arg}'")
    endif()
  endforeach()
  list(JOIN _words " " _line)
  set(${out_var} "${_line}" PARENT_SCOPE)
endfunction()
set(_actual "${OUT_DIR}/${_name}.actual.png")
set(_diff "${OUT_DIR}/${_name}.diff.png")
file(MAKE_DIRECTORY "${OUT_DIR}")
file(REMOVE "${_actual}" "${_diff}")  # a stale image from an earlier run must never be compared

set(_extra "${EXTRA_ARGS}")
if(NOT "${EXTRA_ARGS}" MATCHES ";")
  separate_arguments(_extra UNIX_COMMAND "${EXTRA_ARGS}")
endif()
set(_limits "")
if(DEFINED FAIL AND NOT "${FAIL}" STREQUAL "")
  list(APPEND _limits --fail "${FAIL}")
endif()
if(DEFINED FAILPERCENT AND NOT "${FAILPERCENT}" STREQUAL "")
  list(APPEND _limits --failpercent "${FAILPERCENT}")
endif()
if(DEFINED HARDFAIL AND NOT "${HARDFAIL}" STREQUAL "")
  list(APPEND _limits --hardfail "${HARDFAIL}")
endif()

# The case by hand: the same render (without --stats, which changes no pixel) and compare.
shell_line(_repro_render "${EXE}" render --scene "${SCENE}" --backend "${BACKEND}" --size "${SIZE}"
           --frames "${FRAMES}" --out "${_name}.png" ${_extra})
shell_line(_repro_compare "${EXE}" compare "${GOLDEN}" "${_name}.png" ${_limits})
set(_reproduce "golden ${_name}: reproduce with\n  ${_repro_render}\n  ${_repro_compare}")
message("${_reproduce}")

# A cold picture cache (one per case, prepare/button_pictures.h): a button's picture cached by
# an older build would stand in for this build's render of it, and a golden regenerated over a
# warm cache would hold an older renderer's pictures (seen: universe_panel).
if(DEFINED ENV{PSEUDOSHADOW_CACHE_DIR} AND NOT "$ENV{PSEUDOSHADOW_CACHE_DIR}" STREQUAL "")
  file(REMOVE_RECURSE "$ENV{PSEUDOSHADOW_CACHE_DIR}")
endif()
# ---- 1. render ----
set(_stats "${OUT_DIR}/${_name}.stats.json")
# PSEUDOSHADOW_GOLDEN_GPU: the EGL device the EGL cases render on (--gpu; default: surfaceless).
set(_gpu "")
if(BACKEND STREQUAL "egl" AND NOT "$ENV{PSEUDOSHADOW_GOLDEN_GPU}" STREQUAL "")
  set(_gpu --gpu "$ENV{PSEUDOSHADOW_GOLDEN_GPU}")
endif()
set(_render_cmd "${EXE}" render --scene "${SCENE}" --backend "${BACKEND}" ${_gpu} --size "${SIZE}"
    --frames "${FRAMES}" --out "${_actual}" --stats "${_stats}" ${_extra})
execute_process(COMMAND ${_render_cmd} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out)
if(NOT _rc STREQUAL "0")
  list(JOIN _render_cmd " " _cmd_text)
  golden_fail("golden ${_name}: render failed (exit ${_rc})\n  command: ${_cmd_text}\n${_out}")
endif()
if(NOT EXISTS "${_actual}")
  golden_fail("golden ${_name}: render exited 0 but wrote no image at ${_actual}\n${_out}")
endif()

# Goldens are llvmpipe renders: its float rounding is what the per-case limits were measured on.
# A GPU driver rounds differently (other cos/exp precision, other FMA use), so there the case
# reports SKIPPED (CTest's SKIP_REGULAR_EXPRESSION) instead of failing; the accuracy tests
# against the CPU twins still run on any driver. With PSEUDOSHADOW_GOLDEN_GPU set, a GPU render
# is compared with the same limits instead (never regenerated), to see which cases a driver
# needs a tolerance of its own for.
file(READ "${_stats}" _stats_text)
string(JSON _renderer ERROR_VARIABLE _json_error GET "${_stats_text}" gl_renderer)
file(REMOVE "${_stats}")
if(_json_error)
  golden_fail("golden ${_name}: the render stats have no gl_renderer (${_json_error})")
endif()
if(NOT _renderer MATCHES "llvmpipe" AND (_gpu STREQUAL "" OR "$ENV{UPDATE_GOLDEN}" STREQUAL "1"))
  file(REMOVE "${_actual}")  # and never regenerate a golden from such a render
  message("SKIPPED: goldens are llvmpipe renders; ${BACKEND} renders with ${_renderer}")
  return()
endif()

# Runs `${EXE} compare GOLDEN actual <args>`; sets _cmp_rc and _cmp_out in the caller.
macro(run_compare)
  execute_process(COMMAND "${EXE}" compare "${GOLDEN}" "${_actual}" ${ARGN}
                  RESULT_VARIABLE _cmp_rc OUTPUT_VARIABLE _cmp_out ERROR_VARIABLE _cmp_out)
  string(STRIP "${_cmp_out}" _cmp_out)
endmacro()

# ---- 2. regenerate on request only ----
if("$ENV{UPDATE_GOLDEN}" STREQUAL "1")
  if(EXISTS "${GOLDEN}")
    run_compare(--fail 0 --failpercent 0)
    if(_cmp_rc STREQUAL "0")
      file(REMOVE "${_actual}")
      message("golden unchanged: ${GOLDEN} (pixels identical; file left as is)")
      return()
    endif()
  endif()
  get_filename_component(_golden_dir "${GOLDEN}" DIRECTORY)
  file(MAKE_DIRECTORY "${_golden_dir}")
  file(COPY_FILE "${_actual}" "${GOLDEN}")
  file(REMOVE "${_actual}")
  message("golden updated: ${GOLDEN} (commit it with a message saying why)")
  return()
endif()

if(NOT EXISTS "${GOLDEN}")
  golden_fail("missing golden ${GOLDEN}; run with UPDATE_GOLDEN=1 to create it\n\
  (the image just rendered is ${_actual})")
endif()

# ---- 3. compare ----
run_compare(${_limits} --diff "${_diff}")
if(_cmp_rc STREQUAL "0")
  file(REMOVE "${_actual}" "${_diff}")
  message("golden ${_name}: ${_cmp_out}")
elseif(_cmp_rc STREQUAL "1")
  golden_fail("golden ${_name} differs: ${_cmp_out}
  golden: ${GOLDEN}
  actual: ${_actual}
  diff:   ${_diff} (|golden-actual| x10)
  If the change is intended, rerun with UPDATE_GOLDEN=1 and commit the new golden with a message saying why.")
else()
  golden_fail("golden ${_name}: compare error (exit ${_cmp_rc}): ${_cmp_out}")
endif()
