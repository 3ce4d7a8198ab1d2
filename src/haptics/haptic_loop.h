// The haptic loop: read device -> sanitize -> Kalman filter -> proxy + force against the haptic
// scene (or the render thread's local plane) -> write force -> publish. Runs on its own thread at 1 kHz, scheduled with
// clock.sleep_until(next += period) so the rate does not drift; never calls GL.
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
#include <thread>
#include <vector>

#include "core/snapshot.h"
#include "devices/device.h"
#include "devices/sample_log.h"
#include "devices/sanitizer.h"
#include "haptics/clock.h"
#include "haptics/events.h"
#include "haptics/force_model.h"
#include "haptics/kalman.h"
#include "haptics/loop_stats.h"
#include "haptics/tick_feed.h"
#include "haptics/tick_schedule.h"
#include "world/bodies.h"
#include "world/buttons.h"
#include "fourd/crossing.h"
#include "fourd/rolling.h"
#include "world/god_object.h"

namespace ps {

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

// Charges a person adds and removes while the loop runs (run's C / Shift+C), published by the
// render thread (Snapshot<LiveCharges>) and added to the scene's fields. Each has an id that is
// never reused, so the haptic thread can tell which ones came and went and say so in events.
struct LiveCharges {
  static constexpr int kMax = 16;
  int count = 0;
  std::array<std::uint32_t, kMax> id{};
  std::array<glm::dvec3, kMax> position{};
  std::array<double, kMax> charge_n_mm2{};
  double softening_mm = 2.0;
};

// The camera the renderer draws with, in the device's workspace (published once per frame by the
// render thread): the rolling manifold's screen centre and direction toward the viewer. Until
// one is published the loop uses the scene file's camera.
struct PublishedViewAxes {
  bool valid = false;
  fourd::ViewAxes axes;
};

struct HapticState {
  std::uint64_t tick = 0;
  double time_s = 0.0;               // session time of this tick
  std::int64_t sample_clock_ns = 0;  // clock time at which the device sample was read
  glm::dvec3 device_mm{0.0};         // sanitized raw device position
  glm::dvec3 position_mm{0.0};       // Kalman-filtered
  glm::dvec3 velocity_mm_s{0.0};     // Kalman-filtered; drives the texture amplitude
  glm::dvec3 proxy_mm{0.0};          // what the renderer shows
  glm::dvec3 force_n{0.0};
  double penetration_mm = 0.0;
  int contact_surface = -1;          // haptic scene: surface touched (Scene::surfaces index)
  std::uint32_t local_facets = 0;    // haptic scene: mesh triangles examined this tick
  std::uint32_t buttons = 0;
  glm::dvec3 field_force_n{0.0};     // haptic scene: fields + body springs on the probe this tick
  std::array<glm::dvec3, world::kMaxBodies> body_mm{};  // haptic scene: the bodies' centres
  int body_count = 0;
  int button_pressed = -1;           // haptic scene: the button the probe presses (-1: none)
  double button_depth_mm = 0.0;      // and how far it is in
  std::uint32_t flags = 0;           // haptic scene: bit i = Scene::flags[i], toggled by buttons
  // haptic scene with [navigation]: how far the view has moved (the world position of the
  // workspace's origin). position_mm, device_mm and proxy_mm are world positions (the device's
  // own plus this offset); the renderer moves its camera by it.
  glm::dvec3 view_offset_mm{0.0};
  // haptic scene with a rolling fourd surface (fourd/rolling.h): the workspace also turns,
  // world = view_rotation * workspace + view_offset_mm; the renderer turns its camera with it.
  glm::dmat3 view_rotation{1.0};
  int roll_facet = -1;               // the rolling manifold's interest facet (-1: none)
  // haptic scene: the sheet of a surface embedded in 4D the proxy keeps to (docs/fourd.md):
  // its surface index (-1: none) and the 4D depth w there
  int sheet_surface = -1;
  double sheet_w4 = 0.0;
  bool have_sample = false, in_contact = false;
  double rate_hz = 0.0;              // over the last second
  double jitter_p99_us = 0.0;        // |period - nominal|, p99 over the last second
  SanitizerCounts rejected;
  // Falling behind (haptics/tick_schedule.h): stalls so far, ticks skipped so far, the last
  // stall's lateness, and the force's scale this tick (1 except while ramping after a stall).
  std::uint64_t stalls = 0;
  std::uint64_t skipped_ticks = 0;
  double last_stall_ms = 0.0;
  double force_scale = 1.0;
};

class HapticLoop {
 public:
  // With a haptic scene (not owned; it must outlive the loop) the proxy is a god-object in it
  // (docs/haptics.md, "Haptic geometry"); without one it collides with surface(), the plane
  // the render thread publishes (kept for callers with no scene: the plane-model tests).
  HapticLoop(Device& device, Clock& clock, const HapticLoopParams& params,
             const world::HapticScene* scene = nullptr);
  ~HapticLoop();
  HapticLoop(const HapticLoop&) = delete;
  HapticLoop& operator=(const HapticLoop&) = delete;

