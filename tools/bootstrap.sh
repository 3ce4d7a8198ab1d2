#!/usr/bin/env bash
# Set up a fresh Debian 12 machine and build pseudoshadow. Idempotent: installs only missing
# packages (apt is not touched at all when everything is present), configures build/ only when it
# is not configured yet (later CMakeLists changes are picked up by `cmake --build` itself), then
# builds. Works from any directory. Usage: tools/bootstrap.sh
set -euo pipefail

readonly kPackages=(
  build-essential cmake pkg-config
  libglfw3-dev libglm-dev libosmesa6-dev libegl-dev libegl1-mesa-dev libgl1-mesa-dri libgl-dev
  glslang-dev glslang-tools spirv-tools
  libopenimageio-dev openimageio-tools libpng-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libassimp-dev assimp-testmodels libembree-dev libimgui-dev libtomlplusplus-dev nlohmann-json3-dev
  libcli11-dev gnuplot-nox xvfb xauth clang libclang-rt-14-dev ccache dpkg-dev file
  libopenal-dev libsndfile1-dev libsdl2-dev pybind11-dev python3-dev python3-numpy python3-pytest
  python3-matplotlib parallel xdotool libdbus-1-dev dbus rtkit
)

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${repo_root}/build"
ccache_launcher="env;CCACHE_BASEDIR=${repo_root};CCACHE_NOHASHDIR=true;ccache"

log() { echo "bootstrap: $*"; }
die() { echo "bootstrap: error: $*" >&2; exit 1; }

# `dpkg -s` also succeeds for removed packages whose config files remain, so check the status line.
is_installed() {
  dpkg -s "$1" 2>/dev/null | grep -q '^Status: install ok installed$'
}

missing_packages() {
  local pkg
  for pkg in "${kPackages[@]}"; do
    is_installed "${pkg}" || echo "${pkg}"
  done
}

install_packages() {
  local -a missing
  mapfile -t missing < <(missing_packages)
  if [ "${#missing[@]}" -eq 0 ]; then
    log "all ${#kPackages[@]} packages present"
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
}

configure() {
  # A failed configure leaves a cache but no build files: only then does it count as configured.
  if [ -f "${build_dir}/CMakeCache.txt" ] &&
     { [ -f "${build_dir}/Makefile" ] || [ -f "${build_dir}/build.ninja" ]; }; then
    log "build/ already configured (cmake --build re-runs cmake if CMakeLists changed)"
    return 0
  fi
  log "configuring ${build_dir}"
  # ccache (installed above) makes rebuilds of an unchanged file, in this or another checkout,
  # a cache hit; it never changes what is built. Paths are hashed relative to the checkout
  # (CCACHE_BASEDIR, CCACHE_NOHASHDIR), so a fresh clone elsewhere hits the same entries.
  cmake -S "${repo_root}" -B "${build_dir}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_C_COMPILER_LAUNCHER=${ccache_launcher}" "-DCMAKE_CXX_COMPILER_LAUNCHER=${ccache_launcher}" ||
    die "cmake configure failed"
}

build() {
  log "building with $(nproc) jobs"
  cmake --build "${build_dir}" -j"$(nproc)" || die "build failed"
  log "done; run the tests with: ctest --test-dir ${build_dir} --output-on-failure"
}

main() {
  cd "${repo_root}"
  command -v dpkg >/dev/null 2>&1 || die "dpkg not found: this script targets Debian 12"
  install_packages
  configure
  build
}

main "$@"
