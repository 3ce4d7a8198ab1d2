// The Psi method (Kontsevich & Tyler 1999): a Bayesian adaptive procedure that keeps a posterior
// over a grid of psychometric functions (threshold x slope, optionally x lapse, as in Prins
// 2013's marginal variant) and shows next the level whose answer is expected to leave the least
// posterior entropy (docs/study.md, "The Psi method").
//
// A procedure calls next_level(), shows it, then update(level, correct); estimate() at any time.
// No randomness: the same answers give the same levels (ties go to the lowest level), so a
// simulated run is as deterministic as its observer's seed.
#pragma once

#include <vector>

#include "study/psychometric.h"

namespace ps::study {

struct PsiGrid {
  Shape shape = Shape::kWeibull;
  double guess = 0.5;
  std::vector<double> levels;      // the levels it may show (stimulus units)
  std::vector<double> thresholds;  // alpha's grid (stimulus units)
  std::vector<double> slopes;      // beta's grid
  std::vector<double> lapses{0.0}; // lambda's grid (one value: the lapse is fixed)
  // Least expected entropy of the threshold's marginal posterior instead of the joint one: the
  // slope and lapse become nuisance parameters (Prins 2013, "psi-marginal"), so trials go where
  // they pin the threshold rather than where they teach the slope.
  bool threshold_only = false;
};

// n values from lo to hi evenly in log (lo, hi > 0) or linearly.
std::vector<double> log_spaced(double lo, double hi, int n);
std::vector<double> lin_spaced(double lo, double hi, int n);

struct PsiEstimate {
  double threshold = 0.0, threshold_sd = 0.0;  // posterior mean and SD of alpha
  double slope = 0.0, slope_sd = 0.0;          // of beta
  double lapse = 0.0;                          // posterior mean of lambda
  double entropy_bits = 0.0;                   // of the posterior
};

class PsiMethod {
 public:
  explicit PsiMethod(PsiGrid grid);  // uniform prior over the grid

  double next_level();                 // the level of least expected entropy (cached per trial)
  void update(double level, bool correct);  // any level, not only the grid's
  // Trials whose answer every grid point gave probability 0 (left out of the posterior; a grid
  // without lapse meets them when a person lapses). Non-zero: widen the grid or add a lapse.
  int impossible_answers() const { return impossible_; }
  PsiEstimate estimate() const;
  // The posterior mean of psi^-1(criterion): the criterion level (e.g. 1/sqrt 2) marginalised
  // over every parameter, for comparison with procedures that target that level.
  double threshold_at_criterion(double criterion) const;
  int trials() const { return trials_; }
  const PsiGrid& grid() const { return grid_; }

 private:
  PsychometricParams params_at(std::size_t k) const;  // grid point k of the flat posterior
  // The expected posterior entropy after a trial whose outcomes leave the weights `right` and
  // `wrong` (unnormalised, summing to p_right and 1 - p_right); may fold them in place.
  double expected_entropy(std::vector<double>& right, std::vector<double>& wrong, double p_right) const;

  PsiGrid grid_;
  std::vector<double> posterior_;  // flat: (threshold, slope, lapse), lapse fastest
  std::vector<double> table_;      // psi at levels[i] for grid point k: table_[i * K + k]
  int trials_ = 0;
  int impossible_ = 0;
  int cached_for_ = -1;
  double cached_level_ = 0.0;
};

}  // namespace ps::study