  void set_recorder(SampleRecorder* recorder) { recorder_ = recorder; }  // before start()
  // Before start(): one TickSample per tick pushed into `feed` (not owned; it must outlive the
  // loop), for the vibration signal or the maze's tracker (haptics/tick_feed.h); each feed added
  // gets every tick, at most kMaxTickFeeds of them (asserted). None by default.
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
  void replace_scene(std::shared_ptr<const world::HapticScene> scene, std::string_view label = {},
                     std::optional<glm::dvec3> place_hand_mm = std::nullopt);
  // Puts the hand (and the proxy) at `hand_mm` at the next tick, in the scene in use, for a
  // hovering pointer whose surface moved along `normal` (unit) under it: the hand keeps its
  // velocity across the normal (the texture's speed) and loses the part along it and the part
  // into the surface now under it (`surface_normal`, outward), so neither the filter's coasting
  // between two mouse readings nor the proxy's path cuts through the surface (any thread).
  void place_hand(const glm::dvec3& hand_mm, const glm::dvec3& normal, const glm::dvec3& surface_normal);
  const world::HapticScene* scene() const;  // the one in use (haptic thread / between ticks)
  // Any thread: the view goes back where the scene started ([navigation]'s offset and a rolling
  // surface's turn reset) at the next tick: run's Home key.
  void request_view_home() { home_pending_.store(true, std::memory_order_release); }
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
  const std::vector<double>& periods_us() const { return periods_us_.values(); }
  Percentiles period_stats() const { return percentiles(periods_us_.values()); }
  // Storage of the two logs the thread appends to, fixed at construction (tests check it never
  // grows: a reallocation on the 1 kHz thread would stall a tick).
  std::size_t period_log_capacity() const { return periods_us_.capacity(); }
  std::size_t jitter_window_capacity() const { return window_jitter_us_.capacity(); }

 private:
  void scheduled_tick();  // sleep_until(next += period), then tick()
  void request_realtime(pid_t tid);  // start(): SCHED_FIFO, else RealtimeKit's SCHED_RR
  void tick(Clock::Ns now);
  void update_rate(Clock::Ns now);

  Device& device_;
  Clock& clock_;
  HapticLoopParams params_;
  Clock::Ns period_, start_{0}, last_tick_{0}, window_start_{0};
  TickSchedule schedule_;
  void note_wake(const TickSchedule::Wake& w, Clock::Ns now);  // counts and reports a late wake-up
  bool started_ = false;
  DeviceSanitizer sanitizer_;
  Kalman3 kalman_;
  DeviceSample last_fed_;  // the last sample given to the filter (repeats are predicted over)
  bool have_fed_ = false;
  void adopt_pending_scene(Clock::Ns now);  // haptic thread, at a tick's start
  // Haptic thread: the filter there (at rest, or keeping its velocity across `normal`), the proxy there.
  void place(const glm::dvec3& hand_mm, const std::optional<glm::dvec3>& normal = std::nullopt);
  glm::dvec3 world_forces(double t, double dt);  // fields + bodies on the probe (haptic scene)
  // [navigation]: moves the view by the hand's push past its box's walls; then (with
  // navigation or a rolling surface) turns the hand's workspace position, velocity and device
  // position (local_) into world ones through view_. Returns the walls' force (world).
  glm::dvec3 navigate(double dt);
  fourd::ViewPose view_;            // workspace -> world (navigation's offset, rolling's turn)
  fourd::RollingManifold roll_;     // seed 000 §6 on a fourd surface with fourd_roll
  // After the proxy moved: the rolling manifold's step and its tether's force (world, N).
  glm::dvec3 roll(double dt);
  std::optional<world::GodObject> god_;  // set when a haptic scene is given
  fourd::CrossingDetector crossing_;     // sheet crossings on a surface embedded in 4D
  void detect_crossing(double t);        // after the proxy moved: a sheet_crossing event?
  // Eq. 5's force suggestion on a fourd sheet (zero when off or off the sheet); keeps the
  // contact point to difference its velocity.
  glm::dvec3 suggestion_force(double dt);
  glm::dvec3 last_sheet_point_{0.0};
  bool have_sheet_point_ = false;
  world::BodySet bodies_;                // the scene's bodies (reset with each scene)
  world::ButtonSet buttons_;             // the scene's buttons (reset with each scene)
  void press_buttons(const glm::dvec3& anchor, double t, glm::dvec3& force);
  std::shared_ptr<const world::HapticScene> scene_owned_;  // after replace_scene()
  std::mutex swap_mutex_;  // guards pending_, retired_
  std::shared_ptr<const world::HapticScene> pending_, retired_;
  std::string pending_label_;
  std::optional<glm::dvec3> pending_place_;  // replace_scene's place_hand_mm, under swap_mutex_
  std::optional<glm::dvec3> pending_place_normal_;  // place_hand's normal, under swap_mutex_
  glm::dvec3 pending_place_surface_{0.0};           // place_hand's surface_normal, under swap_mutex_
  std::atomic<bool> swap_pending_{false};
  std::atomic<bool> home_pending_{false};
  HapticState local_;        // haptic thread's working copy
  SampleRecorder* recorder_ = nullptr;
  std::array<TickFeed*, kMaxTickFeeds> tick_feeds_{};  // the first tick_feed_count_ are set
  std::size_t tick_feed_count_ = 0;
  TickSample feed_sample_;  // this tick's record, filled as the tick goes (impact, click)
  void push_tick_sample(const ForceResult& f, double t, Clock::Ns now);
  BoundedLog periods_us_;         // every period, for period_stats()
  BoundedLog window_jitter_us_;   // |period - nominal| of the current 1 s HUD window
  std::uint64_t window_ticks_ = 0;  // ticks in the HUD window (the jitter log may have dropped some)
  Snapshot<HapticState> state_;
  EventQueue events_;
  Snapshot<SurfaceModel> surface_;
  Snapshot<LiveCharges> live_charges_;
  Snapshot<PublishedViewAxes> view_axes_;
  LiveCharges adopted_charges_;  // haptic thread: the set in force, to diff the next one against
  void adopt_live_charges(double t);
  std::string priority_ = "normal";
  std::atomic<bool> stop_{false};
  std::atomic<int> slice_error_{0};  // errno of the slice request (0 = granted or not asked)
  std::thread thread_;
};

}  // namespace ps
