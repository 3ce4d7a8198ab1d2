#include "app/maze/maze_window.h"

#include <cstdio>
#include <filesystem>

#include "app/maze/maze_overlay.h"
#include "app/session/session.h"
#include "gl/context.h"
#include "haptics/session_driver.h"
#include "maze/maze_screen.h"
#include "prepare/prepare.h"

namespace ps {

namespace {

using maze_window::draw;
using maze_window::Events;
using maze_window::floor_plane;
using maze_window::on_plane;
using maze_window::Overlay;
using maze_window::score_text;
using maze_window::Window;

constexpr double kScoreSeconds = 5.0;  // how long a pass's score screen stays up
// Ticks the tracker's feed holds between two frames: 16 s at 1 kHz (a frame that takes longer
// loses ticks, and says so); ~3 MiB.
constexpr std::size_t kTrackFeedTicks = std::size_t{1} << 14;
constexpr double kMmPerCount = 0.15;   // captured mouse: mm on the floor per raw count
constexpr const char* kPracticeOver =
    "That was the practice.\n\nThe real session starts now: a new maze, whose right exits\n"
    "you will learn as you go.\n\nPress Space to start.";

// One pass's live machinery (the practice pass and the scored session each have their own): the
// haptic loop on the window's device with the device stream's recording and the tracker's tick
// feed, drained by each frame (haptics/session_driver.h RecordedLoop, as headless), and its
// vibration. Built before the pass starts (run_pass).
struct LivePass {
  SteadyClock clock;
  // The loop shares the pass's first scene: at the pass's end the core drops its own reference
  // to it before the loop has adopted the next, while the haptic thread still ticks in it.
  RecordedLoop haptics;
  // Fed by the loop: destroyed before it, so the destructor stops the loop first (end_pass
  // does too; this covers a pass left by an error or an exception).
  std::unique_ptr<vibration::LiveVibration> vib;
  // Why the pass ended (session_end's reason unless the tracker ended it: criterion, max_passes).
  maze::EndReason reason = maze::EndReason::kQuit;
  LivePass(Window& w, const maze::SessionOptions& o, const maze::SessionCore& core, const cli::LiveLoopArgs& live)
      : haptics(w.live->device(), clock, o.haptics, core.haptic(), o.record_path, kTrackFeedTicks),
        vib(cli::open_live_vibration(live, core.scene().scene, haptics.loop())) {}
  ~LivePass() {
    haptics.loop().stop();
    if (vib) vib->close();
  }
  LivePass(const LivePass&) = delete;
  LivePass& operator=(const LivePass&) = delete;
  HapticLoop& loop() { return haptics.loop(); }
  TickFeed& ticks() { return *haptics.feed(); }
};

// The window draws `scene` from now on (a new renderer).
Status use_scene(Window& w, const Scene& scene) {
  auto r = open_renderer(scene, RendererOptions{});
  if (!r) return r.error();
  w.renderer = std::move(r.value());
  return ok_status();
}

// The mouse (relative, once captured) or gamepad at the window, or a log played in it.
Status open_device(const DeviceSpec& device, const maze::SessionOptions& o, Window& w) {
  GlfwInputParams params;
  params.mm_per_count = kMmPerCount;
  if (Status s = w.live->open_device(device, params); !s) return s;
  // The hand starts where the probe starts: its point on the floor under the probe's start.
  // A resumed session: where the probe waits, in the hall of the last room left.
  if (GlfwInputDevice* m = w.input()) {
    const glm::dvec3 start = o.resume ? maze::resume_place(o.desc, *o.resume) : w.renderer->probe().position;
    m->place(on_plane(floor_plane(*w.renderer), start));
  }
  return ok_status();
}

Status open_window(const maze::SessionOptions& o, const DeviceSpec& device, const maze::SessionCore& core, Window& w) {
  auto live = LiveWindow::open({o.desc.image_size, o.desc.image_size, "pseudoshadow maze - " + o.info.participant});
  if (!live) return live.error();
  w.live = std::move(live.value());
  w.live->listen(w.events);
  if (Status s = use_scene(w, core.scene().scene); !s) return s;
  w.out_dir = std::filesystem::path(o.log_path).parent_path().string();
  return open_device(device, o, w);
}

// The clutch (docs/maze.md, "A hand a wall has stopped"): a mouse has no force to hold the hand
// at a wall, so the hand runs on while the wall holds the probe. Once it has overshot by more
// than clutch_mm along the floor, the hand is put back under the probe and that is logged.
// The device's next poll publishes the new place as a placement of its own
// (DeviceSample::placements), and the haptic loop restarts its filter there: fed the jump back
// as if it were a motion, the filter would carry the proxy on past the wall's place, away from
// the wall (seen: 7.5 mm, and a second clutch there).
Status apply_clutch(const MazeWindowParams& p, Window& w, maze::SessionCore& core, const HapticState& st,
                    double& quiet_until_s) {
  if (!w.input() || p.clutch_mm <= 0.0 || !st.have_sample || st.time_s < quiet_until_s) return ok_status();
  const PlaneAxes plane = floor_plane(*w.renderer);
  const glm::dvec3 hand = on_plane(plane, st.device_mm), probe = on_plane(plane, st.proxy_mm);
  const double overshoot = glm::length(hand - probe);
  // The proxy follows the filtered hand: a mouse that jumped further than the filter has yet
  // followed is ahead of the proxy with no wall in the way (seen: a clutch at 7.2 mm, the probe
  // mid-corridor, when a 30 mm motion came in two polls). Only a proxy held away from the
  // filtered hand, by a wall, is an overshoot to undo.
  const double held = glm::length(on_plane(plane, st.position_mm) - probe);
  if (overshoot <= p.clutch_mm || held <= p.clutch_mm) return ok_status();
  w.input()->place(probe);
  // The haptic thread reads the placed hand within a tick; 50 ms keeps a frame drawn from a
  // state older than that from clutching twice.
  quiet_until_s = st.time_s + 0.05;
  return core.log_clutch(st.time_s, overshoot, hand, probe);
}

// The window's events since the last frame, applied: quit, height steps, a rebase of the
// relative origin; then the device's poll.
bool take_input(Window& w, const HapticState& st) {
  Events& e = w.events;
  if (e.quit || w.live->should_close()) return false;
  if (w.input()) {
    if (std::exchange(e.rebase, false)) w.input()->rebase();
    w.input()->add_height_steps(std::exchange(e.height_steps, 0));
    w.input()->poll(st.time_s, pointer_view(*w.renderer, floor_plane(*w.renderer)));
  }
  return true;
}

// Returns when the participant quits, the log device ends, or the pass is over (pass_over).
// Every tick since the last frame, so the tracker sees each room the proxy passed through
// however long the frame took (a pass switch's new renderer, a loaded machine).
Status step_session(maze::SessionCore& core, LivePass& pass, const maze::ScoreFn& on_score) {
  Status stepped = ok_status();
  pass.ticks().drain([&](const TickSample& t) {
    if (stepped && !core.finished()) stepped = core.step(t, pass.loop(), on_score);
  });
  return stepped;
}

// A pass switch brings a new renderer and the next room's materials.
Status follow_scene(maze::SessionCore& core, Window& w, LivePass& pass) {
  if (!core.take_scene_changed()) return ok_status();
  if (Status s = use_scene(w, core.scene().scene); !s) return s;
  pass.vib->set_scene(core.scene().scene);
  return ok_status();
}

// A signal asked the command to stop (SessionOptions::stop, the CLI's StopSignals).
bool stop_asked(const maze::SessionOptions& o) { return o.stop && o.stop(); }
// Why a stop was asked: the display gone (gl::display_lost) or a signal.
maze::EndReason stop_reason() {
  return gl::display_lost() ? maze::EndReason::kDisplayLost : maze::EndReason::kTerminated;
}

// The pass is over: kScoreSeconds after the session ended (its last score stays up that long),
// when a log device has played to its end, or when a signal asked to stop (after the ticks so
// far were stepped: every room they crossed is logged).
bool pass_over(const maze::SessionOptions& o, const Window& w, const HapticState& st, double end_at,
               maze::EndReason& reason) {
  if (stop_asked(o)) {
    reason = stop_reason();
    return true;
  }
  if (end_at >= 0.0) return st.time_s > end_at;
  if (w.live->device().duration_s() < 0.0 || st.time_s <= w.live->device().duration_s()) return false;
  reason = maze::EndReason::kDeviceEnded;
  return true;
}

Status window_loop(const maze::SessionOptions& o, const MazeWindowParams& p, maze::SessionCore& core, Window& w,
                   LivePass& pass, bool practice) {
  Overlay ov;
  HapticState st;
  double end_at = -1.0, clutch_quiet_until = 0.0;
  const auto on_score = [&](const maze::PassScore& s) -> Status {
    ov.score = score_text(s, o.info.cues);
    ov.score_until = st.time_s + kScoreSeconds;
    return ok_status();
  };
  for (;;) {
    w.live->poll_events();
    st = pass.loop().state().read();
    if (Status s = apply_clutch(p, w, core, st, clutch_quiet_until); !s) return s;
    if (!take_input(w, st)) return ok_status();
    if (practice && std::exchange(w.events.start, false)) {
      pass.reason = maze::EndReason::kPracticeEnded;
      return ok_status();
    }
    if (Status s = step_session(core, pass, on_score); !s) return s;
    if (core.finished() && end_at < 0.0) {  // logged; the score stays up kScoreSeconds
      end_at = st.time_s + kScoreSeconds;
      ov.done = true;
    }
    if (pass_over(o, w, st, end_at, pass.reason)) return ok_status();
    if (Status s = follow_scene(core, w, pass); !s) return s;
    ov.label = core.label();
    ov.show_hand = p.show_hand && w.input();
    if (Status s = draw(w, o.desc, st, ov, std::exchange(w.events.screenshot, false)); !s) return s;
    if (Status s = pass.haptics.flush_due(st.time_s); !s) return s;  // the recording's flushing thread failed
  }
}

// The render thread's loop: input, the session's step on the newest haptic state, the frame,
// with the pass's haptic thread and vibration running. In practice (`practice`), Space or Enter
// ends the pass early (reason practice_ended).
Status run_pass(const maze::SessionOptions& o, const MazeWindowParams& p, maze::SessionCore& core, Window& w,
                LivePass& pass, bool practice) {
  pass.loop().start();
  pass.haptics.start_flushing();  // the recording, once a second, frames or not
  pass.vib->start();
  return window_loop(o, p, core, w, pass, practice);
}

// Stops the pass and logs its end at the time it ended: at the criterion (or max_passes) that is
// the tick the tracker saw it, not when its score screen closed. The scored session (not
// `practice`) warns when frames came too far apart for the tracker's feed.
Result<maze::SessionResult> end_pass(const maze::SessionOptions& o, maze::SessionCore& core, LivePass& pass,
                                     const Status& looped, bool practice) {
  pass.loop().stop();
  pass.vib->close();
  const bool logged = core.finished();
  const double end_time = logged ? core.end_time_s() : std::max(o.haptics.start_time_s, pass.loop().state().read().time_s);
  auto result = core.finish(end_time, pass.reason);
  if (Status s = pass.haptics.finish(); !s) return s.error();
  if (!looped) return looped.error();
  if (const std::uint64_t lost = pass.ticks().dropped(); lost > 0 && !practice)
    std::fprintf(stderr, "warning: the maze's tracker missed %llu ticks: frames more than %.0f s apart\n",
                 static_cast<unsigned long long>(lost), static_cast<double>(kTrackFeedTicks) / o.haptics.rate_hz);
  return result;
}

// `text` over the start; the clock waits for Space or Enter. False: the participant quit.
Result<bool> wait_for_start(const maze::SessionOptions& o, Window& w, const std::string& text) {
  Overlay ov;
  ov.instructions = text;
  const HapticState still;  // no sample: the scene's own camera and probe at the start
  for (;;) {
    w.live->wait_events(0.05);  // nothing moves: redraw at 20 Hz, not as fast as it can
    if (w.events.quit || w.live->should_close() || stop_asked(o)) return false;
    if (std::exchange(w.events.start, false)) break;
    if (Status s = draw(w, o.desc, still, ov, false); !s) return s.error();
  }
  w.events.screenshot = false;
  w.events.height_steps = 0;
  return true;
}

// The instructions (the description's [instructions] text) over the start; the session's
// clock, the haptic loop and the mouse grab wait for Space or Enter. False: the participant quit.
Result<bool> show_instructions(const maze::SessionOptions& o, Window& w) {
  Result<bool> go = wait_for_start(o, w, o.desc.instructions);
  // The mouse relative (captured): the camera follows the probe, so an absolute pointer would
  // chase it. The gamepad's stick is relative already. The grab is a new relative origin.
  if (go && go.value() && w.input() && w.input()->kind() == GlfwInputDevice::Kind::kMouse) w.input()->toggle_capture();
  return go;
}

// The practice pass (docs/maze.md, "Practice"), then its closing screen; the window's renderer
// is the scored session's again after it. False: the participant quit during it.
Result<bool> run_practice(const maze::SessionOptions& o, const MazeWindowParams& p, Window& w,
                          const cli::LiveLoopArgs& live_args, const maze::SessionCore& scored) {
  auto po = maze::practice_options(o);
  if (!po) return po.error();
  auto opened = maze::SessionCore::open(po.value());
  if (!opened) return opened.error();
  maze::SessionCore& core = *opened.value();
  if (Status s = use_scene(w, core.scene().scene); !s) return s.error();
  LivePass pass(w, po.value(), core, live_args);
  const Status looped = run_pass(po.value(), p, core, w, pass, true);
  auto result = end_pass(po.value(), core, pass, looped, true);
  if (!result) return result.error();
  // Its one pass done (max_passes) or ended early with Space goes on; Esc or a signal stops.
  if (result->reason == maze::EndReason::kQuit || result->reason == maze::EndReason::kTerminated ||
      result->reason == maze::EndReason::kDisplayLost)
    return false;
  if (Status s = use_scene(w, scored.scene().scene); !s) return s.error();
  w.input()->place(on_plane(floor_plane(*w.renderer), w.renderer->scene().probe.position));
  Result<bool> go = wait_for_start(o, w, kPracticeOver);
  w.input()->rebase();  // the mouse moved while the screen waited: a new relative origin
  return go;
}

}  // namespace

int run_maze_window(const cli::Command& cmd, const maze::SessionOptions& o, const DeviceSpec& device,
                    const cli::LiveLoopArgs& live_args, const MazeWindowParams& params, maze::EndReason* ended) {
  auto live = cli::apply_live_loop(live_args);  // before the context and the haptic thread
  if (!live) return cmd.usage_error(live.error());
  auto opened = maze::SessionCore::open(o);
  if (!opened) return cmd.fail(opened.error());
  maze::SessionCore& core = *opened.value();
  Window w;
  if (Status s = open_window(o, device, core, w); !s) return cmd.fail(s.error());
  LivePass pass(w, o, core, live_args);
  Status looped = ok_status();
  // A participant's session starts from the instructions; a log device played in the window
  // has no one to read them.
  auto go = w.input() ? show_instructions(o, w) : Result<bool>(true);
  if (go && go.value() && w.input() && params.practice) go = run_practice(o, params, w, live_args, core);
  if (!go) looped = go.error();
  if (go && go.value()) {
    if (w.input()) w.input()->poll(o.haptics.start_time_s, pointer_view(*w.renderer, floor_plane(*w.renderer)));
    looped = run_pass(o, params, core, w, pass, false);
  } else if (stop_asked(o)) {
    pass.reason = stop_reason();  // before the start, or in the practice
  }
  auto result = end_pass(o, core, pass, looped, false);
  if (!result) return cmd.fail(result.error());
  if (ended) *ended = result->reason;
  std::printf("maze: %s after %d pass%s (%s), %.1f s; log %s\n", o.info.participant.c_str(), result->passes,
              result->passes == 1 ? "" : "es", maze::end_reason_name(result->reason), result->time_s, o.log_path.c_str());
  return cli::kExitOk;
}

}  // namespace ps
