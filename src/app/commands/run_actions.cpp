// `pseudoshadow run`: what keys, live charges, reloads and a button's scene switch do to the
// window session (app/commands/run_live.h).
#include "app/commands/run_live.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <utility>

#include "app/cli/cli.h"
#include "core/output_set.h"
#include "render/present.h"
#include "scene/scene_io.h"

namespace ps::run_live {

namespace {

// Seconds a notice stays in the readouts: long enough to read a short line.
constexpr double kNoticeSeconds = 3.0;

// Backspace always answers: back to the scene a button came from, or a notice saying there is
// none (a scene opened directly), in the readouts and on the console.
void go_back(Session& s) {
  if (!s.pending_scene.empty()) return;  // a switch is already on its way
  if (s.came_from.empty() || s.came_from.back().empty()) {
    s.notice = "nothing to go back to";
    s.notice_until_s = s.now_s + kNoticeSeconds;
    s.readouts_s = -1.0;  // shown at the next frame, not at the next refresh
    std::printf("Backspace: nothing to go back to (this scene was not opened by a button)\n");
    return;
  }
  s.pending_scene = s.came_from.back();
  s.going_back = true;
}

// Home: the view back where the scene started. The mouse's hand goes back to the start height
// over the surface under the pointer in that view, and the proxy with it in the same tick, as
// after a scene switch (docs/window.md); a recorded or scripted device keeps its positions.
void view_home(Session& s) {
  s.loop->request_view_home(place_hand(s, s.floor.scene(), true));
}

// A live charge: attracting, ~0.4 N at 12 mm (the demo scene's charge), 2 mm softening.
constexpr double kLiveChargeNmm2 = -60.0;

// C adds an attracting charge at the proxy (the probe is then pulled back toward where it was);
// Shift+C removes the one nearest the proxy. The haptic thread adopts the set at its next tick
// and raises charge_added / charge_removed (the event log and the sounds follow).
void edit_live_charges(Session& s, bool add) {
  LiveCharges c = s.loop->live_charges().read();  // the render thread is its only writer
  const glm::dvec3 at = s.loop->state().read().proxy_mm;
  if (add) {
    if (c.count == LiveCharges::kMax) {
      std::fprintf(stderr, "live charges: at most %d; remove one first (Shift+C)\n", LiveCharges::kMax);
      return;
    }
    c.id[c.count] = ++s.last_charge_id;
    c.position[c.count] = at;
    c.charge_n_mm2[c.count] = kLiveChargeNmm2;
    ++c.count;
  } else {
    if (c.count == 0) return;
    int nearest = 0;
    for (int i = 1; i < c.count; ++i)
      if (glm::length(c.position[i] - at) < glm::length(c.position[nearest] - at)) nearest = i;
    for (int i = nearest; i + 1 < c.count; ++i) {
      c.id[i] = c.id[i + 1];
      c.position[i] = c.position[i + 1];
      c.charge_n_mm2[i] = c.charge_n_mm2[i + 1];
    }
    --c.count;
  }
  s.loop->live_charges().publish(c);
}

// Keys 1-6 (Shift: back): the fourd surfaces turn 5 degrees in a 4D plane; the renderer is
// rebuilt with the new orientation (the 3D image reprojected) and, like after a panel edit, the
// frame loop hands the haptic thread a haptic scene built with it (the proxy kept).
void turn_fourd_surfaces(Session& s, int (&steps)[6]) {
  const auto edits = fourd_turn_edits(s.tune->renderer().scene(), steps);
  for (int& n : steps) n = 0;
  if (edits.empty()) return;
  for (const auto& [key, value] : edits)
    if (Status st = s.tune->set(key, value); !st) {
      std::fprintf(stderr, "4D turn: %s\n", st.error().message.c_str());
      return;
    }
}

// S: screenshot_NNNN.png of the frame (before the overlays are drawn) and, beside it, the state
// that made it as an override file: the panel's edits, the camera and the probe as this frame
// drew them, so `render --scene S --overrides THIS` repeats it. Both appear together or neither
// does.
Status save_screenshots(Session& s, int w, int h) {
  WindowInput& in = s.input;
  for (; in.screenshots > 0; --in.screenshots) {
    char name[64];
    std::snprintf(name, sizeof name, "screenshot_%04d.png", s.screenshots_saved++);
    const std::string state = std::string(name).substr(0, std::strlen(name) - 4) + ".overrides.toml";
    OutputSet shot;
    if (Status st = stage_image(shot, name, read_back_buffer(w, h)); !st) return st;
    if (Status st = shot.stage_text(state, screenshot_state(*s.tune)); !st) return st;
    if (Status st = shot.publish(); !st) return st;
    std::printf("saved %s and %s\n", name, state.c_str());
  }
  return ok_status();
}

// The mouse's pointer out of the window or the focus elsewhere: [navigation] holds the view (a
// mouse left past a wall would drive it on, 300 mm/s); a gamepad's only without the focus; a
// recorded or scripted device never (it is not the window's). Back again: the cursor is a new
// origin for a captured mouse, so the jump GLFW saw meanwhile never reaches the probe.
void follow_window_presence(Session& s) {
  WindowInput& in = s.input;
  const bool mouse = s.glfw_device && s.glfw_device->kind() == GlfwInputDevice::Kind::kMouse;
  s.loop->hold_navigation(s.glfw_device && !(in.focused && (in.pointer_inside || !mouse)));
  if (std::exchange(in.regained, false) && s.glfw_device) s.glfw_device->rebase();
}

}  // namespace

Status handle_keys(Session& s, int w, int h) {
  WindowInput& in = s.input;
  follow_window_presence(s);
  if (in.toggle_capture && s.glfw_device) s.glfw_device->toggle_capture();
  in.toggle_capture = false;
  if (s.ui->panel().wants_input()) {  // scrolling or dragging over the panel: not for camera or probe
    in.scroll_zoom = in.scroll_height = in.orbit_dx = in.orbit_dy = 0.0;
  }
  if (s.glfw_device) {
    s.glfw_device->add_scroll(in.scroll_height);
    s.glfw_device->add_height_steps(in.height_steps);
  }
  in.scroll_height = 0.0;
  in.height_steps = 0;
  if (in.toggle_panel) s.ui->panel().toggle();
  in.toggle_panel = false;
  // H or ? toggles the help; any other key hides it (the person has started).
  if (in.toggle_help) s.ui->toggle_help();
  else if (in.key_presses > 0) s.ui->hide_help();
  in.toggle_help = false;
  s.frame_keys = std::exchange(in.key_presses, 0);
  ViewFlags& show = s.tune->view().show;
  if (std::exchange(in.toggle_probe, false)) show.probe = !show.probe;
  if (std::exchange(in.toggle_device, false)) show.device = !show.device;
  if (in.add_charge || in.remove_charge) edit_live_charges(s, in.add_charge);
  if (std::exchange(in.back, false)) go_back(s);
  if (std::exchange(in.home, false)) view_home(s);
  in.add_charge = in.remove_charge = false;
  turn_fourd_surfaces(s, in.turn4);
  apply_orbit_zoom(in, s.tune->view().camera);  // after the turn: its rebuild keeps the camera
  return save_screenshots(s, w, h);
}

// A reloaded scene may feel different too (surfaces, materials' haptic keys, fields, bodies):
// the haptic thread gets a haptic scene built from it. A scene the renderer took but the
// haptic side cannot build (a mesh that fails to load there) keeps the last good haptic world.
void reload_haptic_scene(Session& s) {
  auto built = world::HapticScene::build(s.tune->renderer().scene());
  if (!built) {
    std::fprintf(stderr, "haptic reload failed, keeping the last good haptic world: %s\n", built.error().message.c_str());
    return;
  }
  auto felt = std::make_shared<const world::HapticScene>(std::move(built.value()));
  const std::optional<glm::dvec3> hand = place_hand(s, felt, true);  // the loop starts the scene's view afresh
  s.loop->replace_scene(std::move(felt), s.tune->scene_path(), hand);
  s.vibration->set_scene(s.tune->renderer().scene());  // the edited materials' vibration too
}

void poll_reload(Session& s) {
  if (!s.tune->reload_if_changed()) return;
  if (s.tune->last_error().empty()) reload_haptic_scene(s);
  const std::string& err = s.tune->last_error();
  if (err.empty()) std::printf("reloaded (%zu files watched)\n", s.tune->watch().files().size());
  else if (err != s.shown_error) std::fprintf(stderr, "reload failed, keeping the last good state: %s\n", err.c_str());
  s.shown_error = err;
  std::fflush(stdout);
}

// A button's "scene:FILE" action: the window now shows that scene (its own camera and look, in
// the window's size), the haptic thread adopts its haptic scene at its next tick, with the hand
// and the probe placed in it in that tick; a file that fails to load keeps the current scene and
// says why.
std::uint64_t switch_scene(const RunArgs& a, Session& s) {
  const std::string path = std::exchange(s.pending_scene, std::string());
  const bool back = std::exchange(s.going_back, false);
  auto stay = [&path](const Error& e) {
    std::fprintf(stderr, "button: cannot switch to %s, staying: %s\n", path.c_str(), e.message.c_str());
    return std::uint64_t{0};
  };
  auto scene = load_scene(path, {}, cli::switch_allow_paths(a.scene));
  if (!scene) return stay(scene.error());
  auto haptic = world::HapticScene::build(scene.value());
  if (!haptic) return stay(haptic.error());
  const Scene& current = s.tune->renderer().scene();
  scene->render.width = current.render.width;  // the window keeps its size
  scene->render.height = current.render.height;
  // A fresh view of the new scene, with the command line's flags (window_tune_source).
  auto tune = TuneSession::open(window_tune_source(a, path, {}, cli::switch_allow_paths(a.scene)), std::move(scene.value()));
  if (!tune) return stay(tune.error());
  if (back) s.came_from.pop_back();
  else s.came_from.push_back(s.tune->scene_path());
  s.tune = std::move(tune.value());
  s.haptic_edits.clear();
  s.axes = pointer_plane(s.tune->renderer());
  fit_height_to_buttons(s, haptic.value());
  auto felt = std::make_shared<const world::HapticScene>(std::move(haptic.value()));
  const std::optional<glm::dvec3> hand = place_hand(s, felt, true);
  const std::uint64_t serial = s.loop->replace_scene(std::move(felt), std::filesystem::path(path).filename().string(), hand);
  s.vibration->set_scene(s.tune->renderer().scene());
  if (!a.quiet) std::printf("button: switched to %s\n", path.c_str());
  return serial;
}

}  // namespace ps::run_live
