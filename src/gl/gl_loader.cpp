// load_gl / gl_loaded over the generated pointer table (gl_loader_generated.cpp).
#include <cassert>

#include "gl/context_internal.h"
#include "gl/es30.h"
#include "gl/gl.h"

namespace ps::gl {
namespace {
bool g_loaded = false;  // render thread only, like every GL call

int fill_table(ProcLoader loader, const char** first_missing) {
  const int missing = ps_gl_load_table(loader, first_missing);
  g_loaded = glGetString != nullptr && glGetIntegerv != nullptr;
  return missing;
}

// GL_RENDERER and GL_VERSION into the strings; returns major * 10 + minor.
int read_version(std::string& renderer, std::string& version) {
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  renderer = r ? r : "";
  version = v ? v : "";
  return major * 10 + minor;
}

}  // namespace

int load_gl(ProcLoader loader) {
  assert(loader != nullptr && "load_gl: loader is null");
  const char* first_missing = nullptr;
  return fill_table(loader, &first_missing);
}

bool gl_loaded() { return g_loaded; }

namespace detail {

Status load_gl_and_query(ProcLoader loader, std::string& renderer, std::string& version) {
  const char* first_missing = nullptr;
  if (const int missing = fill_table(loader, &first_missing); missing != 0) {
    unload_gl();
    return make_error(std::to_string(missing) + " of " + std::to_string(kPsGlCoreEntryPoints) +
                      " core GL entry points did not resolve (first: " + first_missing + ")");
  }
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  if (read_version(renderer, version) < 45 || (profile & GL_CONTEXT_CORE_PROFILE_BIT) == 0) {
    unload_gl();
    return make_error("context is not 4.5 core (GL_VERSION \"" + version + "\")");
  }
  return ok_status();
}

// ES: only the names of GLES3/gl3.h go to `es_loader` (the rest stay null), so what runs is what
// ES 3.0 and WebGL2 have; then the desktop slots get their stand-ins (gl/es30.h).
namespace {
Loader es_loader = nullptr;
void* es30_only(const char* name) { return ps_gl_is_es30(name) ? es_loader(name) : nullptr; }
}  // namespace

Status load_gles_and_query(Loader loader, std::string& renderer, std::string& version) {
  es_loader = loader;
  ps_gl_load_table(es30_only, nullptr);
  es_loader = nullptr;
  g_loaded = glGetString != nullptr && glGetIntegerv != nullptr;
  // Every ES 3.0 entry point must resolve: the table has no other source for them.
  const char* first_missing = nullptr;
  if (const int missing = ps_gl_es30_missing(loader, &first_missing); missing != 0 || !g_loaded) {
    unload_gl();
    return make_error(std::to_string(missing) + " of the OpenGL ES 3.0 entry points did not resolve (first: " +
                      (first_missing ? first_missing : "glGetString") + ")");
  }
  if (read_version(renderer, version) < 30 || version.rfind("OpenGL ES", 0) != 0) {
    unload_gl();
    return make_error("context is not OpenGL ES 3.0 or later (GL_VERSION \"" + version + "\")");
  }
  install_es30();
  return ok_status();
}

void unload_gl() {
  reset_es30();
  ps_gl_clear_table();
  g_loaded = false;
}

}  // namespace detail
}  // namespace ps::gl
