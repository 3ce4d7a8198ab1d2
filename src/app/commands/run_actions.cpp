// `pseudoshadow run`: what keys, live charges, reloads and a button's scene switch do to the
// window's parts (app/commands/run_live.h).
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
void go_back(SceneTrail& trail, FrameReadouts& ro, double now_s) {
  if (!trail.pending.empty()) return;  // a switch is already on its way
  if (trail.came_from.empty() || trail.came_from.back().empty()) {
    ro.notice = "nothing to go back to";
    ro.notice_until_s = now_s + kNoticeSeconds;
    ro.refreshed_s = -1.0;  // shown at the next frame, not at the next refresh
    std::printf("Backspace: nothing to go back to (this scene was not opened by a button)\n");
    return;
  }
  trail.pending = trail.came_from.back();
  trail.going_back = true;
}

// A live charge: attracting, ~0.4 N at 12 mm (the demo scene's charge), 2 mm softening.
constexpr double kLiveChargeNmm2 = -60.0;

// C adds an attracting charge at the proxy (the probe is then pulled back toward where it was);
// Shift+C removes the one nearest the proxy. The haptic thread adopts the set at its next tick
// and raises charge_added / charge_removed (the event log and the sounds follow).
void edit_live_charges(LiveHaptics& h, bool add) {
  LiveCharges c = h.loop()->live_charges().read();  // the render thread is its only writer
  const glm::dvec3 at = h.loop()->state().read().proxy_mm;
  if (add) {
    if (c.count == LiveCharges::kMax) {
      std::fprintf(stderr, "live charges: at most %d; remove one first (Shift+C)\n", LiveCharges::kMax);
      return;
    }
    c.id[c.count] = ++h.last_charge_id;
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
  h.loop()->live_charges().publish(c);
}

// Keys 1-6 (Shift: back): the fourd surfaces turn 5 degrees in a 4D plane; the renderer is
// rebuilt with the new orientation (the 3D image reprojected) and, like after a panel edit, the
// frame loop hands the haptic thread a haptic scene built with it (the proxy kept).
void turn_fourd_surfaces(TuneSession& tune, int (&steps)[6]) {
  const auto edits = fourd_turn_edits(tune.renderer().scene(), steps);
  for (int& n : steps) n = 0;
  if (edits.empty()) return;
  for (const auto& [key, value] : edits)
    if (Status st = tune.set(key, value); !st) {
      std::fprintf(stderr, "4D turn: %s\n", st.error().message.c_str());
      return;
    }
}

// The mouse's pointer out of the window or the focus elsewhere: [navigation] holds the view (a
// mouse left past a wall would drive it on, 300 mm/s); a gamepad's only without the focus; a
// recorded or scripted device never (it is not the window's). Back again: the cursor is a new
// origin for a captured mouse, so the jump GLFW saw meanwhile never reaches the probe.
void follow_window_presence(WindowInput& in, GlfwInputDevice* device, HapticLoop& loop) {
  const bool mouse = device && device->kind() == GlfwInputDevice::Kind::kMouse;
  loop.hold_navigation(device && !(in.focused && (in.pointer_inside || !mouse)));
  if (std::exchange(in.regained, false) && device) device->rebase();
}

}  // namespace

// S: screenshot_NNNN.png of the frame (before the overlays are drawn) and, beside it, the state
// that made it as an override file: the panel's edits, the camera and the probe as this frame
// drew them, so `render --scene S --overrides THIS` repeats it. Both appear together or neither
// does.
Status save_screenshots(WindowIo& io, const TuneSession& tune, int w, int h) {
  WindowInput& in = io.input;
  for (; in.screenshots > 0; --in.screenshots) {
    char name[64];
    std::snprintf(name, sizeof name, "screenshot_%04d.png", io.screenshots_saved++);
    const std::string state = std::string(name).substr(0, std::strlen(name) - 4) + ".overrides.toml";
    OutputSet shot;
    if (Status st = stage_image(shot, name, read_back_buffer(w, h)); !st) return st;
    if (Status st = shot.stage_text(state, screenshot_state(tune)); !st) return st;
    if (Status st = shot.publish(); !st) return st;
    std::printf("saved %s and %s\n", name, state.c_str());
  }
  return ok_status();
}

int window_keys(WindowIo& io, HapticLoop& loop) {
  WindowInput& in = io.input;
  GlfwInputDevice* const device = io.window->input();
  follow_window_presence(in, device, loop);
  if (in.toggle_capture && device) device->toggle_capture();
  in.toggle_capture = false;
  if (io.ui->panel().wants_input()) {  // scrolling or dragging over the panel: not for camera or probe
    in.scroll_zoom = in.scroll_height = in.orbit_dx = in.orbit_dy = 0.0;
  }
  if (device) {
    device->add_scroll(in.scroll_height);
    device->add_height_steps(in.height_steps);
  }
  in.scroll_height = 0.0;
  in.height_steps = 0;
  if (in.toggle_panel) io.ui->panel().toggle();
  in.toggle_panel = false;
  // H or ? toggles the help; any other key hides it (the person has started).
  if (in.toggle_help) io.ui->toggle_help();
  else if (in.key_presses > 0) io.ui->hide_help();
  in.toggle_help = false;
  return std::exchange(in.key_presses, 0);
}

