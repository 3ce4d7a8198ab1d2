// `study summarize` (docs/study.md, "Summarizing"): every participant's trial log checked
// (study_log.h: a changed line is refused naming file:line), then fitted: a threshold task by
// maximum likelihood per condition (threshold, slope, bootstrap and posterior 95 % intervals,
// Weber fraction), an identification task as a confusion matrix per condition (percent correct,
// information transfer, 2^IT), a targeting task by ISO 9241-9 per condition (fitts.h: effective width,
// throughput, the Fitts regressions). Practice trials are left out. The tables go to CSV, the summary to
// summary.md, the psychometric curves to a gnuplot plot.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "study/fit.h"
#include "study/posterior.h"
#include "study/fitts.h"
#include "study/identification.h"
#include "study/pointing_sim.h"
#include "study/study_log.h"

namespace ps::study {

struct ConditionResult {
  std::string condition;
  int trials = 0;
  // threshold
  std::vector<LevelCounts> data;
  PsychometricFit fit;
  BootstrapResult boot;
  PosteriorResult posterior;  // the credible intervals (posterior.h): these hold the truth at 95 %
  double weber = 0.0;
  Interval weber_ci;
  Interval weber_cred;  // the credible threshold interval over the reference
  // identification
  std::vector<std::vector<int>> confusion;
  IdentificationStats ident;
  // targeting: the movements and their ISO 9241-9 reduction (fitts.h)
  std::vector<PointingTrial> pointing;
  FittsParticipant fitts;
};

struct ParticipantResult {
  std::string participant, log;
  std::string experiment, task;
  Shape shape = Shape::kWeibull;
  double criterion = 0.75, reference = 0.0;
  double level_min = 0.0, level_max = 0.0;  // the levels the procedure could show
  std::vector<std::string> materials;
  // The simulated participant's own function (session_start's "observer"); none for a person.
  std::optional<PsychometricParams> truth;
  Shape truth_shape = Shape::kWeibull;
  std::optional<PointerParams> pointer_truth;  // targeting: the simulated participant's law
  bool complete = false;
  std::string torn;  // a cut-off last line's warning
  std::vector<ConditionResult> conditions;  // in the experiment's order
};

struct SummaryOptions {
  int resamples = 1000;
  std::uint64_t seed = 1;
};

// The trials.jsonl files under each argument: a log itself, a participant's folder, or a study's
// folder (each subfolder's log, in name order).
Result<std::vector<std::string>> find_trial_logs(const std::vector<std::string>& args);
// One participant's log, read and checked (read_trial_log), fitted per condition.
Result<ParticipantResult> summarize_participant(const std::string& log_path, const SummaryOptions& o);
// The same from a log already read and checked; `log_path` names it in errors and the result.
Result<ParticipantResult> summarize_participant(const TrialLog& log, const std::string& log_path, const SummaryOptions& o);

// participants.csv, groups.csv, summary.md and (gnuplot found) psychometric.png or
// confusion.png in `dir` (created); `notes` get the plots skipped and why.
Status write_study_summary(const std::string& dir, const std::vector<ParticipantResult>& people,
                           std::vector<std::string>& notes);

}  // namespace ps::study
