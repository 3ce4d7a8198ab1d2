// A simulated observer run through an adaptive procedure, then fitted (docs/study.md,
// "Simulating"): what `pseudoshadow study simulate` prints, and how the tests show that a
// procedure and the fit after it recover a known psychometric function.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "study/fit.h"
#include "study/posterior.h"
#include "study/psi.h"

namespace ps::study {

enum class Procedure { kPsi, kPsiMarginal, kStaircase };
std::string_view procedure_name(Procedure p);  // "psi", "psi-marginal", "staircase"

struct SimulationSpec {
  Shape shape = Shape::kWeibull;
  PsychometricParams truth{0.1, 3.0, 0.5, 0.02};  // the observer
  int trials = 100;
  std::uint64_t seed = 1;          // the observer's answers (the bootstrap takes seed + 1)
  double level_min = 0.01;         // the levels the procedures may show (stimulus units)
  double level_max = 1.0;
  double psi_lapse = 0.02;         // the lapse rate Psi assumes (Kontsevich & Tyler fix one)
  double criterion = 0.75;         // the reported threshold is psi^-1(criterion)
  int resamples = 1000;            // bootstrap resamples for the 95 % intervals
  double reference = 0.0;          // > 0: Weber fractions against this level
};

struct ProcedureRun {
  Procedure procedure = Procedure::kPsi;
  std::vector<TrialResult> trials;
  double own_estimate = 0.0;   // Psi: posterior mean of the 1/sqrt 2 level; staircase: its threshold
  PsychometricFit fit;         // maximum likelihood over the run's trials (lapse free)
  BootstrapResult boot;        // threshold and slope at the criterion, with 95 % intervals
  PosteriorResult credible;    // their 95 % credible intervals (posterior.h, Psi's slope prior)
};

// The slopes Psi allows, the prior every threshold experiment assumes (the summary's credible
// intervals too, posterior.h): Weibull beta in [1, 8] (2AFC slopes in the literature lie in
// 1-5, Strasburger 2001), the logistic's and normal's in [2, 200] / (level_max - level_min).
struct SlopeRange {
  double low = 0.0, high = 0.0;
};
SlopeRange psi_slope_range(Shape shape, double level_min, double level_max);
// The credible intervals' options at a criterion with that prior (study summarize and simulate).
PosteriorOptions psi_prior(Shape shape, double level_min, double level_max, double criterion);

// The grid Psi uses for a spec: levels and thresholds evenly in log over [level_min, level_max]
// (linear for the logistic and normal), 12 slopes evenly in log over psi_slope_range().
PsiGrid simulation_grid(const SimulationSpec& spec, bool threshold_only);

ProcedureRun simulate_procedure(Procedure procedure, const SimulationSpec& spec);

// The runs as a table beside the truth, one line per procedure (plain text, for a terminal).
std::string format_simulation(const SimulationSpec& spec, const std::vector<ProcedureRun>& runs);

}  // namespace ps::study
