#include "app/session/session.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "frame/haptic_frame.h"

namespace ps {

Status drive_frame(Renderer& renderer, HapticLoop& loop, std::uint64_t frame, HapticState& state) {
  state = loop.state().read();
  HapticFrameSources sources;
  sources.coupling_n_per_mm = loop.params().forces.coupling_n_per_mm;
  sources.charges = loop.live_charges().read();
  const FrameInput input = haptic_frame_input(renderer, state, sources);
  step_deformation(renderer, input, state.time_s);
  const glm::dvec3 shown = drawn_probe(renderer, input);
  const auto drawn = renderer.render(input);
  if (!drawn) return drawn.error();
  // The camera this frame drew with, as the workspace sees it: the rolling manifold's centre.
  loop.view_axes().publish({true, world::view_axes_of(renderer.workspace_camera())});
  const FrameStats& st = drawn.value();
  // The render thread is the only writer of surface(), so reading back its own last value is safe.
  const SurfaceModel model = update_surface_model(loop.surface().read(), st.reference_normal, shown,
                                                  renderer.probe().radius_mm, st.max_penetration_mm,
                                                  st.shadow_pixels > 0, frame);
  loop.surface().publish(model);
  return ok_status();
}

PlaneAxes pointer_plane(const Renderer& renderer) {
  const PlaneFrame& f = renderer.reference();
  return {renderer.camera().target, f.t, f.b, f.n};
}

PointerView pointer_view(const Renderer& renderer, const PlaneAxes& plane, glm::dvec2 window_size) {
  const Scene& sc = renderer.scene();
  PointerView v;
  // The pointer moves the hand in the device's workspace: through the camera as it was before
  // any [navigation] moved or rolling turned the view (the haptic loop maps the hand itself).
  v.camera = renderer.workspace_camera();
  v.aspect = static_cast<double>(sc.render.width) / sc.render.height;
  v.window_size = window_size.x > 0.0 && window_size.y > 0.0 ? window_size : glm::dvec2(sc.render.width, sc.render.height);
  v.plane = plane;
  v.probe_radius_mm = sc.probe.radius_mm;
  return v;
}

Result<LogDeviceSpec> open_device_log(const std::string& spec) {
  const std::string kind = spec.substr(0, spec.find(':'));
  if (kind != "trajectory" && kind != "playback" && kind != "pointer")
    return make_error("device '" + spec + "': expected trajectory:FILE, playback:FILE or pointer:FILE");
  LogDeviceSpec out;
  if (kind == "pointer") {
    auto d = open_pointer_device(spec);
    if (!d) return d.error();
    out.pointer = d.value().get();
    out.device = std::move(d.value());
    return out;
  }
  auto d = open_log_device(spec);
  if (!d) return d.error();
  out.device = std::move(d.value());
  return out;
}

SurfaceModel initial_surface_model(const PlaneAxes& plane, double probe_radius_mm) {
  SurfaceModel m;
  m.normal = plane.n;
  m.point_mm = plane.origin;
  m.probe_radius_mm = probe_radius_mm;
  m.valid = true;
  return m;
}

std::string scene_action_of(const Scene& scene, const HapticEvent& e) {
  if (e.kind != EventKind::button_fired || e.index < 0 || static_cast<std::size_t>(e.index) >= scene.buttons.size())
    return {};
  const Button& b = scene.buttons[static_cast<std::size_t>(e.index)];
  return b.action_kind == ButtonActionKind::kScene ? b.action_target : std::string();
}

namespace {

// Runs the ticks up to `last_tick` included, in blocks of at most half the feed, draining the
// feed after each block.
void run_ticks_to(HapticLoop& loop, std::uint64_t last_tick, std::uint64_t& ticks_done, TickFeed& feed,
                  const ReplayOptions& options) {
  while (ticks_done < last_tick + 1) {
    const std::uint64_t n = std::min<std::uint64_t>(last_tick + 1 - ticks_done, kReplayTickFeedCapacity / 2);
    loop.run_ticks(n);
    ticks_done += n;
    if (options.on_tick) feed.drain(options.on_tick);
  }
}

// The haptic events since the last frame, passed on; the first button that leads to a scene
// hands the loop its haptic scene and returns the renderer that draws it (null: none). That
// renderer draws from the next frame on: this frame's state is from before the loop's next tick,
// which adopts the scene, so drawn by it the new world would show the old world's probe (in
// tests/haptics/data/universe_to_weight.traj, the panel's press: 4.5 mm inside Weight's geometry).
Result<Renderer*> take_events(HapticLoop& loop, const Renderer& renderer, const ReplayOptions& options) {
  std::string switch_to;
  loop.events().drain([&](const HapticEvent& e) {
    if (options.on_event) options.on_event(e);
    if (switch_to.empty()) switch_to = scene_action_of(renderer.scene(), e);
  });
  if (switch_to.empty() || !options.switch_scene) return static_cast<Renderer*>(nullptr);
  auto next = options.switch_scene(switch_to);
  if (!next) return next.error();
  loop.replace_scene(next->haptic, std::filesystem::path(switch_to).filename().string());
  return next->renderer;
}

}  // namespace

Result<ReplayResult> replay_session(Renderer& first_renderer, Device& device, const ReplayOptions& options,
                                    const FrameSink& sink) {
  Renderer* renderer = &first_renderer;
  if (!(options.fps > 0.0)) return make_error("replay: fps must be > 0");
  const double duration = std::max(0.0, device.duration_s());
  const int frames = static_cast<int>(std::floor(duration * options.fps + 1e-9)) + 1;
  FakeClock clock;
  HapticLoop loop(device, clock, options.haptics, options.haptic_scene);
  SampleRecorder recorder(options.record_path);
  if (!options.record_path.empty()) loop.set_recorder(&recorder);
  // Every tick's record for on_tick (the vibration track), drained after each block of ticks:
  // blocks of at most half the feed, so a slow frame rate never drops one.
  TickFeed feed(kReplayTickFeedCapacity);
  if (options.on_tick) loop.add_tick_feed(&feed);
  std::uint64_t ticks_done = 0;
  ReplayResult result;
  for (int i = 0; i < frames; ++i) {
    // Tick k runs at k / rate; frame i shows the state after the tick at (or before) i / fps.
    const auto last_tick = static_cast<std::uint64_t>(std::floor(i / options.fps * options.haptics.rate_hz + 1e-9));
    run_ticks_to(loop, last_tick, ticks_done, feed, options);
    auto next = take_events(loop, *renderer, options);
    if (!next) return next.error();
    HapticState state;
    if (Status s = drive_frame(*renderer, loop, static_cast<std::uint64_t>(i), state); !s) return s.error();
    if (Status s = sink(i, state.time_s, state, *renderer); !s) return s.error();
    if (next.value() != nullptr) renderer = next.value();
    if (!options.record_path.empty() && (i + 1) % std::max(1, static_cast<int>(options.fps)) == 0)
      if (Status s = recorder.flush(); !s) return s.error();  // once per second of session time
    if (options.progress) std::fprintf(stderr, "\rframe %d/%d  t=%.3f s", i + 1, frames, state.time_s);
    result.rejected = state.rejected;
    result.frames = i + 1;
  }
  if (options.progress) std::fputc('\n', stderr);
  if (!options.record_path.empty())
    if (Status s = recorder.close(); !s) return s.error();
  return result;
}

}  // namespace ps
