// OpenGL 4.5 core contexts behind one interface: EGL surfaceless (default headless), OSMesa
// (headless fallback) and GLFW (window, also under Xvfb). All three share one render path:
// the renderer draws into its own FBOs and never touches a default framebuffer.
#pragma once

#include <memory>
#include <string>

#include "core/result.h"

struct GLFWwindow;

namespace ps::gl {

enum class Backend { kAuto, kEgl, kOsmesa, kGlfw };

// "auto" | "egl" | "osmesa" | "glfw" -> Backend; error names the accepted words.
Result<Backend> parse_backend(const std::string& name);
const char* backend_name(Backend backend);

struct ContextDesc {
  Backend backend = Backend::kAuto;  // auto tries EGL, then OSMesa (never GLFW)
  // GLFW only: window size and title; headless backends ignore them.
  int window_width = 800, window_height = 600;
  std::string window_title = "pseudoshadow";
  bool visible = true;
};

class Context {
 public:
  virtual ~Context() = default;
  virtual Backend backend() const = 0;
  virtual void make_current() = 0;
  // GLFW only (nullptr otherwise).
  virtual GLFWwindow* window() { return nullptr; }
  // GL_RENDERER and GL_VERSION strings, read once after creation.
  const std::string& renderer() const { return renderer_; }
  const std::string& version() const { return version_; }

 protected:
  std::string renderer_, version_;
};

// Creates a 4.5 core context, makes it current and loads every GL entry point.
// On failure with kAuto the message names each backend tried and its error, on one line:
// "no OpenGL 4.5 context: egl: <why>; osmesa: <why>".
Result<std::unique_ptr<Context>> create_context(const ContextDesc& desc);

}  // namespace ps::gl
