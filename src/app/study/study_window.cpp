#include "app/study/study_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cctype>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "app/study/targeting_screen.h"
#include "app/window/live_window.h"
#include "haptics/live_heap.h"
#include "render/renderer.h"
#include "scene/scene_io.h"

namespace ps {

StrokePoint stroke_at(const glm::dvec3& centre, const glm::dvec3& velocity, double t_s, bool back_and_forth) {
  double s = t_s;  // seconds into the stroke under way
  double sign = 1.0;
  if (back_and_forth) {
    const double n = std::floor(t_s / kStrokeS);
    s = t_s - n * kStrokeS;
    if (std::fmod(n, 2.0) != 0.0) sign = -1.0;  // every other stroke runs back
  }
  s = std::min(s, kStrokeS);
  // Forward: from centre - v T/2 to centre + v T/2; back: the same path the other way.
  const double along = sign * (s - 0.5 * kStrokeS);
  return {centre + velocity * along, velocity * sign};
}

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A code point as UTF-8.
std::string utf8(unsigned int cp) {
  std::string s;
  if (cp < 0x80) {
    s += static_cast<char>(cp);
  } else if (cp < 0x800) {
    s += static_cast<char>(0xC0 | (cp >> 6));
    s += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    s += static_cast<char>(0xE0 | (cp >> 12));
    s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    s += static_cast<char>(0xF0 | (cp >> 18));
    s += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (cp & 0x3F));
  }
  return s;
}

}  // namespace

std::optional<int> key_choice(const std::vector<std::string>& keys, unsigned int codepoint) {
  const std::string typed = lower(utf8(codepoint));
  if (typed == " ") return named_key_choice(keys, "space");
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (lower(keys[i]) == typed) return static_cast<int>(i);
  return std::nullopt;
}

std::optional<int> named_key_choice(const std::vector<std::string>& keys, const char* name) {
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (lower(keys[i]) == name) return static_cast<int>(i);
  return std::nullopt;
}

// The presses since they were last taken: a frame takes tens of milliseconds on llvmpipe, longer
// than a quick key press, so polling the key state would miss answers.
struct StudyWindow::Keys final : WindowListener {
  const std::vector<std::string>& names;
  std::vector<int> choices;  // indexes into names, in the order typed
  bool quit = false;         // Esc
  bool go = false;           // Space or Enter (the text screens)
  HeightInput height;        // the targeting task's probe height (PageUp/PageDown, Up/Down, wheel)
  explicit Keys(const std::vector<std::string>& n) : names(n) {}
  void clear() {
    choices.clear();
    go = false;
  }
  void on_key(int key, int action, int /*mods*/) override {
    if (action != GLFW_PRESS) return;
    if (key == GLFW_KEY_ESCAPE) quit = true;
    if (key == GLFW_KEY_SPACE || key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER) go = true;
    if (key == GLFW_KEY_PAGE_UP || key == GLFW_KEY_UP) ++height.steps;
    if (key == GLFW_KEY_PAGE_DOWN || key == GLFW_KEY_DOWN) --height.steps;
    const char* name = key == GLFW_KEY_LEFT    ? "left"
                       : key == GLFW_KEY_RIGHT ? "right"
                       : key == GLFW_KEY_UP    ? "up"
                       : key == GLFW_KEY_DOWN  ? "down"
                                               : nullptr;
    if (name)
      if (std::optional<int> c = named_key_choice(names, name)) choices.push_back(*c);
  }
  void on_scroll(double dy, bool /*shift*/) override { height.scroll += dy; }
  void on_char(unsigned int codepoint) override {
    if (std::optional<int> c = key_choice(names, codepoint)) choices.push_back(*c);
  }
};

