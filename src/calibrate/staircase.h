// A 1-up-2-down adaptive staircase for two-alternative forced choice (Levitt 1971): two correct
// answers in a row make the difference harder (delta / factor), one wrong answer makes it easier
// (delta * factor). With equal steps up and down in log units it settles where a step down is as
// likely as a step up, P(correct)^2 = 1/2: the 70.7 %-correct point of the psychometric function,
// the just-noticeable difference (JND) `calibrate` reports (docs/calibrate.md).
#pragma once

#include <vector>

namespace ps::calibrate {

struct StaircaseParams {
  double start_delta = 1.0;   // the first trial's difference (stimulus units: mm or mm/s)
  double min_delta = 1e-6;    // the difference never goes below this ...
  double max_delta = 1e9;     // ... nor above this (an undiscriminable point sits at the cap)
  double coarse_factor = 2.0; // step factor until `coarse_reversals` reversals (finds the range fast)
  double fine_factor = 1.25;  // step factor after them (the reversals that are averaged)
  int coarse_reversals = 4;
  int reversals = 16;         // the staircase ends after this many reversals ...
  int max_trials = 400;       // ... or this many trials
  int average_last = 12;      // threshold: geometric mean of the deltas at the last N reversals
};

class Staircase {
 public:
  explicit Staircase(const StaircaseParams& params);

  double delta() const { return delta_; }  // the difference to show next
  // Records the answer to a trial shown at delta(); returns true when it was a reversal (the
  // direction of the steps changed), and moves delta().
  bool record(bool correct);
  bool done() const;
  // The geometric mean of the deltas at the last average_last reversals (all of them when there
  // are fewer, the current delta before any): the 70.7 %-correct difference's estimate.
  double threshold() const;
  int trials() const { return trials_; }
  int reversal_count() const { return static_cast<int>(reversal_deltas_.size()); }

 private:
  void step(int direction);  // -1: harder (smaller delta), +1: easier

  StaircaseParams params_;
  double delta_;
  int trials_ = 0;
  int correct_run_ = 0;
  int direction_ = 0;  // the last step's direction; 0 before the first
  std::vector<double> reversal_deltas_;
};

}  // namespace ps::calibrate
