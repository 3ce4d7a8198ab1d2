#!/usr/bin/env bash
# Set up a fresh Debian 12 machine and build pseudoshadow. Idempotent: installs only missing
# packages (apt is not touched at all when everything is present), configures build/ only when it
# is not configured yet (later CMakeLists changes are picked up by `cmake --build` itself), then
# builds. Works from any directory.
#
# Usage: tools/bootstrap.sh           the program only: what the first image needs (README command 1)
#        tools/bootstrap.sh --tests   everything: the test binaries and their tools too (command 2)
#
# Each phase prints its elapsed time, so a slow first run shows where the time went.
set -euo pipefail

# What building and running the program needs (the first image, the window, sound, devices).
readonly kPackages=(
  build-essential cmake pkg-config ccache
  libglfw3-dev libx11-dev libglm-dev libosmesa6-dev libegl-dev libegl1-mesa-dev libgl1-mesa-dri libgl-dev libgles-dev
  glslang-dev glslang-tools spirv-tools
  libopenimageio-dev openimageio-tools libpng-dev  # the tools: OpenImageIO's CMake config checks oiiotool
  libgtest-dev libgmock-dev libbenchmark-dev
  libassimp-dev assimp-testmodels libembree-dev libimgui-dev libtomlplusplus-dev nlohmann-json3-dev
  libcli11-dev gnuplot-nox
  libssl-dev  # libcrypto: the SHA-256 checksums of `study run`'s trial logs (docs/study.md)
  libopenal-dev libsndfile1-dev libsdl2-dev pybind11-dev python3-dev python3-numpy
  libdbus-1-dev dbus rtkit
)
# What only the test suite and its sanitizer step need (`--tests`): the window tests' X server
# and input, the compilers for sanitizer and fuzz builds, Python test tools, packaging checks.
readonly kTestPackages=(
  xvfb xauth xdotool clang libclang-rt-14-dev dpkg-dev file
  python3-pytest python3-matplotlib python3-pil parallel  # python3-pil: window tests find targets in screenshots
  r-base-core  # R's glm(): the outside check of the study's psychometric fit (docs/study.md)
)

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${repo_root}/build"
# The sloppiness lets ccache cache files compiled with a precompiled header (src/app's CLI11):
# without it ccache compiles them every time (ccache's manual, "Precompiled headers").
ccache_launcher="env;CCACHE_BASEDIR=${repo_root};CCACHE_NOHASHDIR=true;CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime;ccache"
with_tests=0
installed_now=0  # set when install_packages installed something (configure then re-runs cmake)
started=${SECONDS}
phase_started=${SECONDS}

log() { echo "bootstrap: $*"; }
die() { echo "bootstrap: error: $*" >&2; exit 1; }

# "name: 1 min 05 s (total 3 min 10 s)": how long the phase just finished took, and the run so far.
phase_done() {
  local took=$((SECONDS - phase_started)) total=$((SECONDS - started))
  printf 'bootstrap: %s: %d min %02d s (total %d min %02d s)\n' "$1" $((took / 60)) $((took % 60)) \
    $((total / 60)) $((total % 60))
  phase_started=${SECONDS}
}

# `dpkg -s` also succeeds for removed packages whose config files remain, so check the status line.
is_installed() {
  dpkg -s "$1" 2>/dev/null | grep -q '^Status: install ok installed$'
}

wanted_packages() {
  printf '%s\n' "${kPackages[@]}"
  [ "${with_tests}" -eq 0 ] || printf '%s\n' "${kTestPackages[@]}"
}

missing_packages() {
  local pkg
  while read -r pkg; do
    is_installed "${pkg}" || echo "${pkg}"
  done < <(wanted_packages)
}

install_packages() {
  local -a missing
  mapfile -t missing < <(missing_packages)
  if [ "${#missing[@]}" -eq 0 ]; then
    log "all $(wanted_packages | wc -l) packages present"
    return 0
  fi
  local -a as_root=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null 2>&1 ||
      die "not root and no sudo; as root run: apt-get install -y --no-install-recommends ${missing[*]}"
    as_root=(sudo)
  fi
  log "installing ${#missing[@]} packages: ${missing[*]}"
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update ||
    die "apt-get update failed"
  "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}" ||
    die "apt-get install failed for: ${missing[*]}"
  installed_now=1
}

configure() {
  # A failed configure leaves a cache but no build files: only then does it count as configured.
  if [ -f "${build_dir}/CMakeCache.txt" ] &&
     { [ -f "${build_dir}/Makefile" ] || [ -f "${build_dir}/build.ninja" ]; }; then
    if [ "${installed_now}" -eq 1 ]; then
      # Tests that need a tool (Xvfb, xdotool, pytest, R ...) are registered at configure time
      # only where it is found: command 1 configured before --tests installed them, and without
      # this cmake run command 2 would leave those tests out (seen: 19 window tests).
      log "packages were installed: re-running cmake so the tests that need them are registered"
      cmake -S "${repo_root}" -B "${build_dir}" || die "cmake configure failed"
      return 0
    fi
    log "build/ already configured (cmake --build re-runs cmake if CMakeLists changed)"
    return 0
  fi
  log "configuring ${build_dir}"
  # ccache (installed above) makes rebuilds of an unchanged file, in this or another checkout,
  # a cache hit; it never changes what is built. Paths are hashed relative to the checkout
  # (CCACHE_BASEDIR, CCACHE_NOHASHDIR), so a fresh clone elsewhere hits the same entries.
  # -g1: line tables only (backtraces, core dumps and sanitizer reports keep file:line; no
  # variables): full -g made every file 20-40 % slower to compile (docs/contributing.md, "Compile
  # time"). For a debugger session configure another folder with -DCMAKE_BUILD_TYPE=Debug.
  cmake -S "${repo_root}" -B "${build_dir}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
    "-DCMAKE_C_COMPILER_LAUNCHER=${ccache_launcher}" "-DCMAKE_CXX_COMPILER_LAUNCHER=${ccache_launcher}" ||
    die "cmake configure failed"
}

# Without --tests only the program is built (shaders and data are read from the sources at run
# time through build/share/pseudoshadow); the test binaries, the Python module, the benchmarks'
# extra programs and the shader validation targets come with --tests.
build() {
  if [ "${with_tests}" -eq 1 ]; then
    log "building everything (program and tests) with $(nproc) jobs"
    cmake --build "${build_dir}" -j"$(nproc)" || die "build failed"
    return 0
  fi
  log "building the program with $(nproc) jobs (the tests build with --tests)"
  cmake --build "${build_dir}" -j"$(nproc)" --target pseudoshadow || die "build failed"
}

parse_args() {
  local arg
  for arg in "$@"; do
    case "${arg}" in
      --tests) with_tests=1 ;;
      -h|--help) sed -n '2,10p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
      *) die "unknown argument '${arg}' (use --tests to build the test suite too, or --help)" ;;
    esac
  done
}

main() {
  parse_args "$@"
  cd "${repo_root}"
  command -v dpkg >/dev/null 2>&1 || die "dpkg not found: this script targets Debian 12"
  install_packages
  phase_done "packages"
  configure
  phase_done "configure"
  build
  phase_done "build"
  if [ "${with_tests}" -eq 1 ]; then
    log "done; run the tests with: ctest --test-dir ${build_dir} --output-on-failure -j$(nproc)"
  else
    log "done; the program is ${build_dir}/pseudoshadow"
  fi
}

main "$@"
