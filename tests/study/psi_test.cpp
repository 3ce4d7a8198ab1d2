// The Psi method (study/psi.h): Bayes' rule by hand, the entropy choice on a grid where the
// answer is obvious, determinism, recovery of simulated observers, and the trials it needs
// against calibrate's 1-up-2-down staircase for the same precision.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "calibrate/staircase.h"
#include "study/fit.h"
#include "study/psi.h"

namespace ps::study {
namespace {

// Two candidate thresholds, 1 and 2 (logistic, beta 1, yes/no: guess 0, no lapse). A correct
// answer at level 1: likelihoods 1/2 and 1 / (1 + e) = 0.2689414; posterior 0.6502446 and
// 0.3497554 (each over their sum 0.7689414), posterior mean 1.3497554 (worked by hand).
TEST(PsiMethodTest, UpdateIsBayesRuleByHand) {
  PsiGrid g;
  g.shape = Shape::kLogistic;
  g.guess = 0.0;
  g.levels = {1.0};
  g.thresholds = {1.0, 2.0};
  g.slopes = {1.0};
  PsiMethod psi(g);
  EXPECT_NEAR(psi.estimate().threshold, 1.5, 1e-15);
  EXPECT_NEAR(psi.estimate().entropy_bits, 1.0, 1e-15);
  psi.update(1.0, true);
  EXPECT_NEAR(psi.estimate().threshold, 1.3497554, 1e-7);
  EXPECT_NEAR(psi.estimate().threshold_sd, std::sqrt(0.6502446 * 0.3497554), 1e-7);
}

// Thresholds 1 and 3, a steep logistic (beta 20): at level 2 the two candidates answer almost
// surely differently, so one answer settles which is true; at -10 or 10 both answer alike and
// nothing is learnt. The least expected entropy is level 2, whatever order the levels come in.
TEST(PsiMethodTest, PicksTheLevelThatSeparatesTheCandidates) {
  PsiGrid g;
  g.shape = Shape::kLogistic;
  g.guess = 0.0;
  g.levels = {-10.0, 10.0, 2.0};
  g.thresholds = {1.0, 3.0};
  g.slopes = {20.0};
  PsiMethod psi(g);
  EXPECT_EQ(psi.next_level(), 2.0);
  psi.update(2.0, true);  // "yes" at 2: threshold 1 (P = 1 - 2e-9) against 3 (P = 4e-18)
  EXPECT_NEAR(psi.estimate().threshold, 1.0, 1e-8);
}

// A lapse-free grid whose every function is 1 at level 50 (logistic, thresholds 1 and 2, beta
// 20: 1 / (1 + e^-960) is 1 in double): a wrong answer there has probability 0 under every
// candidate. The posterior stays as it was and the trial is counted as impossible.
TEST(PsiMethodTest, AnAnswerNoCandidateAllowsLeavesThePosterior) {
  PsiGrid g;
  g.shape = Shape::kLogistic;
  g.guess = 0.5;
  g.levels = {1.5};
  g.thresholds = {1.0, 2.0};
  g.slopes = {20.0};
  PsiMethod psi(g);
  psi.update(50.0, false);
  EXPECT_EQ(psi.impossible_answers(), 1);
  EXPECT_EQ(psi.trials(), 1);
  EXPECT_DOUBLE_EQ(psi.estimate().threshold, 1.5);
  psi.update(1.5, true);  // and it goes on learning
  EXPECT_LT(psi.estimate().threshold, 1.5);
  EXPECT_EQ(psi.impossible_answers(), 1);
}

PsiGrid weibull_grid(double lapse) {
  PsiGrid g;
  g.shape = Shape::kWeibull;
  g.guess = 0.5;
  g.levels = log_spaced(0.01, 1.0, 30);
  g.thresholds = log_spaced(0.01, 1.0, 40);
  g.slopes = log_spaced(1.0, 8.0, 12);
  g.lapses = {lapse};
  return g;
}

TEST(PsiMethodTest, SameAnswersGiveTheSameLevels) {
  std::vector<double> a, b;
  for (auto* out : {&a, &b}) {
    PsiMethod psi(weibull_grid(0.02));
    SimulatedObserver o(Shape::kWeibull, {0.1, 3.0, 0.5, 0.02}, 11);
    for (int t = 0; t < 30; ++t) {
      const double x = psi.next_level();
      out->push_back(x);
      psi.update(x, o.respond(x));
    }
  }
  EXPECT_EQ(a, b);
}

// 150 trials, the three thresholds of issue 47 (0.05, 0.1, 0.2), 20 seeds each: the posterior
// mean's error within 3 posterior SDs in every run (the posterior's own statement of its
// precision; at 150 trials its SD is 9-10 % of alpha, measured), and the mean absolute error
// within 12 % (a normal error of SD 10 % has mean |error| 8 %; measured 8-10 %).
TEST(PsiMethodTest, RecoversSimulatedObservers) {
  for (double alpha : {0.05, 0.1, 0.2}) {
    double sum_err = 0.0, sum_sd = 0.0;
    for (int seed = 1; seed <= 20; ++seed) {
      PsiMethod psi(weibull_grid(0.02));
      SimulatedObserver o(Shape::kWeibull, {alpha, 3.0, 0.5, 0.02}, 700 + seed);
      for (int t = 0; t < 150; ++t) {
        const double x = psi.next_level();
        psi.update(x, o.respond(x));
      }
      const PsiEstimate e = psi.estimate();
      EXPECT_LT(std::abs(e.threshold - alpha), 3.0 * e.threshold_sd) << "alpha " << alpha << " seed " << seed;
      sum_err += std::abs(e.threshold / alpha - 1.0);
      sum_sd += e.threshold_sd / alpha;
    }
    std::printf("Psi, alpha %.2f, 150 trials: mean |error| %.1f %%, mean posterior SD %.1f %%\n", alpha,
                100.0 * sum_err / 20.0, 100.0 * sum_sd / 20.0);
    EXPECT_LT(sum_err / 20.0, 0.12) << "alpha " << alpha;
  }
}

// Psi against the staircase of `calibrate` (its default parameters: 1-up-2-down, factor 2 then
// 1.25, threshold the geometric mean of the last 12 reversals), all estimating the 70.7 %-correct
// level of the same simulated observers (Weibull, beta 3, lapse 0.02; Psi assumes that lapse, as
// Kontsevich & Tyler fix theirs), with Psi in both forms: the joint entropy (Kontsevich & Tyler)
// and the threshold's marginal (Prins 2013). For each trial count n, the RMS over 100 seeded
// observers of log(estimate / truth); the trials each needs to first reach an RMS of 0.25 and
// 0.20 (25 % and 20 %). The whole table is printed; docs/study.md quotes it.
struct Curve {
  std::vector<double> sum_sq;  // at n = 10, 20, ...
  double rms(std::size_t i, int runs) const { return std::sqrt(sum_sq[i] / runs); }
};

int trials_to(const Curve& c, int runs, double target) {
  for (std::size_t i = 0; i < c.sum_sq.size(); ++i)
    if (c.rms(i, runs) <= target) return static_cast<int>(10 * (i + 1));
  return 1 << 20;
}

TEST(PsiMethodTest, ReachesTheStaircasesPrecisionInFewerTrials) {
  const PsychometricParams truth{0.1, 3.0, 0.5, 0.02};
  const double criterion = 1.0 / std::sqrt(2.0);
  const double target = threshold_at(Shape::kWeibull, truth, criterion);
  constexpr int kRuns = 100, kTrials = 200, kStep = 10;
  std::vector<Curve> curves(3, Curve{std::vector<double>(kTrials / kStep, 0.0)});  // joint, marginal, staircase
  for (int run = 0; run < kRuns; ++run) {
    PsiGrid marginal = weibull_grid(0.02);
    marginal.threshold_only = true;
    PsiMethod joint(weibull_grid(0.02)), psi_marginal(marginal);
    calibrate::StaircaseParams sp;
    sp.start_delta = 0.4;  // 4 x alpha, a level the observer sees almost surely
    sp.reversals = 1000, sp.max_trials = 1000;  // it runs for the whole comparison
    calibrate::Staircase stair(sp);
    std::vector<SimulatedObserver> observers(3, SimulatedObserver(Shape::kWeibull, truth, 3000 + run));
    for (int t = 1; t <= kTrials; ++t) {
      for (int m = 0; m < 2; ++m) {
        PsiMethod& psi = m == 0 ? joint : psi_marginal;
        const double x = psi.next_level();
        psi.update(x, observers[m].respond(x));
      }
      stair.record(observers[2].respond(stair.delta()));
      if (t % kStep) continue;
      const double e[3] = {std::log(joint.threshold_at_criterion(criterion) / target),
                           std::log(psi_marginal.threshold_at_criterion(criterion) / target),
                           std::log(stair.threshold() / target)};
      for (int m = 0; m < 3; ++m) curves[m].sum_sq[t / kStep - 1] += e[m] * e[m];
    }
  }
  std::printf("trials  RMS log error: Psi  Psi-marginal  staircase\n");
  for (int i = 0; i < kTrials / kStep; ++i)
    std::printf("%6d  %.3f  %.3f  %.3f\n", kStep * (i + 1), curves[0].rms(i, kRuns), curves[1].rms(i, kRuns),
                curves[2].rms(i, kRuns));
  for (double precision : {0.25, 0.20}) {
    const int nj = trials_to(curves[0], kRuns, precision), nm = trials_to(curves[1], kRuns, precision);
    const int ns = trials_to(curves[2], kRuns, precision);
    std::printf("RMS %.2f first reached: Psi %d trials, Psi-marginal %d, staircase %d\n", precision, nj, nm, ns);
    EXPECT_LT(nj, ns) << "RMS " << precision;
    EXPECT_LT(nm, ns) << "RMS " << precision;
  }
}

}  // namespace
}  // namespace ps::study
