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

// --gpu: which EGL display a headless context opens (docs/gl-stack.md, "EGL devices").
struct GpuChoice {
  enum class Kind {
    kDefault,   // no --gpu: Mesa's surfaceless platform (then OSMesa under Backend::kAuto)
    kAuto,      // a hardware EGL device, else surfaceless, else OSMesa (under Backend::kAuto)
    kSoftware,  // Mesa's software EGL device (EGL_MESA_device_software)
    kIndex,     // EGL device `index` of eglQueryDevicesEXT's list
    kList,      // not a context: the CLI prints the devices and exits
  };
  Kind kind = Kind::kDefault;
  int index = -1;  // kIndex only
};
// "auto" | "list" | "software" | N -> GpuChoice; error names the accepted words.
Result<GpuChoice> parse_gpu(const std::string& text);

struct ContextDesc {
  Backend backend = Backend::kAuto;  // auto tries EGL, then OSMesa (never GLFW)
  // GLFW only: window size and title; headless backends ignore them.
  int window_width = 800, window_height = 600;
  std::string window_title = "pseudoshadow";
  bool visible = true;
  GpuChoice gpu;  // EGL and auto only; OSMesa with a --gpu other than the default is an error
  // An OpenGL ES 3.0 context instead of 4.5 core (EGL only): the API a WebGL2 page has. The host
  // code's desktop calls then run through their ES stand-ins (gl/es30.h).
  bool es = false;
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
  // The EGL display it runs on: "surfaceless", "device N (name)", or "none" (OSMesa, GLFW).
  // With --gpu auto it also says why ("... (no hardware EGL device)").
  const std::string& egl_device() const { return egl_device_; }
  void set_egl_device_note(const std::string& note) { egl_device_ += " (" + note + ")"; }

 protected:
  std::string renderer_, version_, egl_device_ = "none";
};

// Creates a 4.5 core context (or ES 3.0 with desc.es), makes it current and loads every GL entry
// point.
// On failure with kAuto the message names each backend tried and its error, on one line:
// "no OpenGL 4.5 context: egl: <why>; osmesa: <why>".
Result<std::unique_ptr<Context>> create_context(const ContextDesc& desc);

// The X display a GLFW window was opened on went away (the X server killed, a remote session
// dropped): any thread. Until then, and without a window, false. The window's loops end their
// session then, as on a stop signal (app/cli/stop_signal.h): calls on the dead connection do
// nothing, and the process is not ended by Xlib with its logs open.
bool display_lost();

}  // namespace ps::gl
