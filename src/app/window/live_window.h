// One window shell for every live program (`run`, `maze --window`, `calibrate --window`), as
// Dear ImGui's examples share one platform backend and one renderer backend: a new live program
// is a new loop body, never a new copy of the shell. A LiveWindow owns
//   - the GLFW window and its OpenGL 4.5 core context (gl/context.h), current on this thread;
//   - the input: one set of GLFW callbacks (keys, characters, scroll, mouse buttons, cursor
//     position, cursor enter/leave, focus) that calls the program's WindowListener
//     (app/window/window_listener.h), installed before Dear ImGui's, which chain to them;
//   - the Dear ImGui scope (context, GLFW and OpenGL 3 backends; no imgui.ini written next to a
//     user's files) and the frame over the picture: begin_frame(), then the program's ImGui
//     calls (its text screens: draw_text_box, app/window/text_box.h; run's readouts and panel,
//     app/window/hud.h), then end_frame() draws them on the back buffer and swaps;
//   - the device the person moves (mouse, gamepad) or a log played as one, opened from a parsed
//     DeviceSpec (devices/device_spec.h).
// ImGui backends: Debian's imgui_impl_glfw.cpp and imgui_impl_opengl3.cpp, the latter built on
// our GL pointer table (gl/gl.h, app/CMakeLists.txt). They save and restore the GL state they
// touch, so the renderer's passes are unaffected.
// Main thread only (GLFW's rule). At most one LiveWindow at a time (one ImGui context).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "app/window/text_box.h"
#include "app/window/window_listener.h"
#include "core/result.h"
#include "devices/device_spec.h"
#include "devices/glfw_input.h"
#include "gl/context.h"

struct GLFWwindow;

namespace ps {

class PointerLogDevice;
class Renderer;

struct LiveWindowDesc {
  int width = 512, height = 512;  // screen coordinates
  std::string title = "pseudoshadow";
};

class LiveWindow {
 public:
  // The window, its context, the callbacks, then ImGui over them.
  static Result<std::unique_ptr<LiveWindow>> open(const LiveWindowDesc& desc);
  ~LiveWindow();
  LiveWindow(const LiveWindow&) = delete;
  LiveWindow& operator=(const LiveWindow&) = delete;

  GLFWwindow* glfw() const { return window_; }
  const gl::Context& context() const { return *ctx_; }

  // Input. Events go to `listener` from now on (before: nowhere); it must outlive the window
  // or be replaced first.
  void listen(WindowListener& listener) { listener_ = &listener; }
  void poll_events();
  void wait_events(double timeout_s);  // nothing moves on screen: sleep until an event or the timeout
  bool should_close() const;           // the window's close button (Esc is each program's own)
  bool hovered() const;                // the pointer is over the window now
  int refresh_hz() const;              // the primary display's refresh rate; 0 where unknown
  glm::ivec2 window_size() const;      // screen coordinates (ImGui's units)
  glm::ivec2 framebuffer_size() const; // pixels
  std::optional<glm::dvec2> pointer_in_window() const;  // screen coordinates; none: outside
  void set_title(const std::string& title);

  // The frame over the picture the program put on the back buffer (a blit, draw_frame_image).
  void begin_frame();
  // The back buffer cleared to black, then begin_frame(): for programs whose pictures do not
  // cover the window (calibrate's pair, the study's stimuli, screens of text).
  void begin_frame_on_black();
  // `renderer`'s last frame into `dst` (window coordinates), straight from its colour target,
  // behind every ImGui window; a window showing more than one renderer (calibrate's pair).
  // Its colour target holds alpha 1 where no probe is drawn see-through (calibrate draws none).
  void draw_frame_image(const Renderer& renderer, const UiRect& dst);
  void end_frame();  // ImGui's draw data onto the default framebuffer, then the swap

  // The device: mouse and gamepad read this window (with `params`), a log plays as recorded.
  // Errors (an unreadable log) say "--device: ...".
  Status open_device(const DeviceSpec& spec, const GlfwInputParams& params = {});
  Device& device() const { return *device_; }
  const DeviceSpec& device_spec() const { return device_spec_; }
  GlfwInputDevice* input() const { return input_; }        // == &device() for mouse and gamepad
  PointerLogDevice* pointer() const { return pointer_; }   // == &device() for pointer:FILE

 private:
  explicit LiveWindow(std::unique_ptr<gl::Context> ctx);
  // Destroyed in reverse: the device (it may release the cursor) before the context.
  std::unique_ptr<gl::Context> ctx_;
  GLFWwindow* window_ = nullptr;
  WindowListener ignore_;                // the listener until listen(), and again at destruction
  WindowListener* listener_ = &ignore_;  // the window's user pointer points at this slot
  DeviceSpec device_spec_;
  std::unique_ptr<Device> device_;
  GlfwInputDevice* input_ = nullptr;
  PointerLogDevice* pointer_ = nullptr;
  mutable glm::ivec2 last_window_size_{0}, last_framebuffer_size_{0};  // asked last (window_size)
};

}  // namespace ps
