// `study run`'s trials (study_run.h), inside the ps_study_run library: where trial k stands in the
// plan, the threshold procedures' tracks, the run's state, and each trial's stimulus, answer and
// log line (study_trials.cpp). study_run.cpp keeps the log: its start, resume and appends.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include <nlohmann/json.hpp>

#include "calibrate/staircase.h"
#include "core/result.h"
#include "study/experiment.h"
#include "study/psi.h"
#include "study/simulate.h"
#include "study/study_plan.h"
#include "study/study_run.h"

namespace ps::study {

using ojson = nlohmann::ordered_json;  // members in the order written

// Each trial's own random draws: trial_seed(seed, trial, stream).
enum Stream : std::uint64_t { kInterval = 1, kObserver = 2, kMaterials = 3, kCells = 4 };

// Where trial k (from 0) stands: practice first, then each block runs the participant's
// conditions in order, `trials` each.
struct Slot {
  bool practice = false;
  int block = 0;      // from 1 (0: practice)
  int condition = 0;  // index into Experiment::conditions
  int in_segment = 0; // the trial's place in its block and condition
};

inline Slot slot_of(const Experiment& e, const PlanEntry& plan, int k) {
  if (k < e.practice) return {true, 0, plan.order[0], k};
  const int m = k - e.practice, per_block = e.trials * static_cast<int>(plan.order.size());
  return {false, m / per_block + 1, plan.order[static_cast<std::size_t>((m % per_block) / e.trials)], m % e.trials};
}

inline int total_trials(const Experiment& e) { return e.practice + e.blocks * static_cast<int>(e.conditions.size()) * e.trials; }

// One condition's adaptive procedure: Psi or calibrate's staircase, over [level_min, level_max].
class Track {
 public:
  explicit Track(const ThresholdSpec& t) {
    if (t.method == Method::kPsi) {
      SimulationSpec s;  // only what simulation_grid reads: the shape, the guess, the levels, the lapse
      s.shape = t.shape;
      s.level_min = t.level_min;
      s.level_max = t.level_max;
      s.psi_lapse = t.lapse;
      psi_.emplace(simulation_grid(s, false));
    } else {
      calibrate::StaircaseParams p;
      p.start_delta = t.level_max / 2.0;  // an easy start, inside the range: the coarse steps find the threshold
      p.min_delta = t.level_min;
      p.max_delta = t.level_max;
      p.max_trials = 1 << 30;  // the experiment's trial count ends it
      stairs_.emplace(p);
    }
  }
  double next() { return psi_ ? psi_->next_level() : stairs_->delta(); }
  void update(double level, bool correct) {
    if (psi_) psi_->update(level, correct);
    else stairs_->record(correct);
  }

 private:
  std::optional<PsiMethod> psi_;
  std::optional<calibrate::Staircase> stairs_;
};

struct RunState {
  const Experiment& e;
  const RunSpec& spec;
  PlanEntry plan;
  std::vector<Track> tracks;  // one per condition
  std::uint64_t observer_seed = 0;
  std::optional<Point3> last_end;  // targeting: the last selection, where the next movement begins
};

// Trial k's line, answered (or, targeting, moved) by the responder, or by the simulated
// participant when there is none; a threshold trial's answer also moves its track and a
// targeting movement's end is where the next begins. None: the responder stopped.
Result<std::optional<ojson>> trial_of(RunState& s, int k);

}  // namespace ps::study
