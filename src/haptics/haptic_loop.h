// The haptic loop, one tick read as a servo loop (HapticLoop::tick, docs/haptics.md):
//   read the device (sanitizer, Kalman filter)
//   -> move the workspace: navigation (workspace.h)
//   -> effects on the probe: fields, buttons, bodies (effects/), the proxy's coupling force
//   -> proxy model: the god-object in the haptic scene, or the render thread's local plane
//      (proxy_model.h, chosen once per scene)
//   -> effects on the hand: sheet crossings, force suggestions; the workspace rolls on the contact
//   -> force: scaled after a stall, written in the device's workspace -> publish.
// Runs on its own thread at 1 kHz, scheduled with clock.sleep_until(next += period) so the rate
// does not drift; never calls GL.
// Exchange with the render thread, one single-writer Snapshot per direction:
//   state()   written only by the haptic thread (HapticState), read by the render thread;
//   surface() written only by the render thread (SurfaceModel), read by the haptic thread.
// With a FakeClock, run_ticks() executes the same scheduling code on the caller's thread
// (tests, `replay`), deterministically.
#pragma once

#include <sys/types.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <span>
#include <thread>
#include <vector>

#include "core/snapshot.h"
#include "devices/sanitizer.h"
#include "haptics/clock.h"
#include "haptics/events.h"
#include "haptics/force_model.h"
#include "haptics/haptic_state.h"
#include "haptics/kalman.h"
#include "haptics/loop_stats.h"
#include "haptics/tick_feed.h"  // add_tick_feed's TickFeed, its callers' TickSample
#include "haptics/tick_schedule.h"

namespace ps {

class SampleRecorder;  // devices/sample_log.h
namespace world { class HapticScene; }

struct HapticLoopParams {
  double rate_hz = 1000.0;
  // Session time of the loop's start (s): every time the loop reports and reads its device at
  // counts on from here. 0, or where a resumed maze session goes on (docs/maze.md), so that its
  // device, its fields' time-varying forces and its log continue the interrupted session's clock.
  double start_time_s = 0.0;
  KalmanParams kalman;
  HapticsParams forces;
  SanitizerParams sanitizer;
  // Raw periods kept for the final statistics (10 min at 1 kHz; 4.8 MB allocated up front: the
  // haptic thread never allocates after start, later periods are dropped).
  std::size_t keep_periods = 600'000;
  // > 0: ask for SCHED_FIFO at this priority (1..99) for the haptic thread. Needs CAP_SYS_NICE
  // (or an RLIMIT_RTPRIO); without it, SCHED_RR through RealtimeKit where the system runs it
  // (haptics/rtkit.h, at most the daemon's maximum, 20 by default); failing both, the loop runs
  // at normal priority and priority() says why. Opt-in: the thread sleeps every tick, but a
  // real-time thread is still a system-wide decision.
  int realtime_priority = 0;
  // Keeping time at normal priority (docs/haptics.md, "Keeping time without privileges"):
  // the haptic thread's timer slack (prctl PR_SET_TIMERSLACK; the kernel's default is 50 us,
  // 0 = leave it) and how long before each tick it stops sleeping and polls the clock.
  std::int64_t timer_slack_ns = 1'000;
  std::int64_t wake_spin_us = 50;
  // EEVDF (Linux >= 6.6) runs the current thread to the end of its slice (~1.5 ms on 2 CPUs)
  // before a woken thread of equal weight; since 6.12 a thread may ask for a shorter slice
  // (sched_setattr sched_runtime, no privilege needed) and then preempts on wake-up. 0 = leave.
  std::int64_t sched_slice_us = 100;
  // Falling behind: missed ticks are skipped, a stall ramps the force back in (tick_schedule.h).
  TickScheduleParams schedule;
};

class HapticLoop {
 public:
  // With a haptic scene (not owned; it must outlive the loop) the proxy is a god-object in it
  // (docs/haptics.md, "Haptic geometry"); without one it collides with surface(), the plane
  // the render thread publishes (kept for callers with no scene: the plane-model tests).
  HapticLoop(Device& device, Clock& clock, const HapticLoopParams& params,
             const world::HapticScene* scene = nullptr);
  // The same with a scene the loop shares: it stays alive while the haptic thread may use it,
  // whatever the caller drops (released, like every scene replace_scene() drops, by the next
  // replace_scene() call after the switch, or with the loop). For a caller whose own reference
  // changes hands while the loop runs (the maze's session core, each pass: a raw pointer there
  // left the haptic thread ticking on a freed scene until it adopted the next).
  HapticLoop(Device& device, Clock& clock, const HapticLoopParams& params,
             std::shared_ptr<const world::HapticScene> scene);
  ~HapticLoop();
  HapticLoop(const HapticLoop&) = delete;
  HapticLoop& operator=(const HapticLoop&) = delete;

