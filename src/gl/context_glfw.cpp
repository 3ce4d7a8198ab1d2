// GLFW backend: a 4.5 core window (GLX or EGL underneath, also under Xvfb). GLFW 3.3 has no
// null platform, so without a display glfwInit fails; its error text is passed on verbatim.
#define GLFW_INCLUDE_NONE  // GL comes from our table; GLFW's <GL/gl.h> would clash with it
#include <GLFW/glfw3.h>

#include <string>

#include "gl/context_internal.h"
#include "gl/x_display.h"

namespace ps::gl::detail {
namespace {

// GLFW reports errors through a callback; keep the last one for the error value.
thread_local std::string g_glfw_error;

void on_glfw_error(int code, const char* description) {
  g_glfw_error = description ? description : ("GLFW error " + std::to_string(code));
}

Error glfw_failure(const char* call) {
  std::string why = g_glfw_error.empty() ? "no reason given" : g_glfw_error;
  return make_error(std::string(call) + " failed: " + why);
}

void* glfw_loader(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

class GlfwContext final : public Context {
 public:
  GlfwContext() = default;
  ~GlfwContext() override {
    unload_gl();
    if (window_ != nullptr) glfwDestroyWindow(window_);
    glfwTerminate();
  }
  GlfwContext(const GlfwContext&) = delete;
  GlfwContext& operator=(const GlfwContext&) = delete;

  Backend backend() const override { return Backend::kGlfw; }
  void make_current() override { glfwMakeContextCurrent(window_); }
  GLFWwindow* window() override { return window_; }
  Status init(const ContextDesc& desc);

 private:
  GLFWwindow* window_ = nullptr;
};

Status GlfwContext::init(const ContextDesc& desc) {
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, desc.visible ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(desc.window_width, desc.window_height, desc.window_title.c_str(),
                             nullptr, nullptr);
  if (window_ == nullptr) return glfw_failure("glfwCreateWindow(4.5 core)");
  glfwMakeContextCurrent(window_);
  return load_gl_and_query(glfw_loader, renderer_, version_);
}

}  // namespace

Result<std::unique_ptr<Context>> create_glfw_context(const ContextDesc& desc) {
  g_glfw_error.clear();
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) return glfw_failure("glfwInit");
  // From here the context object owns GLFW: its destructor terminates it on failure.
  auto context = std::make_unique<GlfwContext>();
  if (Status s = context->init(desc); !s) return s.error();
  watch_x_display();
  return std::unique_ptr<Context>(std::move(context));
}

}  // namespace ps::gl::detail
