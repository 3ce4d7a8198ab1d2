#!/usr/bin/env bash
# Second CI step (docs/hardening.md), run by .ci/run after the README's test command:
#   1. ASan + UBSan build with clang (build-asan/): the unit and GL tests, and every libFuzzer
#      target on a fixed seed and input count (~20 s each), or for PS_FUZZ_SECONDS each if set;
#   2. TSan build (build-tsan/) of the haptic/render snapshot-exchange tests only.
# Expects tools/bootstrap.sh to have installed the packages (clang among them). Usage:
#   tools/sanitize.sh            # everything
#   PS_FUZZ_SECONDS=1800 tools/sanitize.sh   # longer fuzzing
set -euo pipefail
repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# As tools/bootstrap.sh: ccache hashes paths relative to the checkout, so clones share entries.
ccache_launcher="env;CCACHE_BASEDIR=${repo_root};CCACHE_NOHASHDIR=true;ccache"
jobs="$(nproc)"
log() { echo "sanitize: $*"; }

configure() {  # configure DIR [cmake args...] unless DIR is already configured
  local dir="$1"; shift
  if [ -f "${dir}/CMakeCache.txt" ] && [ -f "${dir}/Makefile" ]; then return 0; fi
  # No precompiled header here: ccache would hand clang a header built in another checkout, which
  # clang refuses by its timestamp, and these builds are not what a newcomer waits for.
  cmake -S "${repo_root}" -B "${dir}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_DISABLE_PRECOMPILE_HEADERS=ON \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    "-DCMAKE_C_COMPILER_LAUNCHER=${ccache_launcher}" "-DCMAKE_CXX_COMPILER_LAUNCHER=${ccache_launcher}" "$@" \
    > "${dir}.configure.log" ||
    { cat "${dir}.configure.log"; exit 1; }
}

asan="${repo_root}/build-asan"
log "ASan+UBSan build (${asan})"
configure "${asan}" -DPS_SANITIZE=address -DPS_FUZZ=ON
cmake -S "${repo_root}" -B "${asan}" -DPS_FUZZ_SECONDS="${PS_FUZZ_SECONDS:-}" > /dev/null
cmake --build "${asan}" -j"${jobs}"
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Unit tests: full leak checking. GL tests: leak checking off - Mesa's llvmpipe/OSMesa keep
# allocations until their DRI driver is unloaded at exit, and frames of the unloaded driver
# cannot be symbolized or suppressed; memory errors and undefined behaviour are still fatal.
log "unit tests under ASan+UBSan (leaks checked)"
# tools/lsan_suppressions.txt: leaks inside a library that are not ours, each with its reason.
ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS="suppressions=${repo_root}/tools/lsan_suppressions.txt" \
  ctest --test-dir "${asan}" -L unit --output-on-failure -j"${jobs}"
# The `window` walks (a real window under Xvfb, driven by xdotool for 15-30 s each) are left to
# the plain build: under ASan each would take minutes, and they test timing as a person sees it.
log "GL tests under ASan+UBSan (leaks not checked, see above; not the window walks)"
ASAN_OPTIONS=detect_leaks=0 ctest --test-dir "${asan}" -L gl -LE window --output-on-failure -j"${jobs}"
log "fuzz targets (${PS_FUZZ_SECONDS:-fixed seed and input count}${PS_FUZZ_SECONDS:+ s each})"
ctest --test-dir "${asan}" -L fuzz --output-on-failure -j"${jobs}"

tsan="${repo_root}/build-tsan"
log "TSan build of the snapshot-exchange tests (${tsan})"
configure "${tsan}" -DPS_SANITIZE=thread
cmake --build "${tsan}" -j"${jobs}" --target snapshot_test haptics_test
# Run the binaries directly: ctest would try to discover tests in the targets not built here.
TSAN_OPTIONS=halt_on_error=1 "${tsan}/tests/core/snapshot_test"
TSAN_OPTIONS=halt_on_error=1 "${tsan}/tests/haptics/haptics_test"
log "all sanitizer runs clean"
