// The render-thread half of a haptic session, shared by `run`, `replay`, `bench-haptics` and
// the tests: take the newest haptic state, render it, publish the local surface model back.
#pragma once

#include <functional>
#include <string>

#include "core/result.h"
#include "haptics/haptic_loop.h"
#include "render/renderer.h"

namespace ps {

// One frame: renderer <- (proxy, filtered velocity) of `state`; render; the frame's reference
// normal and penetration -> loop.surface(). `state` is what was rendered.
Status drive_frame(Renderer& renderer, HapticLoop& loop, std::uint64_t frame, HapticState& state);

struct ReplayOptions {
  double fps = 30.0;          // frames per second of session time
  HapticLoopParams haptics;   // the loop runs at haptics.rate_hz on a fake clock
  std::string record_path;    // non-empty: record the device stream read by the loop
  const world::HapticScene* haptic_scene = nullptr;  // the proxy collides with it (null: the render plane)
  bool progress = false;      // "\rframe i/n" on stderr
};

struct ReplayResult {
  int frames = 0;
  SanitizerCounts rejected;
};

// Called after every rendered frame (index from 0, session time in s).
using FrameSink = std::function<Status(int index, double time_s, const HapticState&, const Renderer&)>;

// Deterministic: a FakeClock drives the loop on this thread (no haptic thread), frames at
// exactly i / fps. Same scene + same log => the same images, byte for byte.
Result<ReplayResult> replay_session(Renderer& renderer, Device& device, const ReplayOptions& options,
                                    const FrameSink& sink);

}  // namespace ps
