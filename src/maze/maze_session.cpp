#include "maze/maze_session.h"

#include <chrono>
#include <filesystem>
#include <limits>
#include <thread>

#include "haptics/session_driver.h"

namespace ps::maze {

Result<std::shared_ptr<const world::HapticScene>> build_haptic(const MazeScene& scene) {
  auto hs = world::HapticScene::build(scene.scene);
  if (!hs) return hs.error();
  return std::make_shared<const world::HapticScene>(std::move(hs.value()));
}

int contact_kind(const MazeScene& scene, bool in_contact, int surface) {
  if (!in_contact || surface < 0 || static_cast<std::size_t>(surface) >= scene.kinds.size()) return -1;
  return static_cast<int>(scene.kinds[static_cast<std::size_t>(surface)]);
}

int contact_kind(const MazeScene& scene, const HapticState& state) {
  return contact_kind(scene, state.in_contact, state.contact_surface);
}

Result<std::unique_ptr<SessionCore>> SessionCore::open(const SessionOptions& o) {
  const int pass = o.resume ? o.resume->current.pass : 0;
  auto scene = generate_scene(o.desc, o.route, o.info.cues, pass);
  if (!scene) return scene.error();
  auto haptic = build_haptic(scene.value());
  if (!haptic) return haptic.error();
  auto log = o.resume ? SessionLog::open_existing(o.log_path) : SessionLog::open(o.log_path);
  if (!log) return log.error();
  std::unique_ptr<SessionCore> core(
      new SessionCore(o, std::move(log.value()), std::move(scene.value()), std::move(haptic.value())));
  if (o.resume) {
    if (Status s = core->resume(*o.resume); !s) return s.error();
    return core;
  }
  if (Status s = core->log_.session_start(o.info, o.route); !s) return s.error();
  if (Status s = core->log_.pass_start(0, o.route.order(0), 0.0); !s) return s.error();
  return core;
}

// Picks the session up where its log ends: the tracker at the next unfinished trial, a
// `resumed` line, and what the dead process had not yet written (a pass's end, the next pass's
// start; with them maybe the session's end).
Status SessionCore::resume(const ResumePoint& r) {
  result_.scores = r.done;
  const std::vector<TrackEvent> events = tracker_.resume(r.done, r.current);
  const int room = events.empty() ? tracker_.index() : 0;
  if (Status s = log_.resumed(r.resumes + 1, tracker_.pass(), room, r.time_s, options_.info.device, options_.info.device_log); !s)
    return s;
  if (!events.empty()) return handle(events, r.time_s, nullptr, {});
  if (!r.current_started) return log_.pass_start(tracker_.pass(), options_.route.order(tracker_.pass()), r.time_s);
  return ok_status();
}

Status SessionCore::step(const HapticState& st, HapticLoop& loop, const ScoreFn& on_score) {
  const ProbeStep step{st.time_s, st.proxy_mm, st.force_n, st.field_force_n, contact_kind(scene_, st)};
  return handle(tracker_.feed(step), st.time_s, &loop, on_score);
}

Status SessionCore::step(const TickSample& tick, HapticLoop& loop, const ScoreFn& on_score) {
  const ProbeStep step{tick.time_s, tick.proxy_centre_mm, tick.force_n, tick.field_force_n,
                       contact_kind(scene_, tick.in_contact, tick.surface)};
  return handle(tracker_.feed(step), tick.time_s, &loop, on_score);
}

// Logs what the tracker saw at session time time_s; at a pass's end the next pass's scene goes
// to the loop (when there is one yet: a resume hands it over before the loop is made).
Status SessionCore::handle(const std::vector<TrackEvent>& events, double time_s, HapticLoop* loop, const ScoreFn& on_score) {
  for (const TrackEvent& e : events) {
    if (Status s = log_.event(options_.info, e); !s) return s;
    if (e.kind == TrackEvent::Kind::kBranch) ++result_.branches;
    if (e.kind == TrackEvent::Kind::kPassEnd) {
      result_.scores.push_back(e.score);
      if (on_score)
        if (Status s = on_score(e.score); !s) return s;
    }
    if (e.kind == TrackEvent::Kind::kFinished) {
      finished_by_ = e.criterion ? EndReason::kCriterion : EndReason::kMaxPasses;
      end_time_s_ = time_s;
      if (e.criterion) result_.trials_to_criterion = static_cast<int>(result_.scores.size());
    }
  }
  if (events.empty() || tracker_.finished() || events.back().kind != TrackEvent::Kind::kPassEnd) return ok_status();
  auto next = generate_scene(options_.desc, options_.route, options_.info.cues, tracker_.pass());
  if (!next) return next.error();
  auto hs = build_haptic(next.value());
  if (!hs) return hs.error();
  scene_ = std::move(next.value());
  haptic_ = hs.value();
  if (loop) loop->replace_scene(haptic_, "maze pass " + std::to_string(tracker_.pass() + 1));
  scene_changed_ = true;
  return log_.pass_start(tracker_.pass(), options_.route.order(tracker_.pass()), time_s);
}

Result<SessionResult> SessionCore::finish(double time_s, EndReason reason_if_open) {
  result_.reason = finished_by_.value_or(reason_if_open);
  result_.passes = static_cast<int>(result_.scores.size());
  result_.time_s = time_s;
  if (Status s = log_.session_end(result_.reason, result_.passes, result_.trials_to_criterion, result_.time_s); !s)
    return s.error();
  return result_;
}

namespace {

// The headless session around the driver's ticks: each tick's state to the session, the frames
// (FrameView), the pace.
struct HeadlessTicks {
  const SessionOptions& o;
  SessionCore& core;
  const FrameFn& on_frame;
  const ScoreFn& on_score;
  HapticLoop* loop = nullptr;
  HapticState st{};
  bool stopped = false;
  std::chrono::steady_clock::time_point wall_start = std::chrono::steady_clock::now();

