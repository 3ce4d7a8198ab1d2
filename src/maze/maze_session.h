// A maze session driven by a device log, deterministically: the haptic loop on a fake clock,
// every tick's proxy fed to the tracker (branches at 1 ms resolution), the log written as
// things happen, the scene of the next pass handed to the loop when a pass ends. The caller
// renders (or not) in on_frame, at a fixed frame rate of session time, on the schedule of `replay`
// (haptics/session_driver.h).
// No GL here.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "core/result.h"
#include "devices/device.h"
#include "haptics/haptic_loop.h"
#include "maze/maze_log.h"
#include "maze/maze_resume.h"
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
  // `maze --resume`: where the interrupted session stands (log_path is then its existing log,
  // appended to; haptics.start_time_s must be resume->time_s: the loop's clock goes on from there).
  std::optional<ResumePoint> resume;
  // Asked between ticks (run_session) or frames (the window): true ends the session at once
  // through its normal end, reason kTerminated (the CLI's StopSignals, app/cli/stop_signal.h).
  // Empty: never.
  std::function<bool()> stop;
};

struct FrameView {
  int index = 0;
  const HapticState& state;
  const MazeScene& scene;      // the scene of the pass in progress
  bool scene_changed = false;  // a new pass began since the last frame: make a new renderer
  std::string label;           // the room label to show (empty with cues on)
};

struct SessionResult {
  EndReason reason = EndReason::kDeviceEnded;  // kCriterion, kMaxPasses, kDeviceEnded, kTerminated, ...
  int passes = 0;
  int branches = 0;             // rooms left in this run (a device that took none is suspect)
  int trials_to_criterion = 0;  // the pass (from 1) that had every room right; 0: none
  double time_s = 0.0;
  std::uint64_t ticks = 0;
  std::vector<PassScore> scores;
};

using FrameFn = std::function<Status(const FrameView&)>;
using ScoreFn = std::function<Status(const PassScore&)>;

// The haptic scene a loop collides with, shared so a pass switch can hand it over.
Result<std::shared_ptr<const world::HapticScene>> build_haptic(const MazeScene& scene);

// What a session does with each tick of the haptic loop, whoever drives it: run_session() below
// with each tick's state, the window (app/maze/maze_window.cpp) with each tick's TickSample, drained
// once per frame (fed only the newest state of each frame, the tracker missed a room the proxy
// crossed between two slow frames: 0 passes under load). Owns the log, the tracker and the scene
// of the pass in progress.
class SessionCore {
 public:
  // Generates pass 1, opens the log and writes its first lines.
  static Result<std::unique_ptr<SessionCore>> open(const SessionOptions& options);
  const MazeScene& scene() const { return scene_; }
  const std::shared_ptr<const world::HapticScene>& haptic() const { return haptic_; }
  // Feeds one state to the tracker and logs what happened; at the end of a pass the score goes
  // to on_score and, unless the session is over, the next pass's scene to the loop (adopted at
  // its next tick; seamless: the new scene holds the room the probe is in).
  Status step(const HapticState& state, HapticLoop& loop, const ScoreFn& on_score);
  // The same with a tick's record from the loop's tick feed (HapticLoop::add_tick_feed).
  Status step(const TickSample& tick, HapticLoop& loop, const ScoreFn& on_score);
  bool finished() const { return tracker_.finished(); }
  // True once after each pass switch: the caller draws with a new renderer.
  bool take_scene_changed() { return std::exchange(scene_changed_, false); }
  std::string label() const { return room_label_text(tracker_.room(), options_.info.cues); }
  const Tracker& tracker() const { return tracker_; }
  // The session time of the tick at which the tracker finished (the criterion or max_passes).
  double end_time_s() const { return end_time_s_; }
  // The live window's clutch put the hand back under the probe (SessionLog::clutch).
  Status log_clutch(double time_s, double overshoot_mm, const glm::dvec3& hand_mm, const glm::dvec3& probe_mm) {
    return log_.clutch(time_s, overshoot_mm, hand_mm, probe_mm);
  }
  // Writes session_end (`reason_if_open` when the tracker has not finished: device_ended, quit,
  // terminated).
  Result<SessionResult> finish(double time_s, EndReason reason_if_open);

 private:
  Status resume(const ResumePoint& r);
  Status handle(const std::vector<TrackEvent>& events, double time_s, HapticLoop* loop, const ScoreFn& on_score);
  SessionCore(const SessionOptions& o, SessionLog log, MazeScene scene, std::shared_ptr<const world::HapticScene> h)
      : options_(o), log_(std::move(log)), tracker_(o.desc, o.route, o.desc.max_passes), scene_(std::move(scene)),
        haptic_(std::move(h)) {}
  SessionOptions options_;
  SessionLog log_;
  Tracker tracker_;
  MazeScene scene_;
  std::shared_ptr<const world::HapticScene> haptic_;
  bool scene_changed_ = true;
  double end_time_s_ = 0.0;
  std::optional<EndReason> finished_by_;  // the tracker's end (criterion, max_passes), once reached
  SessionResult result_;
};

Result<SessionResult> run_session(Device& device, const SessionOptions& options, const FrameFn& on_frame,
                                  const ScoreFn& on_score);

// The practice pass's seed: the session's, mixed, so its route (correct exits, room order) is
// another one and practice teaches the task, not the answers.
inline constexpr std::uint64_t kPracticeSeedMix = 0x9e3779b97f4a7c15ull;
// The session's options for its practice pass (`maze --practice`, docs/maze.md "Practice"): the
// same maze and condition, another route, one pass, its own log and device stream in
// DIR/practice/ (created), never resumed, its clock from 0.
Result<SessionOptions> practice_options(const SessionOptions& o);

// The surface kind the loop touches in `state` (-1: none), for the tracker.
int contact_kind(const MazeScene& scene, const HapticState& state);
int contact_kind(const MazeScene& scene, bool in_contact, int surface);

}  // namespace ps::maze
