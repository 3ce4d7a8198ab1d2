// `pseudoshadow study`: experiments on the thesis's open questions (docs/study.md). `plan`,
// `run`, `resume` and `summarize` take an experiment file (study_experiment_cmd.cpp). `simulate`:
// a simulated observer with a known psychometric function answers the Psi method and calibrate's
// staircase, each run is fitted by maximum likelihood with bootstrap 95 % intervals (and the
// threshold's credible one), and the recovered threshold and slope are printed beside the truth
// (study/simulate.h).
#include "app/study/study_cmd.h"

#include <cstdio>
#include <string>
#include <vector>

#include "app/cli/cli.h"
#include "app/study/study_experiment_cmd.h"
#include "core/result.h"
#include "study/simulate.h"

namespace ps {

namespace {

constexpr const char* kSimulateDescription =
    "A simulated 2AFC observer with a known psychometric function (Wichmann & Hill 2001) answers the Psi\n"
    "method (Kontsevich & Tyler 1999), its threshold-only variant (Prins 2013) and the 1-up-2-down\n"
    "staircase of `calibrate`; each run is fitted by maximum likelihood (threshold, slope, lapse in\n"
    "[0, 0.06]) and bootstrapped: the threshold at --criterion and the slope there with 95 % intervals,\n"
    "and the threshold's 95 % credible interval, beside the truth (docs/study.md). Reproducible with --seed.";

struct SimulateArgs {
  std::string shape = "weibull", procedure = "all";
  double threshold = 0.1, slope = 3.0, lapse = 0.02, guess = 0.5, criterion = 0.75;
  double level_min = 0.0, level_max = 0.0, reference = 0.0;
  long long trials = 100, resamples = 1000, seed = 1;
};

void declare_simulate(cli::Command& cmd, SimulateArgs& a) {
  CLI::App& app = cmd.app();
  cli::add_choice(app, "--shape", "weibull|logistic|normal", a.shape, {"weibull", "logistic", "normal"}, "weibull",
                  "the observer's psychometric function (default weibull)");
  cli::add_positive(app, "--threshold", "ALPHA", a.threshold, 1e9, "0.1", "the observer's threshold alpha (default 0.1)");
  cli::add_positive(app, "--slope", "BETA", a.slope, 1e9, "3", "the observer's slope beta (default 3)");
  app.add_option("--lapse", a.lapse, "the observer's lapse rate, in [0, 0.5) (default 0.02)")
      ->check(CLI::Range(0.0, 0.49))->type_name("L");
  app.add_option("--guess", a.guess, "the guess rate: 0.5 for 2AFC (default), 1/m for m alternatives")
      ->check(CLI::Range(0.0, 0.99))->type_name("G");
  app.add_option("--criterion", a.criterion, "the proportion correct the reported threshold is at (default 0.75)")
      ->check(CLI::Range(0.0, 1.0))->type_name("P");
  cli::add_int(app, "--trials", "N", a.trials, 10LL, 100000LL, "trials per procedure (default 100)");
  cli::add_int(app, "--resamples", "N", a.resamples, 10LL, 1000000LL, "bootstrap resamples (default 1000)");
  cli::add_int(app, "--seed", "N", a.seed, 0LL, 9'007'199'254'740'991LL, "the observer's seed (default 1)");
  cli::add_positive(app, "--min", "LEVEL", a.level_min, 1e9, "0.01", "lowest level shown (default threshold / 10)");
  cli::add_positive(app, "--max", "LEVEL", a.level_max, 1e9, "1", "highest level shown (default threshold x 10)");
  cli::add_positive(app, "--reference", "LEVEL", a.reference, 1e9, "2",
                    "print Weber fractions: threshold / this reference level");
  cli::add_choice(app, "--procedure", "all|psi|psi-marginal|staircase", a.procedure,
                  {"all", "psi", "psi-marginal", "staircase"}, "psi", "which procedures run (default all)");
  cmd.usage("pseudoshadow study simulate [--threshold A --slope B --lapse L] [--trials N] [--seed N] [options]");
}

study::SimulationSpec spec_of(const SimulateArgs& a) {
  study::SimulationSpec s;
  s.shape = a.shape == "logistic" ? study::Shape::kLogistic
            : a.shape == "normal" ? study::Shape::kCumulativeNormal
                                  : study::Shape::kWeibull;
  s.truth = {a.threshold, a.slope, a.guess, a.lapse};
  s.trials = static_cast<int>(a.trials);
  s.seed = static_cast<std::uint64_t>(a.seed);
  s.level_min = a.level_min > 0.0 ? a.level_min : a.threshold / 10.0;
  s.level_max = a.level_max > 0.0 ? a.level_max : a.threshold * 10.0;
  s.criterion = a.criterion;
  s.resamples = static_cast<int>(a.resamples);
  s.reference = a.reference;
  return s;
}

int simulate_main(const cli::Command& cmd, const SimulateArgs& a) {
  const study::SimulationSpec spec = spec_of(a);
  if (!(spec.level_min < spec.level_max))
    return cmd.usage_error(make_error("--min must be below --max (e.g. --min 0.01 --max 1)"));
  if (!(a.criterion > a.guess && a.criterion < 1.0 - a.lapse))
    return cmd.usage_error(make_error("--criterion must lie between --guess and 1 - --lapse (e.g. 0.75 in 2AFC)"));
  std::vector<study::ProcedureRun> runs;
  for (study::Procedure p : {study::Procedure::kPsi, study::Procedure::kPsiMarginal, study::Procedure::kStaircase})
    if (a.procedure == "all" || a.procedure == study::procedure_name(p)) runs.push_back(study::simulate_procedure(p, spec));
  std::fputs(study::format_simulation(spec, runs).c_str(), stdout);
  return cli::kExitOk;
}

}  // namespace

int run_study(int argc, char** argv) {
  const std::string_view sub = argc >= 2 ? argv[1] : "";
  if (sub == "simulate")
    return cli::run_command<SimulateArgs>(argc - 1, argv + 1, "study simulate", kSimulateDescription,
                                          declare_simulate, simulate_main);
  if (argc >= 2)
    if (const int rc = run_study_experiment(argc - 1, argv + 1); rc >= 0) return rc;
  std::fprintf(stderr,
               "pseudoshadow study: give a subcommand: `study simulate` (a simulated observer through Psi and the "
               "staircase, fitted with 95 %% intervals), `study plan`, `study run`, `study resume` or `study summarize` "
               "(an experiment file's participants); see docs/study.md\n");
  return sub == "--help" || sub == "-h" ? cli::kExitOk : cli::kExitUsage;
}

}  // namespace ps
