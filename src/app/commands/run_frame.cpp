// `pseudoshadow run`: the device, the session's opening, and the readouts, help and panel over
// each frame (app/commands/run_live.h).
#include "app/commands/run_live.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <filesystem>
#include <optional>
#include <utility>

#include "app/cli/cli.h"
#include "app/window/panel_links.h"
#include "tune/overrides_file.h"

namespace ps::run_live {

namespace {

Status open_device(const RunArgs& a, Session& s) {
  if (Status st = s.window->open_device(a.device); !st) return st;
  s.glfw_device = s.window->input();
  s.pointer_device = s.window->pointer();
  return ok_status();
}

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
    const glm::dmat3& m = st.view_rotation;
    r.rolled_deg = glm::degrees(std::acos(std::clamp(0.5 * (m[0][0] + m[1][1] + m[2][2] - 1.0), -1.0, 1.0)));
  }
}

HudReadouts readouts(const Session& s, const HapticState& st, const ShadowMeasure& shadow) {
  HudReadouts r;
  const std::string& path = s.tune->scene_path();
  r.scene = path.empty() ? cli::scene_display_name(path) : std::filesystem::path(path).filename().string();
  r.frame_ms = s.last_frame_ms;
  if (const auto& gpu = s.tune->renderer().stats().gpu_timings_ms; !gpu.empty()) {
    double total = 0.0;
    for (const auto& [pass, ms] : gpu) total += ms;
    r.gpu_frame_ms = total;
  }
  r.haptic_hz = st.rate_hz;
  r.jitter_p99_us = st.jitter_p99_us;
  // A button's face pushing back is a touch too (the proxy rests on it while it travels).
  const bool on_button = st.button_pressed >= 0 && st.button_depth_mm > 0.0;
  const double coupling = s.loop->params().forces.coupling_n_per_mm;
  r.probe = probe_readout({shadow.min_distance_mm, st.in_contact || on_button, st.position_mm, st.proxy_mm,
                           st.field_force_n / std::max(coupling, 1e-9), st.proxy_catching_up});
  r.speed_mm_s = glm::length(st.velocity_mm_s);
  r.penetration_mm = s.tune->renderer().stats().max_penetration_mm;
  r.force_n = glm::length(st.force_n);
  r.bake_progress = s.tune->renderer().stats().bake_progress;
  r.error = panel_message(s.tune->last_error());  // a panel edit's error speaks of the panel
  if (s.now_s < s.notice_until_s) r.notice = s.notice;
  scene_readouts(s.tune->renderer().scene(), st, r);
  return r;
}

// --readouts-log: this frame's readouts, as the state machine says them, every frame.
Status log_readouts(Session& s, const HapticState& st, const ShadowMeasure& shadow, const HudReadouts& r,
                    std::uint64_t frame) {
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
  f.haptic_hz = r.haptic_hz;
  f.jitter_p99_us = r.jitter_p99_us;
  if (const DeformationStats& d = s.tune->renderer().deformation(); d.surfaces > 0) f.dent_mm = d.max_displacement_mm;
  int w = 0, h = 0;
  double x = 0.0, y = 0.0;
  glfwGetWindowSize(s.window->glfw(), &w, &h);
  glfwGetCursorPos(s.window->glfw(), &x, &y);
  if (x >= 0.0 && y >= 0.0 && x < w && y < h) f.pointer_px = glm::dvec2(x, y);
  if (shadow.core) f.shadow_px = glm::dvec2(shadow.core->first, shadow.core->second);
  return s.readouts_log.write(f);
}

}  // namespace

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
  // The height moves the hand along the pointer plane's normal, which need not be the button's
  // (Illusion's plane faces the camera): a button facing it at cos a needs 1 / cos a as much.
  for (const world::ButtonShape& b : scene.button_shapes())
    deepest = std::max(deepest, world::deepest_press_mm({b}, coupling) /
                                    std::max(glm::dot(b.normal(), s.axes.n), 0.25));
  s.glfw_device->reach_depth(deepest > 0.0 ? deepest + GlfwInputParams{}.height.step_mm : 0.0);
}

