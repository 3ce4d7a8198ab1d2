// The parameter panel of `pseudoshadow run` (Dear ImGui, toggled with F1): every material
// parameter with its unit and valid range, the probe and camera values, live plots of the
// intensity curve and of the speed -> amplitude curve, each editable as a curve (a lookup
// table's rows as vertical sliders, saved with the overrides as table files), the reload status,
// and "Save overrides". Edits go through TuneSession::set, i.e. exactly a --set, and apply to the next
// frame. Drawn after screenshots are taken, so it never appears in them.
//
// Docked: a full-height strip along one side of the window, whose place app/window/ui_layout.h picks
// (away from the pseudo-shadow); collapsible to its title bar. Every label sits on its own line
// above its slider, wrapped if the strip is narrow, so no name is ever cut; units are in the
// slider's value text ("0.5 mm") and in the curves' tooltips (the axis value under the mouse).
//
// The ImGui context and frame belong to the LiveWindow (app/window/live_window.h); WindowUi
// (app/window/hud.h) draws the panel in that frame with the readouts and the help.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app/window/ui_layout.h"
#include "tune/tune_session.h"

namespace ps {

class TunePanel {
 public:
  TunePanel() = default;
  TunePanel(const TunePanel&) = delete;
  TunePanel& operator=(const TunePanel&) = delete;

  void toggle() { visible_ = !visible_; }
  bool visible() const { return visible_; }
  // Collapsed to its title bar (the last frame's state: ImGui's collapse arrow toggles it).
  bool collapsed() const { return collapsed_; }
  // True while the panel has the mouse/keyboard (the probe should then ignore them).
  bool wants_input() const;
  // True while a text field of the panel takes typed keys (a Ctrl+click on a slider): only then
  // are the window's keys (S, Q, Esc, PageDown...) the panel's. A pointer over the panel, or a
  // slider just dragged, leaves every key to the window.
  bool wants_keys() const;

  // Inside an ImGui frame: builds the panel in `dock` (window pixels) and applies edits to
  // `session`. Returns the rectangle it covers (its title bar only when collapsed).
  UiRect draw(TuneSession& session, const UiRect& dock);
  // Where each knob was drawn in the last frame (window pixels), by the scene key it edits:
  // lets a test drive the panel with mouse events as a person would (tests/app/tune_panel_gl_test).
  const std::map<std::string, UiRect>& knob_rects() const { return knob_rects_; }

 private:
  void contents(TuneSession& session);
  void material_section(TuneSession& session);
  void probe_camera_section(TuneSession& session);
  // The haptic world's knobs (Sandia's Virtual Universe): each drawn-stretched surface's
  // stretch (Illusion) and each body's time scale (Weight). Shown only for scenes that have them.
  void world_section(TuneSession& session);
  void fourd_section(TuneSession& session, const Surface& s, std::size_t i);
  bool has_world_knobs(const Scene& scene);
  void plots(TuneSession& session);
  // The curve under a plot as editable lookup-table rows (intensity: true; speed gain: false).
  void curve_editor(TuneSession& session, const Material& m, bool intensity, double x_max);
  void resample_button(TuneSession& session, const Material& m, bool intensity, double x_max, const std::string& key,
                       bool has_table);
  bool row_slider(TuneSession& session, const std::string& key, const Lut& cur, int i, float w, bool intensity);
  // Edits are queued while the panel is built and carried out after it (apply_pending): an edit
  // rebuilds the renderer and with it the Scene every section reads by reference, so applying
  // one mid-section left the rest of that section reading freed memory.
  void set_curve(TuneSession& session, const std::string& key, const Lut& lut);
  void apply(TuneSession& session, const std::string& key, const std::string& value);
  void apply_pending(TuneSession& session);
  struct PendingEdit {
    std::string key, value;
    bool curve = false;
    Lut lut;
  };
  std::vector<PendingEdit> pending_;
  // A slider whose value lives in the panel while it is dragged and is applied (one renderer
  // rebuild) when released or typed: rebuilding on every drag step would cost a JIT each frame.
  struct ActiveEdit {
    std::string key;
    float value[3] = {0, 0, 0};
  };
  ActiveEdit active_;  // the single item ImGui can have active
  bool slider(const std::string& label, const std::string& key, float* v, int n, float lo, float hi, bool log);
  void record_rect(const std::string& key);  // where the last item was drawn, into knob_rects_

  bool visible_ = false;
  bool collapsed_ = false;
  int material_ = 0;
  std::vector<int> stretched_;  // surfaces seen stretched: their slider stays, also at 1
  std::string status_;
  std::map<std::string, UiRect> knob_rects_;
};

}  // namespace ps
