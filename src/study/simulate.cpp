#include "study/simulate.h"

#include <cmath>
#include <cstdio>

#include "calibrate/staircase.h"

namespace ps::study {
namespace {

constexpr double kStaircaseTarget = 0.70710678118654752;  // 1-up-2-down: P(correct)^2 = 1/2

FitOptions fit_options(const SimulationSpec& spec) {
  FitOptions o;
  o.shape = spec.shape;
  o.guess = spec.truth.guess;
  o.fit_lapse = true;
  o.lapse_max = 0.06;
  return o;
}

void run_psi(const SimulationSpec& spec, bool threshold_only, SimulatedObserver& o, ProcedureRun& run) {
  PsiMethod psi(simulation_grid(spec, threshold_only));
  for (int t = 0; t < spec.trials; ++t) {
    const double x = psi.next_level();
    const bool correct = o.respond(x);
    psi.update(x, correct);
    run.trials.push_back({x, correct});
  }
  run.own_estimate = psi.threshold_at_criterion(kStaircaseTarget);
}

// calibrate's staircase as `calibrate` runs it, started at half the top of the range (well above
// any threshold inside it) and kept inside the range.
void run_staircase(const SimulationSpec& spec, SimulatedObserver& o, ProcedureRun& run) {
  calibrate::StaircaseParams p;
  p.start_delta = spec.level_max / 2.0;
  p.min_delta = spec.level_min;
  p.max_delta = spec.level_max;
  p.reversals = spec.trials;  // it stops at the trial count, as Psi does
  p.max_trials = spec.trials;
  calibrate::Staircase s(p);
  while (!s.done()) {
    const double x = s.delta();
    const bool correct = o.respond(x);
    s.record(correct);
    run.trials.push_back({x, correct});
  }
  run.own_estimate = s.threshold();
}

std::string interval(double v, const Interval& ci) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.4g [%.4g, %.4g]", v, ci.low, ci.high);
  return buf;
}

}  // namespace

std::string_view procedure_name(Procedure p) {
  switch (p) {
    case Procedure::kPsi: return "psi";
    case Procedure::kPsiMarginal: return "psi-marginal";
    case Procedure::kStaircase: return "staircase";
  }
  return "?";
}

SlopeRange psi_slope_range(Shape shape, double level_min, double level_max) {
  if (shape == Shape::kWeibull) return {1.0, 8.0};
  const double span = level_max - level_min;
  return {2.0 / span, 200.0 / span};
}

PosteriorOptions psi_prior(Shape shape, double level_min, double level_max, double criterion) {
  PosteriorOptions o;
  o.criterion = criterion;
  const SlopeRange slopes = psi_slope_range(shape, level_min, level_max);
  o.slope_min = slopes.low;
  o.slope_max = slopes.high;
  return o;
}

PsiGrid simulation_grid(const SimulationSpec& spec, bool threshold_only) {
  PsiGrid g;
  g.shape = spec.shape;
  g.guess = spec.truth.guess;
  const bool log_axis = spec.shape == Shape::kWeibull;
  g.levels = log_axis ? log_spaced(spec.level_min, spec.level_max, 30) : lin_spaced(spec.level_min, spec.level_max, 30);
  g.thresholds = log_axis ? log_spaced(spec.level_min, spec.level_max, 40) : lin_spaced(spec.level_min, spec.level_max, 40);
  const SlopeRange slopes = psi_slope_range(spec.shape, spec.level_min, spec.level_max);
  g.slopes = log_spaced(slopes.low, slopes.high, 12);
  g.lapses = {spec.psi_lapse};
  g.threshold_only = threshold_only;
  return g;
}

ProcedureRun simulate_procedure(Procedure procedure, const SimulationSpec& spec) {
  ProcedureRun run;
  run.procedure = procedure;
  SimulatedObserver o(spec.shape, spec.truth, spec.seed);
  if (procedure == Procedure::kStaircase) {
    run_staircase(spec, o, run);
  } else {
    run_psi(spec, procedure == Procedure::kPsiMarginal, o, run);
  }
  const std::vector<LevelCounts> data = group_by_level(run.trials);
  if (data.size() < 2) return run;  // one level only: nothing to fit (the boot stays empty)
  run.fit = fit_psychometric(data, fit_options(spec));
  BootstrapOptions b;
  b.resamples = spec.resamples;
  b.criterion = spec.criterion;
  b.seed = spec.seed + 1;
  run.boot = bootstrap(data, fit_options(spec), run.fit, b);
  run.credible = posterior_intervals(data, fit_options(spec), psi_prior(spec.shape, spec.level_min, spec.level_max, spec.criterion));
  return run;
}

std::string format_simulation(const SimulationSpec& spec, const std::vector<ProcedureRun>& runs) {
  const double true_threshold = threshold_at(spec.shape, spec.truth, spec.criterion);
  char line[512];
  std::snprintf(line, sizeof line,
                "observer: %s, alpha %.4g, beta %.4g, guess %.3g, lapse %.3g; at %.4g correct: threshold %.4g, "
                "slope %.4g (true)\n",
                std::string(shape_name(spec.shape)).c_str(), spec.truth.threshold, spec.truth.slope, spec.truth.guess,
                spec.truth.lapse, spec.criterion, true_threshold, slope_at(spec.shape, spec.truth, true_threshold));
  std::string out = line;
  for (const ProcedureRun& r : runs) {
    std::snprintf(line, sizeof line,
                  "%-12s %4zu trials  threshold %s credible [%.4g, %.4g]  slope %s  alpha %.4g beta %.4g lapse %.3f  "
                  "own estimate (70.7 %%) %.4g",
                  std::string(procedure_name(r.procedure)).c_str(), r.trials.size(),
                  interval(r.boot.threshold, r.boot.threshold_ci).c_str(), r.credible.threshold_ci.low,
                  r.credible.threshold_ci.high, interval(r.boot.slope, r.boot.slope_ci).c_str(),
                  r.fit.params.threshold, r.fit.params.slope, r.fit.params.lapse, r.own_estimate);
    out += line;
    if (spec.reference > 0.0) {
      std::snprintf(line, sizeof line, "  Weber %s",
                    interval(weber_fraction(r.boot.threshold, spec.reference),
                             {r.boot.threshold_ci.low / spec.reference, r.boot.threshold_ci.high / spec.reference})
                        .c_str());
      out += line;
    }
    out += "\n";
  }
  return out;
}

}  // namespace ps::study
