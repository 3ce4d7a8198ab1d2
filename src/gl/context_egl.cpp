// EGL backend: Mesa's surfaceless platform (EGL_MESA_platform_surfaceless) by default, or one EGL
// device (EGL_EXT_platform_device: the NVIDIA driver's only headless path, and Mesa's software
// device). No window system, no default framebuffer, no environment variables either way.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <string>

#include "gl/context_internal.h"
#include "gl/egl_device.h"

namespace ps::gl::detail {
namespace {

const char* egl_error_name(EGLint code) {
  switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "unknown EGL error";
  }
}

// "<call> failed: EGL_BAD_MATCH" from the thread's last EGL error.
Error egl_failure(const char* call) {
  return make_error(std::string(call) + " failed: " + egl_error_name(eglGetError()));
}

void* egl_loader(const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

class EglContext final : public Context {
 public:
  EglContext(EGLDisplay display, std::string device, bool es) : display_(display), es_(es) {
    egl_device_ = std::move(device);
  }
  ~EglContext() override {
    unload_gl();
    // Order: release current, destroy the context, then terminate the display (which would
    // otherwise keep the context alive) and drop this thread's EGL state.
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
    eglReleaseThread();
  }
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  Backend backend() const override { return Backend::kEgl; }
  void make_current() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_);
  }
  Status init();

 private:
  EGLDisplay display_;
  EGLContext context_ = EGL_NO_CONTEXT;
  bool es_ = false;  // OpenGL ES 3.0 (ContextDesc::es)
};

Status EglContext::init() {
  if (es_) {
    if (!eglBindAPI(EGL_OPENGL_ES_API)) return egl_failure("eglBindAPI(EGL_OPENGL_ES_API)");
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (context_ == EGL_NO_CONTEXT) return egl_failure("eglCreateContext(ES 3.0)");
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      return egl_failure("eglMakeCurrent(EGL_NO_SURFACE)");
    return load_gles_and_query(egl_loader, renderer_, version_);
  }
  if (!eglBindAPI(EGL_OPENGL_API)) return egl_failure("eglBindAPI(EGL_OPENGL_API)");
  // No config: surfaceless rendering needs none (EGL_KHR_no_config_context, Mesa supports it).
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                            EGL_CONTEXT_MINOR_VERSION, 5,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                            EGL_NONE};
  context_ = eglCreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
  if (context_ == EGL_NO_CONTEXT) return egl_failure("eglCreateContext(4.5 core)");
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    return egl_failure("eglMakeCurrent(EGL_NO_SURFACE)");
  }
  return load_gl_and_query(egl_loader, renderer_, version_);
}

PFNEGLGETPLATFORMDISPLAYEXTPROC platform_display_entry() {
  return reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
}

Result<EGLDisplay> initialize(EGLDisplay display, const char* what) {
  if (display == EGL_NO_DISPLAY) return egl_failure(what);
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor)) return egl_failure("eglInitialize");
  return display;
}

Result<EGLDisplay> open_surfaceless_display() {
  auto get_display = platform_display_entry();
  if (get_display == nullptr) return make_error("eglGetPlatformDisplayEXT not available");
  return initialize(get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
                    "eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)");
}

// The index --gpu names: N itself, or the software device's place in the list.
Result<EglDeviceInfo> pick_device(const GpuChoice& gpu) {
  auto devices = list_egl_devices();
  if (!devices) return devices.error();
  const int n = static_cast<int>(devices->size());
  if (gpu.kind == GpuChoice::Kind::kIndex) {
    if (gpu.index >= 0 && gpu.index < n) return (*devices)[static_cast<std::size_t>(gpu.index)];
    return make_error("no EGL device " + std::to_string(gpu.index) + " (" + std::to_string(n) +
                      " device" + (n == 1 ? "" : "s") + "; see --gpu list)");
  }
  for (const EglDeviceInfo& d : devices.value())
    if (d.software) return d;
  return make_error("no software EGL device (EGL_MESA_device_software; see --gpu list)");
}

Result<EGLDisplay> open_device_display(const EglDeviceInfo& info) {
  auto devices = query_egl_devices();
  if (!devices) return devices.error();
  auto get_display = platform_display_entry();
  if (get_display == nullptr) return make_error("eglGetPlatformDisplayEXT not available");
  void* device = (*devices)[static_cast<std::size_t>(info.index)];
  return initialize(get_display(EGL_PLATFORM_DEVICE_EXT, device, nullptr),
                    "eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT)");
}

}  // namespace

Result<std::unique_ptr<Context>> create_egl_context(const ContextDesc& desc) {
  std::string device_name = "surfaceless";
  Result<EGLDisplay> display = make_error("unset");
  if (desc.gpu.kind == GpuChoice::Kind::kIndex || desc.gpu.kind == GpuChoice::Kind::kSoftware) {
    auto device = pick_device(desc.gpu);
    if (!device) return device.error();
    device_name = "device " + std::to_string(device->index) + " (" + device->name + ")";
    display = open_device_display(device.value());
  } else {
    display = open_surfaceless_display();
  }
  if (!display) return display.error();
  // From here the context object owns the display: its destructor terminates it on failure.
  auto context = std::make_unique<EglContext>(display.value(), device_name, desc.es);
  if (Status s = context->init(); !s) return s.error();
  return std::unique_ptr<Context>(std::move(context));
}

}  // namespace ps::gl::detail
