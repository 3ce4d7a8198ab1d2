#include "app/calibrate/calibrate_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "app/window/live_window.h"
#include "core/file_io.h"
#include "haptics/live_heap.h"
#include "render/renderer.h"

namespace ps {

namespace {

constexpr int kSide = 512;              // each stimulus, pixels
constexpr double kProbeRadiusMm = 8.0;  // the probe: a sphere as in the thesis's figures
constexpr double kSpeedGapMm = 1.0;     // speed trials: the probe this far above (texture shown)
constexpr double kWrapMm = 1000.0;      // speed trials: the probe (and the view with it) starts over after this
constexpr double kPlaneMm = 4000.0;     // the plane: wide enough for kWrapMm either side
// Between trials: 0.3 s of black, so two identical trials in a row are seen as two (and the eye
// leaves the last pair before the next).
constexpr double kBlankS = 0.3;

// A plane of `m` seen from above (orthographic, 40 mm across) under a sphere probe.
Scene stimulus_scene(const Scene& from, const Material& m) {
  Scene s;
  s.path = from.path;
  s.light = from.light;
  s.camera.projection = Projection::kOrthographic;
  s.camera.position = {0.0, 0.0, 100.0};
  s.camera.target = {0.0, 0.0, 0.0};
  s.camera.up = {0.0, 1.0, 0.0};
  s.camera.ortho_height_mm = 40.0;
  s.render = from.render;
  s.render.width = s.render.height = kSide;
  s.materials.push_back(m);
  s.materials[0].resistance = 0.0;  // the probe stays where it is put
  Surface p;
  p.type = SurfaceType::kPlane;
  p.material = m.name;
  p.size_mm = {kPlaneMm, kPlaneMm};
  p.resolution = 4;
  s.surfaces.push_back(p);
  s.probe.shape = ProbeShape::kSphere;
  s.probe.radius_mm = kProbeRadiusMm;
  s.probe.position = {0.0, 0.0, kProbeRadiusMm + 5.0};
  return s;
}


// The arrow presses since the last frame, from the window's key events: a frame takes ~0.1 s on
// llvmpipe, longer than a quick key press, so polling the key state would miss answers.
struct Answers final : WindowListener {
  std::vector<bool> left;  // in the order pressed
  bool quit = false;       // Esc or Q
  void on_key(int key, int action, int /*mods*/) override {
    if (action != GLFW_PRESS) return;
    if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) quit = true;
    if (key == GLFW_KEY_LEFT || key == GLFW_KEY_RIGHT) left.push_back(key == GLFW_KEY_LEFT);
  }
};

// The two stimuli's renderers, left and right: each draws one side of the window.
struct Pair {
  std::unique_ptr<Renderer> left, right;
};

// The probe of one stimulus `t_s` seconds into the trial: over the plane at the distance, or
// gliding along +x at the speed with the view following it, so the shadow stays in the middle and
// the texture it reveals slides through it (the texture is what moves on screen).
FrameInput placed_probe(calibrate::CurveKind kind, double x, double t_s) {
  FrameInput in;
  if (kind == calibrate::CurveKind::kDistance) {
    in.probe = ProbeMotion{{0.0, 0.0, kProbeRadiusMm + x}, {0.0, 0.0, 0.0}};
    return in;
  }
  const double along = std::fmod(x * t_s, kWrapMm);
  in.probe = ProbeMotion{{along, 0.0, kProbeRadiusMm + kSpeedGapMm}, {x, 0.0, 0.0}};
  in.view = ViewPose{{along, 0.0, 0.0}};
  return in;
}

// One frame: the pair's last frames side by side, each straight from its renderer's colour
// target (none: a blank between trials, or the first frame while the stimuli are prepared),
// and the question and the progress above them.
void present(LiveWindow& win, const Pair* pair, const char* question, const std::string& progress) {
  win.begin_frame_on_black();
  if (pair) {
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    win.draw_frame_image(*pair->left, UiRect{0.f, 0.f, 0.5f * d.x, d.y});
    win.draw_frame_image(*pair->right, UiRect{0.5f * d.x, 0.f, d.x, d.y});
  }
  draw_text_box("question", ImVec2(10, 10),
                std::string(question) + "  Left / Right arrow.  Esc stops (every answer is kept).\n" + progress, 1.0f);
  win.end_frame();
}

// "trial 37 of about 230; staircases done: 1 of 4".
std::string progress_text(const calibrate::Calibration& cal) {
  const std::vector<bool> f = cal.finished();
  char buf[128];
  std::snprintf(buf, sizeof buf, "trial %zu of about %d; staircases done: %zu of %zu", cal.trials().size() + 1,
                cal.expected_trials(), static_cast<std::size_t>(std::count(f.begin(), f.end(), true)), f.size());
  return buf;
}

const char* question_for(calibrate::CurveKind kind) {
  return kind == calibrate::CurveKind::kDistance ? "Which pseudo-shadow is closer?" : "Which texture is moving faster?";
}

// The trial on screen, `now` seconds after it first showed: both stimuli drawn and presented.
Status show_trial(LiveWindow& win, const calibrate::Calibration& cal, const Pair& pair, double now,
                  const char* question) {
  const calibrate::CurveKind kind = cal.spec().kind;
  const calibrate::Trial& t = cal.current();
  const double left = t.comparison_left ? t.comparison : t.reference;
  const double right = t.comparison_left ? t.reference : t.comparison;
  if (auto f = pair.left->render(placed_probe(kind, left, now)); !f) return f.error();
  if (auto f = pair.right->render(placed_probe(kind, right, now)); !f) return f.error();
  present(win, &pair, question, progress_text(cal));
  return ok_status();
}

// The trials, one after another with a blank between, until the staircases finish or the
// person quits; each answer is logged at once.
Status run_trials(LiveWindow& win, calibrate::Calibration& cal, const CalibrateWindowParams& p, const Pair& pair) {
  Answers answers;
  win.listen(answers);
  const char* question = question_for(cal.spec().kind);
  // The first frame says what is coming while the first stimuli are prepared (the first tile
  // bakes: seconds on a software renderer).
  present(win, nullptr, question, progress_text(cal) + "  (preparing the stimuli...)");
  double trial_start = glfwGetTime(), blank_until = 0.0;
  std::size_t shown = static_cast<std::size_t>(-1);  // the last trial drawn (index), none yet
  while (!cal.done() && !win.should_close()) {
    win.poll_events();
    if (answers.quit || (p.stop && p.stop())) break;
    if (glfwGetTime() < blank_until) {  // a blank between trials: the next one is seen to be new
      answers.left.clear();             // a press now would answer a trial not yet shown
      present(win, nullptr, question, progress_text(cal));
      trial_start = glfwGetTime();
      continue;
    }
    // Each press answers the trial on screen when it was pressed (the first press; presses that
    // came in the same frame after it would answer a trial never seen, so they are dropped). A
    // script answers a trial after its first frame.
    if (shown != cal.trials().size()) answers.left.clear();  // nothing on screen yet to answer
    if (p.script && shown == cal.trials().size()) answers.left.assign(1, p.script(cal.current()));
    if (!answers.left.empty()) {
      cal.answer(answers.left.front());
      answers.left.clear();
      if (Status st = write_file_atomic(p.log_path, calibrate::format_trial_log(cal)); !st) return st;
      if (cal.done()) break;
      blank_until = glfwGetTime() + kBlankS;
      continue;
    }
    if (Status st = show_trial(win, cal, pair, glfwGetTime() - trial_start, question); !st) return st;
    shown = cal.trials().size();
  }
  return ok_status();
}

}  // namespace

Status run_calibrate_window(calibrate::Calibration& cal, const CalibrateWindowParams& p) {
  // Of the live commands' set-up (cli::apply_live_loop) only the heap's: a calibration runs for
  // tens of minutes. It has no haptic thread, so no CPU is left spare for one and llvmpipe keeps
  // every core for the two stimuli.
  keep_large_blocks_mapped();
  auto win = LiveWindow::open({2 * kSide, kSide, "pseudoshadow calibrate"});
  if (!win) return win.error();
  const Scene s = stimulus_scene(p.scene, p.material);
  Pair pair;
  for (std::unique_ptr<Renderer>* side : {&pair.left, &pair.right}) {
    auto r = Renderer::create(s, {});
    if (!r) return r.error();
    *side = std::move(r.value());
  }
  return run_trials(*win.value(), cal, p, pair);
}

}  // namespace ps
