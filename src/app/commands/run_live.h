// `pseudoshadow run`'s window session, shared by its three files: the command and its frame
// loop (run_cmd.cpp), the device and what is drawn over each frame (run_frame.cpp), and what
// keys, buttons and reloads do to the session (run_actions.cpp).
#pragma once

#include <cstdint>
#include <map>
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
#include "image/image.h"
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
  RunEventsDesc events;  // --events, --mute, --audio-device (docs/sound.md)
};

// The window's per-frame read-backs (run_frame.cpp, measure_frame_shadow), kept between frames.
struct AovBuffers {
  Image intensity, distance;
  std::vector<float> raw;  // the AOV target's four channels, as GL hands them over
};

struct Session {  // everything the window loop touches, grouped by owner thread
  std::unique_ptr<LiveWindow> window;  // context, ImGui, input callbacks, the device
  std::unique_ptr<TuneSession> tune;  // owns the Renderer; swaps in a new one on reload
  std::unique_ptr<WindowUi> ui;       // readouts, help, parameter panel (one ImGui frame)
  HudReadouts readouts;               // shown until the next refresh
  double readouts_s = -1.0;           // session time of their last refresh
  std::vector<UiFrameReport> ui_frames;  // --ui-report
  std::string shown_error;            // last reload error printed to the console
  std::uint32_t last_charge_id = 0;   // live charges: ids are never reused
  GlfwInputDevice* glfw_device = nullptr;  // == window->input(): mouse/gamepad
  PointerLogDevice* pointer_device = nullptr;  // == window->pointer(): pointer:FILE
  SteadyClock clock;
  std::shared_ptr<const world::HapticScene> haptic_scene;  // before the loop: it must outlive the haptic thread
  FreeHeight floor;                   // the surface under the pointer: the mouse's height counts from it
  std::unique_ptr<vibration::LiveVibration> vibration;  // before the loop too: the loop feeds it ticks
  std::unique_ptr<HapticLoop> loop;
  std::unique_ptr<SampleRecorder> recorder;
  std::unique_ptr<RunEvents> events;  // the one consumer of loop->events(): log, sound, ...
  WindowInput input;
  int screenshots_saved = 0;          // numbers the next screenshot_NNNN.png
  PlaneAxes axes;
  // Every frame's wall time and sample->frame latency, for the summary at exit: fixed memory
  // however long the window runs.
  StreamingPercentiles latency_ms, frame_ms;
  double last_frame_ms = 0.0;
  AovBuffers aov_buffers;  // the shadow measure's read-backs, reused every frame
  std::string pending_scene;          // a button's scene action, carried out after this frame
  std::vector<std::string> came_from; // scenes a button switched away from (Backspace goes back)
  bool going_back = false;            // the pending switch is a Backspace: do not remember it
  std::string notice;                 // a short answer shown in the readouts until notice_until_s
  double notice_until_s = 0.0, now_s = 0.0;  // now_s: this frame's window time
  std::map<std::string, std::string> haptic_edits;  // the panel's edits the haptic scene was built with
  ReadoutsLog readouts_log;           // --readouts-log
  int frame_keys = 0;                 // key presses handled this frame (the readouts log's `keys`)
};

// run_frame.cpp: the device, the session's opening and what is drawn over each frame.
// The window's tuning session for `scene` (from `scene_path` with the `sets`): its renderer's
// options and its first view's flags, the same at the start and after a button's scene switch.
TuneSource window_tune_source(const RunArgs& a, std::string scene_path, std::vector<std::string> sets,
                              std::vector<std::string> allow_paths);
Status open_session(const RunArgs& a, Scene scene, Session& s);
// The hand must be able to push every button of the scene past its travel (see run_frame.cpp).
void fit_height_to_buttons(Session& s, const world::HapticScene& scene);
// The pointer devices map through the camera this frame draws with and the window's size.
// `view_at_rest`: the workspace is the world (a new haptic scene's view starts there).
void poll_device(Session& s, double now_s, bool poll_glfw, bool view_at_rest = false);
// The geometry felt changed: the hand goes back to the hover height (see run_frame.cpp).
std::optional<glm::dvec3> place_hand(Session& s, std::shared_ptr<const world::HapticScene> felt, bool new_view);
// The panel's edits, camera and probe of this frame as an override file (screenshots).
std::string screenshot_state(const TuneSession& tune);
Status draw_overlays(const RunArgs& a, Session& s, const HapticState& st, std::uint64_t frame, double now_s);
void print_summary(const Session& s);

// run_actions.cpp: keys, live charges, reloads and a button's scene switch.
Status handle_keys(Session& s, int w, int h);
void reload_haptic_scene(Session& s);
void poll_reload(Session& s);
// Returns the new scene's number (HapticLoop::replace_scene); 0: it stayed (the file failed to load).
std::uint64_t switch_scene(const RunArgs& a, Session& s);

}  // namespace ps::run_live
