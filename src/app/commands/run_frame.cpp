// `pseudoshadow run`: the device, the window's opening, and the readouts, help and panel over
// each frame (app/commands/run_live.h).
#include "app/commands/run_live.h"

#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <utility>

#include "app/cli/cli.h"
#include "app/window/panel_links.h"
#include "tune/overrides_file.h"

namespace ps::run_live {

namespace {

// The readouts (and the title) change 4 times a second: legible numbers, and the distance AOV
// is read back only then.
constexpr double kReadoutPeriodS = 0.25;

// The frame's pseudo-shadow, measured on its own AOVs: where the overlays must not go (every
// frame) and, with `distance`, the probe-surface distance the readouts show. Each AOV is one
// float read-back of the image: ~6 ms at 512^2 on llvmpipe (measured on this project's
// machine), so the distance is read only when the readouts refresh.
// The images are read into `buf`, kept from frame to frame: no allocation per frame (three
// image-size buffers a frame, allocated and freed, left the heap fragmented over hours).
Result<ShadowMeasure> measure_frame_shadow(const Renderer& r, int w, int h, bool distance, AovBuffers& buf) {
  if (Status s = r.read_aov_into(Aov::kIntensity, buf.intensity, buf.raw); !s) return s.error();
  if (!distance) return measure_shadow(buf.intensity, nullptr, w, h);
  if (Status s = r.read_aov_into(Aov::kDistance, buf.distance, buf.raw); !s) return s.error();
  return measure_shadow(buf.intensity, &buf.distance, w, h);
}

// What the scene adds to the readouts: the button pressed, the flags set, the 4D turn, the roll.
void scene_readouts(const Scene& sc, const HapticState& st, HudReadouts& r) {
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
    r.rolled_deg = view_turn_deg(st.view_rotation);  // the readouts log's view_turn_deg
  }
}

// The readouts of this frame; `coupling`: the haptic loop's, N/mm.
HudReadouts current_readouts(const TuneSession& tune, const FrameReadouts& ro, double coupling, const HapticState& st,
                             const ShadowMeasure& shadow, double now_s) {
  HudReadouts r;
  const std::string& path = tune.scene_path();
  r.scene = path.empty() ? cli::scene_display_name(path) : std::filesystem::path(path).filename().string();
  r.frame_ms = ro.last_frame_ms;
  if (const auto& gpu = tune.renderer().stats().gpu_timings_ms; !gpu.empty()) {
    double total = 0.0;
    for (const auto& [pass, ms] : gpu) total += ms;
    r.gpu_frame_ms = total;
  }
  r.haptic_hz = st.rate_hz;
  r.jitter_p99_us = st.jitter_p99_us;
  // A button's face pushing back is a touch too (the proxy rests on it while it travels).
  const bool on_button = st.button_pressed >= 0 && st.button_depth_mm > 0.0;
  r.probe = probe_readout({shadow.min_distance_mm, st.in_contact || on_button, st.position_mm, st.proxy_mm,
                           st.field_force_n / std::max(coupling, 1e-9), st.proxy_catching_up});
  r.speed_mm_s = glm::length(st.velocity_mm_s);
  r.penetration_mm = tune.renderer().stats().max_penetration_mm;
  r.force_n = glm::length(st.force_n);
  r.bake_progress = tune.renderer().stats().bake_progress;
  r.error = panel_message(tune.last_error());  // a panel edit's error speaks of the panel
  if (now_s < ro.notice_until_s) r.notice = ro.notice;
  scene_readouts(tune.renderer().scene(), st, r);
  return r;
}

// --readouts-log: this frame's readouts, as the state machine says them, every frame (what the
// renderer and the haptic state tell; the caller adds the rest).
ReadoutsFrame readouts_frame(const Renderer& renderer, const HapticState& st, const ShadowMeasure& shadow,
                             const HudReadouts& r, std::uint64_t frame) {
  ReadoutsFrame f;
  f.frame = frame;
  f.t_s = st.time_s;
  f.scene = r.scene;
  f.probe = r.probe;
  f.distance_mm = shadow.min_distance_mm;
  f.penetration_mm = r.penetration_mm;
  f.force_n = r.force_n;
  f.view_offset_mm = st.view_offset_mm;
  f.view_turn_deg = view_turn_deg(st.view_rotation);
  f.hand_mm = st.position_mm;
  f.proxy_mm = st.proxy_mm;
  f.button = r.button;
  f.button_depth_mm = r.button_depth_mm;
  f.button_travel_mm = r.button_travel_mm;
  const Scene& sc = renderer.scene();
  if (!sc.flags.empty()) {
    f.flags.emplace();
    for (std::size_t i = 0; i < sc.flags.size(); ++i)
      if ((st.flags >> i) & 1u) f.flags->push_back(sc.flags[i]);
  }
  f.haptic_hz = r.haptic_hz;
  f.jitter_p99_us = r.jitter_p99_us;
  if (const DeformationStats& d = renderer.deformation(); d.surfaces > 0) f.dent_mm = d.max_displacement_mm;
  if (shadow.core) f.shadow_px = glm::dvec2(shadow.core->first, shadow.core->second);
  f.surface_scale = renderer.stats().surface_scale;
  f.view_moved = renderer.stats().view_moved;
  return f;
}

Status log_readouts(const LiveWindow& win, const Renderer& renderer, const LiveHaptics& h, FrameReadouts& ro,
                    const HapticState& st, const ShadowMeasure& shadow, const HudReadouts& r, std::uint64_t frame) {
  ReadoutsFrame f = readouts_frame(renderer, st, shadow, r, frame);
  f.buried_mm = h.floor.scene() ? buried_mm(*h.floor.scene(), st.proxy_mm) : 0.0;
  f.keys = ro.frame_keys;
  f.pointer_px = win.pointer_in_window();
  return ro.log.write(f);
}

}  // namespace

