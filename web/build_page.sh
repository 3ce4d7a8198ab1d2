#!/usr/bin/env bash
# The page's WebAssembly build with Debian's Emscripten (docs/web.md): the scene model, the world,
# the renderer, its passes and the scene preparation compiled as they are for the desktop, with
# web/src's entry points (page_main.cpp), the browser's image decoding (image_web.cpp) and the
# stand-ins for what has no WebAssembly build (stand_ins.cpp: assimp's mesh files, Embree).
#   sudo apt-get install emscripten
#   cmake --build build --target ps_gl_loader_gen ps_scene   # the generated sources it takes
#   bash web/build_page.sh [OUT_DIR]                          # default: build/web
# Writes OUT_DIR/pseudoshadow.{js,wasm,data} and the page's files (web/page/) beside them; serve
# OUT_DIR with any static server (python3 -m http.server). Compilations go through ccache when
# it is installed, so a second build compiles only what changed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/build/web}"
if ! command -v em++ > /dev/null; then
  echo "build_page: em++ not found: install Debian's emscripten (apt-get install emscripten)" >&2
  exit 2
fi
native="${PS_NATIVE_BUILD:-$root/build}"  # the configured desktop build (its generated sources)
gen_gl="$native/src/gl/include"
scene_text="$native/src/scene/default_scene_text.cpp"
for f in "$gen_gl/gl/gl_loader_generated.cpp" "$scene_text"; do
  [[ -f "$f" ]] || { echo "build_page: $f missing: configure build/ and build ps_gl_loader_gen and ps_scene first" >&2; exit 2; }
done
# Debian's emcc runs acorn from Debian's node modules.
export NODE_PATH=/usr/share/nodejs
command -v ccache > /dev/null && export EM_COMPILER_WRAPPER=ccache
mkdir -p "$out/obj" "$out/inc/GL"
# Header-only libraries and the desktop GL header the generated table is declared from.
ln -sfn /usr/include/glm "$out/inc/glm"
ln -sfn /usr/include/toml++ "$out/inc/toml++"
ln -sfn /usr/include/nlohmann "$out/inc/nlohmann"
ln -sfn /usr/include/GL/glcorearb.h "$out/inc/GL/glcorearb.h"
cd "$root"
# What has no place in the page: contexts other than WebGL2's, the image files' readers (libpng,
# OpenImageIO), assimp's files, the Embree BVH, the loop's own thread and RealtimeKit, GLFW input.
sources=$(ls src/core/*.cpp src/fourd/*.cpp src/scene/*.cpp src/world/*.cpp src/image/*.cpp src/gl/*.cpp \
  src/reference/*.cpp src/passes/*.cpp src/render/*.cpp src/prepare/*.cpp |
  grep -v -e 'src/gl/context' -e egl_device -e x_display -e glslcheck_main -e mesh_file -e mesh_bvh \
    -e png_io -e oiio_module -e 'src/image/image_io.cpp')
flags=(-std=c++20 -O2 -I src -I "$gen_gl" -I "$out/inc")
compile() {  # source -> object; prints the first error line on failure
  local f=$1 o
  o="$out/obj/$(echo "$f" | tr / _).o"
  em++ "${flags[@]}" -c "$f" -o "$o" 2> "$o.log" || { echo "  $f: $(grep -m1 'error' "$o.log")"; return 1; }
}
export -f compile
export out
export flags_string="${flags[*]}"
started=${SECONDS}
all=($sources "$scene_text" "$gen_gl/gl/gl_loader_generated.cpp" web/src/page_main.cpp web/src/image_web.cpp web/src/stand_ins.cpp)
echo "build_page: compiling ${#all[@]} files for WebAssembly"
rm -f "$out"/obj/*.o "$out/pseudoshadow".*
printf '%s\n' "${all[@]}" | xargs -P "$(nproc)" -I{} bash -c 'flags=($flags_string); compile "$@"' _ {}
compiled=$(ls "$out"/obj/*.o | wc -l)
[[ $compiled -eq ${#all[@]} ]] || { echo "build_page: $((${#all[@]} - compiled)) files did not compile (above)" >&2; exit 1; }
exports=_ps_web_open_gl,_ps_web_render,_ps_web_error,_ps_web_gl_version,_ps_web_pixels,_ps_web_width,_ps_web_height
em++ -O2 "$out"/obj/*.o -o "$out/pseudoshadow.js" \
  -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2 -sALLOW_MEMORY_GROWTH=1 \
  -sEXPORTED_FUNCTIONS="$exports" -sEXPORTED_RUNTIME_METHODS=ccall,UTF8ToString \
  --use-preload-plugins --preload-file glsl@/share/pseudoshadow/glsl --preload-file scenes@/share/pseudoshadow/scenes \
  --preload-file textures@/share/pseudoshadow/textures \
  --exclude-file '*.md'
cp web/page/* "$out/"
echo "build_page: $out/pseudoshadow.{js,wasm,data} and the page in $((SECONDS - started)) s; serve it with: python3 -m http.server -d $out"
