// The maze window's frame: its GLFW events, what it holds (context, renderer, device) and what
// it draws over the rendered state (the room label, the score, the instructions, the hand's
// ring). The session's loop, passes and practice are in app/maze/maze_window.cpp.
#pragma once

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <memory>
#include <string>

#include "devices/glfw_input.h"
#include "devices/pointer_map.h"
#include "gl/context.h"
#include "haptics/haptic_loop.h"
#include "maze/maze_session.h"
#include "render/renderer.h"

namespace ps::maze_window {

// What the window hears from GLFW, from its callbacks (installed before ImGui, which chains to
// them): a frame can take longer than a quick tap, so polled key state would lose taps.
struct Events {
  bool quit = false, screenshot = false, start = false;  // start: Space or Enter (the instructions)
  int height_steps = 0;  // PageUp/Up +1, PageDown/Down -1 (0.5 mm each, HeightControl); repeats count
  // GLFW moved its virtual cursor without the person moving the mouse (the pointer entered the
  // window, focus came back and the cursor was grabbed again): the next poll rebases on it.
  bool rebase = false;
  static Events& of(GLFWwindow* win) { return *static_cast<Events*>(glfwGetWindowUserPointer(win)); }
  static void on_key(GLFWwindow* win, int key, int /*scancode*/, int action, int /*mods*/) {
    if (action == GLFW_RELEASE) return;
    Events& e = of(win);
    if (key == GLFW_KEY_PAGE_UP || key == GLFW_KEY_UP) ++e.height_steps;
    if (key == GLFW_KEY_PAGE_DOWN || key == GLFW_KEY_DOWN) --e.height_steps;
    if (action != GLFW_PRESS) return;  // a held S or Esc acts once
    if (key == GLFW_KEY_S) e.screenshot = true;
    if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) e.quit = true;
    if (key == GLFW_KEY_SPACE || key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER) e.start = true;
  }
  static void on_enter(GLFWwindow* win, int /*entered*/) { of(win).rebase = true; }
  static void on_focus(GLFWwindow* win, int /*focused*/) { of(win).rebase = true; }
  void install(GLFWwindow* win) {
    glfwSetWindowUserPointer(win, this);
    glfwSetKeyCallback(win, &Events::on_key);
    glfwSetCursorEnterCallback(win, &Events::on_enter);
    glfwSetWindowFocusCallback(win, &Events::on_focus);
  }
};

struct Window {  // context first: the renderer's GL objects die before it
  std::unique_ptr<gl::Context> ctx;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<Device> device;
  GlfwInputDevice* input = nullptr;  // == device.get() for the mouse or gamepad
  Events events;                     // its callbacks point here: it lives as long as the window
  std::string out_dir;
  int screenshots = 0;
};

// The floor under the camera target: the plane the captured mouse moves the probe over.
PlaneAxes floor_plane(const Renderer& r);

// `p` dropped onto `plane` along its normal.
glm::dvec3 on_plane(const PlaneAxes& plane, const glm::dvec3& p);

// What the window shows over the frame: the label (cues off), the last score for a while.
struct Overlay {
  std::string label, score, instructions;
  double score_until = -1.0;
  bool done = false, show_hand = false;
};

// A pass's score screen: each room's cue (with cues off) and exit, right or wrong.
std::string score_text(const maze::PassScore& s, bool cues);

// Renders the state, stamps a screenshot if asked (the frame plus the label, as headless
// frames have it), blits, draws the overlay.
Status draw(Window& w, const maze::MazeDesc& desc, const HapticState& st, const Overlay& ov, bool screenshot);

}  // namespace ps::maze_window
