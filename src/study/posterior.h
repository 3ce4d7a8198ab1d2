// The Bayesian interval for a psychometric function's threshold and slope: the posterior over a
// grid of (threshold, slope, lapse) given forced-choice counts, with flat priors over the box the
// maximum-likelihood fit searches (fit.h: fit_box; flat in log threshold for the Weibull, in log
// slope, in the lapse over [0, lapse_max]), and its equal-tailed credible intervals for the
// threshold at a criterion and the slope there (docs/study.md, "Credible intervals").
//
// Why beside the bootstrap: the parametric bootstrap draws new answers at the run's own levels,
// from the fitted function as if it were the truth. When an adaptive procedure (Psi, a staircase)
// chose those levels from the answers, and 60 trials leave the slope loose, those intervals hold
// the truth in 86-92 % of runs rather than 95 %. The posterior integrates over every slope the
// answers allow instead of fixing the fitted one, and the likelihood does not depend on how the
// levels were chosen: its intervals hold the truth at their nominal rate (measured in
// docs/study.md; Schuett et al. 2016 report the same for psignifit 4).
#pragma once

#include <span>

#include "study/fit.h"

namespace ps::study {

struct PosteriorOptions {
  int thresholds = 200, slopes = 40, lapses = 7;  // grid points (lapses: 1 when the lapse is fixed)
  double criterion = 0.75;
  double confidence = 0.95;
  double slope_min = 0.0, slope_max = 0.0;  // the slope prior's range; 0: the fit box's
};

struct PosteriorResult {
  Interval threshold_ci, slope_ci;  // equal-tailed: the (1-c)/2 and (1+c)/2 posterior quantiles
  double threshold_median = 0.0;
};

// `data` needs at least two levels (as fit_psychometric).
PosteriorResult posterior_intervals(std::span<const LevelCounts> data, const FitOptions& options,
                                    const PosteriorOptions& posterior = {});

}  // namespace ps::study
