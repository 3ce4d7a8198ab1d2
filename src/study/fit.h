// Maximum-likelihood fit of a psychometric function (study/psychometric.h) to forced-choice
// trials, its parametric bootstrap, and the simulated observer the tests and `study simulate`
// answer with (docs/study.md, "Fitting" and "Bootstrap").
#pragma once

#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "study/psychometric.h"

namespace ps::study {

struct TrialResult {
  double level = 0.0;
  bool correct = false;
};

// Trials grouped by level: the likelihood depends on the data only through these counts.
struct LevelCounts {
  double level = 0.0;
  int trials = 0;
  int correct = 0;
};
std::vector<LevelCounts> group_by_level(std::span<const TrialResult> trials);  // sorted by level

struct FitOptions {
  Shape shape = Shape::kLogistic;
  double guess = 0.5;        // gamma, fixed (1/2 in 2AFC, 1/m in m-AFC, 0 for yes/no)
  bool fit_lapse = true;     // lambda free in [0, lapse_max] (Wichmann & Hill 2001) ...
  double lapse_max = 0.06;
  double fixed_lapse = 0.0;  // ... or fixed here
};

struct PsychometricFit {
  PsychometricParams params;
  double log_likelihood = 0.0;  // natural log, without the binomial coefficients
  int evaluations = 0;
  bool converged = false;
};

// The box the fit searches, in the optimiser's coordinates: a = threshold (Weibull: log
// threshold), b = log slope. Threshold within the levels' range widened by its span on each side
// (Weibull: a factor 10 in log), slope within [0.2, 2000] / span (Weibull: [0.2, 50]).
struct FitBox {
  double a_lo = 0.0, a_hi = 0.0, b_lo = 0.0, b_hi = 0.0;
};
FitBox fit_box(std::span<const LevelCounts> data, const FitOptions& options);

// log L = sum_i k_i log psi(x_i) + (n_i - k_i) log(1 - psi(x_i)).
double log_likelihood(Shape shape, const PsychometricParams& p, std::span<const LevelCounts> data);

// The maximum-likelihood parameters: a coarse grid over threshold, slope and lapse picks the
// start (the likelihood can have shallow ridges), Nelder-Mead polishes it, inside fit_box();
// `data` needs at least two levels.
PsychometricFit fit_psychometric(std::span<const LevelCounts> data, const FitOptions& options);
// The same from a known start (the bootstrap's refits start at the fit they resample).
PsychometricFit fit_psychometric_from(std::span<const LevelCounts> data, const FitOptions& options,
                                      const PsychometricParams& start);

// A uniform in [0, 1) from the engine's 53 high bits: std::uniform_real_distribution and
// std::binomial_distribution are implementation-defined, mt19937_64's output is not, so the same
// seed gives the same trials with every standard library.
double uniform01(std::mt19937_64& rng);

// An observer with a known psychometric function: correct with probability psi(level).
class SimulatedObserver {
 public:
  SimulatedObserver(Shape shape, PsychometricParams truth, std::uint64_t seed);
  bool respond(double level);
  const PsychometricParams& truth() const { return truth_; }
  Shape shape() const { return shape_; }

 private:
  Shape shape_;
  PsychometricParams truth_;
  std::mt19937_64 rng_;
};

struct Interval {
  double low = 0.0, high = 0.0;
  bool contains(double v) const { return v >= low && v <= high; }
};

struct BootstrapOptions {
  int resamples = 1000;
  double criterion = 0.75;    // the thresholds are psi^-1(criterion)
  double confidence = 0.95;   // percentile interval: the (1-c)/2 and (1+c)/2 quantiles
  std::uint64_t seed = 1;
};

struct BootstrapResult {
  double threshold = 0.0;     // the fit's psi^-1(criterion)
  double slope = 0.0;         // the fit's dpsi/dx there
  Interval threshold_ci, slope_ci, alpha_ci, beta_ci;
  int resamples = 0;          // refits that reached the criterion (the others are left out)
  int failed = 0;
};

// Parametric bootstrap (Wichmann & Hill 2001b): `resamples` data sets drawn from the fitted
// function at the data's own levels and trial counts, each refitted; percentile intervals.
BootstrapResult bootstrap(std::span<const LevelCounts> data, const FitOptions& options,
                          const PsychometricFit& fit, const BootstrapOptions& boot);

// The q-quantile of `values` (sorted in place), linear between order statistics (type 7).
double quantile(std::vector<double>& values, double q);

}  // namespace ps::study
