// `study run` with a person answering (docs/study.md, "In the window"): the experiment's stimuli in
// a window, the answers from the keyboard. A StudyWindow is the study::Responder that
// study::run_participant asks for each trial's answer, so the trial log, the procedures, resume
// and the summaries are the headless run's own.
//
// What a trial shows: each stimulus is the experiment's scene with that stimulus's overrides,
// drawn under a scripted stroke of the probe: the probe glides for kStrokeS at the scene's own
// probe velocity through the scene's probe position (held still where the velocity is 0, as in
// the distance experiment). Every participant sees the same strokes, so what differs between
// participants is theirs, not their hands'. Threshold: interval 1, a blank, interval 2, then the
// question; identification: the one stimulus stroked back and forth until it is named.
//
// Targeting: the person touches the ring's targets with the probe, moved by the mouse
// (app/study/targeting_screen.h).
//
// The window's title says where the run stands ("pseudoshadow study: trial 5 of 64, answer" while
// an answer is taken), which a test driving it with X events waits on.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "core/result.h"
#include "devices/device_spec.h"
#include "study/experiment.h"
#include "study/study_run.h"

namespace ps {

class LiveWindow;
class Renderer;
class TargetingScreen;

struct StudyWindowParams {
  // Asked every frame: true ends the run as Esc does (the CLI's SIGTERM/SIGINT/SIGHUP or a lost
  // display, app/cli/stop_signal.h). Empty: never.
  std::function<bool()> stop;
  // The targeting task's device: the mouse (the default) or a gamepad (app/study/targeting_screen.h).
  DeviceSpec device;
};

// The seconds of one stroke (one interval), and of the blank between intervals and trials.
inline constexpr double kStrokeS = 1.2;
inline constexpr double kStudyBlankS = 0.4;

// Where a stimulus's probe is `t_s` seconds into its stroke: through `centre` at `velocity`, the
// stroke's middle at kStrokeS / 2; `back_and_forth`: strokes one after another, each the way
// back of the last (identification's stimulus stays on screen until it is named).
struct StrokePoint {
  glm::dvec3 position_mm{0.0}, velocity_mm_s{0.0};
};
StrokePoint stroke_at(const glm::dvec3& centre, const glm::dvec3& velocity, double t_s, bool back_and_forth);

// The answer a typed key gives: the index of `keys` it names, or none. A key is a character
// (letters in either case) or one of the names "left", "right", "up", "down", "space".
std::optional<int> key_choice(const std::vector<std::string>& keys, unsigned int codepoint);
std::optional<int> named_key_choice(const std::vector<std::string>& keys, const char* name);

class StudyWindow final : public study::Responder {
 public:
  // The window, sized to the scene's image. Errors: no display, a scene that does not load.
  static Result<std::unique_ptr<StudyWindow>> open(const study::Experiment& e, StudyWindowParams p);
  ~StudyWindow() override;
  StudyWindow(const StudyWindow&) = delete;
  StudyWindow& operator=(const StudyWindow&) = delete;

  Result<std::optional<int>> answer(const study::TrialStimulus& t) override;
  // The targeting task (app/study/targeting_screen.h).
  Result<std::optional<study::Pointed>> point(const study::TrialStimulus& t) override;
  nlohmann::json describe() const override;

  // Why the last answer() gave none: the person pressed Esc (or closed the window) rather than
  // p.stop asking.
  bool stopped_by_person() const { return by_person_; }

 private:
  struct Keys;
  StudyWindow(const study::Experiment& e, StudyWindowParams p, std::unique_ptr<LiveWindow> win);
  // The instructions before the first trial shown, the "practice over" screen before the first
  // that counts; false: stopped.
  bool begin(const study::TrialStimulus& t);
  // A screen of text until Space or Enter; false: stopped.
  bool wait_for_space(const std::string& title, const std::string& text);
  // Stimulus `which` of a trial, drawn by a renderer of its own. A threshold task's reference is
  // the same in every trial of a condition: its renderer is kept (a software renderer takes about
  // 0.9 s to make one), the comparison's is made afresh.
  Result<Renderer*> stimulus(const study::TrialStimulus& t, int which);
  bool stopping();

  const study::Experiment& e_;
  StudyWindowParams p_;
  std::unique_ptr<LiveWindow> win_;
  std::unique_ptr<Keys> keys_;
  std::map<int, std::unique_ptr<Renderer>> references_;  // by condition
  std::unique_ptr<Renderer> fresh_[2];                   // this trial's other stimuli
  std::unique_ptr<TargetingScreen> targeting_;           // the targeting task's (after win_: it uses it)
  bool started_ = false, by_person_ = false;
};

}  // namespace ps
