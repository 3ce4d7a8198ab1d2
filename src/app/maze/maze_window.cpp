#include "app/maze/maze_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "app/window/imgui_scope.h"

#include <cstdio>
#include <filesystem>

#include "app/session/session.h"
#include "devices/glfw_input.h"
#include "devices/sample_log.h"
#include "gl/context.h"
#include "maze/maze_screen.h"
#include "prepare/prepare.h"
#include "render/present.h"
#include "frame/haptic_frame.h"
#include "render/renderer.h"

namespace ps {

namespace {

constexpr double kScoreSeconds = 5.0;  // how long a pass's score screen stays up
// Ticks the tracker's feed holds between two frames: 16 s at 1 kHz (a frame that takes longer
// loses ticks, and says so); ~3 MiB.
constexpr std::size_t kTrackFeedTicks = std::size_t{1} << 14;
constexpr double kMmPerCount = 0.15;   // captured mouse: mm on the floor per raw count
// The practice pass's seed: the session's, mixed, so its route (correct exits, room order) is
// another one and practice teaches the task, not the answers.
constexpr std::uint64_t kPracticeSeedMix = 0x9e3779b97f4a7c15ull;
constexpr const char* kPracticeOver =
    "That was the practice.\n\nThe real session starts now: a new maze, whose right exits\n"
    "you will learn as you go.\n\nPress Space to start.";

// What the window hears from GLFW, from its callbacks (installed before ImGui, which chains to
// them): a frame can take longer than a quick tap, so polled key state would lose taps.
struct Events {
  bool quit = false, screenshot = false, start = false;  // start: Space or Enter (the instructions)
  int height_steps = 0;  // PageUp/Up +1, PageDown/Down -1 (0.5 mm each, HeightControl); repeats count
  // GLFW moved its virtual cursor without the person moving the mouse (the pointer entered the
  // window, focus came back and the cursor was grabbed again): the next poll rebases on it.
  bool rebase = false;
  static Events& of(GLFWwindow* win) { return *static_cast<Events*>(glfwGetWindowUserPointer(win)); }
  static void on_key(GLFWwindow* win, int key, int /*scancode*/, int action, int /*mods*/) {
    if (action == GLFW_RELEASE) return;
    Events& e = of(win);
    if (key == GLFW_KEY_PAGE_UP || key == GLFW_KEY_UP) ++e.height_steps;
    if (key == GLFW_KEY_PAGE_DOWN || key == GLFW_KEY_DOWN) --e.height_steps;
    if (action != GLFW_PRESS) return;  // a held S or Esc acts once
    if (key == GLFW_KEY_S) e.screenshot = true;
    if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) e.quit = true;
    if (key == GLFW_KEY_SPACE || key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER) e.start = true;
  }
  static void on_enter(GLFWwindow* win, int /*entered*/) { of(win).rebase = true; }
  static void on_focus(GLFWwindow* win, int /*focused*/) { of(win).rebase = true; }
  void install(GLFWwindow* win) {
    glfwSetWindowUserPointer(win, this);
    glfwSetKeyCallback(win, &Events::on_key);
    glfwSetCursorEnterCallback(win, &Events::on_enter);
    glfwSetWindowFocusCallback(win, &Events::on_focus);
  }
};

struct Window {  // context first: the renderer's GL objects die before it
  std::unique_ptr<gl::Context> ctx;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<Device> device;
  GlfwInputDevice* input = nullptr;  // == device.get() for the mouse or gamepad
  Events events;                     // its callbacks point here: it lives as long as the window
  std::string out_dir;
  int screenshots = 0;
};

// The floor under the camera target: the plane the captured mouse moves the probe over.
PlaneAxes floor_plane(const Renderer& r) {
  return {r.camera().target, glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
}

glm::dvec3 on_plane(const PlaneAxes& plane, const glm::dvec3& p) { return p - glm::dot(p - plane.origin, plane.n) * plane.n; }

// The window draws `scene` from now on (a new renderer).
Status use_scene(Window& w, const Scene& scene) {
  auto r = open_renderer(scene, RendererOptions{});
  if (!r) return r.error();
  w.renderer = std::move(r.value());
  return ok_status();
}

Status open_device(const std::string& device, const maze::SessionOptions& o, Window& w) {
  if (device.empty() || device == "mouse" || device == "gamepad") {
    GlfwInputParams params;
    params.mm_per_count = kMmPerCount;
    const bool mouse = device != "gamepad";
    auto m = std::make_unique<GlfwInputDevice>(mouse ? GlfwInputDevice::Kind::kMouse : GlfwInputDevice::Kind::kGamepad,
                                               w.ctx->window(), params);
    // The hand starts where the probe starts: its point on the floor under the probe's start.
    const PlaneAxes plane = floor_plane(*w.renderer);
    // A resumed session: where the probe waits, in the hall of the last room left.
    m->place(on_plane(plane, o.resume ? maze::resume_place(o.desc, *o.resume) : w.renderer->probe().position));
    w.input = m.get();
    w.device = std::move(m);
    return ok_status();
  }
  auto d = open_device_log(device);
  if (!d) return make_error("--device: " + d.error().message);
  w.device = std::move(d->device);
  return ok_status();
}

Status open_window(const maze::SessionOptions& o, const std::string& device, const maze::SessionCore& core, Window& w) {
  gl::ContextDesc desc;
  desc.backend = gl::Backend::kGlfw;
  desc.window_width = desc.window_height = o.desc.image_size;
  desc.window_title = "pseudoshadow maze - " + o.info.participant;
  auto ctx = gl::create_context(desc);
  if (!ctx) return ctx.error();
  w.ctx = std::move(ctx.value());
  w.events.install(w.ctx->window());  // before ImGui (it chains to them) and before the grab
  if (Status s = use_scene(w, core.scene().scene); !s) return s;
  w.out_dir = std::filesystem::path(o.log_path).parent_path().string();
  return open_device(device, o, w);
}

void text_window(const char* id, ImVec2 pos, const std::string& text, float scale) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin(id, nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs);
  ImGui::SetWindowFontScale(scale);
  ImGui::TextUnformatted(text.c_str());
  ImGui::End();
}

std::string score_text(const maze::PassScore& s, bool cues) {
  std::string t = "Pass " + std::to_string(s.pass + 1) + ": " + std::to_string(s.correct()) + " of 6 rooms right\n";
  for (const maze::Trial& r : s.trials)
    t += "\nroom " + std::to_string(r.index + 1) + (cues ? "" : std::string("  ") + maze::cue_label(r.cue)) + "  " +
         maze::exit_name(r.chosen) + "  " + (r.ok ? "RIGHT" : "WRONG");
  return t;
}

// What the window shows over the frame: the label (cues off), the last score for a while.
struct Overlay {
  std::string label, score, instructions;
  double score_until = -1.0;
  bool done = false, show_hand = false;
};

// A faint ring where the hand is, once a wall holds the probe away from it: the participant sees
// how far the hand has run on (the clutch brings it back past MazeWindowParams::clutch_mm).
void draw_hand(const Window& w, const HapticState& st) {
  const PlaneAxes plane = floor_plane(*w.renderer);
  const glm::dvec3 hand = on_plane(plane, st.device_mm);
  if (glm::length(hand - on_plane(plane, st.proxy_mm)) < 0.5) return;  // under the probe: nothing to show
  int ww = 0, wh = 0;
  glfwGetWindowSize(w.ctx->window(), &ww, &wh);
  const PointerView view = pointer_view(*w.renderer, plane, glm::dvec2(ww, wh));
  const glm::dvec2 c = project_to_window(view, hand);
  const double r = glm::length(project_to_window(view, hand + view.probe_radius_mm * plane.t) - c);
  ImGui::GetBackgroundDrawList()->AddCircle(ImVec2(static_cast<float>(c.x), static_cast<float>(c.y)),
                                            static_cast<float>(r), IM_COL32(255, 255, 255, 90), 32, 2.0f);
}

// Renders the state, stamps a screenshot if asked (the frame plus the label, as headless
// frames have it), blits, draws the overlay.
Status draw(Window& w, const maze::MazeDesc& desc, const HapticState& st, const Overlay& ov, bool screenshot) {
  const HapticFrameSources maze{.proxy_only = true, .camera = maze::follow_camera(desc, st.proxy_mm)};
  if (auto f = w.renderer->render(haptic_frame_input(*w.renderer, st, maze)); !f) return f.error();
  if (screenshot) {
    Image im = w.renderer->read_color();
    maze::stamp_label(im, ov.label);
    char name[48];
    std::snprintf(name, sizeof name, "/screenshot_%04d.png", w.screenshots++);
    if (Status s = write_image(w.out_dir + name, im); !s) return s;
  }
  int fw = 0, fh = 0;
  glfwGetFramebufferSize(w.ctx->window(), &fw, &fh);
  present_to_default_framebuffer(*w.renderer, fw, fh);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  if (ov.show_hand && st.have_sample) draw_hand(w, st);
  if (!ov.instructions.empty()) text_window("##instructions", ImVec2(30, 60), ov.instructions, 1.3f);
  if (!ov.label.empty()) text_window("##label", ImVec2(10, 10), ov.label, 2.0f);
  if (st.time_s < ov.score_until) text_window("##score", ImVec2(40, 80), ov.score, 1.6f);
  if (ov.done) text_window("##done", ImVec2(40, fh - 60.0f), "The session is over.", 1.6f);
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glfwSwapBuffers(w.ctx->window());
  return ok_status();
}


// The clutch (docs/maze.md, "A hand a wall has stopped"): a mouse has no force to hold the hand
// at a wall, so the hand runs on while the wall holds the probe. Once it has overshot by more
// than clutch_mm along the floor, the hand is put back under the probe and that is logged.
Status apply_clutch(const MazeWindowParams& p, Window& w, maze::SessionCore& core, const HapticState& st,
                    double& quiet_until_s) {
  if (!w.input || p.clutch_mm <= 0.0 || !st.have_sample || st.time_s < quiet_until_s) return ok_status();
  const PlaneAxes plane = floor_plane(*w.renderer);
  const glm::dvec3 hand = on_plane(plane, st.device_mm), probe = on_plane(plane, st.proxy_mm);
  const double overshoot = glm::length(hand - probe);
  if (overshoot <= p.clutch_mm) return ok_status();
  w.input->place(probe);
  // The haptic thread reads the placed hand within a tick; 50 ms keeps a frame drawn from a
  // state older than that from clutching twice.
  quiet_until_s = st.time_s + 0.05;
  return core.log_clutch(st.time_s, overshoot, hand, probe);
}

// The window's events since the last frame, applied: quit, height steps, a rebase of the
// relative origin; then the device's poll.
bool take_input(Window& w, const HapticState& st) {
  Events& e = w.events;
  if (e.quit || glfwWindowShouldClose(w.ctx->window())) return false;
  if (w.input) {
    if (std::exchange(e.rebase, false)) w.input->rebase();
    w.input->add_height_steps(std::exchange(e.height_steps, 0));
    w.input->poll(st.time_s, pointer_view(*w.renderer, floor_plane(*w.renderer)));
  }
  return true;
}

// The render thread's loop: input, the session's step on the newest haptic state (a pass switch
// brings a new renderer), the frame. Returns when the participant quits, the log device ends, or
// kScoreSeconds after the session ended (its last score stays up that long).
// In practice (`practice`), Space or Enter ends the pass early (reason "practice_ended").
Status window_loop(const maze::SessionOptions& o, const MazeWindowParams& p, maze::SessionCore& core, Window& w,
                   HapticLoop& loop, TickFeed& ticks, SampleRecorder& recorder, std::string& reason,
                   vibration::LiveVibration& vib, bool practice = false) {
  Overlay ov;
  HapticState st;
  double last_flush = 0.0, end_at = -1.0, clutch_quiet_until = 0.0;
  const auto on_score = [&](const maze::PassScore& s) -> Status {
    ov.score = score_text(s, o.info.cues);
    ov.score_until = st.time_s + kScoreSeconds;
    return ok_status();
  };
  for (;;) {
    glfwPollEvents();
    st = loop.state().read();
    if (Status s = apply_clutch(p, w, core, st, clutch_quiet_until); !s) return s;
    if (!take_input(w, st)) return ok_status();
    if (practice && std::exchange(w.events.start, false)) {
      reason = "practice_ended";
      return ok_status();
    }
    // Every tick since the last frame, so the tracker sees each room the proxy passed through
    // however long the frame took (a pass switch's new renderer, a loaded machine).
    Status stepped = ok_status();
    ticks.drain([&](const TickSample& t) {
      if (stepped && !core.finished()) stepped = core.step(t, loop, on_score);
    });
    if (!stepped) return stepped;
    if (core.finished() && end_at < 0.0) {
      end_at = st.time_s + kScoreSeconds;
      reason = "logged";
      ov.done = true;
    }
    if ((end_at >= 0.0 && st.time_s > end_at) || (end_at < 0.0 && w.device->duration_s() >= 0.0 && st.time_s > w.device->duration_s())) {
      if (end_at < 0.0) reason = "device_ended";
      return ok_status();
    }
    if (core.take_scene_changed()) {
      auto r = open_renderer(core.scene().scene, RendererOptions{});
      if (!r) return r.error();
      w.renderer = std::move(r.value());
      vib.set_scene(core.scene().scene);  // the next room's materials
    }
    ov.label = core.label();
    ov.show_hand = p.show_hand && w.input;
    if (Status s = draw(w, o.desc, st, ov, std::exchange(w.events.screenshot, false)); !s) return s;
    if (st.time_s - last_flush >= 1.0) {  // the device stream, about once a second
      last_flush = st.time_s;
      if (Status s = recorder.flush(); !s) return s;
    }
  }
}

// `text` over the start; the clock waits for Space or Enter. False: the participant quit.
Result<bool> wait_for_start(const maze::SessionOptions& o, Window& w, const std::string& text) {
  Overlay ov;
  ov.instructions = text;
  const HapticState still;  // no sample: the scene's own camera and probe at the start
  for (;;) {
    glfwWaitEventsTimeout(0.05);  // nothing moves: redraw at 20 Hz, not as fast as it can
    if (w.events.quit || glfwWindowShouldClose(w.ctx->window())) return false;
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
  if (go && go.value() && w.input && w.input->name() == "mouse") w.input->toggle_capture();
  return go;
}

// The session's options for its practice pass: the same maze and condition, another route, one
// pass, its own log and device stream in DIR/practice/.
Result<maze::SessionOptions> practice_options(const maze::SessionOptions& o) {
  maze::SessionOptions po = o;
  const std::filesystem::path dir = std::filesystem::path(o.log_path).parent_path() / "practice";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return make_error(dir.string() + ": cannot create the practice folder: " + ec.message());
  po.log_path = (dir / "session.jsonl").string();
  po.record_path = (dir / "device.log").string();
  po.info.seed = o.info.seed ^ kPracticeSeedMix;
  po.route = maze::draw_route(po.info.seed);
  po.desc.max_passes = po.info.max_passes = 1;
  po.resume.reset();
  po.haptics.start_time_s = 0.0;
  return po;
}

// The practice pass (docs/maze.md, "Practice"), then its closing screen; the window's renderer
// is the scored session's again after it. False: the participant quit during it.
Result<bool> run_practice(const maze::SessionOptions& o, const MazeWindowParams& p, Window& w,
                          const cli::LiveLoopArgs& live_args, const maze::SessionCore& scored) {
  auto po = practice_options(o);
  if (!po) return po.error();
  auto opened = maze::SessionCore::open(po.value());
  if (!opened) return opened.error();
  maze::SessionCore& core = *opened.value();
  if (Status s = use_scene(w, core.scene().scene); !s) return s.error();
  SteadyClock clock;
  HapticLoop loop(*w.device, clock, po->haptics, core.haptic().get());
  std::unique_ptr<vibration::LiveVibration> vib = cli::open_live_vibration(live_args, core.scene().scene, loop);
  SampleRecorder recorder(po->record_path);
  loop.set_recorder(&recorder);
  TickFeed ticks(kTrackFeedTicks);
  loop.add_tick_feed(&ticks);
  std::string reason = "quit";
  loop.start();
  vib->start();
  Status looped = window_loop(po.value(), p, core, w, loop, ticks, recorder, reason, *vib, true);
  loop.stop();
  vib->close();
  const double end = reason == "logged" ? core.end_time_s() : loop.state().read().time_s;
  auto result = core.finish(end, reason == "logged" ? "quit" : reason);
  if (Status s = recorder.close(); !s) return s.error();
  if (!looped) return looped.error();
  if (!result) return result.error();
  if (reason == "quit") return false;
  if (Status s = use_scene(w, scored.scene().scene); !s) return s.error();
  w.input->place(on_plane(floor_plane(*w.renderer), w.renderer->scene().probe.position));
  Result<bool> go = wait_for_start(o, w, kPracticeOver);
  w.input->rebase();  // the mouse moved while the screen waited: a new relative origin
  return go;
}

}  // namespace

int run_maze_window(const cli::Command& cmd, const maze::SessionOptions& o, const std::string& device,
                    const cli::LiveLoopArgs& live_args, const MazeWindowParams& params) {
  auto live = cli::apply_live_loop(live_args);  // before the context and the haptic thread
  if (!live) return cmd.usage_error(live.error());
  auto opened = maze::SessionCore::open(o);
  if (!opened) return cmd.fail(opened.error());
  maze::SessionCore& core = *opened.value();
  Window w;
  if (Status s = open_window(o, device, core, w); !s) return cmd.fail(s.error());
  SteadyClock clock;
  std::unique_ptr<vibration::LiveVibration> vib;  // before the loop: it feeds it ticks
  HapticLoop loop(*w.device, clock, o.haptics, core.haptic().get());
  vib = cli::open_live_vibration(live_args, core.scene().scene, loop);
  SampleRecorder recorder(o.record_path);
  loop.set_recorder(&recorder);
  TickFeed track_ticks(kTrackFeedTicks);  // the tracker's ticks, drained by each frame
  loop.add_tick_feed(&track_ticks);
  std::string reason = "quit";
  Status looped = ok_status();
  {
    ImGuiScope imgui(w.ctx->window());
    // A participant's session starts from the instructions; a log device played in the window
    // has no one to read them.
    auto go = w.input ? show_instructions(o, w) : Result<bool>(true);
    if (go && go.value() && w.input && params.practice) go = run_practice(o, params, w, live_args, core);
    if (!go) looped = go.error();
    if (go && go.value()) {
      if (w.input) w.input->poll(o.haptics.start_time_s, pointer_view(*w.renderer, floor_plane(*w.renderer)));
      loop.start();
      vib->start();
      looped = window_loop(o, params, core, w, loop, track_ticks, recorder, reason, *vib);
    }
  }
  loop.stop();
  vib->close();
  // The session's end is logged at the time it ended: at the criterion (or max_passes) that is
  // the tick the tracker saw it, not when its score screen closed.
  const double end_time = reason == "logged" ? core.end_time_s() : std::max(o.haptics.start_time_s, loop.state().read().time_s);
  auto result = core.finish(end_time, reason == "logged" ? "quit" : reason);
  if (Status s = recorder.close(); !s) return cmd.fail(s.error());
  if (!looped) return cmd.fail(looped.error());
  if (const std::uint64_t lost = track_ticks.dropped(); lost > 0)
    std::fprintf(stderr, "warning: the maze's tracker missed %llu ticks: frames more than %.0f s apart\n",
                 static_cast<unsigned long long>(lost), static_cast<double>(kTrackFeedTicks) / o.haptics.rate_hz);
  if (!result) return cmd.fail(result.error());
  std::printf("maze: %s after %d pass%s (%s), %.1f s; log %s\n", o.info.participant.c_str(), result->passes,
              result->passes == 1 ? "" : "es", result->reason.c_str(), result->time_s, o.log_path.c_str());
  return cli::kExitOk;
}

}  // namespace ps
