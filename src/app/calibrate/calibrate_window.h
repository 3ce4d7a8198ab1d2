// `calibrate`'s window: the two stimuli of each trial side by side, the answer from the arrow
// keys (docs/calibrate.md). The staircases are calibrate::Calibration's, the same as headless.
#pragma once

#include <functional>
#include <string>

#include "calibrate/calibration.h"
#include "core/result.h"
#include "scene/scene.h"

namespace ps {

struct CalibrateWindowParams {
  const Scene& scene;        // its light is used; the stimuli get their own plane, probe and camera
  const Material& material;  // the material whose curve is shown
  std::string log_path;      // the trial log, rewritten atomically after every answer
  // Set: answers each trial once its stimuli have been drawn (true: left), instead of the keys
  // (`--observer simulated --window`: the scripted observer, shown).
  std::function<bool(const calibrate::Trial&)> script;
  // Asked every frame: true ends the trials as Esc does (the CLI's SIGTERM/SIGINT/SIGHUP,
  // app/cli/stop_signal.h). Empty: never.
  std::function<bool()> stop;
};

// Runs until the calibration is done, the window is closed (Esc, Q) or p.stop says so: an early
// stop is not an error, cal.done() tells.
Status run_calibrate_window(calibrate::Calibration& cal, const CalibrateWindowParams& p);

}  // namespace ps
