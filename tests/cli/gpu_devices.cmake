# cmake -DEXE=pseudoshadow -DOUT=dir -P gpu_devices.cmake
# --gpu as a user meets it (docs/gl-stack.md, "EGL devices"), on Mesa's EGL, which offers one
# software device:
#   list         prints a header and one line per device, exit 0, writes nothing;
#   99           (no such device) one line, exit 1, nothing written;
#   auto         says on stderr which display it took;
#   0            --stats names the device (egl_device) and has gpu_timings_ms for the passes
#                that timings_ms has (llvmpipe finishes every pass: lag 0).
function(run)
  execute_process(COMMAND ${EXE} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(rc "${rc}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()
function(fail text)
  message(FATAL_ERROR "${text}\nexit ${rc}\nstdout: ${out}\nstderr: ${err}")
endfunction()

set(img ${OUT}/gpu_devices.png)
set(stats ${OUT}/gpu_devices.json)
file(REMOVE ${img} ${stats})

run(render --gpu list --out ${img})
if(NOT rc STREQUAL "0" OR NOT out MATCHES "^index  name  kind  render node\n0  [^\n]+  (software|hardware)  ")
  fail("--gpu list: expected exit 0 and a line per device")
endif()
if(NOT out MATCHES "\n[0-9]+  [^\n]+  software  -\n")
  message("SKIPPED: this EGL has no software device (Mesa's): ${out}")
  return()
endif()
if(EXISTS ${img})
  fail("--gpu list wrote ${img}")
endif()

run(render --gpu 99 --out ${img} --stats ${stats})
string(STRIP "${err}" line)
if(NOT rc STREQUAL "1" OR NOT line MATCHES "^pseudoshadow render: no OpenGL 4.5 context: egl: no EGL device 99 \\([0-9]+ devices?; see --gpu list\\)$")
  fail("--gpu 99: expected one line and exit 1")
endif()
if(EXISTS ${img} OR EXISTS ${stats})
  fail("--gpu 99 wrote an output")
endif()

run(render --gpu auto --size 64x64 --out ${img})  # not -q: that silences the line too
if(NOT rc STREQUAL "0" OR NOT err MATCHES "^gpu: egl, (surfaceless \\(gpu auto: [^\n]+\\)|device [0-9]+ \\([^\n]+\\) \\(gpu auto: [^\n]+\\))\n$")
  fail("--gpu auto: expected exit 0 and one line saying which display it took")
endif()

run(render --gpu 0 --size 64x64 --frames 2 --out ${img} --stats ${stats} -q)
if(NOT rc STREQUAL "0")
  fail("--gpu 0 failed")
endif()
file(READ ${stats} json)
string(JSON device GET "${json}" egl_device)
if(NOT device MATCHES "^device 0 \\(")
  fail("egl_device is \"${device}\", expected \"device 0 (...)\"")
endif()
string(JSON lag GET "${json}" gpu_timings_lag)
if(NOT lag STREQUAL "0")  # llvmpipe: the CPU timer's glFinish after each pass makes every result ready
  fail("gpu_timings_lag is ${lag}, expected 0 on llvmpipe")
endif()
string(JSON n LENGTH "${json}" timings_ms)
math(EXPR last "${n} - 1")
foreach(i RANGE ${last})
  string(JSON pass MEMBER "${json}" timings_ms ${i})
  string(JSON ms ERROR_VARIABLE missing GET "${json}" gpu_timings_ms ${pass})
  if(missing)
    fail("gpu_timings_ms has no \"${pass}\" (timings_ms has):\n${json}")
  endif()
  if(ms LESS 0)
    fail("gpu_timings_ms.${pass} = ${ms} < 0")
  endif()
endforeach()
message("--gpu list, 99, auto and 0 as documented; egl_device \"${device}\"")