// The hand must be able to push every button of the scene past its travel through the coupling
// (world::deepest_press_mm), with one height step to spare so that PageDown lands beyond it.
// The height is measured from the pointer's plane (LiveHaptics::axes), which need not pass through a
// button's face: Weight's plane is the camera target's, 20 mm above the floor its button sits
// in, so that button needs 20 mm more.
void fit_height_to_buttons(const LiveWindow& win, const LiveHaptics& h, const world::HapticScene& scene) {
  if (!win.input()) return;
  const double coupling = h.loop()->params().forces.coupling_n_per_mm;
  double deepest = 0.0;
  // The hover height counts from the surface under the pointer (app/session/free_height.h), a button's
  // face included: the range needs the deepest press below a face, not below the plane.
  // The height moves the hand along the pointer plane's normal, which need not be the button's
  // (Illusion's plane faces the camera): a button facing it at cos a needs 1 / cos a as much.
  for (const world::ButtonShape& b : scene.button_shapes())
    deepest = std::max(deepest, world::deepest_press_mm({b}, coupling) /
                                    std::max(glm::dot(b.normal(), h.axes.n), 0.25));
  win.input()->reach_depth(deepest > 0.0 ? deepest + GlfwInputParams{}.height.step_mm : 0.0);
}

// The pointer devices map through the camera this frame draws with (it orbits and zooms) and
// the window's current size (the image is stretched to it).
// `view_at_rest`: the workspace is the world (a new haptic scene's view starts there).
void poll_device(const LiveWindow& win, const Renderer& r, LiveHaptics& h, double now_s, bool poll_glfw,
                 bool view_at_rest) {
  const glm::ivec2 size = win.window_size();
  PointerView view = pointer_view(r, h.axes, glm::dvec2(size));
  if (win.pointer()) win.pointer()->set_view(view);
  GlfwInputDevice* const device = win.input();
  if (!device || !poll_glfw) return;
  // The mouse hovers over the surface under the pointer (app/session/free_height.h), lowered from the
  // camera's height over the plane; the workspace moves with a [navigation] box or a rolling view.
  const HapticState st = h.loop() && !view_at_rest ? h.loop()->state().read() : HapticState{};
  h.floor.set_pose(st.view_rotation, st.view_offset_mm);
  h.floor.set_top_mm(std::max(glm::dot(view.camera.position - view.plane.origin, view.plane.n), 60.0));
  view.floor = &h.floor;
  const glm::dvec3 before = device->newest().position_mm;
  device->poll(now_s, view);
  // The surface under a hovering pointer rose or fell (a slope, a silhouette: off a box's top
  // onto the floor): the hand is put at its new height rather than pulled there, so neither the
  // hand's straight way between two readings (4-60 a second) nor the proxy's path cuts through
  // the surface. 0.25 mm: half a height step, so the keys' own steps are not placements. So is a
  // point under the pointer that jumped across a silhouette (off a bump onto what lies behind
  // it: pointing by ray), 1 mm: the surface's parallax is smooth elsewhere, so strokes over it
  // keep their speed.
  // So is a hover whose straight way from the last reading to this one (the hand's way between
  // them: GlfwInputDevice::read; and half as far again, a margin for the filter behind it) comes
  // within half the hover height of a surface: over a curved surface the hovering places lie on a
  // curve and the chord between two cuts it.
  const glm::dvec3 after = device->newest().position_mm;
  const double hover = device->height_mm();
  const bool rose_or_fell = std::abs(glm::dot(after - before, view.plane.n)) > 0.25;
  // The cheap checks first: the path is traced only when they do not already place the hand.
  const auto cuts = [&] {
    return hover > 0.25 && !h.floor.path_clear(before, after + 0.5 * (after - before), view.probe_radius_mm, 0.5 * hover);
  };
  // So is a pointer at rest whose proxy was left behind a raised part (proxy_stranded: readings
  // 100+ ms apart skipped its top, the hand went below it, and the proxy stayed pressed against
  // its side, 90 mm from the pointer, until the pointer came back). At rest the proxy of a
  // hovering hand has reached it unless something holds it: 2 mm past the hover height.
  const auto stranded = [&] {
    if (glm::length(after - before) > 0.25 || st.proxy_catching_up || !st.have_sample) return false;
    const glm::dvec3 proxy = glm::transpose(st.view_rotation) * (st.proxy_mm - st.view_offset_mm);
    return proxy_stranded(h.floor, after, proxy, hover + 2.0);
  };
  if (h.loop() && hover >= 0.0 && (rose_or_fell || device->parallax_jump_mm() > 1.0 || cuts() || stranded())) {
    device->snap();  // else the hand would go on along the way from `before` the loop places it off
    h.loop()->place_hand(after, view.plane.n, h.floor.last_normal());
  }
}

