// A simulated observer through each procedure, fitted and bootstrapped (study/simulate.h): what
// `study simulate` prints. The truth must fall inside the 95 % intervals about 95 % of the time.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "study/simulate.h"

namespace ps::study {
namespace {

// 20 seeds per procedure, 120 trials, 300 resamples. At a true coverage of 0.95, 16 or more of 20
// happens with probability 0.984 (binomial), so fewer says the intervals are too narrow (or the
// procedure's data cannot pin the threshold). The staircase's trials cluster at its 70.7 % point,
// so its intervals on the 75 % point lean on the fitted slope.
TEST(SimulateTest, ThresholdIntervalsCoverTheTruth) {
  for (Procedure p : {Procedure::kPsi, Procedure::kPsiMarginal, Procedure::kStaircase}) {
    int covered = 0, credible = 0;
    double width = 0.0;
    for (int seed = 1; seed <= 20; ++seed) {
      SimulationSpec spec;
      spec.trials = 120;
      spec.resamples = 300;
      spec.seed = static_cast<std::uint64_t>(seed);
      const ProcedureRun run = simulate_procedure(p, spec);
      ASSERT_EQ(run.trials.size(), 120u);
      const double truth = threshold_at(spec.shape, spec.truth, spec.criterion);
      covered += run.boot.threshold_ci.contains(truth) ? 1 : 0;
      credible += run.credible.threshold_ci.contains(truth) ? 1 : 0;
      width += (run.boot.threshold_ci.high - run.boot.threshold_ci.low) / truth / 20.0;
    }
    std::printf("%s: the true threshold in %d of 20 intervals, mean width %.0f %% of it; in %d of 20 credible ones\n",
                std::string(procedure_name(p)).c_str(), covered, 100.0 * width, credible);
    // The staircase: its intervals come from resampling at the run's own levels, not from running
    // the staircase again, and a design that followed the answers makes such intervals run narrow
    // (measured 16 of 20); at least 14 (probability 0.9997 at 0.95) still catches a broken fit.
    EXPECT_GE(covered, p == Procedure::kStaircase ? 14 : 16) << procedure_name(p);
    // The credible intervals (posterior.h) integrate over the slope rather than fix the fitted
    // one, so the staircase's need no allowance: 16 of 20 for every procedure.
    EXPECT_GE(credible, 16) << procedure_name(p);
  }
}

TEST(SimulateTest, SameSpecSameReport) {
  SimulationSpec spec;
  spec.trials = 40;
  spec.resamples = 50;
  spec.reference = 2.0;
  std::string a, b;
  for (std::string* out : {&a, &b}) {
    std::vector<ProcedureRun> runs;
    for (Procedure p : {Procedure::kPsi, Procedure::kStaircase}) runs.push_back(simulate_procedure(p, spec));
    *out = format_simulation(spec, runs);
  }
  EXPECT_EQ(a, b);
  EXPECT_NE(a.find("psi "), std::string::npos);
  EXPECT_NE(a.find("staircase"), std::string::npos);
  EXPECT_NE(a.find("Weber"), std::string::npos);
}

}  // namespace
}  // namespace ps::study