  void set_recorder(SampleRecorder* recorder) { recorder_ = recorder; }  // before start()
  // Before start(): one TickSample per tick pushed into `feed` (not owned; it must outlive the
  // loop), for the vibration signal or the maze's tracker (haptics/tick_feed.h); each feed added
  // gets every tick, at most kMaxTickFeeds of them (more aborts, with a line). None by default.
  static constexpr std::size_t kMaxTickFeeds = 2;
  void add_tick_feed(TickFeed* feed);
  // Hands the loop a new haptic scene (a live reload, a button's scene switch): any thread, at
  // any time; the haptic thread adopts it at the start of its next tick, keeps the proxy where it
  // is (pushed out of anything it now sits in, GodObject::reset) and queues a scene_switched
  // event labelled `label`. The loop shares ownership; the scene it drops is released by the
  // next replace_scene() call, not on the haptic thread. Replaces a scene given at construction
  // too (that one stays the caller's).
  // `place_hand_mm`: the hand's new position (the device's, e.g. over the surface under the
  // pointer): the filter restarts there at rest and the proxy is put there instead of kept, so
  // nothing the person did not do buries it (docs/window.md, "When the hand is inside geometry").
  // Returns the scene's number: the first state() whose scene_serial reaches it was published by
  // the tick that adopted it (and placed the probe in it), or by a later one.
  std::uint64_t replace_scene(std::shared_ptr<const world::HapticScene> scene, std::string_view label = {},
                              std::optional<glm::dvec3> place_hand_mm = std::nullopt);
  // Puts the hand (and the proxy) at `hand_mm` at the next tick, in the scene in use, for a
  // hovering pointer whose surface moved along `normal` (unit) under it: the hand keeps its
  // velocity across the normal (the texture's speed) and loses the part along it and the part
  // into the surface now under it (`surface_normal`, outward), so neither the filter's coasting
  // between two mouse readings nor the proxy's path cuts through the surface (any thread).
  void place_hand(const glm::dvec3& hand_mm, const glm::dvec3& normal, const glm::dvec3& surface_normal);
  const world::HapticScene* scene() const;  // the one in use (haptic thread / between ticks)
  // Any thread: the view goes back where the scene started ([navigation]'s offset and a rolling
  // surface's turn reset) at the next tick: run's Home key. With `place_hand_mm` (the hand over
  // the surface under the pointer in the home view) the hand and the proxy are put there in the
  // same tick: a proxy left where the old view had it would be dragged through the surface to
  // the hand, and on a rolling surface that contact turns the view away from home again.
  void request_view_home(std::optional<glm::dvec3> place_hand_mm = std::nullopt);
  // Any thread: while held, [navigation] does not move the view (its walls still push): run's
  // window holds it while the pointer is outside it or the window has lost the focus.
  void hold_navigation(bool hold) { navigation_held_.store(hold, std::memory_order_relaxed); }
  void start();        // spawns the thread
  // After start(): "SCHED_FIFO 80", "SCHED_RR 20 (RealtimeKit)", "normal" or
  // "normal (SCHED_FIFO refused: <why>; RealtimeKit ...: <why>)".
  const std::string& priority() const { return priority_; }
  // After the thread's first tick: the priority and the time-keeping settings in force, e.g.
  // "normal, slice 100 us, timer slack 1000 ns, wake spin 50 us" (a refused slice says why).
  std::string scheduling() const;
  void stop();         // joins it; idempotent
  void run_ticks(std::uint64_t n);  // on the caller's thread (fake clock)

  const HapticLoopParams& params() const { return params_; }
  const Snapshot<HapticState>& state() const { return state_; }
  // Events the haptic thread raised (contact start/end, ...): drained by one consumer, the
  // render thread or `replay` (haptics/events.h).
  EventQueue& events() { return events_; }
  Snapshot<SurfaceModel>& surface() { return surface_; }
  // Written by one thread (the render thread), read by the haptic thread every tick.
  Snapshot<LiveCharges>& live_charges() { return live_charges_; }
  // Written by the render thread once per frame, read by the haptic thread (rolling manifold).
  Snapshot<PublishedViewAxes>& view_axes() { return view_axes_; }
  // After stop() (or between run_ticks): measured periods in microseconds.
  std::span<const double> periods_us() const { return periods_us_.values(); }
  Percentiles period_stats() const { return percentiles(periods_us_.values()); }
  // Storage of the two logs the thread appends to, fixed at construction (tests check it never
  // grows: a reallocation on the 1 kHz thread would stall a tick).
  std::size_t period_log_capacity() const { return periods_us_.capacity(); }
  std::size_t jitter_window_capacity() const { return window_jitter_us_.capacity(); }

