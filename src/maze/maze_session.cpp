#include "maze/maze_session.h"

#include <chrono>
#include <cmath>
#include <thread>

#include "devices/sample_log.h"

namespace ps::maze {

Result<std::shared_ptr<const world::HapticScene>> build_haptic(const MazeScene& scene) {
  auto hs = world::HapticScene::build(scene.scene);
  if (!hs) return hs.error();
  return std::make_shared<const world::HapticScene>(std::move(hs.value()));
}

int contact_kind(const MazeScene& scene, const HapticState& state) {
  if (!state.in_contact || state.contact_surface < 0 || static_cast<std::size_t>(state.contact_surface) >= scene.kinds.size())
    return -1;
  return static_cast<int>(scene.kinds[static_cast<std::size_t>(state.contact_surface)]);
}

namespace {

// Session state that the tick loop and its helpers share.
struct Run {
  const SessionOptions& o;
  SessionLog log;
  Tracker tracker;
  MazeScene scene;
  std::shared_ptr<const world::HapticScene> haptic;
  bool scene_changed = false;
  SessionResult result;

  // The tracker's events of one tick: logged; a finished pass is scored, and unless the session
  // is over the next pass's scene goes to the loop (adopted at its next tick, seamless: the new
  // scene holds the room the probe is in).
  Status handle(const std::vector<TrackEvent>& events, HapticLoop& loop, double t, const ScoreFn& on_score) {
    for (const TrackEvent& e : events) {
      if (Status s = log.event(o.info, e); !s) return s;
      if (e.kind == TrackEvent::Kind::kPassEnd) {
        result.scores.push_back(e.score);
        if (on_score)
          if (Status s = on_score(e.score); !s) return s;
      }
      if (e.kind == TrackEvent::Kind::kFinished) {
        result.reason = e.criterion ? "criterion" : "max_passes";
        if (e.criterion) result.trials_to_criterion = static_cast<int>(result.scores.size());
      }
    }
    if (events.empty() || tracker.finished() || events.back().kind != TrackEvent::Kind::kPassEnd) return ok_status();
    auto next = generate_scene(o.desc, o.route, o.info.cues, tracker.pass());
    if (!next) return next.error();
    auto hs = build_haptic(next.value());
    if (!hs) return hs.error();
    scene = std::move(next.value());
    haptic = hs.value();
    loop.replace_scene(haptic, "maze pass " + std::to_string(tracker.pass() + 1));
    scene_changed = true;
    return log.pass_start(tracker.pass(), o.route.order(tracker.pass()), t);
  }
};

}  // namespace

Result<SessionResult> run_session(Device& device, const SessionOptions& o, const FrameFn& on_frame,
                                  const ScoreFn& on_score) {
  auto scene = generate_scene(o.desc, o.route, o.info.cues, 0);
  if (!scene) return scene.error();
  auto haptic = build_haptic(scene.value());
  if (!haptic) return haptic.error();
  auto log = SessionLog::open(o.log_path);
  if (!log) return log.error();
  Run run{o, std::move(log.value()), Tracker(o.desc, o.route, o.desc.max_passes), std::move(scene.value()),
          haptic.value(), true, {}};
  if (Status s = run.log.session_start(o.info, o.route); !s) return s.error();
  if (Status s = run.log.pass_start(0, o.route.order(0), 0.0); !s) return s.error();
  FakeClock clock;
  HapticLoop loop(device, clock, o.haptics, run.haptic.get());
  SampleRecorder recorder(o.record_path);
  if (!o.record_path.empty()) loop.set_recorder(&recorder);
  const double rate = o.haptics.rate_hz;
  const auto ticks = static_cast<std::uint64_t>(std::floor(std::max(0.0, device.duration_s()) * rate + 1e-9)) + 1;
  const auto wall_start = std::chrono::steady_clock::now();
  int frame = 0;
  HapticState st;
  for (std::uint64_t k = 0; k < ticks && !run.tracker.finished(); ++k) {
    loop.run_ticks(1);
    st = loop.state().read();
    const ProbeStep step{st.time_s, st.proxy_mm, st.force_n, st.field_force_n, contact_kind(run.scene, st)};
    if (Status s = run.handle(run.tracker.feed(step), loop, st.time_s, on_score); !s) return s.error();
    run.result.ticks = k + 1;
    // Frame i shows the state after the tick at (or before) i / fps, as in `replay`.
    if (on_frame && o.fps > 0.0 && k == static_cast<std::uint64_t>(std::floor(frame / o.fps * rate + 1e-9))) {
      const FrameView view{frame, st, run.scene, run.scene_changed,
                           room_label_text(run.tracker.room(), o.info.cues)};
      if (Status s = on_frame(view); !s) return s.error();
      run.scene_changed = false;
      ++frame;
    }
    if (!o.record_path.empty() && (k + 1) % static_cast<std::uint64_t>(rate) == 0)
      if (Status s = recorder.flush(); !s) return s.error();  // once per second of session time
    if (o.pace > 0.0 && k % 10 == 0)
      std::this_thread::sleep_until(wall_start + std::chrono::duration<double>(st.time_s / o.pace));
  }
  if (run.result.reason.empty()) run.result.reason = "device_ended";
  run.result.passes = static_cast<int>(run.result.scores.size());
  run.result.time_s = st.time_s;
  if (Status s = run.log.session_end(run.result.reason, run.result.passes, run.result.trials_to_criterion, st.time_s); !s)
    return s.error();
  if (!o.record_path.empty())
    if (Status s = recorder.close(); !s) return s.error();
  return run.result;
}

}  // namespace ps::maze
