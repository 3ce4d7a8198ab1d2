#include "app/window/window_input.h"

#include "scene/scene.h"

#include <cstdio>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

namespace ps {

void WindowInput::on_key(int key, int action, int mods) { handle_key(*this, key, action, mods); }

void WindowInput::on_char(unsigned int codepoint) {
  if (codepoint == '?' && !keys_captured) toggle_help = true;
}

void WindowInput::on_scroll(double dy, bool shift) { handle_scroll(*this, dy, shift); }

void WindowInput::on_mouse_button(int button, int action, double x, double y) {
  if (button != GLFW_MOUSE_BUTTON_RIGHT) return;
  dragging = action == GLFW_PRESS;
  last_x = x;
  last_y = y;
}

void WindowInput::on_cursor(double x, double y) {
  if (dragging) {
    orbit_dx += x - last_x;
    orbit_dy += y - last_y;
  }
  last_x = x;
  last_y = y;
}

void WindowInput::on_enter(bool entered) {
  regained = regained || (entered && !pointer_inside);
  pointer_inside = entered;
}

void WindowInput::on_focus(bool now_focused) {
  regained = regained || (now_focused && !focused);
  focused = now_focused;
}

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
