// What `pseudoshadow run` draws over the image, in one Dear ImGui frame per window frame:
//   - the readouts: a small box in a corner (frame time, haptic rate and jitter, distance,
//     speed, penetration, contact, force, scene), the corner away from the pseudo-shadow;
//   - the help: keys, mouse and what the shadow means (app/window/run_keys.h), shown at start and on
//     H or ?, hidden by any other key or, the first time, after kHelpSeconds;
//   - the parameter panel (F1, app/window/tune_panel.h), docked to the side the shadow leaves free.
// Where each goes is decided by app/window/ui_layout.h from the shadow's bounding box measured on the
// frame's own pixels. The readouts and help take no input (clicks go through to the probe).
//
// WindowUi draws inside the window's ImGui frame (LiveWindow::begin_frame .. end_frame,
// app/window/live_window.h, which owns the ImGui context and backends). Drawn after screenshots
// (S) are read back, so they never appear in them.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/window/button_overlay.h"
#include "app/window/readout_state.h"
#include "app/window/tune_panel.h"
#include "app/window/ui_layout.h"

namespace ps {

// The numbers the readouts show, gathered by the window loop once per frame.
struct HudReadouts {
  std::string scene;                     // the scene file's name, "default.toml"
  double frame_ms = 0.0;
  // GL timer queries' time of the newest frame whose results came back (sum of its passes);
  // none: no results yet (docs/benchmarks.md, "GPU timers").
  std::optional<double> gpu_frame_ms;
  double haptic_hz = 0.0, jitter_p99_us = 0.0;
  ProbeReadout probe;                    // out of reach / hovering d mm / touching, pressed p mm
  double speed_mm_s = 0.0;
  double penetration_mm = 0.0;
  double force_n = 0.0;
  double bake_progress = 1.0;            // Gabor tile bake, 0..1 (< 1: the per-pixel sum is drawn)
  std::string error;                     // a failed reload's message; empty: none
  std::string notice;                    // a short answer to a key ("nothing to go back to"); empty: none
  int button = -1;                       // the button pressed (-1: none), how far, and its travel
  double button_depth_mm = 0.0, button_travel_mm = 0.0;
  std::optional<std::string> flags;      // the scene's flags that are on ("" none); none: no flags
  std::optional<glm::dvec3> view_mm;     // [navigation]: how far the view has moved; none: no box
  std::optional<double> rolled_deg;      // rolling manifold: how far the view has turned; none: no rolling
  // surfaces embedded in 4D: the turn in the xy, xz, xw, yz, yw, zw planes (keys 1-6), degrees
  std::optional<std::array<double, 6>> turn4_deg;
};

// The readouts as "name  value" lines (the box draws them in this order).
std::vector<std::string> hud_lines(const HudReadouts& r);
// The window title: "pseudoshadow — default.toml — 1.2 mm" (or "out of reach", "touching",
// "RELOAD FAILED: ..."): short, so no title bar cuts the distance off.
std::string title_summary(const HudReadouts& r);

// Seconds the help stays up at start when no key is pressed.
constexpr double kHelpSeconds = 15.0;

class WindowUi {
 public:
  TunePanel& panel() { return panel_; }
  const TunePanel& panel() const { return panel_; }
  // Either one means the person has taken over: the start's timeout no longer applies.
  void toggle_help() { help_ = !help_; help_timeout_ = false; }
  void hide_help() { help_ = false; help_timeout_ = false; }
  bool help_shown() const { return help_; }

  // Inside the window's ImGui frame (LiveWindow::begin_frame .. end_frame): lays the boxes out
  // around `shadow`, draws them and applies panel edits to `session`. `now_s`: session time, for the
  // help's timeout. Returns the rectangles drawn (window pixels).
  // `buttons`: the scene's buttons on screen (app/window/button_overlay.h): each gets its label, and
  // the readouts and help keep off them.
  UiFrameReport draw(const HudReadouts& readouts, const ShadowMeasure& shadow, TuneSession& session,
                     double now_s, const std::vector<ButtonOverlay>& buttons = {});

 private:
  // draw()'s layout problem: the window, the shadow, the buttons, the boxes' sizes, the pointer.
  UiLayoutInput layout_input(const ShadowMeasure& shadow, const std::vector<ButtonOverlay>& buttons,
                             const std::string& hud_text, const std::string& help, const std::string& help_narrow) const;
  TunePanel panel_;
  UiPlacement placement_;
  bool help_ = true;
  bool help_timeout_ = true;  // hide the help at kHelpSeconds (the start's help only)
};

}  // namespace ps
