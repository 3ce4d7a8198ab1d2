// A maze session driven by a device log, deterministically: the haptic loop on a fake clock,
// every tick's proxy fed to the tracker (branches at 1 ms resolution), the log written as
// things happen, the scene of the next pass handed to the loop when a pass ends. The caller
// renders (or not) in on_frame, at a fixed frame rate of session time, exactly like `replay`.
// No GL here.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "core/result.h"
#include "devices/device.h"
#include "haptics/haptic_loop.h"
#include "maze/maze_log.h"
#include "maze/maze_track.h"
#include "world/haptic_scene.h"

namespace ps::maze {

struct SessionOptions {
  MazeDesc desc;
  Route route;
  SessionInfo info;           // info.cues is the condition
  std::string log_path;       // the JSON-lines session log (required)
  std::string record_path;    // the device stream in the recording format ("" = none)
  HapticLoopParams haptics;
  double fps = 30.0;          // frames per second of session time given to on_frame
  double pace = 0.0;          // > 0: session time runs at `pace` x real time (1: as live)
};

struct FrameView {
  int index = 0;
  const HapticState& state;
  const MazeScene& scene;      // the scene of the pass in progress
  bool scene_changed = false;  // a new pass began since the last frame: make a new renderer
  std::string label;           // the room label to show (empty with cues on)
};

struct SessionResult {
  std::string reason;  // "criterion", "max_passes", "device_ended"
  int passes = 0;
  int trials_to_criterion = 0;  // the pass (from 1) that had every room right; 0: none
  double time_s = 0.0;
  std::uint64_t ticks = 0;
  std::vector<PassScore> scores;
};

using FrameFn = std::function<Status(const FrameView&)>;
using ScoreFn = std::function<Status(const PassScore&)>;

// The haptic scene a loop collides with, shared so a pass switch can hand it over.
Result<std::shared_ptr<const world::HapticScene>> build_haptic(const MazeScene& scene);

Result<SessionResult> run_session(Device& device, const SessionOptions& options, const FrameFn& on_frame,
                                  const ScoreFn& on_score);

// The surface kind the loop touches in `state` (-1: none), for the tracker.
int contact_kind(const MazeScene& scene, const HapticState& state);

}  // namespace ps::maze
