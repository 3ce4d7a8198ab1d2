#include "app/window/live_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdint>

#include "app/session/session.h"
#include "gl/context.h"
#include "gl/gl.h"
#include "render/renderer.h"

namespace ps {

namespace {

// The window's user pointer is LiveWindow::listener_'s address: the slot, not the listener, so
// listen() needs no GLFW call and a destroyed window's late events reach `ignore_`.
WindowListener& listener_of(GLFWwindow* w) { return **static_cast<WindowListener**>(glfwGetWindowUserPointer(w)); }

void on_key(GLFWwindow* w, int key, int /*scancode*/, int action, int mods) {
  listener_of(w).on_key(key, action, mods);
}
void on_char(GLFWwindow* w, unsigned int codepoint) { listener_of(w).on_char(codepoint); }

void on_scroll(GLFWwindow* w, double /*dx*/, double dy) {
  const bool shift =
      glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS || glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  listener_of(w).on_scroll(dy, shift);
}

void on_button(GLFWwindow* w, int button, int action, int /*mods*/) {
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(w, &x, &y);
  listener_of(w).on_mouse_button(button, action, x, y);
}

void on_cursor(GLFWwindow* w, double x, double y) { listener_of(w).on_cursor(x, y); }
void on_enter(GLFWwindow* w, int entered) { listener_of(w).on_enter(entered != 0); }
void on_focus(GLFWwindow* w, int focused) { listener_of(w).on_focus(focused != 0); }

// Ours first: ImGui_ImplGlfw_InitForOpenGL(..., true) then chains every callback it installs to
// the one it found.
void install_callbacks(GLFWwindow* w) {
  glfwSetKeyCallback(w, on_key);
  glfwSetCharCallback(w, on_char);
  glfwSetScrollCallback(w, on_scroll);
  glfwSetMouseButtonCallback(w, on_button);
  glfwSetCursorPosCallback(w, on_cursor);
  glfwSetCursorEnterCallback(w, on_enter);
  glfwSetWindowFocusCallback(w, on_focus);
}

}  // namespace

Result<std::unique_ptr<LiveWindow>> LiveWindow::open(const LiveWindowDesc& desc) {
  gl::ContextDesc cd;
  cd.backend = gl::Backend::kGlfw;
  cd.window_width = desc.width;
  cd.window_height = desc.height;
  cd.window_title = desc.title;
  auto ctx = gl::create_context(cd);
  if (!ctx) return ctx.error();
  return std::unique_ptr<LiveWindow>(new LiveWindow(std::move(ctx.value())));
}

LiveWindow::LiveWindow(std::unique_ptr<gl::Context> ctx) : ctx_(std::move(ctx)), window_(ctx_->window()) {
  glfwSetWindowUserPointer(window_, &listener_);
  install_callbacks(window_);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
}

LiveWindow::~LiveWindow() {
  listener_ = &ignore_;  // the listener may be gone already; events while closing are dropped
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void LiveWindow::poll_events() { glfwPollEvents(); }
void LiveWindow::wait_events(double timeout_s) { glfwWaitEventsTimeout(timeout_s); }
bool LiveWindow::should_close() const { return glfwWindowShouldClose(window_) != 0; }
bool LiveWindow::hovered() const {
  return !gl::display_lost() && glfwGetWindowAttrib(window_, GLFW_HOVERED) == GLFW_TRUE;
}

int LiveWindow::refresh_hz() const {
  if (gl::display_lost()) return 0;
  GLFWmonitor* const monitor = glfwGetPrimaryMonitor();
  const GLFWvidmode* const mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
  return mode ? std::max(mode->refreshRate, 0) : 0;
}

// Once the display is gone (gl::display_lost; the very call that finds it so may be this one)
// the window's size can no longer be asked (GLFW leaves garbage): the last size asked stands,
// and the session's loop ends its session.
glm::ivec2 LiveWindow::window_size() const {
  glm::ivec2 s(0);
  if (!gl::display_lost()) glfwGetWindowSize(window_, &s.x, &s.y);
  if (!gl::display_lost()) last_window_size_ = s;
  return last_window_size_;
}

glm::ivec2 LiveWindow::framebuffer_size() const {
  glm::ivec2 s(0);
  if (!gl::display_lost()) glfwGetFramebufferSize(window_, &s.x, &s.y);
  if (!gl::display_lost()) last_framebuffer_size_ = s;
  return last_framebuffer_size_;
}

std::optional<glm::dvec2> LiveWindow::pointer_in_window() const {
  if (gl::display_lost()) return std::nullopt;
  const glm::ivec2 size = window_size();
  glm::dvec2 p(0.0);
  glfwGetCursorPos(window_, &p.x, &p.y);
  if (p.x >= 0.0 && p.y >= 0.0 && p.x < size.x && p.y < size.y) return p;
  return std::nullopt;
}

void LiveWindow::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

void LiveWindow::begin_frame_on_black() {
  const glm::ivec2 fb = framebuffer_size();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, fb.x, fb.y);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  begin_frame();
}

void LiveWindow::begin_frame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGuiIO& io = ImGui::GetIO();
  const ImVec2 size = io.DisplaySize, scale = io.DisplayFramebufferScale;
  if (!gl::display_lost()) ImGui_ImplGlfw_NewFrame();
  if (gl::display_lost()) {  // the window cannot be asked (window_size): the last frame's size stands
    io.DisplaySize = size;
    io.DisplayFramebufferScale = scale;
    io.DeltaTime = 1.f / 60.f;
  }
  ImGui::NewFrame();
}

void LiveWindow::draw_frame_image(const Renderer& renderer, const UiRect& dst) {
  const gl::Texture& color = renderer.color_texture();
  // The colour target may be larger than the image (padded): sample the image's region only.
  GLint tw = 1, th = 1;
  glGetTextureLevelParameteriv(color.id(), 0, GL_TEXTURE_WIDTH, &tw);
  glGetTextureLevelParameteriv(color.id(), 0, GL_TEXTURE_HEIGHT, &th);
  const float u = static_cast<float>(renderer.scene().render.width) / static_cast<float>(tw);
  const float v = static_cast<float>(renderer.scene().render.height) / static_cast<float>(th);
  // GL's first row is the bottom one: v runs from the image's top (v) down to 0.
  const auto id = reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(color.id()));
  ImGui::GetBackgroundDrawList()->AddImage(id, ImVec2(dst.x0, dst.y0), ImVec2(dst.x1, dst.y1), ImVec2(0.f, v), ImVec2(u, 0.f));
}

void LiveWindow::end_frame() {
  ImGui::Render();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);  // the back buffer, whatever a pass or a blit left bound
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (!gl::display_lost()) glfwSwapBuffers(window_);
}

Status LiveWindow::open_device(const DeviceSpec& spec, const GlfwInputParams& params) {
  device_spec_ = spec;
  if (!spec.is_log()) {
    const auto kind = spec.kind == DeviceKind::kMouse ? GlfwInputDevice::Kind::kMouse : GlfwInputDevice::Kind::kGamepad;
    auto d = std::make_unique<GlfwInputDevice>(kind, window_, params);
    input_ = d.get();
    device_ = std::move(d);
    return ok_status();
  }
  auto d = open_device_log(spec);
  if (!d) return make_error("--device: " + d.error().message);
  device_ = std::move(d->device);
  pointer_ = d->pointer;
  return ok_status();
}

}  // namespace ps
