// `pseudoshadow run`: the interactive window. Main thread: GLFW events, device polling (mouse/
// gamepad), rendering through the same Renderer as headless, blit to the window, readouts, help
// and parameter panel over it (app/window/hud.h), a short summary in the title. Haptic thread:
// HapticLoop at 1 kHz. They meet only in the loop's two Snapshots.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <thread>
#include <utility>

#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "app/commands.h"
#include "app/session/free_height.h"
#include "app/window/hud.h"
#include "app/window/panel_links.h"
#include "app/window/readouts_log.h"
#include "app/session/run_events.h"
#include "app/window/run_keys.h"
#include "app/session/session.h"
#include "app/window/window_input.h"
#include "core/file_io.h"
#include "core/output_set.h"
#include "devices/glfw_input.h"
#include "gl/context.h"
#include "render/present.h"
#include "scene/scene_io.h"
#include "tune/overrides_file.h"
#include "tune/tune_session.h"

namespace ps {

namespace {

// The key list comes from app/window/run_keys.h (the help overlay shows the same table).
constexpr const char* kRunNotes = R"(The probe follows the pointer: its shadow's centre sits under it, on any camera and zoom.
Scroll raises (up) or lowers (down) it 0.5 mm per notch; PageUp/Up and PageDown/Down step it
0.5 mm per press and repeat while held; it starts 1 mm above the surface under the pointer
(whatever is there: a sphere, a mesh, a button's face), goes down to 4 mm into it and back to
1 mm after a scene switch, a 4D turn, a panel edit or a reload. M captures the mouse (raw relative motion, 0.1 mm per count, where supported; M again
puts the probe back under the pointer).
The probe itself is hidden by default (P shows it): the pseudo-shadow is the display; when
shown it is drawn where the haptic proxy is, after the push-out. D draws the hand's own position
(the device) as a faint ghost: the gap to the proxy is what fields, viscosity and surfaces do
to it. C puts an attracting charge at the probe, Shift+C removes the nearest one. S saves screenshot_NNNN.png
(without the overlays) and screenshot_NNNN.overrides.toml (panel edits, camera, probe: `render
--scene FILE --overrides screenshot_NNNN.overrides.toml` draws the same image).
Saved changes to the shaders, the scene or its textures are reloaded within 0.5 s; a broken
file keeps the last good state running and shows its file:line in the title and the console.
A box in a corner shows frame time, haptic rate and jitter, distance, speed, penetration,
contact, force and the scene; the title shows the scene and the distance.
)";

std::string run_footer() { return "keys and mouse:\n" + run_keys_text("  ", 1) + kRunNotes; }

constexpr const char* kDescription =
    "Opens a window and lets you move the probe over the scene with a device; the haptic loop\n"
    "runs at 1 kHz on its own thread. Works under Xvfb (xvfb-run -a pseudoshadow run ...).";

struct RunArgs {
  cli::SceneArgs scene;
  std::string device = "mouse", record, stats_path, ui_report, readouts_log;
  long long frames = 0, realtime = 0;
  cli::LiveLoopArgs live;  // --render-threads, --spare-cpu
  double quit_after_s = 0.0;
  bool quiet = false, watch = true, show_probe = false, show_device = false, panel = false;
  RunEventsDesc events;  // --events, --mute, --audio-device (docs/sound.md)
};

void check_device(const std::string& d) {
  const bool log_device = d.rfind("trajectory:", 0) == 0 || d.rfind("playback:", 0) == 0 || d.rfind("pointer:", 0) == 0;
  if (d != "mouse" && d != "gamepad" && !log_device)
    throw cli::UsageError("--device: unknown device '" + d +
                          "' (mouse, gamepad, trajectory:FILE, playback:FILE, pointer:FILE)");
}

void declare(cli::Command& cmd, RunArgs& a) {
  CLI::App& app = cmd.app();
  cli::add_scene_options(app, a.scene);
  cli::add_probe_options(app, a.scene);
  cli::add_image_options(app, a.scene);
  app.add_option_function<std::string>("--device", [&a](const std::string& v) { check_device(v); a.device = v; },
                                       "mouse (default) | gamepad | trajectory:FILE | playback:FILE | pointer:FILE "
                                       "(lines 'time_s x_px y_px height_mm buttons', mapped like the mouse)")
      ->type_name("D");
  app.add_option("--record", a.record, "record the device stream (replay it with `pseudoshadow replay`)")
      ->type_name("FILE")
      ->group(cli::kOutputGroup);
  cli::add_stats_option(app, a.stats_path);
  app.add_option("--events", a.events.log_path, "write every haptic event as a JSON line (docs/sound.md)")
      ->type_name("FILE")
      ->group(cli::kOutputGroup);
  app.add_flag("--mute", a.events.audio.mute, "no event sounds");
  app.add_option("--audio-device", a.events.audio.device, "OpenAL output device (default: the system's default)")
      ->type_name("NAME");
  app.add_option("--ui-report", a.ui_report,
                 "at exit, write JSON with every frame's overlay, help and panel rectangles and the "
                 "pseudo-shadow's bounding box, in window pixels")
      ->type_name("FILE")
      ->group(cli::kOutputGroup);
  app.add_option("--readouts-log", a.readouts_log,
                 "write one JSON line per frame: what the readouts say (state, distance, pressed depth, "
                 "force), hand, proxy, view offset, button, flags, key presses (docs/window.md)")
      ->type_name("FILE")
      ->group(cli::kOutputGroup);
  app.add_option_function<std::string>(
         "--backend",
         [](const std::string& v) {
           if (v != "glfw") throw cli::UsageError("--backend: only glfw opens a window (got '" + v + "')");
         },
         "glfw, the only window backend")
      ->type_name("B")
      ->group(cli::kGlGroup);
  app.add_flag("--show-probe", a.show_probe, "start with the probe drawn (P toggles it)");
  app.add_flag("--show-device", a.show_device,
               "start with the device's own position drawn faintly (D toggles it): the gap to the drawn proxy "
               "is the pseudo-haptic feedback of fields, viscosity and surfaces");
  app.add_flag("--panel", a.panel, "start with the parameter panel shown (F1 toggles it)");
  app.add_flag_callback("--no-watch", [&a] { a.watch = false; },
                        "do not reload the scene, its textures and glsl/ when they change");
  cli::add_int(app, "--realtime", "PRIO", a.realtime, 1, 99,
               "haptic thread SCHED_FIFO at PRIO (1..99; needs CAP_SYS_NICE), much lower jitter on a loaded machine");
  cli::add_live_loop_options(app, a.live);
  cli::add_int(app, "--frames", "N", a.frames, 1, 100'000'000, "quit after N frames");
  cli::add_positive(app, "--quit-after", "S", a.quit_after_s, 1e9, "5", "quit after S seconds");
  cli::add_quiet_option(app, a.quiet, "no summary");
  app.footer(run_footer() + cli::kExitStatusHelp);
}

struct Session {  // everything the window loop touches, grouped by owner thread
  std::unique_ptr<gl::Context> ctx;
  std::unique_ptr<TuneSession> tune;  // owns the Renderer; swaps in a new one on reload
  std::unique_ptr<WindowUi> ui;       // readouts, help, parameter panel (one ImGui frame)
  HudReadouts readouts;               // shown until the next refresh
  double readouts_s = -1.0;           // session time of their last refresh
  std::vector<UiFrameReport> ui_frames;  // --ui-report
  std::string shown_error;            // last reload error printed to the console
  std::uint32_t last_charge_id = 0;   // live charges: ids are never reused
  std::unique_ptr<Device> device;
  GlfwInputDevice* glfw_device = nullptr;  // == device.get() for mouse/gamepad
  PointerLogDevice* pointer_device = nullptr;  // == device.get() for pointer:FILE
  SteadyClock clock;
  std::shared_ptr<const world::HapticScene> haptic_scene;  // before the loop: it must outlive the haptic thread
  FreeHeight floor;                   // the surface under the pointer: the mouse's height counts from it
  std::unique_ptr<vibration::LiveVibration> vibration;  // before the loop too: the loop feeds it ticks
  std::unique_ptr<HapticLoop> loop;
  std::unique_ptr<SampleRecorder> recorder;
  std::unique_ptr<RunEvents> events;  // the one consumer of loop->events(): log, sound, ...
  WindowInput input;
  int screenshots_saved = 0;          // numbers the next screenshot_NNNN.png
  PlaneAxes axes;
  std::vector<double> latency_ms, frame_ms;
  std::string pending_scene;          // a button's scene action, carried out after this frame
  std::vector<std::string> came_from; // scenes a button switched away from (Backspace goes back)
  bool going_back = false;            // the pending switch is a Backspace: do not remember it
  std::string notice;                 // a short answer shown in the readouts until notice_until_s
  double notice_until_s = 0.0, now_s = 0.0;  // now_s: this frame's window time
  std::map<std::string, std::string> haptic_edits;  // the panel's edits the haptic scene was built with
  ReadoutsLog readouts_log;           // --readouts-log
  int frame_keys = 0;                 // key presses handled this frame (the readouts log's `keys`)
};

Status open_device(const RunArgs& a, Session& s) {
  if (a.device == "mouse" || a.device == "gamepad") {
    auto kind = a.device == "mouse" ? GlfwInputDevice::Kind::kMouse : GlfwInputDevice::Kind::kGamepad;
    auto d = std::make_unique<GlfwInputDevice>(kind, s.ctx->window(), GlfwInputParams{});
    s.glfw_device = d.get();
    s.device = std::move(d);
    return ok_status();
  }
  auto d = open_device_log(a.device);
  if (!d) return make_error("--device: " + d.error().message);
  s.device = std::move(d->device);
  s.pointer_device = d->pointer;
  return ok_status();
}

// The hand must be able to push every button of the scene past its travel through the coupling
// (world::deepest_press_mm), with one height step to spare so that PageDown lands beyond it.
// The height is measured from the pointer's plane (s.axes), which need not pass through a
// button's face: Weight's plane is the camera target's, 20 mm above the floor its button sits
// in, so that button needs 20 mm more.
void fit_height_to_buttons(Session& s, const world::HapticScene& scene) {
  if (!s.glfw_device) return;
  const double coupling = s.loop->params().forces.coupling_n_per_mm;
  double deepest = 0.0;
  // The hover height counts from the surface under the pointer (app/session/free_height.h), a button's
  // face included: the range needs the deepest press below a face, not below the plane.
  for (const world::ButtonShape& b : scene.button_shapes())
    deepest = std::max(deepest, world::deepest_press_mm({b}, coupling));
  s.glfw_device->reach_depth(deepest > 0.0 ? deepest + GlfwInputParams{}.height.step_mm : 0.0);
}

// The pointer devices map through the camera this frame draws with (it orbits and zooms) and
// the window's current size (the image is stretched to it).
// `view_at_rest`: the workspace is the world (a new haptic scene's view starts there).
void poll_device(Session& s, double now_s, bool poll_glfw, bool view_at_rest = false) {
  int w = 0, h = 0;
  glfwGetWindowSize(s.ctx->window(), &w, &h);
  PointerView view = pointer_view(s.tune->renderer(), s.axes, {static_cast<double>(w), static_cast<double>(h)});
  if (s.pointer_device) s.pointer_device->set_view(view);
  if (!s.glfw_device || !poll_glfw) return;
  // The mouse hovers over the surface under the pointer (app/session/free_height.h), lowered from the
  // camera's height over the plane; the workspace moves with a [navigation] box or a rolling view.
  const HapticState st = s.loop && !view_at_rest ? s.loop->state().read() : HapticState{};
  s.floor.set_pose(st.view_rotation, st.view_offset_mm);
  s.floor.set_top_mm(std::max(glm::dot(view.camera.position - view.plane.origin, view.plane.n), 60.0));
  view.floor = &s.floor;
  const glm::dvec3 before = s.glfw_device->read(0.0).position_mm;
  s.glfw_device->poll(now_s, view);
  // The surface under a hovering pointer rose or fell (a slope, a silhouette: off a box's top
  // onto the floor): the hand is put at its new height rather than pulled there, so neither the
  // filter's coasting between two readings (4-30 a second) nor the proxy's path cuts through
  // the surface. 0.25 mm: half a height step, so the keys' own steps are not placements.
  const glm::dvec3 after = s.glfw_device->read(0.0).position_mm;
  if (s.loop && s.glfw_device->height_mm() >= 0.0 && std::abs(glm::dot(after - before, view.plane.n)) > 0.25)
    s.loop->place_hand(after, view.plane.n, s.floor.last_normal());
}

// The geometry felt changed (a scene switch, a reload, a panel edit, a 4D turn): the hand goes
// back to the hover height over the surface now under the pointer, and the proxy with it, so
// nothing the person did not do leaves the proxy buried (docs/window.md). Recorded devices
// (logs) keep their own positions.
std::optional<glm::dvec3> place_hand(Session& s, std::shared_ptr<const world::HapticScene> felt, bool new_view) {
  s.floor.set_scene(std::move(felt));
  if (!s.glfw_device) return std::nullopt;
  s.glfw_device->reset_height();
  poll_device(s, s.loop->state().read().time_s, true, new_view);
  return s.glfw_device->read(0.0).position_mm;
}

// The scene is loaded once, before the window: its render.size is the window's size.
Status open_session(const RunArgs& a, Scene scene, Session& s) {
  gl::ContextDesc desc{gl::Backend::kGlfw, scene.render.width, scene.render.height, "pseudoshadow", true, {}};
  auto ctx = gl::create_context(desc);
  if (!ctx) return ctx.error();
  s.ctx = std::move(ctx.value());
  // The Gabor tile bakes between frames, a band of ~40 ms each (about one 512^2 frame with the
  // per-pixel sum on llvmpipe: frames come at half rate and the tile is ready in about twice
  // its whole bake), so the first frame comes at once; until then the per-pixel sum is drawn.
  RendererOptions options;
  options.bake_slice_ms = 40.0;
  auto tune = TuneSession::open({a.scene.path, a.scene.lines(), options, a.scene.allow_paths}, std::move(scene));
  if (!tune) return tune.error();
  s.tune = std::move(tune.value());
  s.axes = pointer_plane(s.tune->renderer());  // fixed at start so the mapping stays put
  if (Status st = open_device(a, s); !st) return st;
  HapticLoopParams params;
  params.realtime_priority = static_cast<int>(a.realtime);
  auto haptic_scene = world::HapticScene::build(s.tune->renderer().scene());
  if (!haptic_scene) return haptic_scene.error();
  s.haptic_scene = std::make_shared<const world::HapticScene>(std::move(haptic_scene.value()));
  s.floor.set_scene(s.haptic_scene);  // the first sample already hovers over what is under the pointer
  s.loop = std::make_unique<HapticLoop>(*s.device, s.clock, params, s.haptic_scene.get());
  fit_height_to_buttons(s, *s.haptic_scene);
  s.vibration = cli::open_live_vibration(a.live, s.tune->renderer().scene(), *s.loop);
  if (s.glfw_device || s.pointer_device) {  // they move over the plane: distance known from the start
    s.loop->surface().publish(initial_surface_model(s.axes, s.tune->renderer().scene().probe.radius_mm));
    poll_device(s, 0.0, true);  // the first tick already has a sample
  }
  if (!a.record.empty()) {
    s.recorder = std::make_unique<SampleRecorder>(a.record);
    s.loop->set_recorder(s.recorder.get());
  }
  install_window_input(s.ctx->window(), s.input);
  s.ui = std::make_unique<WindowUi>(s.ctx->window());  // after: chains to our callbacks
  if (a.panel) s.ui->panel().toggle();
  s.tune->renderer().set_show_probe(a.show_probe);
  s.tune->renderer().set_show_device(a.show_device);
  return ok_status();
}

// The readouts (and the title) change 4 times a second: legible numbers, and the distance AOV
// is read back only then.
constexpr double kReadoutPeriodS = 0.25;

// The frame's pseudo-shadow, measured on its own AOVs: where the overlays must not go (every
// frame) and, with `distance`, the probe-surface distance the readouts show. Each AOV is one
// float read-back of the image: ~6 ms at 512^2 on llvmpipe (measured on this project's
// machine), so the distance is read only when the readouts refresh.
Result<ShadowMeasure> measure_frame_shadow(const Renderer& r, int w, int h, bool distance) {
  auto intensity = r.read_aov(Aov::kIntensity);
  if (!intensity) return intensity.error();
  if (!distance) return measure_shadow(intensity.value(), nullptr, w, h);
  auto d = r.read_aov(Aov::kDistance);
  if (!d) return d.error();
  return measure_shadow(intensity.value(), &d.value(), w, h);
}

HudReadouts readouts(const Session& s, const HapticState& st, const ShadowMeasure& shadow) {
  HudReadouts r;
  const std::string& path = s.tune->scene_path();
  r.scene = path.empty() ? cli::scene_display_name(path) : std::filesystem::path(path).filename().string();
  r.frame_ms = s.frame_ms.empty() ? 0.0 : s.frame_ms.back();
  if (const auto& gpu = s.tune->renderer().stats().gpu_timings_ms; !gpu.empty()) {
    double total = 0.0;
    for (const auto& [pass, ms] : gpu) total += ms;
    r.gpu_frame_ms = total;
  }
  r.haptic_hz = st.rate_hz;
  r.jitter_p99_us = st.jitter_p99_us;
  r.probe = probe_readout({shadow.min_distance_mm, st.in_contact, st.position_mm, st.proxy_mm});
  r.speed_mm_s = glm::length(st.velocity_mm_s);
  r.penetration_mm = s.tune->renderer().stats().max_penetration_mm;
  r.force_n = glm::length(st.force_n);
  r.bake_progress = s.tune->renderer().stats().bake_progress;
  r.error = panel_message(s.tune->last_error());  // a panel edit's error speaks of the panel
  if (s.now_s < s.notice_until_s) r.notice = s.notice;
  const Scene& sc = s.tune->renderer().scene();
  if (st.button_pressed >= 0 && static_cast<std::size_t>(st.button_pressed) < sc.buttons.size()) {
    r.button = st.button_pressed;
    r.button_depth_mm = st.button_depth_mm;
    r.button_travel_mm = sc.buttons[static_cast<std::size_t>(st.button_pressed)].travel_mm;
  }
  if (!sc.flags.empty()) {
    std::string on;
    for (std::size_t i = 0; i < sc.flags.size(); ++i)
      if ((st.flags >> i) & 1u) on += (on.empty() ? "" : ", ") + sc.flags[i];
    r.flags = on;
  }
  if (sc.navigation.enabled) r.view_mm = st.view_offset_mm;
  // The 4D turn of the first surface embedded in 4D (keys 1-6 turn them all alike).
  for (const Surface& x : sc.surfaces)
    if (x.type == SurfaceType::kFourd) {
      r.turn4_deg = x.fourd.rotation_deg;
      break;
    }
  // A rolling fourd surface: the angle the view has turned from the scene's (docs/fourd.md).
  if (std::any_of(sc.surfaces.begin(), sc.surfaces.end(), [](const Surface& x) { return x.fourd.roll.on; })) {
    const glm::dmat3& m = st.view_rotation;
    r.rolled_deg = glm::degrees(std::acos(std::clamp(0.5 * (m[0][0] + m[1][1] + m[2][2] - 1.0), -1.0, 1.0)));
  }
  return r;
}

std::string screenshot_state(const TuneSession& tune) {
  const Renderer& r = tune.renderer();
  std::map<std::string, std::string> state = tune.edits();
  state["camera.position"] = cli::override_value(r.camera().position);
  state["camera.target"] = cli::override_value(r.camera().target);
  state["camera.up"] = cli::override_value(r.camera().up);
  // A rolling view turned the light with the camera (FrameInput::view).
  if (r.view_rotation() != glm::dmat3(1.0)) state["light.direction"] = cli::override_value(r.light().direction);
  // The frame was drawn before its displacement moved the probe.
  state["probe.position"] = cli::override_value(r.probe().position - r.stats().displacement);
  state["probe.velocity"] = cli::override_value(r.probe().velocity);
  return format_overrides(state, cli::scene_display_name(tune.scene_path()));
}

void edit_live_charges(Session& s, bool add);  // below, with the reload

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
void turn_fourd_surfaces(Session& s, int (&steps)[6]);  // below: keys 1-6, a 4D turn

Status handle_keys(Session& s, int w, int h) {
  WindowInput& in = s.input;
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
  if (in.toggle_probe) s.tune->renderer().set_show_probe(!s.tune->renderer().show_probe());
  in.toggle_probe = false;
  if (in.toggle_device) s.tune->renderer().set_show_device(!s.tune->renderer().show_device());
  in.toggle_device = false;
  if (in.add_charge || in.remove_charge) edit_live_charges(s, in.add_charge);
  if (std::exchange(in.back, false)) go_back(s);
  if (std::exchange(in.home, false)) s.loop->request_view_home();
  in.add_charge = in.remove_charge = false;
  turn_fourd_surfaces(s, in.turn4);
  Camera cam = s.tune->renderer().camera();
  apply_orbit_zoom(in, cam);
  s.tune->renderer().set_camera(cam);
  for (; in.screenshots > 0; --in.screenshots) {
    char name[64];
    std::snprintf(name, sizeof name, "screenshot_%04d.png", s.screenshots_saved++);
    // Beside it, the state that made it as an override file: the panel's edits, the camera
    // and the probe as this frame drew them, so `render --scene S --overrides THIS` repeats it.
    // Both appear together or neither does.
    const std::string state = std::string(name).substr(0, std::strlen(name) - 4) + ".overrides.toml";
    OutputSet shot;
    if (Status st = stage_image(shot, name, read_back_buffer(w, h)); !st) return st;
    if (Status st = shot.stage_text(state, screenshot_state(*s.tune)); !st) return st;
    if (Status st = shot.publish(); !st) return st;
    std::printf("saved %s and %s\n", name, state.c_str());
  }
  return ok_status();
}

// Files are polled 5 times a second, so a saved change is on screen within ~0.2 s plus one
// rebuild (shader compile and JIT, ~0.1-0.2 s on llvmpipe).
constexpr double kWatchPeriodS = 0.2;

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

void print_summary(const Session& s) {
  const Percentiles p = s.loop->period_stats(), lat = percentiles(s.latency_ms), fr = percentiles(s.frame_ms);
  std::printf("frames %zu (median %.1f ms); haptic ticks %zu, period p50 %.0f us p99 %.0f us p99.9 %.0f us "
              "max %.0f us; ", fr.count, fr.p50, p.count + 1, p.p50, p.p99, p.p999, p.max);
  if (lat.count == 0) std::printf("no device samples (latency not measured)\n");
  else std::printf("latency sample->frame p50 %.1f ms p99 %.1f ms\n", lat.p50, lat.p99);
}

// --readouts-log: this frame's readouts, as the state machine says them, every frame.
Status log_readouts(Session& s, const HapticState& st, const ShadowMeasure& shadow, std::uint64_t frame) {
  const HudReadouts r = readouts(s, st, shadow);
  ReadoutsFrame f;
  f.frame = frame;
  f.t_s = st.time_s;
  f.scene = r.scene;
  f.probe = r.probe;
  f.distance_mm = shadow.min_distance_mm;
  f.penetration_mm = r.penetration_mm;
  f.buried_mm = s.floor.scene() ? buried_mm(*s.floor.scene(), st.proxy_mm) : 0.0;
  f.force_n = r.force_n;
  f.view_offset_mm = st.view_offset_mm;
  f.hand_mm = st.position_mm;
  f.proxy_mm = st.proxy_mm;
  f.button = r.button;
  f.button_depth_mm = r.button_depth_mm;
  f.button_travel_mm = r.button_travel_mm;
  const Scene& sc = s.tune->renderer().scene();
  if (!sc.flags.empty()) {
    f.flags.emplace();
    for (std::size_t i = 0; i < sc.flags.size(); ++i)
      if ((st.flags >> i) & 1u) f.flags->push_back(sc.flags[i]);
  }
  f.keys = s.frame_keys;
  return s.readouts_log.write(f);
}

// Readouts, help and panel over the frame, placed around its shadow; drawn after the
// screenshots are read back, so they are never in them. With --readouts-log the distance is
// read back every frame (one more AOV read-back a frame), else 4 times a second.
Status draw_overlays(const RunArgs& a, Session& s, const HapticState& st, std::uint64_t frame, double now_s) {
  const bool refresh = now_s - s.readouts_s >= kReadoutPeriodS;
  int w = 0, h = 0;  // ImGui's units: window coordinates, not framebuffer pixels
  glfwGetWindowSize(s.ctx->window(), &w, &h);
  auto shadow = measure_frame_shadow(s.tune->renderer(), w, h, refresh || s.readouts_log.is_open());
  if (!shadow) return shadow.error();
  if (s.readouts_log.is_open())
    if (Status r = log_readouts(s, st, shadow.value(), frame); !r) return r;
  if (refresh) {
    s.readouts = readouts(s, st, shadow.value());
    glfwSetWindowTitle(s.ctx->window(), title_summary(s.readouts).c_str());
    s.readouts_s = now_s;
  }
  const Scene& sc = s.tune->renderer().scene();  // its camera: the one this frame drew with
  const auto buttons = project_buttons(sc, sc.camera, static_cast<double>(sc.render.width) / sc.render.height,
                                       static_cast<float>(w), static_cast<float>(h));
  UiFrameReport report = s.ui->draw(s.readouts, shadow.value(), *s.tune, now_s, buttons);
  report.frame = frame;
  if (!a.ui_report.empty()) s.ui_frames.push_back(report);
  return ok_status();
}

// The event consumers, before the haptic thread starts. No audio device is one warning line.
Status open_events(const RunArgs& a, Session& s) {
  auto events = RunEvents::open(a.events);
  if (!events) return events.error();
  s.events = std::move(events.value());
  if (!s.events->warning().empty()) std::fprintf(stderr, "warning: %s\n", s.events->warning().c_str());
  s.events->dispatcher().subscribe("buttons", [&s](const HapticEvent& e) {
    if (s.pending_scene.empty()) s.pending_scene = scene_action_of(s.tune->renderer().scene(), e);
  });
  return ok_status();
}

// A button's "scene:FILE" action: the window now shows that scene (its own camera and look, in
// the window's size), the haptic thread adopts its haptic scene at its next tick; a file that
// fails to load keeps the current scene and says why.
void switch_scene(const RunArgs& a, Session& s) {
  const std::string path = std::exchange(s.pending_scene, std::string());
  const bool back = std::exchange(s.going_back, false);
  auto stay = [&path](const Error& e) {
    std::fprintf(stderr, "button: cannot switch to %s, staying: %s\n", path.c_str(), e.message.c_str());
  };
  auto scene = load_scene(path, {}, cli::switch_allow_paths(a.scene));
  if (!scene) return stay(scene.error());
  auto haptic = world::HapticScene::build(scene.value());
  if (!haptic) return stay(haptic.error());
  const Scene& current = s.tune->renderer().scene();
  scene->render.width = current.render.width;  // the window keeps its size
  scene->render.height = current.render.height;
  RendererOptions options;
  options.bake_slice_ms = 40.0;
  auto tune = TuneSession::open({path, {}, options, cli::switch_allow_paths(a.scene)}, std::move(scene.value()));
  if (!tune) return stay(tune.error());
  if (back) s.came_from.pop_back();
  else s.came_from.push_back(s.tune->scene_path());
  s.tune = std::move(tune.value());
  s.haptic_edits.clear();
  s.tune->renderer().set_show_probe(a.show_probe);
  s.tune->renderer().set_show_device(a.show_device);
  s.axes = pointer_plane(s.tune->renderer());
  fit_height_to_buttons(s, haptic.value());
  auto felt = std::make_shared<const world::HapticScene>(std::move(haptic.value()));
  const std::optional<glm::dvec3> hand = place_hand(s, felt, true);
  s.loop->replace_scene(std::move(felt), std::filesystem::path(path).filename().string(), hand);
  s.vibration->set_scene(s.tune->renderer().scene());
  if (!a.quiet) std::printf("button: switched to %s\n", path.c_str());
}

Status window_loop(const RunArgs& a, Session& s) {
  GLFWwindow* win = s.ctx->window();
  const auto t0 = std::chrono::steady_clock::now();
  double last_flush = 0.0, last_watch = 0.0;
  for (std::uint64_t frame = 0;; ++frame) {
    const auto f0 = std::chrono::steady_clock::now();
    const double now_s = std::chrono::duration<double>(f0 - t0).count();
    s.now_s = now_s;
    glfwPollEvents();
    if (glfwWindowShouldClose(win) || s.input.quit) break;
    if ((a.frames > 0 && static_cast<long long>(frame) >= a.frames) || (a.quit_after_s > 0 && now_s >= a.quit_after_s)) break;
    poll_device(s, s.loop->state().read().time_s, !s.ui->panel().wants_input());
    HapticState st;
    if (a.watch && now_s - last_watch >= kWatchPeriodS) {
      last_watch = now_s;
      poll_reload(s);
    }
    if (Status r = drive_frame(s.tune->renderer(), *s.loop, frame, st); !r) return r;
    if (Status r = s.events->pump(s.loop->events()); !r) return r;
    if (!s.pending_scene.empty()) switch_scene(a, s);
    int w = 0, h = 0;
    glfwGetFramebufferSize(win, &w, &h);
    present_to_default_framebuffer(s.tune->renderer(), w, h);
    if (Status r = handle_keys(s, w, h); !r) return r;  // screenshots read GL_BACK before the swap
    if (Status r = draw_overlays(a, s, st, frame, now_s); !r) return r;  // after the screenshots
    if (s.tune->edits() != s.haptic_edits) {  // a panel edit may change the feel (a body's time scale)
      s.haptic_edits = s.tune->edits();
      reload_haptic_scene(s);
    }
    s.input.keys_captured = s.ui->panel().wants_input();
    glfwSwapBuffers(win);
    const auto f1 = std::chrono::steady_clock::now();
    s.frame_ms.push_back(std::chrono::duration<double, std::milli>(f1 - f0).count());
    if (st.have_sample) s.latency_ms.push_back(static_cast<double>(f1.time_since_epoch().count() - st.sample_clock_ns) * 1e-6);
    if (s.recorder && now_s - last_flush >= 1.0) {  // a crash loses at most the last second
      if (Status r = s.recorder->flush(); !r) return r;
      last_flush = now_s;
    }
  }
  return ok_status();
}

int run(const cli::Command& cmd, const RunArgs& a) {
  auto scene = cli::load_scene_or_default(a.scene);
  if (!scene) return cmd.fail(scene.error(), cli::scene_exit_code(scene.error()));
  Session s;
  auto live = cli::apply_live_loop(a.live);  // before the context and the haptic thread
  if (!live) return cmd.usage_error(live.error());
  if (Status st = open_session(a, std::move(scene.value()), s); !st) return cmd.fail(st.error());
  if (Status st = open_events(a, s); !st) return cmd.fail(st.error());
  if (!a.readouts_log.empty())
    if (Status st = s.readouts_log.open(a.readouts_log); !st) return cmd.fail(st.error());
  s.loop->start();
  s.vibration->start();
  // The first frame shows the device's probe, not the scene's: wait for the first tick (about
  // 1 ms; bounded, as a gamepad may have nothing to give yet).
  for (int i = 0; i < 100 && !s.loop->state().read().have_sample; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  if (!a.quiet) std::printf("haptic thread: %s; %s\n", s.loop->scheduling().c_str(), live->report().c_str());
  const Status looped = window_loop(a, s);
  s.loop->stop();  // join the haptic thread before touching what it wrote
  s.vibration->close();
  if (s.recorder)
    if (Status st = s.recorder->close(); !st) return cmd.fail(st.error());
  if (Status st = s.events->close(s.loop->events()); !st) return cmd.fail(st.error());
  if (!looped) return cmd.fail(looped.error());
  if (Status st = s.readouts_log.close(); !st) return cmd.fail(st.error());
  if (!a.stats_path.empty()) {
    const Renderer& r = s.tune->renderer();
    const std::string json = stats_json(r.stats(), gl::backend_name(s.ctx->backend()), s.ctx->egl_device(), s.ctx->renderer(),
                                        static_cast<int>(s.frame_ms.size()));
    if (Status st = write_file_atomic(a.stats_path, json); !st) return cmd.fail(st.error());
  }
  if (!a.ui_report.empty()) {
    int w = 0, h = 0;
    glfwGetWindowSize(s.ctx->window(), &w, &h);
    if (Status st = write_file_atomic(a.ui_report, ui_report_json(w, h, s.ui_frames)); !st) return cmd.fail(st.error());
  }
  if (!a.quiet) print_summary(s);
  if (!a.quiet && s.vibration->active()) std::printf("%s\n", s.vibration->summary().c_str());
  return cli::kExitOk;
}

}  // namespace

int run_window(int argc, char** argv) {
  return cli::run_command<RunArgs>(argc, argv, "run", kDescription, declare, run);
}

}  // namespace ps
