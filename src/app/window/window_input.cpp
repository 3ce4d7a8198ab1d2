#include "app/window/window_input.h"

#include "scene/scene.h"

#include <cstdio>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

namespace ps {

namespace {

WindowInput& input_of(GLFWwindow* w) { return *static_cast<WindowInput*>(glfwGetWindowUserPointer(w)); }

void on_key(GLFWwindow* w, int key, int, int action, int mods) { handle_key(input_of(w), key, action, mods); }

// '?' by the character it types, whatever the keyboard layout puts it on.
void on_char(GLFWwindow* w, unsigned int codepoint) {
  WindowInput& in = input_of(w);
  if (codepoint == '?' && !in.keys_captured) in.toggle_help = true;
}

void on_scroll(GLFWwindow* w, double, double dy) {
  const bool shift = glfwGetKey(w, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                     glfwGetKey(w, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  handle_scroll(input_of(w), dy, shift);
}

void on_button(GLFWwindow* w, int button, int action, int) {
  if (button != GLFW_MOUSE_BUTTON_RIGHT) return;
  WindowInput& in = input_of(w);
  in.dragging = action == GLFW_PRESS;
  glfwGetCursorPos(w, &in.last_x, &in.last_y);
}

void on_cursor(GLFWwindow* w, double x, double y) {
  WindowInput& in = input_of(w);
  if (in.dragging) {
    in.orbit_dx += x - in.last_x;
    in.orbit_dy += y - in.last_y;
  }
  in.last_x = x;
  in.last_y = y;
}

// Left or unfocused: a mouse parked past a [navigation] wall must not move the view on.
void on_enter(GLFWwindow* w, int entered) {
  WindowInput& in = input_of(w);
  in.regained = in.regained || (entered && !in.pointer_inside);
  in.pointer_inside = entered != 0;
}

void on_focus(GLFWwindow* w, int focused) {
  WindowInput& in = input_of(w);
  in.regained = in.regained || (focused && !in.focused);
  in.focused = focused != 0;
}

}  // namespace

void handle_key(WindowInput& in, int key, int action, int mods) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  if (action == GLFW_PRESS) ++in.key_presses;
  if (key == GLFW_KEY_F1 && action == GLFW_PRESS) in.toggle_panel = true;
  if (in.keys_captured) return;  // the user is typing into the parameter panel
  // The height keys step on every press and keep stepping while held (the system's key repeat).
  if (key == GLFW_KEY_PAGE_UP || key == GLFW_KEY_UP) ++in.height_steps;
  if (key == GLFW_KEY_PAGE_DOWN || key == GLFW_KEY_DOWN) --in.height_steps;
  if (action != GLFW_PRESS) return;  // the other keys act once per press
  if (key == GLFW_KEY_H) in.toggle_help = true;
  if (key == GLFW_KEY_S) ++in.screenshots;
  if (key == GLFW_KEY_M) in.toggle_capture = true;
  if (key == GLFW_KEY_P) in.toggle_probe = true;
  if (key == GLFW_KEY_D) in.toggle_device = true;
  if (key == GLFW_KEY_BACKSPACE) in.back = true;
  if (key == GLFW_KEY_HOME) in.home = true;
  if (key == GLFW_KEY_C) ((mods & GLFW_MOD_SHIFT) ? in.remove_charge : in.add_charge) = true;
  if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) in.quit = true;
  if (key >= GLFW_KEY_1 && key <= GLFW_KEY_6) in.turn4[key - GLFW_KEY_1] += (mods & GLFW_MOD_SHIFT) ? -1 : 1;
}

std::vector<std::pair<std::string, std::string>> fourd_turn_edits(const Scene& scene, const int steps[6],
                                                                  double step_deg) {
  static constexpr const char* kPlanes[6] = {"xy", "xz", "xw", "yz", "yw", "zw"};  // fourd::kRotationPlanes
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
    if (scene.surfaces[i].type != SurfaceType::kFourd) continue;
    for (int p = 0; p < 6; ++p) {
      if (steps[p] == 0) continue;
      // Kept within (-360, 360]: the scene key's range is +-3600 and a long session could pass it.
      const double deg = std::fmod(scene.surfaces[i].fourd.rotation_deg[static_cast<std::size_t>(p)] + steps[p] * step_deg, 360.0);
      char value[32];
      std::snprintf(value, sizeof value, "%.6g", deg);
      out.emplace_back("surfaces." + std::to_string(i) + ".fourd_rotation_" + kPlanes[p] + "_deg", value);
    }
  }
  return out;
}

void handle_scroll(WindowInput& in, double dy, bool shift) {
  // Plain scroll is the height: pressing the probe into the surface is what a newcomer reaches
  // for under the hand; zoom is set once and left, so it takes the modifier.
  (shift ? in.scroll_zoom : in.scroll_height) += dy;
}

void install_window_input(GLFWwindow* window, WindowInput& input) {
  glfwSetWindowUserPointer(window, &input);
  glfwSetKeyCallback(window, on_key);
  glfwSetCharCallback(window, on_char);
  glfwSetScrollCallback(window, on_scroll);
  glfwSetMouseButtonCallback(window, on_button);
  glfwSetCursorPosCallback(window, on_cursor);
  glfwSetCursorEnterCallback(window, on_enter);  // before WindowUi: ImGui chains to these
  glfwSetWindowFocusCallback(window, on_focus);
  input.pointer_inside = glfwGetWindowAttrib(window, GLFW_HOVERED) == GLFW_TRUE;
}

void apply_orbit_zoom(WindowInput& in, Camera& camera) {
  if (in.orbit_dx == 0.0 && in.orbit_dy == 0.0 && in.scroll_zoom == 0.0) return;
  const glm::dvec3 d = camera.position - camera.target;
  double r = glm::length(d);
  double azimuth = std::atan2(d.y, d.x);
  double elevation = std::asin(std::clamp(d.z / std::max(r, 1e-9), -1.0, 1.0));
  azimuth -= 0.005 * in.orbit_dx;
  elevation = std::clamp(elevation + 0.005 * in.orbit_dy, -1.5, 1.5);  // stay off the pole
  r = std::clamp(r * std::pow(0.9, in.scroll_zoom), camera.near_mm * 2.0, camera.far_mm * 0.5);
  camera.position = camera.target + r * glm::dvec3(std::cos(elevation) * std::cos(azimuth),
                                                   std::cos(elevation) * std::sin(azimuth),
                                                   std::sin(elevation));
  in.orbit_dx = in.orbit_dy = in.scroll_zoom = 0.0;
}

}  // namespace ps
