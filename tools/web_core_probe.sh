#!/usr/bin/env bash
# The CPU core (scene model, haptic scene, haptic loop) compiled to WebAssembly with Debian's
# Emscripten and run by node, against the same probe built natively: the first step of a browser
# build (docs/web.md). Not part of the test suite (CI has no Emscripten); run it by hand:
#   sudo apt-get install emscripten        # Debian 12: Emscripten 3.1.6, clang 14, node-acorn
#   cmake --build build --target ps_haptics ps_world ps_scene ps_devices ps_fourd ps_image ps_file_io
#   bash tools/web_core_probe.sh [OUT_DIR]  # default: build/web_core_probe
# Prints the files that do not compile for WebAssembly, the two probes' outputs, and exits 0 when
# they are equal to the last digit.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/build/web_core_probe}"
if ! command -v em++ > /dev/null; then
  echo "web_core_probe: em++ not found: install Debian's emscripten (apt-get install emscripten)" >&2
  exit 2
fi
[[ -f "$root/build/src/scene/default_scene_text.cpp" ]] || { echo "web_core_probe: configure and build build/ first" >&2; exit 2; }
# Debian's emcc runs acorn from Debian's node modules; node >= 18's fetch breaks 3.1.6's loader
# for local .wasm files, hence --no-experimental-fetch below.
export NODE_PATH=/usr/share/nodejs
mkdir -p "$out/obj" "$out/inc"
ln -sfn /usr/include/glm "$out/inc/glm"
ln -sfn /usr/include/toml++ "$out/inc/toml++"
# The CPU rooms, less what a page does differently: the loop's own thread (a page drives it with
# haptics/catch_up.h), RealtimeKit, GLFW input, assimp's mesh files, the Embree BVH.
cd "$root"
sources=$(ls src/core/*.cpp src/fourd/*.cpp src/devices/*.cpp src/scene/*.cpp src/world/*.cpp src/haptics/*.cpp \
  src/haptics/effects/*.cpp | grep -v -e glfw_input -e mesh_file -e mesh_bvh -e rtkit -e haptic_loop_thread)
compiled=0 failed=()
for f in $sources build/src/scene/default_scene_text.cpp; do
  o="$out/obj/$(echo "$f" | tr / _).o"
  if em++ -std=c++20 -O2 -I src -I "$out/inc" -c "$f" -o "$o" 2> "$o.log"; then
    compiled=$((compiled + 1))
  else
    failed+=("$f: $(grep -m1 'error' "$o.log" || true)")
    rm -f "$o"
  fi
done
echo "compiled for WebAssembly: $compiled files; failed: ${#failed[@]}"
for f in "${failed[@]}"; do echo "  $f"; done
em++ -std=c++20 -O2 -I src -I "$out/inc" -c tools/web_core_probe/probe_main.cpp -o "$out/probe_main.o"
em++ -std=c++20 -O2 -I src -I "$out/inc" -c web/src/stand_ins.cpp -o "$out/stand_ins.o"
em++ -std=c++20 -O2 -I src -I "$out/inc" -c tools/web_core_probe/no_images.cpp -o "$out/no_images.o"
em++ -O2 "$out/probe_main.o" "$out/stand_ins.o" "$out/no_images.o" "$out"/obj/*.o -o "$out/probe.js" -sNODERAWFS=1 -sALLOW_MEMORY_GROWTH=1
libs=build/src
g++ -std=c++20 -O2 -I src tools/web_core_probe/probe_main.cpp build/src/scene/default_scene_text.cpp -o "$out/probe_native" \
  $libs/haptics/libps_haptics.a $libs/world/libps_world.a $libs/devices/libps_devices.a $libs/scene/libps_scene.a \
  $libs/fourd/libps_fourd.a $libs/image/libps_image.a $libs/core/libps_file_io.a \
  -ltomlplusplus -lembree3 -lassimp -lpng -ldbus-1 -lpthread -ldl
wasm_out=$(node --no-experimental-fetch "$out/probe.js" "$root/scenes")
native_out=$("$out/probe_native" "$root/scenes")
echo "native:"; echo "$native_out"
echo "WebAssembly:"; echo "$wasm_out"
if [[ "$wasm_out" == "$native_out" ]]; then
  echo "web_core_probe: the same state to the last digit"
else
  echo "web_core_probe: the states differ" >&2
  exit 1
fi
