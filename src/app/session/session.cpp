#include "app/session/session.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "frame/haptic_frame.h"
#include "haptics/session_driver.h"

namespace ps {

Status drive_frame(Renderer& renderer, HapticLoop& loop, std::uint64_t frame, HapticState& state,
                   const std::optional<Camera>& camera) {
  state = loop.state().read();
  HapticFrameSources sources;
  sources.camera = camera;
  sources.coupling_n_per_mm = loop.params().forces.coupling_n_per_mm;
  sources.charges = loop.live_charges().read();
  const FrameInput input = haptic_frame_input(renderer, state, sources);
  View& view = renderer.view();  // the session's (RendererOptions::view)
  step_deformation(view.deformables.get(), view.probe, input, state.time_s);
  const glm::dvec3 shown = drawn_probe(renderer, input);
  const auto drawn = renderer.render(input);
  if (!drawn) return drawn.error();
  // The camera this frame drew with, as the workspace sees it: the rolling manifold's centre.
  loop.view_axes().publish({true, world::view_axes_of(view.workspace_camera())});
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
  v.camera = renderer.view().workspace_camera();
  v.aspect = static_cast<double>(sc.render.width) / sc.render.height;
  v.window_size = window_size.x > 0.0 && window_size.y > 0.0 ? window_size : glm::dvec2(sc.render.width, sc.render.height);
  v.plane = plane;
  v.probe_radius_mm = sc.probe.radius_mm;
  return v;
}

Result<LogDeviceSpec> open_device_log(const DeviceSpec& spec) {
  LogDeviceSpec out;
  if (spec.kind == DeviceKind::kPointer) {
    auto d = open_pointer_device(spec);
    if (!d) return d.error();
    out.pointer = d.value().get();
    out.device = std::move(d.value());
    return out;
  }
  if (!spec.is_log()) return device_spec_error(spec.text(), kLogDeviceKinds);
  auto d = open_log_device(spec);
  if (!d) return d.error();
  out.device = std::move(d.value());
  return out;
}

Result<LogDeviceSpec> open_device_log(const std::string& spec) {
  auto parsed = parse_device_spec(spec, kLogDeviceKinds);
  if (!parsed) return parsed.error();
  return open_device_log(parsed.value());
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

// The haptic events before a frame, passed on; the first button that leads to a scene hands the
// loop its haptic scene, and the renderer that draws it takes over from the next frame on: this
// frame's state is from before the loop's next tick, which adopts the scene, so drawn by it the
// new world would show the old world's probe (in tests/haptics/data/universe_to_weight.traj, the
// panel's press: 4.5 mm inside Weight's geometry).
struct ReplayFrames {
  const ReplayOptions& options;
  const FrameSink& sink;
  SessionDriver* driver = nullptr;
  Renderer* renderer;
  std::string switch_to;
  ReplayResult result;
  int frames = 0;

  void event(const HapticEvent& e) {
    if (options.on_event) options.on_event(e);
    if (switch_to.empty()) switch_to = scene_action_of(renderer->scene(), e);
  }
  // The renderer of the scene a button switched to (null: none).
  Result<Renderer*> take_switch() {
    const std::string path = std::exchange(switch_to, {});
    if (path.empty() || !options.switch_scene) return static_cast<Renderer*>(nullptr);
    auto next = options.switch_scene(path);
    if (!next) return next.error();
    driver->loop().replace_scene(next->haptic, std::filesystem::path(path).filename().string());
    return next->renderer;
  }
  Status frame(int i) {
    auto next = take_switch();
    if (!next) return next.error();
    HapticState state;
    if (Status s = drive_frame(*renderer, driver->loop(), static_cast<std::uint64_t>(i), state); !s) return s;
    if (Status s = sink(i, state.time_s, state, *renderer); !s) return s;
    if (next.value() != nullptr) renderer = next.value();
    if (options.progress) std::fprintf(stderr, "\rframe %d/%d  t=%.3f s", i + 1, frames, state.time_s);
    result.rejected = state.rejected;
    result.frames = i + 1;
    return ok_status();
  }
};

}  // namespace

Result<ReplayResult> replay_session(Renderer& first_renderer, Device& device, const ReplayOptions& options,
                                    const FrameSink& sink) {
  if (!(options.fps > 0.0)) return make_error("replay: fps must be > 0");
  const FrameSchedule schedule{options.fps, options.haptics.rate_hz};
  ReplayFrames frames{options, sink, nullptr, &first_renderer, {}, {}, schedule.frames_in(device.duration_s())};
  DriverHooks hooks;
  hooks.on_tick = options.on_tick;
  hooks.on_event = [&frames](const HapticEvent& e) { frames.event(e); };
  hooks.on_frame = [&frames](int i) { return frames.frame(i); };
  SessionDriver driver(device, options.haptics, options.haptic_scene, options.record_path, schedule, std::move(hooks));
  frames.driver = &driver;
  // The ticks up to the last frame's: no tick after it is run (or recorded).
  auto run = driver.run(schedule.tick_of_frame(frames.frames - 1) + 1, frames.frames);
  if (!run) return run.error();
  if (options.progress) std::fputc('\n', stderr);
  if (Status s = driver.finish(); !s) return s.error();
  return frames.result;
}

}  // namespace ps