// The pointer devices map through the camera this frame draws with (it orbits and zooms) and
// the window's current size (the image is stretched to it).
// `view_at_rest`: the workspace is the world (a new haptic scene's view starts there).
void poll_device(Session& s, double now_s, bool poll_glfw, bool view_at_rest) {
  int w = 0, h = 0;
  glfwGetWindowSize(s.window->glfw(), &w, &h);
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
  // the surface. 0.25 mm: half a height step, so the keys' own steps are not placements. So is a
  // point under the pointer that jumped across a silhouette (off a bump onto what lies behind
  // it: pointing by ray), 1 mm: the surface's parallax is smooth elsewhere, so strokes over it
  // keep their speed.
  // So is a hover whose straight way from the last reading to this one (and half as far again:
  // the filter coasts on between readings) comes within half the hover height of a surface: over
  // a curved surface the hovering places lie on a curve and the chord between two cuts it.
  const glm::dvec3 after = s.glfw_device->read(0.0).position_mm;
  const double hover = s.glfw_device->height_mm();
  const bool rose_or_fell = std::abs(glm::dot(after - before, view.plane.n)) > 0.25;
  // The cheap checks first: the path is traced only when they do not already place the hand.
  const auto cuts = [&] {
    return hover > 0.25 && !s.floor.path_clear(before, after + 0.5 * (after - before), view.probe_radius_mm, 0.5 * hover);
  };
  if (s.loop && hover >= 0.0 && (rose_or_fell || s.glfw_device->parallax_jump_mm() > 1.0 || cuts()))
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

// The Gabor tile bakes between frames, a band of ~40 ms each (about one 512^2 frame with the
// per-pixel sum on llvmpipe: frames come at half rate and the tile is ready in about twice its
// whole bake), so the first frame comes at once; until then the per-pixel sum is drawn.
constexpr double kWindowBakeSliceMs = 40.0;

TuneSource window_tune_source(const RunArgs& a, std::string scene_path, std::vector<std::string> sets,
                              std::vector<std::string> allow_paths) {
  TuneSource source{std::move(scene_path), std::move(sets), {}, std::move(allow_paths), {}};
  source.renderer.bake_slice_ms = kWindowBakeSliceMs;
  source.renderer.incremental = !a.no_incremental;
  source.show = ViewFlags{a.show_probe, false, a.show_device};  // probe, path, device
  return source;
}

// The scene is loaded once, before the window: its render.size is the window's size.
Status open_session(const RunArgs& a, Scene scene, Session& s) {
  auto window = LiveWindow::open({scene.render.width, scene.render.height, "pseudoshadow"});
  if (!window) return window.error();
  s.window = std::move(window.value());
  auto tune = TuneSession::open(window_tune_source(a, a.scene.path, a.scene.lines(), a.scene.allow_paths), std::move(scene));
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
  s.loop = std::make_unique<HapticLoop>(s.window->device(), s.clock, params, s.haptic_scene.get());
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
  s.window->listen(s.input);
  s.input.pointer_inside = s.window->hovered();
  s.ui = std::make_unique<WindowUi>();
  if (a.panel) s.ui->panel().toggle();
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

void print_summary(const Session& s) {
  const Percentiles p = s.loop->period_stats(), lat = s.latency_ms.percentiles(), fr = s.frame_ms.percentiles();
  std::printf("frames %zu (median %.1f ms); haptic ticks %zu, period p50 %.0f us p99 %.0f us p99.9 %.0f us "
              "max %.0f us; ", fr.count, fr.p50, p.count + 1, p.p50, p.p99, p.p999, p.max);
  if (lat.count == 0) std::printf("no device samples (latency not measured)\n");
  else std::printf("latency sample->frame p50 %.1f ms p99 %.1f ms\n", lat.p50, lat.p99);
}

// Readouts, help and panel over the frame, placed around its shadow; drawn after the
// screenshots are read back, so they are never in them. With --readouts-log the distance is
// read back every frame (one more AOV read-back a frame), else 4 times a second.
Status draw_overlays(const RunArgs& a, Session& s, const HapticState& st, std::uint64_t frame, double now_s) {
  const bool refresh = now_s - s.readouts_s >= kReadoutPeriodS;
  int w = 0, h = 0;  // ImGui's units: window coordinates, not framebuffer pixels
  glfwGetWindowSize(s.window->glfw(), &w, &h);
  auto shadow = measure_frame_shadow(s.tune->renderer(), w, h, refresh || s.readouts_log.is_open(), s.aov_buffers);
  if (!shadow) return shadow.error();
  // Built once a frame when it is logged, else only at a refresh (4 times a second).
  std::optional<HudReadouts> now;
  if (s.readouts_log.is_open() || refresh) now = readouts(s, st, shadow.value());
  if (s.readouts_log.is_open())
    if (Status r = log_readouts(s, st, shadow.value(), *now, frame); !r) return r;
  if (refresh) {
    s.readouts = std::move(*now);
    glfwSetWindowTitle(s.window->glfw(), title_summary(s.readouts).c_str());
    s.readouts_s = now_s;
  }
  // Through the camera this frame drew with (orbited, zoomed, moved by [navigation] or a rolling
  // view), not the scene file's: each label stays on its plate while the view moves (Field's
  // label had stayed where the plate started).
  const Scene& sc = s.tune->renderer().scene();
  const auto buttons = project_buttons(sc, s.tune->view().camera,
                                       static_cast<double>(sc.render.width) / sc.render.height,
                                       static_cast<float>(w), static_cast<float>(h));
  UiFrameReport report = s.ui->draw(s.readouts, shadow.value(), *s.tune, now_s, buttons);
  report.frame = frame;
  if (!a.ui_report.empty()) s.ui_frames.push_back(report);
  return ok_status();
}

}  // namespace ps::run_live