  // Before each tick: the session is over, or a stop was asked.
  bool stop() { return core.finished() || (stopped = o.stop && o.stop()); }
  Status after_tick(std::uint64_t k, const HapticState& state) {
    st = state;
    if (Status s = core.step(st, *loop, on_score); !s) return s;
    if (o.pace > 0.0 && k % 10 == 0)
      std::this_thread::sleep_until(wall_start + std::chrono::duration<double>((st.time_s - o.haptics.start_time_s) / o.pace));
    return ok_status();
  }
  Status frame(int i) { return on_frame(FrameView{i, st, core.scene(), core.take_scene_changed(), core.label()}); }
};

DriverHooks hooks_of(HeadlessTicks& t) {
  DriverHooks h;
  h.stop = [&t] { return t.stop(); };
  h.after_tick = [&t](std::uint64_t k, const HapticState& st) { return t.after_tick(k, st); };
  if (t.on_frame) h.on_frame = [&t](int i) { return t.frame(i); };
  return h;
}

}  // namespace

Result<SessionOptions> practice_options(const SessionOptions& o) {
  SessionOptions po = o;
  const std::filesystem::path dir = std::filesystem::path(o.log_path).parent_path() / "practice";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return make_error(dir.string() + ": cannot create the practice folder: " + ec.message());
  po.log_path = (dir / "session.jsonl").string();
  po.record_path = (dir / "device.log").string();
  po.info.seed = o.info.seed ^ kPracticeSeedMix;
  po.route = draw_route(po.info.seed);
  po.desc.max_passes = po.info.max_passes = 1;
  po.resume.reset();
  po.haptics.start_time_s = 0.0;
  return po;
}

Result<SessionResult> run_session(Device& device, const SessionOptions& o, const FrameFn& on_frame,
                                  const ScoreFn& on_score) {
  auto opened = SessionCore::open(o);
  if (!opened) return opened.error();
  SessionCore& core = *opened.value();
  HeadlessTicks ticks{o, core, on_frame, on_score};
  // The loop's clock starts at start_time_s (a resumed session: where it stopped).
  ticks.st.time_s = o.haptics.start_time_s;
  const FrameSchedule schedule{o.fps, o.haptics.rate_hz};
  SessionDriver driver(device, o.haptics, core.haptic().get(), o.record_path, schedule, hooks_of(ticks));
  ticks.loop = &driver.loop();
  auto run = driver.run(schedule.ticks_in(device.duration_s() - o.haptics.start_time_s), std::numeric_limits<int>::max());
  if (!run) return run.error();
  auto result = core.finish(ticks.st.time_s, ticks.stopped ? EndReason::kTerminated : EndReason::kDeviceEnded);
  if (!result) return result.error();
  result->ticks = run->ticks;
  if (Status s = driver.finish(); !s) return s.error();
  return result;
}

}  // namespace ps::maze
