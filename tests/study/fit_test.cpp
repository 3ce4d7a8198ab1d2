// The maximum-likelihood fit (study/fit.h) against a published fit, an independent solver and an
// exhaustive search, simulated observers recovered, and the bootstrap's intervals' coverage.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "constant_stimuli.h"
#include "study/fit.h"

namespace ps::study {
namespace {

// Bliss (1935): beetles killed after five hours of carbon disulphide, at eight log10 doses. The
// logistic regression of these counts is the worked example of Dobson & Barnett, *An
// Introduction to Generalized Linear Models* (§7.3.1, Table 7.3): logit p = -60.72 + 34.27 x;
// the probit -34.94 + 19.73 x. In this project's form beta (x - alpha): beta = 34.27, alpha =
// 60.72 / 34.27 = 1.7718; probit beta = 19.73, alpha = 34.94 / 19.73 = 1.7709. A yes/no task:
// guess 0, lapse fixed at 0. Tolerances: the book's two decimals (beta +-0.005, and alpha's
// rounding through the ratio, +-0.0003).
const std::vector<LevelCounts> kBliss{{1.6907, 59, 6},  {1.7242, 60, 13}, {1.7552, 62, 18}, {1.7842, 56, 28},
                                      {1.8113, 63, 52}, {1.8369, 59, 53}, {1.8610, 62, 61}, {1.8839, 60, 60}};

FitOptions yes_no(Shape shape) {
  FitOptions o;
  o.shape = shape;
  o.guess = 0.0;
  o.fit_lapse = false;
  o.fixed_lapse = 0.0;
  return o;
}

TEST(PsychometricFitTest, MatchesThePublishedBlissFits) {
  const PsychometricFit logit = fit_psychometric(kBliss, yes_no(Shape::kLogistic));
  EXPECT_NEAR(logit.params.slope, 34.27, 0.005);
  EXPECT_NEAR(logit.params.threshold, 60.72 / 34.27, 0.0003);
  const PsychometricFit probit = fit_psychometric(kBliss, yes_no(Shape::kCumulativeNormal));
  EXPECT_NEAR(probit.params.slope, 19.73, 0.005);
  EXPECT_NEAR(probit.params.threshold, 34.94 / 19.73, 0.0003);
  std::printf("Bliss logistic: alpha %.5f beta %.4f; probit: alpha %.5f beta %.4f\n", logit.params.threshold,
              logit.params.slope, probit.params.threshold, probit.params.slope);
}

// An independent solver: iteratively reweighted least squares for logit p = b0 + b1 x (Newton's
// method on the same likelihood, McCullagh & Nelder §4.4), written here without the library.
std::pair<double, double> irls_logit(const std::vector<LevelCounts>& data) {
  double b0 = 0.0, b1 = 0.0;
  for (int it = 0; it < 50; ++it) {
    double h00 = 0, h01 = 0, h11 = 0, g0 = 0, g1 = 0;
    for (const LevelCounts& d : data) {
      const double p = 1.0 / (1.0 + std::exp(-(b0 + b1 * d.level)));
      const double w = d.trials * p * (1.0 - p), r = d.correct - d.trials * p;
      h00 += w, h01 += w * d.level, h11 += w * d.level * d.level;
      g0 += r, g1 += r * d.level;
    }
    const double det = h00 * h11 - h01 * h01;
    b0 += (h11 * g0 - h01 * g1) / det;
    b1 += (h00 * g1 - h01 * g0) / det;
  }
  return {b0, b1};
}

// The Nelder-Mead fit stops on tolerances of 1e-9 in its coordinates; 1e-6 relative leaves room.
TEST(PsychometricFitTest, AgreesWithAnIndependentNewtonSolver) {
  const auto [b0, b1] = irls_logit(kBliss);
  const PsychometricFit fit = fit_psychometric(kBliss, yes_no(Shape::kLogistic));
  EXPECT_NEAR(fit.params.slope, b1, 1e-6 * b1);
  EXPECT_NEAR(fit.params.threshold, -b0 / b1, 1e-6);
}

// The test's own 2AFC likelihood (not the library's): psi = 1/2 + (1/2 - l) W(x).
double own_log_likelihood(const std::vector<LevelCounts>& data, double a, double b, double l) {
  double ll = 0.0;
  for (const LevelCounts& d : data) {
    const double p = 0.5 + (0.5 - l) * (1.0 - std::exp(-std::pow(d.level / a, b)));
    ll += d.correct * std::log(p) + (d.trials - d.correct) * std::log(1.0 - p);
  }
  return ll;
}

// A 2AFC Weibull with a free lapse: the fit's likelihood is at least the best of an exhaustive
// 120 x 120 x 61 search of the test's own likelihood, and its parameters lie within a few grid
// cells of that point (the likelihood is flat along the lapse, so that is the loosest).
TEST(PsychometricFitTest, TwoAfcFitBeatsAnExhaustiveSearch) {
  SimulatedObserver o(Shape::kWeibull, {0.1, 3.0, 0.5, 0.02}, 7);
  const auto data = constant_stimuli(o, kLevels, 60);
  const PsychometricFit fit = fit_psychometric(data, two_afc_weibull());
  double best = -INFINITY, ba = 0, bb = 0, bl = 0;
  for (int i = 0; i < 120; ++i)
    for (int j = 0; j < 120; ++j)
      for (int k = 0; k <= 60; ++k) {
        const double a = 0.06 + 0.08 * i / 119.0, b = 1.0 + 7.0 * j / 119.0, l = 0.06 * k / 60.0;
        const double ll = own_log_likelihood(data, a, b, l);
        if (ll > best) best = ll, ba = a, bb = b, bl = l;
      }
  EXPECT_GE(fit.log_likelihood, best - 1e-9);
  EXPECT_NEAR(own_log_likelihood(data, fit.params.threshold, fit.params.slope, fit.params.lapse), fit.log_likelihood, 1e-9);
  EXPECT_NEAR(fit.params.threshold, ba, 3 * 0.08 / 119.0);
  EXPECT_NEAR(fit.params.slope, bb, 3 * 7.0 / 119.0);
  EXPECT_NEAR(fit.params.lapse, bl, 3 * 0.001);
}

// Three simulated observers (thresholds 0.05, 0.1, 0.2, as issue 47 names for lambda in mm),
// Weibull beta 3, lapse 0.02, 7 levels x 100 trials, 50 seeds each. The tolerance: at the
// steepest level the binomial SE of p is sqrt(0.75 * 0.25 / 100) = 0.043 and dpsi/dx there is
// 0.48 * 3 / (e alpha) = 0.53 / alpha, so one level pins alpha to 0.082 alpha; about three levels
// carry the information, so SE(alpha) ~ 0.047 alpha. Each run within 3.5 SE (16 %), and the mean
// of 50 runs within 3 SE of a mean (3 x 0.047 / sqrt 50 = 2 %): no bias at this trial count.
TEST(PsychometricFitTest, RecoversSimulatedObservers) {
  for (double alpha : {0.05, 0.1, 0.2}) {
    std::vector<double> levels;
    for (double x : kLevels) levels.push_back(x * alpha / 0.1);
    double sum = 0.0, sum_beta = 0.0, worst = 0.0;
    for (int seed = 1; seed <= 50; ++seed) {
      SimulatedObserver o(Shape::kWeibull, {alpha, 3.0, 0.5, 0.02}, 1000 * seed + static_cast<int>(alpha * 1000));
      const PsychometricFit fit = fit_psychometric(constant_stimuli(o, levels, 100), two_afc_weibull());
      const double err = fit.params.threshold / alpha - 1.0;
      worst = std::max(worst, std::abs(err));
      sum += err;
      sum_beta += fit.params.slope;
      EXPECT_LT(std::abs(err), 0.16) << "alpha " << alpha << " seed " << seed;
    }
    EXPECT_LT(std::abs(sum / 50.0), 0.02) << "alpha " << alpha;
    // The slope is known to come out high at small N (Wichmann & Hill 2001a, Fig. 5); at 700
    // trials the mean is within 15 %.
    EXPECT_NEAR(sum_beta / 50.0, 3.0, 0.45) << "alpha " << alpha;
    std::printf("alpha %.2f: mean threshold error %+.2f %%, worst %.1f %%, mean beta %.3f\n", alpha,
                100.0 * sum / 50.0, 100.0 * worst, sum_beta / 50.0);
  }
}

TEST(BootstrapTest, IsDeterministicForASeed) {
  SimulatedObserver o(Shape::kWeibull, {0.1, 3.0, 0.5, 0.02}, 3);
  const auto data = constant_stimuli(o, kLevels, 40);
  const PsychometricFit fit = fit_psychometric(data, two_afc_weibull());
  BootstrapOptions b;
  b.resamples = 100;
  const BootstrapResult r1 = bootstrap(data, two_afc_weibull(), fit, b);
  const BootstrapResult r2 = bootstrap(data, two_afc_weibull(), fit, b);
  EXPECT_EQ(r1.threshold_ci.low, r2.threshold_ci.low);
  EXPECT_EQ(r1.threshold_ci.high, r2.threshold_ci.high);
  b.seed = 2;
  const BootstrapResult r3 = bootstrap(data, two_afc_weibull(), fit, b);
  EXPECT_NE(r1.threshold_ci.low, r3.threshold_ci.low);
  EXPECT_LT(r1.threshold_ci.low, r1.threshold);
  EXPECT_GT(r1.threshold_ci.high, r1.threshold);
}

// Coverage: 200 simulated experiments (7 levels x 60 trials), each fitted and bootstrapped (400
// resamples); the true 75 % point should fall inside the 95 % interval about 95 % of the time.
// The band: a binomial count of 200 at 0.95 has SD sqrt(0.95 * 0.05 / 200) = 1.5 %, so 3 SD is
// [0.904, 0.996]; percentile intervals are known to run a little narrow (Wichmann & Hill 2001b),
// which is what the lower edge would catch.
TEST(BootstrapTest, NinetyFivePercentIntervalsCoverTheTruth) {
  const PsychometricParams truth{0.1, 3.0, 0.5, 0.02};
  const double true_threshold = threshold_at(Shape::kWeibull, truth, 0.75);
  int covered = 0, covered_slope = 0;
  const int runs = 200;
  for (int run = 0; run < runs; ++run) {
    SimulatedObserver o(Shape::kWeibull, truth, 50000 + run);
    const auto data = constant_stimuli(o, kLevels, 60);
    const PsychometricFit fit = fit_psychometric(data, two_afc_weibull());
    BootstrapOptions b;
    b.resamples = 400;
    b.seed = 90000 + run;
    const BootstrapResult r = bootstrap(data, two_afc_weibull(), fit, b);
    covered += r.threshold_ci.contains(true_threshold) ? 1 : 0;
    covered_slope += r.slope_ci.contains(slope_at(Shape::kWeibull, truth, true_threshold)) ? 1 : 0;
  }
  const double coverage = static_cast<double>(covered) / runs;
  std::printf("threshold coverage %.3f, slope coverage %.3f over %d runs\n", coverage,
              static_cast<double>(covered_slope) / runs, runs);
  EXPECT_GE(coverage, 0.904);
  EXPECT_LE(coverage, 0.996);
}

}  // namespace
}  // namespace ps::study
