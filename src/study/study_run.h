// `study run --simulate` (docs/study.md, "Running"): one participant through an experiment, each
// trial answered by a simulated participant and appended to DIR/PARTICIPANT/trials.jsonl
// (study_log.h) before the next is chosen. Run again on the same DIR, it resumes after the last
// whole trial: the procedures are rebuilt by replaying the logged answers, and every trial's
// random draws (which interval holds the comparison, which material is shown, the simulated
// answer) come from the participant's seed and the trial's number alone, so a resumed run writes
// exactly the trials an unbroken one would have.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/result.h"
#include "study/experiment.h"
#include "study/pointing_sim.h"
#include "study/psychometric.h"

namespace ps::study {

// The simulated participant: a psychometric function for threshold tasks (the level is the
// difference shown), a probability of naming the shown material for identification (a wrong
// answer names one of the others, each alike), a Fitts law and end-point scatter for targeting.
struct ObserverSpec {
  Shape shape = Shape::kWeibull;
  PsychometricParams truth{0.1, 3.0, 0.5, 0.02};
  double p_correct = 0.6;
  PointerParams pointer;
  std::uint64_t seed = 0;  // 0: the participant's own seed
};

// What one trial shows, chosen (from the procedure and the seeds) before anyone answers it.
struct TrialStimulus {
  int trial = 0;           // from 1
  int total = 0;           // trials in the experiment, practice included
  bool practice = false;
  int block = 0;           // from 1 (0: practice)
  int condition = 0;       // index into Experiment::conditions
  // threshold: the difference shown, the two values and where the comparison is (interval 1 or 2)
  double level = 0.0, reference = 0.0, comparison = 0.0;
  int interval = 0;
  int shown = -1;          // identification: the material shown (index into Experiment::materials)
  // targeting: one movement of a sequence across a ring (study/targeting.h), from target `from`
  // (centre `start`) to target `to` (centre `target`); `step` from 0 (0: the sequence's first
  // movement), `sequence` from 1 in its block and condition.
  int sequence = 0, step = 0, from = 0, to = 0;
  double ring_diameter = 0.0, distance = 0.0, width = 0.0;  // D, the chord moved, W (mm)
  Point3 start, target;
};

// A targeting movement as made: where it began (the last selection), where the selection was
// made (on the ring's plane) and the time between the two selections.
struct Pointed {
  Point3 began, end;
  double movement_time_s = 0.0;
};

// Who answers the trials: the simulated participant (RunSpec::observer) when none is given, or
// a person at the window (app/study/study_window.h).
class Responder {
 public:
  virtual ~Responder() = default;
  // The answer: threshold, the interval named (1 or 2); identification, the material named
  // (its index). None: the person stopped (Esc, a signal); the run ends there, every trial
  // answered before it kept, and `study resume` goes on from it.
  virtual Result<std::optional<int>> answer(const TrialStimulus& t) = 0;
  // A targeting trial's movement, as answer()'s none: the person stopped.
  virtual Result<std::optional<Pointed>> point(const TrialStimulus& t) = 0;
  // Who answered, for the log's "observer" member: {"kind": "person", ...}.
  virtual nlohmann::json describe() const = 0;
};

struct RunSpec {
  std::string participant;  // P01, ...
  std::string out_dir;      // the study's directory: the log goes to out_dir/participant/trials.jsonl
  ObserverSpec observer;    // the simulated participant, when `responder` is null
  Responder* responder = nullptr;
  int stop_after = 0;       // > 0: stop after this many new trials (a break; run again to go on)
  bool resume_only = false; // `study resume`: an error when there is no log to go on from
};

struct RunReport {
  std::string log_path;
  int total = 0;         // trials in the experiment, practice included
  int done_before = 0;   // whole trials already in the log
  int written = 0;       // trials this run added
  bool complete = false; // session_end written (now or before)
  bool stopped = false;  // the responder stopped before the end (Esc, a signal)
  std::string torn;      // the warning for a cut-off last line, when there was one
};

Result<RunReport> run_participant(const Experiment& e, const RunSpec& spec);

// A 64-bit mix of a seed and a trial number (splitmix64's finaliser): each trial's own draws.
std::uint64_t trial_seed(std::uint64_t seed, std::uint64_t trial, std::uint64_t stream);

}  // namespace ps::study
