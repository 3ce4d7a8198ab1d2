// The page's entry points, compiled to WebAssembly with Emscripten (web/build_page.sh): a WebGL2
// context on the page's canvas, and a scene rendered as `pseudoshadow render` renders it (the
// same load_scene_or_default, make_view, open_renderer and render_scene_frames as
// src/app/commands/render_cmd.cpp), its colour read back as the 8-bit bytes the CLI's PNG holds.
// The page (web/page/) calls these through Module.ccall; docs/web.md.
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gl/context_internal.h"
#include "gl/gl.h"
#include "prepare/prepare.h"
#include "render/scene_frames.h"
#include "render/view.h"
#include "scene/scene_io.h"

namespace {

struct Page {
  EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = 0;
  std::string error, gl_renderer, gl_version;
  std::vector<std::uint8_t> rgba;  // the last render, top row first, alpha 255
  int width = 0, height = 0;
};
Page g_page;

// WebGL2 leaves out buffer mapping (WebGL 2.0 specification, 5.14), the only ES 3.0 calls it has
// not. The host code maps no buffer; these fill the four slots so the table is whole, and say so
// if anything ever calls them.
void no_mapping(const char* name) { std::fprintf(stderr, "pseudoshadow: WebGL2 has no %s (no buffer mapping)\n", name); }
void* APIENTRY map_buffer_range(GLenum, GLintptr, GLsizeiptr, GLbitfield) { return no_mapping("glMapBufferRange"), nullptr; }
GLboolean APIENTRY unmap_buffer(GLenum) { return no_mapping("glUnmapBuffer"), GL_FALSE; }
void APIENTRY flush_mapped_buffer_range(GLenum, GLintptr, GLsizeiptr) { no_mapping("glFlushMappedBufferRange"); }
void APIENTRY get_buffer_pointerv(GLenum, GLenum, void** params) {
  no_mapping("glGetBufferPointerv");
  *params = nullptr;
}

void* webgl_proc(const char* name) {
  if (void* p = emscripten_webgl_get_proc_address(name)) return p;
  const std::string n = name;
  if (n == "glMapBufferRange") return reinterpret_cast<void*>(map_buffer_range);
  if (n == "glUnmapBuffer") return reinterpret_cast<void*>(unmap_buffer);
  if (n == "glFlushMappedBufferRange") return reinterpret_cast<void*>(flush_mapped_buffer_range);
  if (n == "glGetBufferPointerv") return reinterpret_cast<void*>(get_buffer_pointerv);
  return nullptr;
}

int fail(const std::string& message) {
  g_page.error = message;
  return 1;
}

// As the CLI writes a PNG (src/image/png_io.cpp): clamp to [0,1], NaN as 0, round to nearest.
std::uint8_t to_byte(float v) {
  if (!(v > 0.0f)) return 0;
  if (v >= 1.0f) return 255;
  return static_cast<std::uint8_t>(v * 255.0f + 0.5f);
}

// The shipped data sits in the page's file system as an install puts it, at
// /share/pseudoshadow/{glsl,scenes,textures} (web/build_page.sh), and the desktop code finds it
// as it finds an install's (core/install_layout.h): from the file of the binary that holds the
// code, which it reads from /proc/self/maps. The page has no such file, so it writes one that
// names /bin/pseudoshadow as the binary, whose prefix holds the data; the scene loader then takes
// the shipped scenes, textures and shaders for what they are.
void name_the_binary() {
  std::filesystem::create_directories("/proc/self");
  std::ofstream("/proc/self/maps") << "00000000-ffffffff r-xp 00000000 00:00 0 /bin/pseudoshadow\n";
}

}  // namespace

extern "C" {

// Opens a WebGL2 context on the canvas `selector` ("#canvas") with the two extensions the
// renderer needs (float render targets, filtered float textures) and fills the GL table with its
// ES 3.0 entry points. 0 on success; else ps_web_error() says why.
EMSCRIPTEN_KEEPALIVE int ps_web_open_gl(const char* selector) {
  name_the_binary();
  EmscriptenWebGLContextAttributes attrs;
  emscripten_webgl_init_context_attributes(&attrs);
  attrs.majorVersion = 2;
  attrs.minorVersion = 0;
  attrs.alpha = false;
  attrs.depth = false;
  attrs.stencil = false;
  attrs.antialias = false;
  attrs.preserveDrawingBuffer = true;
  g_page.context = emscripten_webgl_create_context(selector, &attrs);
  if (g_page.context <= 0) return fail(std::string("no WebGL2 context on ") + selector);
  if (emscripten_webgl_make_context_current(g_page.context) != EMSCRIPTEN_RESULT_SUCCESS)
    return fail("the WebGL2 context could not be made current");
  for (const char* ext : {"EXT_color_buffer_float", "OES_texture_float_linear"})
    if (!emscripten_webgl_enable_extension(g_page.context, ext))
      return fail(std::string("this browser's WebGL2 lacks ") + ext + ", which the renderer needs");
  if (ps::Status s = ps::gl::detail::load_gles_and_query(webgl_proc, g_page.gl_renderer, g_page.gl_version); !s)
    return fail(s.error().message);
  return 0;
}

// Renders `scene_path` (a path in the page's file system; "" for the default scene) with
// `overrides` (newline-separated KEY=VALUE lines, as --set takes them) for the scene's
// render.frames frames. 0 on success; the image is then ps_web_pixels().
EMSCRIPTEN_KEEPALIVE int ps_web_render(const char* scene_path, const char* overrides) {
  std::vector<std::string> lines;
  std::istringstream in(overrides);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  auto scene = ps::load_scene_or_default(scene_path, lines);
  if (!scene) return fail(scene.error().message);
  auto view = ps::make_view(scene.value(), ps::ViewFlags{});  // the scene's start view, as `render`
  if (!view) return fail(view.error().message);
  ps::RendererOptions options;
  options.expected_frames = scene->render.frames;
  options.view = view.value();
  auto renderer = ps::open_renderer(scene.value(), options);
  if (!renderer) return fail(renderer.error().message);
  if (ps::Status s = ps::render_scene_frames(*renderer.value(), scene->render.frames); !s) return fail(s.error().message);
  const ps::Image color = renderer.value()->read_color();
  g_page.width = color.width;
  g_page.height = color.height;
  g_page.rgba.assign(static_cast<size_t>(color.width) * color.height * 4, 255);
  for (size_t p = 0; p < static_cast<size_t>(color.width) * color.height; ++p)
    for (int c = 0; c < 3; ++c) g_page.rgba[p * 4 + c] = to_byte(color.pixels[p * color.channels + c]);
  if (const GLenum e = glGetError(); e != GL_NO_ERROR) return fail("a WebGL error after the frames: " + std::to_string(e));
  return 0;
}

EMSCRIPTEN_KEEPALIVE const char* ps_web_error() { return g_page.error.c_str(); }
EMSCRIPTEN_KEEPALIVE const char* ps_web_gl_version() { return g_page.gl_version.c_str(); }
EMSCRIPTEN_KEEPALIVE const std::uint8_t* ps_web_pixels() { return g_page.rgba.data(); }
EMSCRIPTEN_KEEPALIVE int ps_web_width() { return g_page.width; }
EMSCRIPTEN_KEEPALIVE int ps_web_height() { return g_page.height; }

}  // extern "C"
