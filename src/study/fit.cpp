#include "study/fit.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>

#include "study/nelder_mead.h"

namespace ps::study {
namespace {

// The optimiser's coordinates: a = threshold (Weibull: log threshold), b = log slope and, with
// the lapse free, u with lapse = lapse_max sin^2 u (the bound 0 is reachable, and it is where the
// maximum often lies). The box keeps a and b where a fit means something.
struct Coordinates : FitBox {
  const FitOptions& options;

  Coordinates(std::span<const LevelCounts> data, const FitOptions& o) : FitBox(fit_box(data, o)), options(o) {}
  bool inside(const std::vector<double>& v) const {
    return v[0] >= a_lo && v[0] <= a_hi && v[1] >= b_lo && v[1] <= b_hi;
  }
  PsychometricParams params(const std::vector<double>& v) const {
    PsychometricParams p;
    p.threshold = options.shape == Shape::kWeibull ? std::exp(v[0]) : v[0];
    p.slope = std::exp(v[1]);
    p.guess = options.guess;
    const double s = options.fit_lapse ? std::sin(v[2]) : 0.0;
    p.lapse = options.fit_lapse ? options.lapse_max * s * s : options.fixed_lapse;
    return p;
  }
  std::vector<double> coords(const PsychometricParams& p) const {
    std::vector<double> v{options.shape == Shape::kWeibull ? std::log(p.threshold) : p.threshold, std::log(p.slope)};
    if (options.fit_lapse) v.push_back(std::asin(std::sqrt(std::clamp(p.lapse / options.lapse_max, 0.0, 1.0))));
    return v;
  }
};

// rounds = 2 with tight tolerances for a fit; the bootstrap's refits take one looser round.
PsychometricFit polish(std::span<const LevelCounts> data, const Coordinates& c, std::vector<double> start,
                       int rounds = 2, double x_tolerance = 1e-9) {
  const Objective neg_ll = [&](const std::vector<double>& v) {
    return c.inside(v) ? -log_likelihood(c.options.shape, c.params(v), data) : INFINITY;
  };
  NelderMeadParams nm;
  nm.step = {(c.a_hi - c.a_lo) / 40.0, 0.3};
  if (c.options.fit_lapse) nm.step.push_back(0.3);
  nm.x_tolerance = x_tolerance;
  nm.f_tolerance = x_tolerance * 0.1;
  PsychometricFit fit;
  // A second start from the first result: Nelder-Mead can stall on a simplex that collapsed
  // along a ridge; restarting rebuilds it (a common remedy, Lagarias et al. 1998 discuss it).
  for (int round = 0; round < rounds; ++round) {
    const NelderMeadResult r = nelder_mead(neg_ll, start, nm);
    fit.evaluations += r.evaluations;
    fit.converged = r.converged;
    start = r.x;
  }
  fit.params = c.params(start);
  fit.log_likelihood = log_likelihood(c.options.shape, fit.params, data);
  return fit;
}

PsychometricFit refit(std::span<const LevelCounts> data, const FitOptions& options, const PsychometricParams& start,
                      int rounds, double x_tolerance) {
  const Coordinates c(data, options);
  std::vector<double> v = c.coords(start);
  v[0] = std::clamp(v[0], c.a_lo, c.a_hi);
  v[1] = std::clamp(v[1], c.b_lo, c.b_hi);
  return polish(data, c, v, rounds, x_tolerance);
}

}  // namespace

FitBox fit_box(std::span<const LevelCounts> data, const FitOptions& o) {
  const double lo = data.front().level, hi = data.back().level, span = hi - lo;
  assert(span > 0.0 && "fit_psychometric: the data need at least two levels");
  FitBox b;
  if (o.shape == Shape::kWeibull) {
    double lo_pos = hi;
    for (const auto& d : data) if (d.level > 0.0) lo_pos = std::min(lo_pos, d.level);
    assert(hi > 0.0 && "fit_psychometric: a Weibull needs positive levels");
    b.a_lo = std::log(lo_pos) - std::log(10.0), b.a_hi = std::log(hi) + std::log(10.0);
    b.b_lo = std::log(0.2), b.b_hi = std::log(50.0);
  } else {
    b.a_lo = lo - span, b.a_hi = hi + span;
    b.b_lo = std::log(0.2 / span), b.b_hi = std::log(2000.0 / span);
  }
  return b;
}

std::vector<LevelCounts> group_by_level(std::span<const TrialResult> trials) {
  std::map<double, LevelCounts> by_level;
  for (const TrialResult& t : trials) {
    LevelCounts& g = by_level[t.level];
    g.level = t.level;
    ++g.trials;
    g.correct += t.correct ? 1 : 0;
  }
  std::vector<LevelCounts> out;
  for (const auto& [level, g] : by_level) out.push_back(g);
  return out;
}

double log_likelihood(Shape shape, const PsychometricParams& p, std::span<const LevelCounts> data) {
  constexpr double kFloor = 1e-300;  // log(0) only where a count is 0 too; 0 * log(tiny) = 0
  double ll = 0.0;
  for (const LevelCounts& d : data) {
    const double q = psi(shape, p, d.level);
    if (d.correct > 0) ll += d.correct * std::log(std::max(q, kFloor));
    if (d.trials > d.correct) ll += (d.trials - d.correct) * std::log(std::max(1.0 - q, kFloor));
  }
  return ll;
}

PsychometricFit fit_psychometric(std::span<const LevelCounts> data, const FitOptions& options) {
  const Coordinates c(data, options);
  constexpr int kA = 30, kB = 20;
  const std::vector<double> lapses = options.fit_lapse ? std::vector<double>{0.0, 0.25, 0.5, 1.0} : std::vector<double>{0.0};
  std::vector<double> best;
  double best_ll = -INFINITY;
  for (int i = 0; i < kA; ++i)
    for (int j = 0; j < kB; ++j)
      for (double l : lapses) {
        std::vector<double> v{c.a_lo + (c.a_hi - c.a_lo) * (i + 0.5) / kA, c.b_lo + (c.b_hi - c.b_lo) * (j + 0.5) / kB};
        if (options.fit_lapse) v.push_back(std::asin(std::sqrt(l)));
        const double ll = log_likelihood(options.shape, c.params(v), data);
        if (ll > best_ll) best_ll = ll, best = v;
      }
  return polish(data, c, best);
}

PsychometricFit fit_psychometric_from(std::span<const LevelCounts> data, const FitOptions& options,
                                      const PsychometricParams& start) {
  return refit(data, options, start, 2, 1e-9);
}

double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

SimulatedObserver::SimulatedObserver(Shape shape, PsychometricParams truth, std::uint64_t seed)
    : shape_(shape), truth_(truth), rng_(seed) {}

bool SimulatedObserver::respond(double level) { return uniform01(rng_) < psi(shape_, truth_, level); }

double quantile(std::vector<double>& values, double q) {
  assert(!values.empty() && "quantile: no values");
  std::sort(values.begin(), values.end());
  const double h = q * static_cast<double>(values.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(h));
  if (i + 1 >= values.size()) return values.back();
  return values[i] + (h - static_cast<double>(i)) * (values[i + 1] - values[i]);
}

BootstrapResult bootstrap(std::span<const LevelCounts> data, const FitOptions& options,
                          const PsychometricFit& fit, const BootstrapOptions& boot) {
  BootstrapResult out;
  out.threshold = threshold_at(options.shape, fit.params, boot.criterion);
  out.slope = slope_at(options.shape, fit.params, out.threshold);
  std::mt19937_64 rng(boot.seed);
  std::vector<double> thresholds, slopes, alphas, betas;
  std::vector<LevelCounts> sample(data.begin(), data.end());
  for (int r = 0; r < boot.resamples; ++r) {
    for (LevelCounts& s : sample) {
      const double p = psi(options.shape, fit.params, s.level);
      s.correct = 0;
      for (int t = 0; t < s.trials; ++t) s.correct += uniform01(rng) < p ? 1 : 0;
    }
    // One Nelder-Mead round to 1e-6 in the coordinates (a relative 1e-6 of alpha and beta): a
    // resample's maximum lies near the fit it was drawn from, and the interval's ends, whose own
    // sampling error is a few percent, do not move for more.
    const PsychometricFit again = refit(sample, options, fit.params, 1, 1e-6);
    const double th = threshold_at(options.shape, again.params, boot.criterion);
    if (!std::isfinite(th)) { ++out.failed; continue; }
    thresholds.push_back(th);
    slopes.push_back(slope_at(options.shape, again.params, th));
    alphas.push_back(again.params.threshold);
    betas.push_back(again.params.slope);
  }
  out.resamples = static_cast<int>(thresholds.size());
  if (thresholds.empty()) return out;
  const double lo = (1.0 - boot.confidence) / 2.0, hi = (1.0 + boot.confidence) / 2.0;
  out.threshold_ci = {quantile(thresholds, lo), quantile(thresholds, hi)};
  out.slope_ci = {quantile(slopes, lo), quantile(slopes, hi)};
  out.alpha_ci = {quantile(alphas, lo), quantile(alphas, hi)};
  out.beta_ci = {quantile(betas, lo), quantile(betas, hi)};
  return out;
}

}  // namespace ps::study