// Home: the view back where the scene started. The mouse's hand goes back to the start height
// over the surface under the pointer in that view, and the proxy with it in the same tick, as
// after a scene switch (docs/window.md); a recorded or scripted device keeps its positions.
void haptic_keys(WindowInput& in, const LiveWindow& win, const Renderer& r, LiveHaptics& h) {
  if (in.add_charge || in.remove_charge) edit_live_charges(h, in.add_charge);
  in.add_charge = in.remove_charge = false;
  if (std::exchange(in.home, false)) h.loop()->request_view_home(place_hand(win, r, h, h.floor.scene(), true));
}

void back_key(WindowInput& in, SceneTrail& trail, FrameReadouts& ro, double now_s) {
  if (std::exchange(in.back, false)) go_back(trail, ro, now_s);
}

void view_keys(WindowInput& in, TuneSession& tune) {
  ViewFlags& show = tune.view().show;
  if (std::exchange(in.toggle_probe, false)) show.probe = !show.probe;
  if (std::exchange(in.toggle_device, false)) show.device = !show.device;
  turn_fourd_surfaces(tune, in.turn4);
  apply_orbit_zoom(in, tune.view().camera);  // after the turn: its rebuild keeps the camera
}

// A reloaded scene may feel different too (surfaces, materials' haptic keys, fields, bodies):
// the haptic thread gets a haptic scene built from it. A scene the renderer took but the
// haptic side cannot build (a mesh that fails to load there) keeps the last good haptic world.
void reload_haptic_scene(const LiveWindow& win, const TuneSession& tune, LiveHaptics& h) {
  auto built = world::HapticScene::build(tune.renderer().scene());
  if (!built) {
    std::fprintf(stderr, "haptic reload failed, keeping the last good haptic world: %s\n", built.error().message.c_str());
    return;
  }
  auto felt = std::make_shared<const world::HapticScene>(std::move(built.value()));
  // The loop starts the scene's view afresh.
  const std::optional<glm::dvec3> hand = place_hand(win, tune.renderer(), h, felt, true);
  h.loop()->replace_scene(std::move(felt), tune.scene_path(), hand);
  h.vibration->set_scene(tune.renderer().scene());  // the edited materials' vibration too
}

void poll_reload(const LiveWindow& win, TuneSession& tune, LiveHaptics& h, std::string& shown_error) {
  if (!tune.reload_if_changed()) return;
  if (tune.last_error().empty()) reload_haptic_scene(win, tune, h);
  const std::string& err = tune.last_error();
  if (err.empty()) std::printf("reloaded (%zu files watched)\n", tune.watch().files().size());
  else if (err != shown_error) std::fprintf(stderr, "reload failed, keeping the last good state: %s\n", err.c_str());
  shown_error = err;
  std::fflush(stdout);
}

// A button's "scene:FILE" action: the window now shows that scene (its own camera and look, in
// the window's size), the haptic thread adopts its haptic scene at its next tick, with the hand
// and the probe placed in it in that tick; a file that fails to load keeps the current scene and
// says why.
std::uint64_t switch_scene(const RunArgs& a, const LiveWindow& win, std::unique_ptr<TuneSession>& tune,
                           LiveHaptics& h, SceneTrail& trail) {
  const std::string path = std::exchange(trail.pending, std::string());
  const bool back = std::exchange(trail.going_back, false);
  auto stay = [&path](const Error& e) {
    std::fprintf(stderr, "button: cannot switch to %s, staying: %s\n", path.c_str(), e.message.c_str());
    return std::uint64_t{0};
  };
  auto scene = load_scene(path, {}, cli::switch_allow_paths(a.scene));
  if (!scene) return stay(scene.error());
  auto haptic = world::HapticScene::build(scene.value());
  if (!haptic) return stay(haptic.error());
  const Scene& current = tune->renderer().scene();
  scene->render.width = current.render.width;  // the window keeps its size
  scene->render.height = current.render.height;
  // A fresh view of the new scene, with the command line's flags (window_tune_source).
  auto fresh = TuneSession::open(window_tune_source(a, path, {}, cli::switch_allow_paths(a.scene)), std::move(scene.value()));
  if (!fresh) return stay(fresh.error());
  if (back) trail.came_from.pop_back();
  else trail.came_from.push_back(tune->scene_path());
  tune = std::move(fresh.value());
  h.edits_generation = tune->edits_generation();  // a fresh tuning: no edits yet
  h.axes = pointer_plane(tune->renderer());
  fit_height_to_buttons(win, h, haptic.value());
  auto felt = std::make_shared<const world::HapticScene>(std::move(haptic.value()));
  const std::optional<glm::dvec3> hand = place_hand(win, tune->renderer(), h, felt, true);
  const std::uint64_t serial = h.loop()->replace_scene(std::move(felt), std::filesystem::path(path).filename().string(), hand);
  h.vibration->set_scene(tune->renderer().scene());
  if (!a.quiet) std::printf("button: switched to %s\n", path.c_str());
  return serial;
}

}  // namespace ps::run_live
