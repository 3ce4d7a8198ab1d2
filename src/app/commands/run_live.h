// `pseudoshadow run`'s window, shared by its three files: the command and its frame loop
// (run_cmd.cpp), the device and what is drawn over each frame (run_frame.cpp), and what keys,
// buttons and reloads do (run_actions.cpp). Its state is in owned parts, each function taking
// the parts it needs: the window's I/O (WindowIo), the live haptics (LiveHaptics), the readouts
// (FrameReadouts) and the scenes a button switched through (SceneTrail). Only the frame loop
// holds them all (RunState).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/cli_groups.h"
#include "app/session/free_height.h"
#include "app/session/run_events.h"
#include "app/session/session.h"
#include "app/window/hud.h"
#include "app/window/live_window.h"
#include "app/window/readouts_log.h"
#include "app/window/window_input.h"
#include "devices/device_spec.h"
#include "devices/glfw_input.h"
#include "haptics/loop_stats.h"
#include "haptics/session_driver.h"
#include "image/image.h"
#include "render/adaptive_scale.h"
#include "tune/tune_session.h"

namespace ps::run_live {

struct RunArgs {
  cli::SceneArgs scene;
  DeviceSpec device;  // --device, parsed once (default: the mouse)
  std::string record, stats_path, ui_report, readouts_log;
  long long frames = 0, realtime = 0;
  cli::LiveLoopArgs live;  // --render-threads, --spare-cpu
  double quit_after_s = 0.0;
  bool quiet = false, watch = true, show_probe = false, show_device = false, panel = false;
  bool no_incremental = false;  // RendererOptions::incremental off
  // Adaptive resolution while the view moves (docs/adaptive.md): off with --no-adaptive; the
  // frame time it holds, --frame-budget.
  bool adaptive = true;
  double frame_budget_ms = 16.7;
  // At most this many frames a second (--max-fps; 0: as many as the machine draws; -1, the
  // default: the display's refresh rate, 60 where it is unknown). Software GL and Xvfb have no
  // vertical sync, so a still view was redrawn 80-120 times a second on 2 cores: a display
  // shows 60, and the rest took CPU from the haptic thread and everything else.
  long long max_fps = -1;
  RunEventsDesc events;  // --events, --mute, --audio-device (docs/sound.md)
};

// The window's I/O: the window with its context and device, its input, the ImGui frame over the
// picture (readouts, help, panel) and what is written of it (screenshots, --ui-report).
struct WindowIo {
  std::unique_ptr<LiveWindow> window;  // context, ImGui, input callbacks, the device
  std::unique_ptr<WindowUi> ui;        // readouts, help, parameter panel (one ImGui frame)
  WindowInput input;
  int screenshots_saved = 0;             // numbers the next screenshot_NNNN.png
  UiReportLog ui_report;                 // --ui-report, streamed
};

// The render thread's side of the haptic loop: the haptic scene it feels, the surface under the
// pointer and the plane it moves over, the loop itself and what consumes it.
struct LiveHaptics {
  SteadyClock clock;
  std::shared_ptr<const world::HapticScene> scene;  // before the loop: it must outlive the haptic thread
  FreeHeight floor;  // the surface under the pointer: the mouse's height counts from it
  PlaneAxes axes;    // the pointer's plane, fixed per scene so the mapping stays put
  std::unique_ptr<vibration::LiveVibration> vibration;  // before the loop too: the loop feeds it ticks
  // The loop on the window's device with the device stream's recording (--record), flushed
  // about once a second (haptics/session_driver.h, as replay's and the maze's).
  std::unique_ptr<RecordedLoop> recorded;
  HapticLoop* loop() const { return recorded ? &recorded->loop() : nullptr; }
  std::unique_ptr<RunEvents> events;  // the one consumer of loop->events(): log, sound, ...
  std::uint32_t last_charge_id = 0;   // live charges: ids are never reused
  // The tuning's edits the haptic scene was built with (TuneSession::edits_generation).
  std::uint64_t edits_generation = 0;
};

// The window's per-frame read-backs (run_frame.cpp, measure_frame_shadow), kept between frames.
struct AovBuffers {
  Image intensity, distance;
  std::vector<float> raw;  // the AOV target's four channels, as GL hands them over
};

// What the readouts show and log, and the frames' counts for the summary at exit.
struct FrameReadouts {
  HudReadouts shown;          // shown until the next refresh
  double refreshed_s = -1.0;  // window time of their last refresh
  std::string notice;         // a short answer shown in the readouts until notice_until_s
  double notice_until_s = 0.0;
  ReadoutsLog log;            // --readouts-log
  int frame_keys = 0;         // key presses handled this frame (the readouts log's `keys`)
  AovBuffers aov_buffers;     // the shadow measure's read-backs, reused every frame
  // Every frame's wall time and sample->frame latency, for the summary at exit: fixed memory
  // however long the window runs.
  StreamingPercentiles latency_ms, frame_ms;
  double last_frame_ms = 0.0;
};

// The scenes a button switched through (Backspace goes back) and the switch asked for.
struct SceneTrail {
  std::string pending;                 // a button's scene action, carried out after this frame
  std::vector<std::string> came_from;  // scenes a button switched away from
  bool going_back = false;             // the pending switch is a Backspace: do not remember it
};

// The parts, owned together by the frame loop (run_cmd.cpp). Declared in the order they must
// outlive each other: the window (its context and device) outlives the renderer and the haptic
// loop; the loop's event consumers hold the trail and the tuning.
struct RunState {
  WindowIo io;
  std::unique_ptr<TuneSession> tune;  // owns the Renderer; swaps in a new one on reload
  std::string shown_error;            // last reload error printed to the console
  SceneTrail trail;
  LiveHaptics haptics;
  FrameReadouts readouts;
  AdaptiveScale adaptive;  // the next frame's surface scale, from the last frames' cost
};

// run_frame.cpp: the device, the window's opening and what is drawn over each frame.
// The window's tuning session for `scene` (from `scene_path` with the `sets`): its renderer's
// options and its first view's flags, the same at the start and after a button's scene switch.
TuneSource window_tune_source(const RunArgs& a, std::string scene_path, std::vector<std::string> sets,
                              std::vector<std::string> allow_paths);
Status open_run(const RunArgs& a, Scene scene, RunState& s);
// The hand must be able to push every button of the scene past its travel (see run_frame.cpp).
void fit_height_to_buttons(const LiveWindow& win, const LiveHaptics& h, const world::HapticScene& scene);
// The pointer devices map through the camera this frame draws with and the window's size.
// `view_at_rest`: the workspace is the world (a new haptic scene's view starts there).
void poll_device(const LiveWindow& win, const Renderer& r, LiveHaptics& h, double now_s, bool poll_glfw,
                 bool view_at_rest = false);
// The geometry felt changed: the hand goes back to the hover height (see run_frame.cpp).
std::optional<glm::dvec3> place_hand(const LiveWindow& win, const Renderer& r, LiveHaptics& h,
                                     std::shared_ptr<const world::HapticScene> felt, bool new_view);
// The panel's edits, camera and probe of this frame as an override file (screenshots).
std::string screenshot_state(const TuneSession& tune);
// Refreshes and logs the readouts; returns the frame's shadow (where the overlays must not go).
Result<ShadowMeasure> update_readouts(LiveWindow& win, const TuneSession& tune, const LiveHaptics& h,
                                      FrameReadouts& ro, const HapticState& st, std::uint64_t frame, double now_s);
// Readouts, help and panel over the frame, around `shadow` (after the screenshots).
void draw_overlays(const RunArgs& a, WindowIo& io, TuneSession& tune, const HudReadouts& shown,
                   const ShadowMeasure& shadow, std::uint64_t frame, double now_s);
void print_summary(const HapticLoop& loop, const FrameReadouts& ro);

// run_actions.cpp: keys, live charges, reloads and a button's scene switch, in the order the
// frame loop calls them (handle_keys there).
// The window's own keys (capture, panel, help, height), the window's presence; returns the keys
// pressed this frame.
int window_keys(WindowIo& io, HapticLoop& loop);
// C, Shift+C (live charges) and Home (the view back where the scene started).
void haptic_keys(WindowInput& in, const LiveWindow& win, const Renderer& r, LiveHaptics& h);
// Backspace: back to the scene a button came from, or a notice saying there is none.
void back_key(WindowInput& in, SceneTrail& trail, FrameReadouts& ro, double now_s);
// P, D (flags), 1-6 (4D turn), orbit and zoom: the tuning's view.
void view_keys(WindowInput& in, TuneSession& tune);
// S: the frame and the state that made it (before the overlays are drawn).
Status save_screenshots(WindowIo& io, const TuneSession& tune, int w, int h);
void reload_haptic_scene(const LiveWindow& win, const TuneSession& tune, LiveHaptics& h);
void poll_reload(const LiveWindow& win, TuneSession& tune, LiveHaptics& h, std::string& shown_error);
// Returns the new scene's number (HapticLoop::replace_scene); 0: it stayed (the file failed to load).
std::uint64_t switch_scene(const RunArgs& a, const LiveWindow& win, std::unique_ptr<TuneSession>& tune,
                           LiveHaptics& h, SceneTrail& trail);

}  // namespace ps::run_live
