// A deterministic session's schedule, shared by `replay` (app/session/session.h, replay_session)
// and the maze's headless sessions (maze/maze_session.h, run_session): the haptic loop on a fake
// clock on the caller's thread, tick by tick, and around its ticks
//   - the frames: tick k runs at session time start + k / rate; frame i shows the state after
//     the tick at (or before) i / fps, so frame i is drawn right after tick tick_of_frame(i);
//   - the haptic events (the event log, the sounds, a button's scene switch), drained before
//     each frame, in push (= time) order;
//   - every tick's record (haptics/tick_feed.h) handed on in order, right after its tick;
//   - the device stream's recording, flushed once per second of session time (after each tick
//     k with (k + 1) / rate a whole second past the last flush: RecordedLoop::flush_due) and
//     closed by finish(), however the session ended.
// The loop with its recording and tick feed (RecordedLoop) is also the maze window's, whose loop
// runs live on its own thread; `bench-haptics` measures that thread and records nothing, so it
// drives frames itself (app/session/session.h drive_frame).
// No GL: drawing is the caller's on_frame.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "core/result.h"
#include "devices/device.h"
#include "devices/sample_log.h"
#include "haptics/clock.h"
#include "haptics/haptic_loop.h"
#include "haptics/tick_feed.h"

namespace ps {

// Ticks and frames of a session at `fps` frames per second of session time.
struct FrameSchedule {
  double fps = 30.0;
  double rate_hz = 1000.0;
  // The tick after which frame i is drawn: floor(i / fps * rate), to within 1e-9 of a tick.
  std::uint64_t tick_of_frame(int i) const;
  // The ticks that cover `duration_s` of session time: floor(duration * rate) + 1 (none less than 1).
  std::uint64_t ticks_in(double duration_s) const;
  // The frames that cover `duration_s`: one per 1 / fps, plus the first (none less than 1).
  int frames_in(double duration_s) const;
};

struct DriverHooks {
  // Asked before each tick: true ends the session there (a request to stop, or a session that
  // is over). Empty: never.
  std::function<bool()> stop;
  // After each tick k, with the state it published (HapticLoop::state()). Empty: the state is
  // not read per tick.
  std::function<Status(std::uint64_t k, const HapticState&)> after_tick;
  // Each tick's record, in order, right after its tick. Empty: the loop keeps no tick feed.
  std::function<void(const TickSample&)> on_tick;
  // Each haptic event, drained before each frame. Empty: the events are not drained.
  std::function<void(const HapticEvent&)> on_event;
  // Frame i (from 0), after tick schedule.tick_of_frame(i). Empty: no frames.
  std::function<Status(int i)> on_frame;
};

struct DriveResult {
  std::uint64_t ticks = 0;  // ticks run
  int frames = 0;           // frames drawn
  bool stopped = false;     // hooks.stop ended it
};

// A session's haptic loop with the device stream's recording and the loop's tick feed, whoever
// ticks it: SessionDriver below (a fake clock, on the caller's thread) or a live window's haptic
// thread (the steady clock; app/maze/maze_window.cpp).
class RecordedLoop {
 public:
  // `record_path` non-empty: the device stream the loop reads is recorded there. `feed_ticks` > 0:
  // every tick's record goes to a tick feed of that many ticks (feed()), for one consumer to drain.
  // The loop shares `scene` (HapticLoop's shared constructor; null: no haptic scene).
  RecordedLoop(Device& device, Clock& clock, const HapticLoopParams& params,
               std::shared_ptr<const world::HapticScene> scene, const std::string& record_path, std::size_t feed_ticks);
  ~RecordedLoop();
  RecordedLoop(const RecordedLoop&) = delete;
  RecordedLoop& operator=(const RecordedLoop&) = delete;
  HapticLoop& loop() { return loop_; }
  TickFeed* feed() { return feed_.get(); }  // null without one
  // The recording's pending samples to "<path>.partial" when `time_s` (the session's clock, in
  // s) is a second or more past the last flush (the first: past 0): a crash loses at most about
  // the last second, and a caller may ask after every tick or every frame.
  // After start_flushing(): flushes nothing, and returns the flushing thread's error if it had one.
  Status flush_due(double time_s);
  // Live windows: a thread of the recording's own flushes it once a second of wall time, frames
  // or not. A window minimised or covered for minutes draws no frames while the haptic loop goes
  // on recording; flushed only at frames, all of that would wait in memory, lost to a crash.
  // Nothing without a recording. Stopped by finish() and the destructor.
  void start_flushing();
  // Closes the recording (its last samples flushed, the file published): at the end, on stop too.
  Status finish();

 private:
  void flush_every_second();  // the flushing thread
  void stop_flushing();
  bool recording_;
  double flushed_s_ = 0.0;  // the session time of the last flush
  std::thread flusher_;
  std::mutex flush_mutex_;  // guards flush_stop_, flush_error_
  std::condition_variable flush_wake_;
  bool flush_stop_ = false;
  std::string flush_error_;  // the flushing thread's failure; it stops at the first
  SampleRecorder recorder_;
  std::unique_ptr<TickFeed> feed_;
  HapticLoop loop_;  // last: it holds the recorder and the feed (and is stopped first)
};

class SessionDriver {
 public:
  // `record_path` non-empty: the device stream the loop reads is recorded there. The loop
  // collides with `scene` (null: the render thread's plane); the hooks are fixed here because
  // a tick feed must be added before the first tick.
  SessionDriver(Device& device, const HapticLoopParams& params, const world::HapticScene* scene,
                const std::string& record_path, FrameSchedule schedule, DriverHooks hooks);
  HapticLoop& loop() { return recorded_.loop(); }
  const FrameSchedule& schedule() const { return schedule_; }
  // Runs ticks 0 .. ticks - 1 (fewer when hooks.stop says so), drawing at most max_frames frames.
  Result<DriveResult> run(std::uint64_t ticks, int max_frames);
  // Closes the recording (its last samples flushed, the file published): at the end, on stop too.
  Status finish() { return recorded_.finish(); }

 private:
  Status tick(std::uint64_t k);
  Status frames_due(std::uint64_t k, int max_frames, int& frame);

  FrameSchedule schedule_;
  DriverHooks hooks_;
  FakeClock clock_;
  RecordedLoop recorded_;  // after the clock it reads
};

}  // namespace ps
