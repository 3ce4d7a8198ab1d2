// The render-thread half of a haptic session, shared by `run`, `replay`, `bench-haptics` and
// the tests: take the newest haptic state, render it, publish the local surface model back.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/result.h"
#include "devices/device_spec.h"
#include "devices/pointer_map.h"
#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "render/renderer.h"
#include "world/haptic_scene.h"

namespace ps {

// One frame: renderer <- (proxy, filtered velocity) of `state`; render; the frame's reference
// normal and penetration -> loop.surface(). `state` is what was rendered. `camera`, when given,
// is the camera this frame draws with (bench-haptics --orbit moves the view this way).
Status drive_frame(Renderer& renderer, HapticLoop& loop, std::uint64_t frame, HapticState& state,
                   const std::optional<Camera>& camera = std::nullopt);

// The plane a pointer maps onto: through the camera target, along the renderer's reference
// frame (taken once when a session opens, so the mapping stays put while the plane converges).
PlaneAxes pointer_plane(const Renderer& renderer);
// The pointer mapping's view of what `renderer` draws now: its camera and aspect, the plane,
// the probe radius, and the window the pointer moves in (default: the image size).
PointerView pointer_view(const Renderer& renderer, const PlaneAxes& plane, glm::dvec2 window_size = {0.0, 0.0});

// A device given as a log: trajectory:FILE, playback:FILE or pointer:FILE.
struct LogDeviceSpec {
  std::unique_ptr<Device> device;
  PointerLogDevice* pointer = nullptr;  // == device.get() for pointer:FILE: set_view() it
};
Result<LogDeviceSpec> open_device_log(const DeviceSpec& spec);
Result<LogDeviceSpec> open_device_log(const std::string& spec);  // parsed by parse_device_spec

// The surface model a session starts from: the pointer's plane, so that distance and contact
// are known before the first contact (later frames keep or replace it, update_surface_model).
SurfaceModel initial_surface_model(const PlaneAxes& plane, double probe_radius_mm);

// What a button's "scene:FILE" action switches to: the renderer that draws from the next frame
// on (owned by the caller, alive until the replay ends) and the haptic scene the loop adopts.
struct SceneSwitch {
  Renderer* renderer = nullptr;
  std::shared_ptr<const world::HapticScene> haptic;
};

// The scene file of a button_fired event's "scene:FILE" action, its button looked up in `scene`
// (the one the render side draws, which the haptic thread's follows); empty for any other event
// or a flag action.
std::string scene_action_of(const Scene& scene, const HapticEvent& e);

struct ReplayOptions {
  double fps = 30.0;          // frames per second of session time
  HapticLoopParams haptics;   // the loop runs at haptics.rate_hz on a fake clock
  std::string record_path;    // non-empty: record the device stream read by the loop
  const world::HapticScene* haptic_scene = nullptr;  // the proxy collides with it (null: the render plane)
  bool progress = false;      // "\rframe i/n" on stderr
  // Each event of the loop's queue, in push (= time) order, drained after each frame's ticks
  // (the one consumer of HapticLoop::events() in a replay; app/session/event_dispatch.h fans it out).
  std::function<void(const HapticEvent&)> on_event;
  // A button's scene action, drained with the frame's events (the first one per frame): opens
  // the file; the loop adopts the new haptic scene at its next tick and the next frame is drawn
  // by the new renderer (this one still shows the old world, from the state before that tick),
  // so a replay switches at the same tick every run. Null: actions are only logged.
  std::function<Result<SceneSwitch>(const std::string& scene_path)> switch_scene;
  // Each tick of the loop (haptics/tick_feed.h), in order, before that frame's events (the
  // vibration track of `replay --vibration`). Null: the loop keeps no tick feed.
  std::function<void(const TickSample&)> on_tick;
};

struct ReplayResult {
  int frames = 0;
  SanitizerCounts rejected;
};

// Called after every rendered frame (index from 0, session time in s).
using FrameSink = std::function<Status(int index, double time_s, const HapticState&, const Renderer&)>;

// Deterministic: a FakeClock drives the loop on this thread (no haptic thread), frames at
// exactly i / fps (haptics/session_driver.h: the schedule, the events, the recording). Same
// scene + same log => the same images, byte for byte. A pointer device must have its view set
// (pointer_view) before.
Result<ReplayResult> replay_session(Renderer& renderer, Device& device, const ReplayOptions& options,
                                    const FrameSink& sink);

}  // namespace ps