// The geometry felt changed (a scene switch, a reload, a panel edit, a 4D turn): the hand goes
// back to the hover height over the surface now under the pointer, and the proxy with it, so
// nothing the person did not do leaves the proxy buried (docs/window.md). Recorded devices
// (logs) keep their own positions.
std::optional<glm::dvec3> place_hand(const LiveWindow& win, const Renderer& r, LiveHaptics& h,
                                     std::shared_ptr<const world::HapticScene> felt, bool new_view) {
  h.floor.set_scene(std::move(felt));
  if (!win.input()) return std::nullopt;
  win.input()->reset_height();
  poll_device(win, r, h, h.loop()->state().read().time_s, true, new_view);
  win.input()->snap();  // the hand is put there, not led there from the old scene's place
  return win.input()->newest().position_mm;
}

// The Gabor tile bakes between frames, a band as long as the last frame but at least ~40 ms
// (render/tile_bake.h: frames come at half rate and the tile is ready in about twice its whole
// bake), so the first frame comes at once; until then the per-pixel sum is drawn.
constexpr double kWindowBakeSliceMs = 40.0;

TuneSource window_tune_source(const RunArgs& a, std::string scene_path, std::vector<std::string> sets,
                              std::vector<std::string> allow_paths) {
  TuneSource source{std::move(scene_path), std::move(sets), {}, std::move(allow_paths), {}};
  source.renderer.bake_slice_ms = kWindowBakeSliceMs;
  source.renderer.incremental = !a.no_incremental;
  source.show = ViewFlags{a.show_probe, false, a.show_device};  // probe, path, device
  return source;
}

// The haptic side: the haptic scene, the loop on the window's device with its recording, the
// vibration; the pointer devices already placed over the scene.
Status open_haptics(const RunArgs& a, const LiveWindow& win, const Renderer& r, LiveHaptics& h) {
  h.axes = pointer_plane(r);  // fixed at start so the mapping stays put
  HapticLoopParams params;
  params.realtime_priority = static_cast<int>(a.realtime);
  auto haptic_scene = world::HapticScene::build(r.scene());
  if (!haptic_scene) return haptic_scene.error();
  h.scene = std::make_shared<const world::HapticScene>(std::move(haptic_scene.value()));
  h.floor.set_scene(h.scene);  // the first sample already hovers over what is under the pointer
  // The loop with the device stream's recording (--record; flushed once a second by a thread of
  // its own, frames or not: start_flushing).
  h.recorded = std::make_unique<RecordedLoop>(win.device(), h.clock, params, h.scene, a.record, 0);
  fit_height_to_buttons(win, h, *h.scene);
  h.vibration = cli::open_live_vibration(a.live, r.scene(), *h.loop());
  if (win.input() || win.pointer()) {  // they move over the plane: distance known from the start
    h.loop()->surface().publish(initial_surface_model(h.axes, r.scene().probe.radius_mm));
    poll_device(win, r, h, 0.0, true);  // the first tick already has a sample
  }
  return ok_status();
}