namespace {

// One frame: `r`'s last frame over the whole window (none: black) and the text above it.
void present(LiveWindow& win, const Renderer* r, const std::string& text) {
  win.begin_frame_on_black();
  if (r) {
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    win.draw_frame_image(*r, UiRect{0.f, 0.f, d.x, d.y});
  }
  if (!text.empty()) draw_text_box("study", ImVec2(10, 10), text, 1.0f);
  win.end_frame();
}

// "practice trial 2 of 4" / "trial 7 of 124".
std::string progress(const study::Experiment& e, const study::TrialStimulus& t) {
  if (t.practice) return "practice trial " + std::to_string(t.trial) + " of " + std::to_string(e.practice);
  return "trial " + std::to_string(t.trial - e.practice) + " of " + std::to_string(t.total - e.practice);
}

// The keys and what each answers: "1 = first, 2 = second" / "1 = fine, 2 = coarse, ..."; the
// targeting task's controls.
std::string key_help(const study::Experiment& e) {
  if (e.task == study::Task::kTargeting)
    return "the mouse (a gamepad's left stick) moves the probe; the wheel, PageUp/PageDown or Up/Down (its triggers) "
           "lift and lower it";
  std::string s;
  for (std::size_t i = 0; i < e.response_keys.size(); ++i) {
    if (i) s += ", ";
    const std::string what = e.task == study::Task::kThreshold ? (i == 0 ? "first" : "second") : e.materials[i].name;
    s += e.response_keys[i] + " = " + what;
  }
  return s;
}

}  // namespace

StudyWindow::StudyWindow(const study::Experiment& e, StudyWindowParams p, std::unique_ptr<LiveWindow> win)
    : e_(e), p_(std::move(p)), win_(std::move(win)), keys_(std::make_unique<Keys>(e.response_keys)) {
  win_->listen(*keys_);
}

StudyWindow::~StudyWindow() = default;

Result<std::unique_ptr<StudyWindow>> StudyWindow::open(const study::Experiment& e, StudyWindowParams p) {
  // As calibrate's window: a session runs for tens of minutes. The threshold and identification
  // tasks have no haptic thread (the strokes are scripted), so llvmpipe keeps every core for the
  // stimulus; the targeting task's screen runs one (targeting_screen.h).
  keep_large_blocks_mapped();
  const Result<Scene> scene = load_scene(e.scene, e.task == study::Task::kThreshold ? study::threshold_overrides(e, e.conditions[0], e.threshold.reference)
                                                  : e.task == study::Task::kTargeting ? study::condition_overrides(e, e.conditions[0])
                                                                                      : study::material_overrides(e, e.conditions[0], e.materials[0]));
  if (!scene) return scene.error();
  auto win = LiveWindow::open({scene->render.width, scene->render.height, "pseudoshadow study: " + e.name});
  if (!win) return win.error();
  std::unique_ptr<StudyWindow> w(new StudyWindow(e, std::move(p), std::move(win.value())));
  if (e.task == study::Task::kTargeting) {  // the probe moved by the mouse, a haptic loop (targeting_screen.h)
    auto t = TargetingScreen::open(e, *w->win_, w->keys_->height, w->p_.device);
    if (!t) return t.error();
    w->targeting_ = std::move(t.value());
  }
  return w;
}

nlohmann::json StudyWindow::describe() const { return {{"kind", "person"}, {"answered_in", "window"}}; }

bool StudyWindow::stopping() {
  if (keys_->quit || win_->should_close()) {
    by_person_ = true;
    return true;
  }
  return p_.stop && p_.stop();
}

bool StudyWindow::wait_for_space(const std::string& title, const std::string& text) {
  win_->set_title("pseudoshadow study: " + title);
  keys_->clear();
  while (!keys_->go) {
    win_->poll_events();
    if (stopping()) return false;
    present(*win_, nullptr, text);
    win_->wait_events(0.05);
  }
  keys_->clear();
  return true;
}

// Stimulus `which` of a trial: threshold, interval 1 or 2 (the comparison where t.interval says);
// identification, the material shown.
Result<Renderer*> StudyWindow::stimulus(const study::TrialStimulus& t, int which) {
  const study::Variant& c = e_.conditions[static_cast<std::size_t>(t.condition)];
  const bool reference = e_.task == study::Task::kThreshold && which != t.interval;
  if (reference)
    if (const auto it = references_.find(t.condition); it != references_.end()) return it->second.get();
  const std::vector<std::string> overrides =
      e_.task == study::Task::kThreshold
          ? study::threshold_overrides(e_, c, reference ? t.reference : t.comparison)
          : study::material_overrides(e_, c, e_.materials[static_cast<std::size_t>(t.shown)]);
  Result<Scene> scene = load_scene(e_.scene, overrides);
  if (!scene) return scene.error();
  auto r = Renderer::create(scene.value(), {});
  if (!r) return r.error();
  std::unique_ptr<Renderer>& slot = reference ? references_[t.condition] : fresh_[which - 1];
  slot = std::move(r.value());
  return slot.get();
}

