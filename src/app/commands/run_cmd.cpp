// `pseudoshadow run`: the interactive window. Main thread: GLFW events, device polling (mouse/
// gamepad), rendering through the same Renderer as headless, blit to the window, readouts, help
// and parameter panel over it (app/window/hud.h), a short summary in the title. Haptic thread:
// HapticLoop at 1 kHz. They meet only in the loop's two Snapshots.
#include <chrono>
#include <cstdio>
#include <thread>

#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "app/cli/stop_signal.h"
#include "app/commands.h"
#include "app/commands/run_live.h"
#include "app/window/run_keys.h"
#include "core/file_io.h"
#include "devices/device_spec.h"
#include "render/present.h"

namespace ps {

namespace {

using run_live::FrameReadouts;
using run_live::LiveHaptics;
using run_live::RunArgs;
using run_live::RunState;
using run_live::SceneTrail;

// The key list comes from app/window/run_keys.h (the help overlay shows the same table).
constexpr const char* kRunNotes = R"(The probe follows the pointer: its shadow's centre sits under it, on any camera and zoom.
Scroll raises (up) or lowers (down) it 0.5 mm per notch; PageUp/Up and PageDown/Down step it
0.5 mm per press and repeat while held; it starts 1 mm above the surface under the pointer
(whatever is there: a sphere, a mesh, a button's face), goes down to 4 mm into it and back to
1 mm after a scene switch, a 4D turn, a panel edit or a reload. M captures the mouse (raw relative motion, 0.1 mm per count, where supported; M again
puts the probe back under the pointer).
The probe itself is hidden by default (P shows it): the pseudo-shadow is the display; when
shown it is drawn where the haptic proxy is, after the push-out. D draws the hand's own position
(the device) as a faint ghost: the gap to the proxy is what fields, viscosity and surfaces do
to it. C puts an attracting charge at the probe, Shift+C removes the nearest one. S saves screenshot_NNNN.png
(without the overlays) and screenshot_NNNN.overrides.toml (panel edits, camera, probe: `render
--scene FILE --overrides screenshot_NNNN.overrides.toml` draws the same image).
Saved changes to the shaders, the scene or its textures are reloaded within 0.5 s; a broken
file keeps the last good state running and shows its file:line in the title and the console.
A box in a corner shows frame time, haptic rate and jitter, distance, speed, penetration,
contact, force and the scene; the title shows the scene and the distance.
)";

std::string run_footer() { return "keys and mouse:\n" + run_keys_text("  ", 1) + kRunNotes; }

constexpr const char* kDescription =
    "Opens a window and lets you move the probe over the scene with a device; the haptic loop\n"
    "runs at 1 kHz on its own thread. Works under Xvfb (xvfb-run -a pseudoshadow run ...).";

DeviceSpec parsed_device(const std::string& d) {
  auto parsed = parse_device_spec(d);
  if (!parsed) throw cli::UsageError("--device: " + parsed.error().message);
  return parsed.value();
}

// What `run` writes besides the window (and its sounds, which go with the event log).
void declare_outputs(CLI::App& app, RunArgs& a) {
  cli::add_output(app, "--record", a.record, "FILE",
                  "record the device stream (replay it with `pseudoshadow replay`)");
  cli::add_stats_option(app, a.stats_path);
  cli::add_output(app, "--events", a.events.log_path, "FILE",
                  "write every haptic event as a JSON line (docs/sound.md)");
  app.add_flag("--mute", a.events.audio.mute, "no event sounds");
  app.add_option("--audio-device", a.events.audio.device, "OpenAL output device (default: the system's default)")
      ->type_name("NAME");
  cli::add_output(app, "--ui-report", a.ui_report, "FILE",
                  "write JSON with every frame's overlay, help and panel rectangles and the "
                  "pseudo-shadow's bounding box, in window pixels (streamed; FILE appears at exit)");
  cli::add_output(app, "--readouts-log", a.readouts_log, "FILE",
                  "write one JSON line per frame: what the readouts say (state, distance, pressed depth, "
                  "force), hand, proxy, view offset, button, flags, key presses (docs/window.md)");
}

void declare(cli::Command& cmd, RunArgs& a) {
  CLI::App& app = cmd.app();
  cli::add_scene_options(app, a.scene);
  cli::add_probe_options(app, a.scene);
  cli::add_image_options(app, a.scene);
  app.add_option_function<std::string>("--device", [&a](const std::string& v) { a.device = parsed_device(v); },
                                       "mouse (default) | gamepad | trajectory:FILE | playback:FILE | pointer:FILE "
                                       "(lines 'time_s x_px y_px height_mm buttons', mapped like the mouse)")
      ->type_name("D");
  declare_outputs(app, a);
  app.add_option_function<std::string>(
         "--backend",
         [](const std::string& v) {
           if (v != "glfw") throw cli::UsageError("--backend: only glfw opens a window (got '" + v + "')");
         },
         "glfw, the only window backend")
      ->type_name("B")
      ->group(cli::kGlGroup);
  app.add_flag("--show-probe", a.show_probe, "start with the probe drawn (P toggles it)");
  app.add_flag("--show-device", a.show_device,
               "start with the device's own position drawn faintly (D toggles it): the gap to the drawn proxy "
               "is the pseudo-haptic feedback of fields, viscosity and surfaces");
  app.add_flag("--panel", a.panel, "start with the parameter panel shown (F1 toggles it)");
  app.add_flag("--no-incremental", a.no_incremental,
               "redraw every pixel of every frame (default: while only the probe moves, only its shadow's "
               "rectangles; the same images)");
  app.add_flag_callback("--no-adaptive", [&a] { a.adaptive = false; },
                        "draw every frame at full resolution (default: while the view moves, the surface pass at "
                        "a reduced scale that holds --frame-budget, full resolution again at rest; docs/adaptive.md)");
  cli::add_positive(app, "--frame-budget", "MS", a.frame_budget_ms, 1000.0, "16.7",
                    "the frame time adaptive resolution holds while the view moves");
  cli::add_int(app, "--max-fps", "N", a.max_fps, 0, 1000,
               "draw at most N frames a second (default: the display's refresh rate, 60 where it is unknown; "
               "0: as many as the machine draws, as software GL has no vertical sync)");
  app.add_flag_callback("--no-watch", [&a] { a.watch = false; },
                        "do not reload the scene, its textures and glsl/ when they change");
  cli::add_int(app, "--realtime", "PRIO", a.realtime, 1, 99,
               "haptic thread SCHED_FIFO at PRIO (1..99; needs CAP_SYS_NICE), much lower jitter on a loaded machine");
  cli::add_live_loop_options(app, a.live);
  cli::add_int(app, "--frames", "N", a.frames, 1, 100'000'000, "quit after N frames");
  cli::add_positive(app, "--quit-after", "S", a.quit_after_s, 1e9, "5", "quit after S seconds");
  cli::add_quiet_option(app, a.quiet, "no summary");
  app.footer(run_footer() + cli::kExitStatusHelp + cli::kExitSignalHelp);
}

// Files are polled 5 times a second, so a saved change is on screen within ~0.2 s plus one
// rebuild (shader compile and JIT, ~0.1-0.2 s on llvmpipe).
constexpr double kWatchPeriodS = 0.2;

// The event consumers, before the haptic thread starts. No audio device is one warning line.
// A button's scene action waits in the trail for the end of the frame (the tuning then draws).
Status open_events(const RunArgs& a, LiveHaptics& h, SceneTrail& trail, const std::unique_ptr<TuneSession>& tune) {
  auto events = RunEvents::open(a.events);
  if (!events) return events.error();
  h.events = std::move(events.value());
  if (!h.events->warning().empty()) std::fprintf(stderr, "warning: %s\n", h.events->warning().c_str());
  h.events->dispatcher().subscribe("buttons", [&trail, &tune](const HapticEvent& e) {
    if (trail.pending.empty()) trail.pending = scene_action_of(tune->renderer().scene(), e);
  });
  return ok_status();
}

// The frame's wall time and, with a device sample in it, the latency from sample to frame.
void count_frame(FrameReadouts& ro, const HapticState& st, std::chrono::steady_clock::time_point f0) {
  const auto f1 = std::chrono::steady_clock::now();
  ro.last_frame_ms = std::chrono::duration<double, std::milli>(f1 - f0).count();
  ro.frame_ms.add(ro.last_frame_ms);
  if (st.have_sample) ro.latency_ms.add(static_cast<double>(f1.time_since_epoch().count() - st.sample_clock_ns) * 1e-6);
}

// How long a switch's frame waits for the haptic thread to adopt the new scene, s: it does at its
// next tick (1 ms), so only a stalled haptic thread takes longer; 0.25 s is one slow frame.
constexpr double kSceneAdoptWaitS = 0.25;

// A switch (serial: replace_scene's number; 0: it stayed) is drawn as the new world's first frame:
// from the state of the tick that adopted it and placed the probe in it, by the new renderer (past
// the wait, a stalled haptic thread's, from the state there is).
// Drawn from the state read before the switch, the new world showed the old world's probe, the
// press 2-3 mm into the old button's pocket, for a frame (and its readouts said so).
Status draw_switched_scene(Renderer& r, HapticLoop& loop, std::uint64_t serial, std::uint64_t frame, HapticState& st) {
  if (serial == 0) return ok_status();
  const auto start = std::chrono::steady_clock::now();
  while (loop.state().read().scene_serial < serial &&
         std::chrono::steady_clock::now() - start < std::chrono::duration<double>(kSceneAdoptWaitS))
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  return drive_frame(r, loop, frame, st);
}

// The frame loop's bookkeeping: when the files were last polled (the recording's flush is
// RecordedLoop's).
struct LoopTimes {
  double last_watch = 0.0;
};

// The keys, in the order they act: the window's own, the live charges and Home (the hand placed
// through the camera this frame drew with), Backspace, then the view's (flags, 4D turn, orbit);
// the screenshots read GL_BACK before the overlays are drawn.
Status handle_keys(RunState& s, glm::ivec2 fb, double now_s) {
  WindowInput& in = s.io.input;
  s.readouts.frame_keys = run_live::window_keys(s.io, *s.haptics.loop());
  run_live::haptic_keys(in, *s.io.window, s.tune->renderer(), s.haptics);
  run_live::back_key(in, s.trail, s.readouts, now_s);
  run_live::view_keys(in, *s.tune);
  return run_live::save_screenshots(s.io, *s.tune, fb.x, fb.y);
}

// One frame: the device, a reload, the frame itself (and a button's switch), the keys, then the
// overlays. A panel edit may change the feel (a body's time scale): the haptic scene is rebuilt
// when the tuning's edits changed.
Status live_frame(const RunArgs& a, RunState& s, std::uint64_t frame, double now_s, LoopTimes& t, HapticState& st) {
  LiveWindow& win = *s.io.window;
  LiveHaptics& h = s.haptics;
  run_live::poll_device(win, s.tune->renderer(), h, h.loop()->state().read().time_s, !s.io.ui->panel().wants_input());
  if (a.watch && now_s - t.last_watch >= kWatchPeriodS) {
    t.last_watch = now_s;
    run_live::poll_reload(win, *s.tune, h, s.shown_error);
  }
  // The scale this frame draws at if its view moves (or stays), from the last frames' cost; a
  // renderer rebuilt or switched below draws its first frame whole.
  s.tune->renderer().set_surface_scale(a.adaptive ? s.adaptive.next(now_s * 1e3) : SurfaceScale{});
  if (Status r = drive_frame(s.tune->renderer(), *h.loop(), frame, st); !r) return r;
  if (Status r = h.events->pump(h.loop()->events()); !r) return r;
  if (!s.trail.pending.empty()) {
    const std::uint64_t serial = run_live::switch_scene(a, win, s.tune, h, s.trail);
    if (Status r = draw_switched_scene(s.tune->renderer(), *h.loop(), serial, frame, st); !r) return r;
  }
  const glm::ivec2 fb = win.framebuffer_size();
  present_to_default_framebuffer(s.tune->renderer(), fb.x, fb.y);
  if (Status r = handle_keys(s, fb, now_s); !r) return r;  // screenshots read GL_BACK before the swap
  win.begin_frame();
  auto shadow = run_live::update_readouts(win, *s.tune, h, s.readouts, st, frame, now_s);
  if (!shadow) return shadow.error();
  run_live::draw_overlays(a, s.io, *s.tune, s.readouts.shown, shadow.value(), frame, now_s);  // after the screenshots
  if (s.tune->edits_generation() != h.edits_generation) {
    h.edits_generation = s.tune->edits_generation();
    run_live::reload_haptic_scene(win, *s.tune, h);
  }
  s.io.input.keys_captured = s.io.ui->panel().wants_keys();
  win.end_frame();
  return ok_status();
}

// `stop`: a signal asked to stop (app/cli/stop_signal.h): the loop ends as Esc ends it.
Status window_loop(const RunArgs& a, RunState& s, const cli::StopSignals& stop) {
  const auto t0 = std::chrono::steady_clock::now();
  LoopTimes times;
  // --max-fps: a frame starts no sooner than one period after the last one started; the wait
  // comes before the input is polled, so what a frame draws is as fresh as without it, and it
  // is not part of the frame's time (the readouts, adaptive resolution).
  constexpr int kUnknownRefreshHz = 60;
  const int display_hz = s.io.window->refresh_hz();
  const long long fps = a.max_fps >= 0 ? a.max_fps : (display_hz > 0 ? display_hz : kUnknownRefreshHz);
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(fps > 0 ? 1.0 / static_cast<double>(fps) : 0.0));
  auto next_start = t0;
  for (std::uint64_t frame = 0;; ++frame) {
    if (fps > 0) std::this_thread::sleep_until(next_start);
    const auto f0 = std::chrono::steady_clock::now();
    next_start = f0 + period;
    const double now_s = std::chrono::duration<double>(f0 - t0).count();
    s.io.window->poll_events();
    if (s.io.window->should_close() || s.io.input.quit || stop.requested()) break;
    if ((a.frames > 0 && static_cast<long long>(frame) >= a.frames) || (a.quit_after_s > 0 && now_s >= a.quit_after_s)) break;
    HapticState st;
    if (Status r = live_frame(a, s, frame, now_s, times, st); !r) return r;
    count_frame(s.readouts, st, f0);
    const FrameStats& drawn = s.tune->renderer().stats();
    s.adaptive.frame(now_s * 1e3 + s.readouts.last_frame_ms, s.readouts.last_frame_ms, drawn.surface_scale,
                     drawn.view_moved, drawn.measures_full_redraw());
    // The recording's flushing thread failed (a full disk): the session stops here.
    if (Status r = s.haptics.recorded->flush_due(st.time_s); !r) return r;
  }
  return ok_status();
}

// At exit: --stats (the renderer's last frame) and --ui-report (every frame's rectangles).
Status write_reports(const RunArgs& a, run_live::WindowIo& io, const Renderer& r, std::size_t frames) {
  if (!a.stats_path.empty()) {
    const gl::Context& ctx = io.window->context();
    const std::string json = stats_json(r.stats(), gl::backend_name(ctx.backend()), ctx.egl_device(), ctx.renderer(),
                                        static_cast<int>(frames));
    if (Status st = write_file_atomic(a.stats_path, json); !st) return st;
  }
  if (!a.ui_report.empty()) {
    const glm::ivec2 size = io.window->window_size();
    if (Status st = io.ui_report.close(size.x, size.y); !st) return st;
  }
  return ok_status();
}

// After a signal: what was closed as at a normal end, and how to see it again; 128 + the signal.
int report_stop(const RunArgs& a, const cli::StopSignals& stop) {
  std::string what, path = a.record, next;
  if (!a.record.empty()) {
    what = "recording";
    next = "replay with: pseudoshadow replay --log " + a.record + " --out DIR";
  }
  if (!a.events.log_path.empty()) {
    what += what.empty() ? "event log" : " and event log";
    path += path.empty() ? a.events.log_path : ", " + a.events.log_path;
  }
  std::fprintf(stderr, "%s\n", cli::stop_line("run", stop, what, path, next).c_str());
  return stop.exit_code();
}

// Joins the haptic thread before touching what it wrote, then closes what the loop wrote to.
Status close_haptics(LiveHaptics& h) {
  h.loop()->stop();
  h.vibration->close();
  if (Status st = h.recorded->finish(); !st) return st;
  return h.events->close(h.loop()->events());
}

int run(const cli::Command& cmd, const RunArgs& a) {
  auto scene = cli::load_scene_or_default(a.scene);
  if (!scene) return cmd.fail(scene.error(), cli::scene_exit_code(scene.error()));
  RunState s;
  AdaptiveScaleParams scale_params;
  scale_params.budget_ms = a.frame_budget_ms;
  s.adaptive = AdaptiveScale(scale_params);
  LiveHaptics& h = s.haptics;
  auto live = cli::apply_live_loop(a.live);  // before the context and the haptic thread
  if (!live) return cmd.usage_error(live.error());
  if (Status st = run_live::open_run(a, std::move(scene.value()), s); !st) return cmd.fail(st.error());
  if (Status st = open_events(a, h, s.trail, s.tune); !st) return cmd.fail(st.error());
  if (!a.readouts_log.empty())
    if (Status st = s.readouts.log.open(a.readouts_log); !st) return cmd.fail(st.error());
  if (!a.ui_report.empty())
    if (Status st = s.io.ui_report.open(a.ui_report); !st) return cmd.fail(st.error());
  h.loop()->start();
  h.recorded->start_flushing();  // the recording, once a second, frames or not
  h.vibration->start();
  // The first frame shows the device's probe, not the scene's: wait for the first tick (about
  // 1 ms; bounded, as a gamepad may have nothing to give yet).
  for (int i = 0; i < 100 && !h.loop()->state().read().have_sample; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  if (!a.quiet) std::printf("haptic thread: %s; %s\n", h.loop()->scheduling().c_str(), live->report().c_str());
  const cli::StopSignals stop;  // SIGTERM, SIGINT, SIGHUP: the window closes as with Esc
  const Status looped = window_loop(a, s, stop);
  if (Status st = close_haptics(h); !st) return cmd.fail(st.error());
  if (!looped) return cmd.fail(looped.error());
  if (Status st = s.readouts.log.close(); !st) return cmd.fail(st.error());
  if (Status st = write_reports(a, s.io, s.tune->renderer(), s.readouts.frame_ms.count()); !st)
    return cmd.fail(st.error());
  if (!a.quiet) run_live::print_summary(*h.loop(), s.readouts);
  if (!a.quiet && h.vibration->active()) std::printf("%s\n", h.vibration->summary().c_str());
  if (!a.quiet && h.events->warning().empty()) std::printf("%s\n", h.events->audio().summary().c_str());
  return stop.requested() ? report_stop(a, stop) : cli::kExitOk;
}

}  // namespace

int run_window(int argc, char** argv) {
  return cli::run_command<RunArgs>(argc, argv, "run", kDescription, declare, run);
}

}  // namespace ps