// The scene is loaded once, before the window: its render.size is the window's size.
Status open_run(const RunArgs& a, Scene scene, RunState& s) {
  auto window = LiveWindow::open({scene.render.width, scene.render.height, "pseudoshadow"});
  if (!window) return window.error();
  WindowIo& io = s.io;
  io.window = std::move(window.value());
  auto tune = TuneSession::open(window_tune_source(a, a.scene.path, a.scene.lines(), a.scene.allow_paths), std::move(scene));
  if (!tune) return tune.error();
  s.tune = std::move(tune.value());
  if (Status st = io.window->open_device(a.device); !st) return st;
  if (Status st = open_haptics(a, *io.window, s.tune->renderer(), s.haptics); !st) return st;
  io.window->listen(io.input);
  io.input.pointer_inside = io.window->hovered();
  io.ui = std::make_unique<WindowUi>();
  if (a.panel) io.ui->panel().toggle();
  return ok_status();
}

std::string screenshot_state(const TuneSession& tune) {
  const View& v = tune.view();
  std::map<std::string, std::string> state = tune.edits();
  state["camera.position"] = cli::override_value(v.camera.position);
  state["camera.target"] = cli::override_value(v.camera.target);
  state["camera.up"] = cli::override_value(v.camera.up);
  // A rolling view turned the light with the camera (FrameInput::view).
  if (v.pose.rotation != glm::dmat3(1.0)) state["light.direction"] = cli::override_value(v.light.direction);
  // The frame was drawn before its displacement moved the probe.
  state["probe.position"] = cli::override_value(v.probe.position - tune.renderer().stats().displacement);
  state["probe.velocity"] = cli::override_value(v.probe.velocity);
  return format_overrides(state, cli::scene_display_name(tune.scene_path()));
}

void print_summary(const HapticLoop& loop, const FrameReadouts& ro) {
  const Percentiles p = loop.period_stats(), lat = ro.latency_ms.percentiles(), fr = ro.frame_ms.percentiles();
  std::printf("frames %zu (median %.1f ms); haptic ticks %zu, period p50 %.0f us p99 %.0f us p99.9 %.0f us "
              "max %.0f us; ", fr.count, fr.p50, p.count + 1, p.p50, p.p99, p.p999, p.max);
  if (lat.count == 0) std::printf("no device samples (latency not measured)\n");
  else std::printf("latency sample->frame p50 %.1f ms p99 %.1f ms\n", lat.p50, lat.p99);
}

// The frame's shadow is measured every frame (where the overlays must not go); the readouts are
// refreshed from it 4 times a second, with the title. With --readouts-log the distance is read
// back every frame (one more AOV read-back a frame) and the readouts built for each.
Result<ShadowMeasure> update_readouts(LiveWindow& win, const TuneSession& tune, const LiveHaptics& h,
                                      FrameReadouts& ro, const HapticState& st, std::uint64_t frame, double now_s) {
  const bool refresh = now_s - ro.refreshed_s >= kReadoutPeriodS;
  const glm::ivec2 size = win.window_size();  // ImGui's units: window coordinates, not framebuffer pixels
  auto shadow = measure_frame_shadow(tune.renderer(), size.x, size.y, refresh || ro.log.is_open(), ro.aov_buffers);
  if (!shadow) return shadow.error();
  // Built once a frame when it is logged, else only at a refresh (4 times a second).
  std::optional<HudReadouts> now;
  const double coupling = h.loop()->params().forces.coupling_n_per_mm;
  if (ro.log.is_open() || refresh) now = current_readouts(tune, ro, coupling, st, shadow.value(), now_s);
  if (ro.log.is_open())
    if (Status r = log_readouts(win, tune.renderer(), h, ro, st, shadow.value(), *now, frame); !r) return r.error();
  if (refresh) {
    ro.shown = std::move(*now);
    win.set_title(title_summary(ro.shown));
    ro.refreshed_s = now_s;
  }
  return shadow;
}

// Readouts, help and panel over the frame, placed around its shadow; drawn after the
// screenshots are read back, so they are never in them.
void draw_overlays(const RunArgs& a, WindowIo& io, TuneSession& tune, const HudReadouts& shown,
                   const ShadowMeasure& shadow, std::uint64_t frame, double now_s) {
  const glm::ivec2 size = io.window->window_size();
  // Through the camera this frame drew with (orbited, zoomed, moved by [navigation] or a rolling
  // view), not the scene file's: each label stays on its plate while the view moves (Field's
  // label had stayed where the plate started).
  const Scene& sc = tune.renderer().scene();
  const auto buttons = project_buttons(sc, tune.view().camera, static_cast<double>(sc.render.width) / sc.render.height,
                                       static_cast<float>(size.x), static_cast<float>(size.y));
  UiFrameReport report = io.ui->draw(shown, shadow, tune, now_s, buttons);
  report.frame = frame;
  if (!a.ui_report.empty()) io.ui_report.add(report);
}

}  // namespace ps::run_live
