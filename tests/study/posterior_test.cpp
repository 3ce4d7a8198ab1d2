// The credible intervals of study/posterior.h: against an independent integral, against the
// published standard errors of a textbook fit, and their coverage over simulated experiments.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "constant_stimuli.h"
#include "study/fit.h"
#include "study/posterior.h"
#include "study/simulate.h"

namespace ps::study {
namespace {

// With the slope and lapse fixed the posterior is one-dimensional: flat in log alpha over the
// fit's box times the likelihood. The test integrates it itself (200 000 midpoints, its own
// cumulative sum and linear interpolation) and maps the quantiles of alpha to the threshold,
// which is monotone in alpha. Tolerance: the grid's quantile is the first of its 200 cell
// centres past q, so it lies within one cell (the box's log width / 200) of the exact one.
TEST(PosteriorTest, MatchesAnIndependentIntegralWhenOnlyTheThresholdIsFree) {
  SimulatedObserver o(Shape::kWeibull, {0.1, 3.0, 0.5, 0.02}, 11);
  const std::vector<LevelCounts> data = constant_stimuli(o, kLevels, 20);
  const FitOptions f = two_afc_weibull(false);
  PosteriorOptions p;
  p.slope_min = p.slope_max = 3.0;
  const PosteriorResult r = posterior_intervals(data, f, p);
  const FitBox box = fit_box(data, f);
  const int n = 200000;
  std::vector<double> a(n), w(n);
  double best = -INFINITY;
  for (int i = 0; i < n; ++i) {
    a[i] = box.a_lo + (box.a_hi - box.a_lo) * (i + 0.5) / n;
    w[i] = log_likelihood(Shape::kWeibull, {std::exp(a[i]), 3.0, 0.5, 0.02}, data);
    best = std::max(best, w[i]);
  }
  double total = 0.0;
  for (double& v : w) total += (v = std::exp(v - best));
  const auto quantile_threshold = [&](double q) -> double {
    double acc = 0.0;
    for (int i = 0; i < n; ++i) {
      if (acc + w[i] / total >= q) {
        const double t = (q - acc) / (w[i] / total);  // within the cell
        const double alpha = std::exp(a[i] - 0.5 * (box.a_hi - box.a_lo) / n + t * (box.a_hi - box.a_lo) / n);
        return threshold_at(Shape::kWeibull, {alpha, 3.0, 0.5, 0.02}, 0.75);
      }
      acc += w[i] / total;
    }
    return NAN;
  };
  const double cell = (box.a_hi - box.a_lo) / p.thresholds;
  EXPECT_NEAR(std::log(r.threshold_ci.low), std::log(quantile_threshold(0.025)), cell);
  EXPECT_NEAR(std::log(r.threshold_ci.high), std::log(quantile_threshold(0.975)), cell);
  EXPECT_NEAR(std::log(r.threshold_median), std::log(quantile_threshold(0.5)), cell);
  std::printf("2.5 %%: %.5f (integral %.5f), 97.5 %%: %.5f (integral %.5f)\n", r.threshold_ci.low, quantile_threshold(0.025),
              r.threshold_ci.high, quantile_threshold(0.975));
}

// Bliss (1935), the worked logistic regression of Dobson & Barnett (§7.3.1, Table 7.3):
// slope 34.27 with standard error 2.91. With 481 beetles the posterior of a flat prior is close
// to normal around the maximum-likelihood fit, so the 95 % credible interval of beta should be
// the Wald interval 34.27 +- 1.96 * 2.91 = [28.57, 39.97]. The interval here is the slope at the
// 50 % point, beta / 4 for the logistic. Tolerance 0.35 in beta (6 % of the half-width): the
// posterior is not exactly normal (its skew moves the ends by a few tenths), the book rounds to
// two decimals, and the slope grid steps by 2.3 %.
TEST(PosteriorTest, AgreesWithTheTextbookStandardErrorOfTheBlissFit) {
  const std::vector<LevelCounts> bliss{{1.6907, 59, 6},  {1.7242, 60, 13}, {1.7552, 62, 18}, {1.7842, 56, 28},
                                       {1.8113, 63, 52}, {1.8369, 59, 53}, {1.8610, 62, 61}, {1.8839, 60, 60}};
  FitOptions f;
  f.shape = Shape::kLogistic;
  f.guess = 0.0;
  f.fit_lapse = false;
  PosteriorOptions p;
  p.criterion = 0.5;
  p.thresholds = 1000;
  p.slope_min = 20.0;
  p.slope_max = 50.0;
  const PosteriorResult r = posterior_intervals(bliss, f, p);
  EXPECT_NEAR(4.0 * r.slope_ci.low, 34.27 - 1.96 * 2.91, 0.35);
  EXPECT_NEAR(4.0 * r.slope_ci.high, 34.27 + 1.96 * 2.91, 0.35);
  std::printf("beta 95 %% credible interval [%.2f, %.2f], Wald [%.2f, %.2f]\n", 4.0 * r.slope_ci.low, 4.0 * r.slope_ci.high,
              34.27 - 1.96 * 2.91, 34.27 + 1.96 * 2.91);
}

// Coverage at fixed levels: 200 simulated experiments (7 levels x 60 trials, lapse free), the
// slope prior the studies use (psi_slope_range). The band is the bootstrap test's: 3 binomial
// SDs of 200 runs around 95 %, [0.904, 0.996].
TEST(PosteriorTest, NinetyFivePercentIntervalsCoverTheTruth) {
  const PsychometricParams truth{0.1, 3.0, 0.5, 0.02};
  const double true_threshold = threshold_at(Shape::kWeibull, truth, 0.75);
  const SlopeRange slopes = psi_slope_range(Shape::kWeibull, 0.01, 1.0);
  PosteriorOptions p;
  p.slope_min = slopes.low;
  p.slope_max = slopes.high;
  int covered = 0;
  const int runs = 200;
  for (int run = 0; run < runs; ++run) {
    SimulatedObserver o(Shape::kWeibull, truth, 50000 + run);
    const auto data = constant_stimuli(o, kLevels, 60);
    covered += posterior_intervals(data, two_afc_weibull(true), p).threshold_ci.contains(true_threshold) ? 1 : 0;
  }
  const double coverage = static_cast<double>(covered) / runs;
  std::printf("threshold coverage %.3f over %d runs\n", coverage, runs);
  EXPECT_GE(coverage, 0.904);
  EXPECT_LE(coverage, 0.996);
}

}  // namespace
}  // namespace ps::study
