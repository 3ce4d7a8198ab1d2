// Window-side input of `run`: camera orbit/zoom and the app keys, collected by GLFW callbacks
// on the main thread (the probe itself is moved by the mouse/gamepad Device).
#pragma once

#include "scene/scene.h"

struct GLFWwindow;

namespace ps {

struct WindowInput {
  double scroll_zoom = 0.0;     // accumulated scroll steps (camera zoom)
  double scroll_height = 0.0;   // accumulated Shift+scroll steps (probe height)
  int screenshots = 0;          // S presses not handled yet
  bool toggle_capture = false;  // M
  bool quit = false;            // Esc / Q
  bool toggle_panel = false;    // F1: parameter panel
  bool toggle_probe = false;    // P: draw the probe itself (the displayed proxy)
  bool toggle_help = false;     // H or ?: the help overlay
  int key_presses = 0;          // every key pressed (any key hides the help overlay)
  bool keys_captured = false;   // set by the panel while it has the keyboard: S/M/Q ignored
  bool dragging = false;        // right button held
  double last_x = 0.0, last_y = 0.0;
  double orbit_dx = 0.0, orbit_dy = 0.0;  // accumulated drag, pixels
};

// Installs the callbacks; `input` must outlive the window.
void install_window_input(GLFWwindow* window, WindowInput& input);

// Applies and clears the accumulated orbit (0.005 rad per pixel) and zoom (10 % per step)
// around camera.target, with +Z up.
void apply_orbit_zoom(WindowInput& input, Camera& camera);

}  // namespace ps
