// Window-side input of `run`: camera orbit/zoom, the probe's height steps and the app keys,
// collected from its LiveWindow's events on the main thread (app/window/live_window.h; the probe
// itself is moved by the mouse/gamepad Device). handle_key / handle_scroll are the events'
// bodies as free functions, so the key handling is testable headless.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "app/window/window_listener.h"
#include "scene/scene.h"

namespace ps {

struct Scene;

struct WindowInput final : WindowListener {
  double scroll_zoom = 0.0;     // accumulated Shift+scroll steps (camera zoom)
  double scroll_height = 0.0;   // accumulated scroll steps (probe height; up = raise)
  int height_steps = 0;         // PageUp/Up minus PageDown/Down presses, key repeats included
  int screenshots = 0;          // S presses not handled yet
  bool toggle_capture = false;  // M
  bool quit = false;            // Esc / Q
  bool toggle_panel = false;    // F1: parameter panel
  bool toggle_probe = false;    // P: draw the probe itself (the displayed proxy)
  bool toggle_device = false;   // D: draw the device's own position, faint (pseudo-haptic gap)
  bool add_charge = false;      // C: a live charge at the proxy (docs/haptics.md, "Fields")
  bool remove_charge = false;   // Shift+C: remove the live charge nearest the proxy
  bool back = false;            // Backspace: back to the scene a button switched from
  bool home = false;            // Home: [navigation]'s view back where the scene started
  bool toggle_help = false;     // H or ?: the help overlay
  int key_presses = 0;          // every key pressed (any key hides the help overlay)
  bool keys_captured = false;   // set by the panel while it has the keyboard: S/M/Q ignored
  bool dragging = false;        // right button held
  // The pointer over the window and the window focused (GLFW's cursor-enter and focus events):
  // [navigation] travels only while both hold. `regained`: one came back since the last frame.
  bool pointer_inside = true, focused = true, regained = false;
  double last_x = 0.0, last_y = 0.0;
  double orbit_dx = 0.0, orbit_dy = 0.0;  // accumulated drag, pixels
  // 1 ... 6 (Shift: the other way): steps of a 4D turn of the scene's fourd surfaces in the xy,
  // xz, xw, yz, yw, zw plane (docs/fourd.md), not handled yet
  int turn4[6] = {0, 0, 0, 0, 0, 0};

  // What `run`'s window hears (app/window/window_listener.h).
  void on_key(int key, int action, int mods) override;
  void on_char(unsigned int codepoint) override;  // '?' by the character, whatever the layout
  void on_scroll(double dy, bool shift) override;
  void on_mouse_button(int button, int action, double x, double y) override;  // the right one drags
  void on_cursor(double x, double y) override;
  // Left or unfocused: a mouse parked past a [navigation] wall must not move the view on.
  void on_enter(bool entered) override;
  void on_focus(bool now_focused) override;
};

// The scene edits (--set KEY, VALUE) that turn every fourd surface of `scene` by
// steps[i] x step_deg in plane i (fourd::kRotationPlanes order); none when no step is set or
// the scene has no fourd surface. `run` applies them like panel edits (renderer and haptic
// scene rebuilt), so the 3D image is reprojected live.
std::vector<std::pair<std::string, std::string>> fourd_turn_edits(const Scene& scene, const int steps[6],
                                                                  double step_deg = 5.0);

// A key event (GLFW key, action, mods): presses and, for the height keys, repeats count.
void handle_key(WindowInput& input, int key, int action, int mods);
// A scroll event: plain scroll moves the probe's height, Shift+scroll zooms the camera.
void handle_scroll(WindowInput& input, double dy, bool shift);

// Applies and clears the accumulated orbit (0.005 rad per pixel) and zoom (10 % per step)
// around camera.target, with +Z up.
void apply_orbit_zoom(WindowInput& input, Camera& camera);

}  // namespace ps