bool StudyWindow::begin(const study::TrialStimulus& t) {
  const std::string esc = "Esc stops; every answer given is kept and `study resume` goes on.";
  if (!started_) {
    const std::string where = t.trial > 1 ? "Going on from " + progress(e_, t) + ".\n\n" : "";
    if (!wait_for_space("instructions", e_.instructions + "\n\n" + where + "Keys: " + key_help(e_) +
                                            "\nPress Space to begin. " + esc))
      return false;
    started_ = true;
  }
  return !(e_.practice > 0 && t.trial == e_.practice + 1 &&
           !wait_for_space("practice over", "The practice is over; from now on every answer counts.\nPress Space to go on."));
}

Result<std::optional<study::Pointed>> StudyWindow::point(const study::TrialStimulus& t) {
  by_person_ = false;
  if (!targeting_) return make_error("study: " + e_.path + " is not a targeting task: its trials are answered, not pointed");
  if (!begin(t)) return std::optional<study::Pointed>();
  return targeting_->point(t, progress(e_, t) + "\n", "pseudoshadow study: " + progress(e_, t), [this] { return stopping(); });
}

Result<std::optional<int>> StudyWindow::answer(const study::TrialStimulus& t) {
  by_person_ = false;
  if (targeting_) return make_error("study: " + e_.path + " is a targeting task: its trials are pointed, not answered");
  if (!begin(t)) return std::optional<int>();
  const std::string head = progress(e_, t) + "    Keys: " + key_help(e_) + "\n";
  win_->set_title("pseudoshadow study: " + progress(e_, t));
  // A blank while the stimuli are prepared (a software renderer takes a moment for each): the
  // next trial is seen to be a new one.
  present(*win_, nullptr, head + "(preparing...)");
  const double blank_until = glfwGetTime() + kStudyBlankS;
  const bool pair = e_.task == study::Task::kThreshold;
  Renderer* shown[2] = {nullptr, nullptr};
  for (int i = 0; i < (pair ? 2 : 1); ++i) {
    auto r = stimulus(t, i + 1);
    if (!r) return r.error();
    shown[i] = r.value();
  }
  while (glfwGetTime() < blank_until) {
    win_->poll_events();
    if (stopping()) return std::optional<int>();
    present(*win_, nullptr, head);
    win_->wait_events(0.02);
  }
  // The timeline: threshold, interval 1, a blank, interval 2, then the question (answers are
  // taken from interval 2's start: both have been seen); identification, strokes until named.
  keys_->clear();
  const double start = glfwGetTime();
  const double second = kStrokeS + kStudyBlankS, end = second + kStrokeS;
  bool taking = false;
  for (;;) {
    win_->poll_events();
    if (stopping()) return std::optional<int>();
    const double now = glfwGetTime() - start;
    const bool take = !pair || now >= second;
    if (take && !taking) {
      taking = true;
      keys_->choices.clear();  // a press before both were seen answers nothing
      win_->set_title("pseudoshadow study: " + progress(e_, t) + ", answer");
    }
    if (taking && !keys_->choices.empty()) {
      const int c = keys_->choices.front();
      keys_->clear();
      return std::optional<int>(pair ? c + 1 : c);
    }
    if (!taking) keys_->choices.clear();
    Renderer* r = nullptr;
    double into = now;
    std::string text = head;
    if (!pair) {
      r = shown[0];
      text += "Name the texture.";
    } else if (now < kStrokeS) {
      r = shown[0];
      text += "First";
    } else if (now >= second && now < end) {
      r = shown[1];
      into = now - second;
      text += "Second";
    } else if (now >= end) {
      text += "Which one? " + key_help(e_);
    }
    if (r) {
      const Probe& probe = r->scene().probe;
      const StrokePoint sp = stroke_at(probe.position, probe.velocity, into, !pair);
      FrameInput in;
      in.probe = ProbeMotion{sp.position_mm, sp.velocity_mm_s};
      if (auto f = r->render(in); !f) return f.error();
    }
    present(*win_, r, text);
    if (!r) win_->wait_events(0.02);
  }
}

}  // namespace ps