 private:
  // The tick's stages after the filter: the workspace, the proxy model and the effects
  // (haptic_loop.cpp). Behind a pointer so that this header needs none of their rooms.
  struct Stages;

  void scheduled_tick();  // sleep_until(next += period), then tick()
  void request_realtime(pid_t tid);  // start(): SCHED_FIFO, else RealtimeKit's SCHED_RR
  void note_wake(const TickSchedule::Wake& w, Clock::Ns now);  // counts and reports a late wake-up
  void update_rate(Clock::Ns now);
  void tick(Clock::Ns now);
  double session_time_s(Clock::Ns now) const;
  double tick_period_s(Clock::Ns now) const;  // the filter's T
  void read_device(double t, double dt, Clock::Ns now);  // sanitizer and Kalman filter
  void servo(double t, double dt, Clock::Ns now);        // workspace -> proxy -> effects -> force
  void take_proxy_step(const ForceResult& f, double t);  // contact events, proxy readouts
  void push_tick_sample(const ForceResult& f, double t, Clock::Ns now);
  void adopt_pending_scene(Clock::Ns now);  // haptic thread, at a tick's start
  // Haptic thread: the filter there (at rest, or keeping its velocity across `normal`), the proxy there.
  void place(const glm::dvec3& hand_mm, const std::optional<glm::dvec3>& normal = std::nullopt);
  void restart_filter_now();  // haptic thread: at rest from the next sample on

  Device& device_;
  Clock& clock_;
  HapticLoopParams params_;
  Clock::Ns period_, start_{0}, last_tick_{0}, window_start_{0};
  TickSchedule schedule_;
  bool started_ = false;
  DeviceSanitizer sanitizer_;
  Kalman3 kalman_;
  DeviceSample last_fed_;  // the last sample given to the filter (repeats are predicted over)
  bool have_fed_ = false;
  std::uint32_t placements_seen_ = 0;  // DeviceSample::placements at the last sample read
  std::unique_ptr<Stages> stages_;
  std::shared_ptr<const world::HapticScene> scene_owned_;  // after replace_scene(), or shared at construction
  std::mutex swap_mutex_;  // guards pending_, retired_
  std::shared_ptr<const world::HapticScene> pending_, retired_;
  std::string pending_label_;
  std::uint64_t scenes_requested_ = 0;  // replace_scene calls so far, under swap_mutex_
  std::optional<glm::dvec3> pending_place_;  // replace_scene's place_hand_mm, under swap_mutex_
  std::optional<glm::dvec3> pending_place_normal_;  // place_hand's normal, under swap_mutex_
  glm::dvec3 pending_place_surface_{0.0};           // place_hand's surface_normal, under swap_mutex_
  std::atomic<bool> swap_pending_{false};
  std::atomic<bool> home_pending_{false};
  std::atomic<bool> navigation_held_{false};  // hold_navigation
  bool pending_home_ = false;  // request_view_home with a placement: both in one tick, under swap_mutex_
  HapticState local_;        // haptic thread's working copy
  SampleRecorder* recorder_ = nullptr;
  std::array<TickFeed*, kMaxTickFeeds> tick_feeds_{};  // the first tick_feed_count_ are set
  std::size_t tick_feed_count_ = 0;
  BoundedLog periods_us_;         // every period, for period_stats()
  BoundedLog window_jitter_us_;   // |period - nominal| of the current 1 s HUD window
  std::uint64_t window_ticks_ = 0;  // ticks in the HUD window (the jitter log may have dropped some)
  Snapshot<HapticState> state_;
  EventQueue events_;
  Snapshot<SurfaceModel> surface_;
  Snapshot<LiveCharges> live_charges_;
  Snapshot<PublishedViewAxes> view_axes_;
  std::string priority_ = "normal";
  std::atomic<bool> stop_{false};
  std::atomic<int> slice_error_{0};  // errno of the slice request (0 = granted or not asked)
  std::thread thread_;
};

}  // namespace ps
