// The targeting task in the study window (docs/study.md, "Targeting in the window"): a person
// touches the targets of ISO 9241-9's ring with the probe, under the condition's feedback.
//
// What the person does: the mouse moves the probe over the surface (the absolute mapping of
// `run`: the probe's shadow centre under the pointer, devices/glfw_input.h); the pointer itself
// is hidden over the window, so only the condition's feedback (the pseudo-shadow, the probe
// drawn, its cast shadow, or nothing) shows where the probe is. The wheel, PageUp/PageDown and
// the Up/Down arrows set its height as in `run` (start 1 mm, 0.5 mm a step). A gamepad instead:
// its left stick moves the probe, its triggers lift and lower it. A selection is the haptic tick
// on which the probe touches the surface (study::TouchSelector); the next one counts after a
// lift of more than 0.25 mm held for 60 ms. Each ring begins with a touch anywhere (the start
// target is shown green): that touch starts the clock and is where the first movement begins;
// each movement's time is from one selection's tick to the next one's.
//
// The haptic loop runs on its own thread at 1 kHz on the window's device, as in `run`: contact
// is the haptic scene's, not the picture's. A condition's renderer and haptic scene are kept
// while its trials last (the next condition's replace them).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "core/result.h"
#include "devices/device_spec.h"
#include "devices/pointer_map.h"
#include "haptics/clock.h"
#include "study/experiment.h"
#include "study/study_run.h"
#include "study/targeting.h"

namespace ps {

class LiveWindow;
class RecordedLoop;
class Renderer;
namespace world {
class HapticScene;
}

// The height input since the last frame: PageUp/Up +1, PageDown/Down -1 steps; wheel notches.
struct HeightInput {
  int steps = 0;
  double scroll = 0.0;
};

class TargetingScreen {
 public:
  // Opens the window's device (the mouse or a gamepad) and hides the pointer over the window.
  static Result<std::unique_ptr<TargetingScreen>> open(const study::Experiment& e, LiveWindow& win, HeightInput& height,
                                                       const DeviceSpec& device);
  ~TargetingScreen();
  TargetingScreen(const TargetingScreen&) = delete;
  TargetingScreen& operator=(const TargetingScreen&) = delete;

  // Trial t's movement, the frames drawn until it is made; `head` is the trial's line of text,
  // `title` the window's ("..., touch to start" / "..., touch the target" is added: a test driving
  // the window waits on it). None: `stopping` said so.
  Result<std::optional<study::Pointed>> point(const study::TrialStimulus& t, const std::string& head,
                                              const std::string& title, const std::function<bool()>& stopping);

 private:
  struct Selection {
    study::Point3 at;
    double time_s = 0.0;
  };
  TargetingScreen(const study::Experiment& e, LiveWindow& win, HeightInput& height);
  Status use_condition(int condition);  // its renderer, haptic scene and loop
  void poll_device();
  // The selections since the last frame: the first, with the ticks after it still fed to the selector.
  std::optional<Selection> take_selection();
  void draw(const study::TrialStimulus& t, const std::string& text);

  const study::Experiment& e_;
  LiveWindow& win_;
  HeightInput& height_;
  SteadyClock clock_;
  int condition_ = -1;
  std::unique_ptr<Renderer> renderer_;
  std::shared_ptr<const world::HapticScene> haptic_;
  std::unique_ptr<RecordedLoop> loop_;  // after the scene it shares
  PlaneAxes axes_;
  study::TouchSelector selector_;
  std::optional<Selection> last_;  // the last selection of this ring: where the next movement begins
  std::uint64_t frame_ = 0;
};

}  // namespace ps
