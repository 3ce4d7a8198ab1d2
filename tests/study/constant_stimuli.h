// The method of constant stimuli for the statistics tests: seven levels around the simulated
// observers' alpha 0.1, `per_level` answers of an observer at each, counted, and the 2AFC
// Weibull fit the tests use.
#pragma once

#include <vector>

#include "study/fit.h"

namespace ps::study {

inline const std::vector<double> kLevels{0.04, 0.06, 0.08, 0.1, 0.12, 0.15, 0.2};  // x alpha / 0.1

// Guess 1/2; the lapse free in [0, 0.06], or fixed at 0.02 (the simulated observers' own).
inline FitOptions two_afc_weibull(bool free_lapse = true) {
  FitOptions o;
  o.shape = Shape::kWeibull;
  o.guess = 0.5;
  o.fit_lapse = free_lapse;
  o.fixed_lapse = 0.02;
  return o;
}

inline std::vector<LevelCounts> constant_stimuli(SimulatedObserver& o, const std::vector<double>& levels, int per_level) {
  std::vector<LevelCounts> data;
  for (double x : levels) {
    LevelCounts d{x, per_level, 0};
    for (int t = 0; t < per_level; ++t) d.correct += o.respond(x) ? 1 : 0;
    data.push_back(d);
  }
  return data;
}

}  // namespace ps::study
