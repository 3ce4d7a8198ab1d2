#include "calibrate/calibration.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>

namespace ps::calibrate {

namespace {

constexpr double kZ707 = 0.5448710710;  // Phi^-1(1/sqrt 2): the 1-up-2-down target's z-score

double phi(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// The JND at t: linear between the references, the end values beyond them.
double jnd_at(const std::vector<double>& refs, const std::vector<double>& jnds, double t) {
  if (t <= refs.front()) return jnds.front();
  if (t >= refs.back()) return jnds.back();
  const auto hi = std::upper_bound(refs.begin(), refs.end(), t);
  const std::size_t i = static_cast<std::size_t>(hi - refs.begin());
  const double f = (t - refs[i - 1]) / (refs[i] - refs[i - 1]);
  return jnds[i - 1] + f * (jnds[i] - jnds[i - 1]);
}

}  // namespace

std::string_view curve_name(CurveKind kind) { return kind == CurveKind::kDistance ? "distance" : "speed"; }

Calibration::Calibration(Spec spec) : spec_(std::move(spec)), rng_(spec_.seed) {
  assert(!spec_.references.empty() && "Calibration: at least one reference point");
  for (std::size_t i = 0; i < spec_.references.size(); ++i) stairs_.emplace_back(spec_.staircase);
  if (!done()) draw_trial();
}

bool Calibration::done() const {
  return std::all_of(stairs_.begin(), stairs_.end(), [](const Staircase& s) { return s.done(); });
}

void Calibration::draw_trial() {
  std::vector<int> open;
  for (std::size_t i = 0; i < stairs_.size(); ++i)
    if (!stairs_[i].done()) open.push_back(static_cast<int>(i));
  Trial t;
  t.index = static_cast<int>(log_.size());
  t.point = open[std::uniform_int_distribution<std::size_t>(0, open.size() - 1)(rng_)];
  t.reference = spec_.references[static_cast<std::size_t>(t.point)];
  t.comparison = t.reference + stairs_[static_cast<std::size_t>(t.point)].delta();
  t.comparison_left = std::bernoulli_distribution(0.5)(rng_);
  current_ = t;
}

void Calibration::answer(bool left) {
  assert(!done() && "Calibration::answer: the calibration is over");
  Trial t = current_;
  t.answered_left = left;
  // Distance: the closer is the reference; speed: the faster is the comparison.
  const bool want_comparison = spec_.kind == CurveKind::kSpeed;
  t.correct = (left == t.comparison_left) == want_comparison;
  t.reversal = stairs_[static_cast<std::size_t>(t.point)].record(t.correct);
  log_.push_back(t);
  if (!done()) draw_trial();
}

std::vector<double> Calibration::jnds() const {
  std::vector<double> out;
  for (const Staircase& s : stairs_) out.push_back(s.threshold());
  return out;
}

std::vector<int> Calibration::reversals() const {
  std::vector<int> out;
  for (const Staircase& s : stairs_) out.push_back(s.reversal_count());
  return out;
}

SimulatedObserver::SimulatedObserver(CurveFn shown, ObserverParams params)
    : shown_(std::move(shown)), params_(params), rng_(params.seed) {}

double SimulatedObserver::p_correct(double a, double b) const {
  const double qa = shown_(a), qb = shown_(b);
  const double jnd = params_.jnd_min + params_.weber * 0.5 * (qa + qb);
  return phi(kZ707 * std::abs(qa - qb) / jnd);
}

bool SimulatedObserver::answer_left(const Trial& t, CurveKind kind) {
  // The right answer: the reference is closer; the comparison is faster.
  const bool right_is_left = kind == CurveKind::kSpeed ? t.comparison_left : !t.comparison_left;
  const bool correct = std::bernoulli_distribution(p_correct(t.reference, t.comparison))(rng_);
  return correct ? right_is_left : !right_is_left;
}

double true_jnd(const SimulatedObserver& o, double x, double max_delta) {
  const double target = 1.0 / std::sqrt(2.0);
  if (o.p_correct(x, x + max_delta) < target) return max_delta;
  double lo = 0.0, hi = max_delta;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (o.p_correct(x, x + mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void run_simulated(Calibration& c, SimulatedObserver& o, const std::function<bool()>& stop) {
  while (!c.done() && !(stop && stop())) c.answer(o.answer_left(c.current(), c.spec().kind));
}

Lut equalising_lut(CurveKind kind, const CurveFn& shown, const std::vector<double>& refs,
                   const std::vector<double>& jnds, double range_max, double tail_max, int rows) {
  assert(refs.size() == jnds.size() && !refs.empty() && rows >= 2 && range_max > 0.0 &&
         "equalising_lut: one JND per reference, a positive range");
  constexpr int kSteps = 4096;
  std::vector<double> s(kSteps + 1, 0.0);  // S at t_k = range_max k / kSteps (trapezoid rule)
  for (int k = 1; k <= kSteps; ++k) {
    const double a = range_max * (k - 1) / kSteps, b = range_max * k / kSteps;
    s[k] = s[k - 1] + 0.5 * (b - a) * (1.0 / jnd_at(refs, jnds, a) + 1.0 / jnd_at(refs, jnds, b));
  }
  auto h = [&](double x) {  // S^-1(S(range_max) x / range_max), linear between grid points
    const double target = s.back() * x / range_max;
    const auto it = std::lower_bound(s.begin(), s.end(), target);
    if (it == s.begin()) return 0.0;
    if (it == s.end()) return range_max;
    const std::size_t k = static_cast<std::size_t>(it - s.begin());
    const double f = (target - s[k - 1]) / (s[k] - s[k - 1]);
    return range_max * (static_cast<double>(k - 1) + f) / kSteps;
  };
  Lut lut;
  lut.axis = kind == CurveKind::kDistance ? LutAxis::kDistanceMm : LutAxis::kSpeedMmS;
  for (int i = 0; i < rows; ++i) {
    const double x = range_max * i / (rows - 1);
    lut.points.push_back({x, std::clamp(shown(h(x)), 0.0, 1.0)});
  }
  if (tail_max > range_max) {
    constexpr int kTail = 16;
    for (int i = 1; i <= kTail; ++i) {
      const double x = range_max + (tail_max - range_max) * i / kTail;
      lut.points.push_back({x, std::clamp(shown(x), 0.0, 1.0)});
    }
  }
  return lut;
}

std::string format_trial_log(const Calibration& c) {
  std::string out = "trial,curve,point,reference,comparison,delta,comparison_side,answer,correct,reversal\n";
  char line[256];
  for (const Trial& t : c.trials()) {
    std::snprintf(line, sizeof line, "%d,%s,%d,%.9g,%.9g,%.9g,%s,%s,%d,%d\n", t.index,
                  std::string(curve_name(c.spec().kind)).c_str(), t.point, t.reference, t.comparison,
                  t.comparison - t.reference, t.comparison_left ? "left" : "right", t.answered_left ? "left" : "right",
                  t.correct ? 1 : 0, t.reversal ? 1 : 0);
    out += line;
  }
  return out;
}

}  // namespace ps::calibrate

namespace ps::calibrate {

std::vector<bool> Calibration::finished() const {
  std::vector<bool> out;
  for (const Staircase& s : stairs_) out.push_back(s.done());
  return out;
}

int Calibration::expected_trials() const {
  double total = static_cast<double>(log_.size());
  const int want = spec_.staircase.reversals;
  for (const Staircase& s : stairs_) {
    if (s.done()) continue;
    const double per = s.reversal_count() >= 2 ? static_cast<double>(s.trials()) / s.reversal_count() : 4.0;
    const double left = std::min(per * (want - s.reversal_count()), static_cast<double>(spec_.staircase.max_trials - s.trials()));
    total += std::max(0.0, left);
  }
  return static_cast<int>(std::lround(total));
}

Result<std::vector<LoggedAnswer>> parse_trial_log(std::string_view text, const std::string& source) {
  std::vector<LoggedAnswer> out;
  int n = 0;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string line(text.substr(at, end - at));
    at = end + 1;
    if (++n == 1 || line.empty()) continue;  // the header
    int index = 0, point = 0, correct = 0, reversal = 0;
    double ref = 0.0, cmp = 0.0, delta = 0.0;
    char curve[16], side[8], answer[8];
    if (std::sscanf(line.c_str(), "%d,%15[^,],%d,%lf,%lf,%lf,%7[^,],%7[^,],%d,%d", &index, curve, &point, &ref, &cmp, &delta,
                    side, answer, &correct, &reversal) != 10)
      return make_error(source + ":" + std::to_string(n) + ": not a trial log row (give the .trials.csv `calibrate` wrote)");
    out.push_back({point, ref, cmp, std::string(side) == "left", std::string(answer) == "left"});
  }
  return out;
}

Status replay_answer(Calibration& c, const LoggedAnswer& a, const std::string& where) {
  const Trial& t = c.current();
  // The log writes 9 significant digits: the same trial agrees to that.
  auto same = [](double x, double y) { return std::abs(x - y) <= 1e-8 * std::max(1.0, std::abs(x)); };
  if (c.done() || t.point != a.point || !same(t.reference, a.reference) || !same(t.comparison, a.comparison) ||
      t.comparison_left != a.comparison_left)
    return make_error(where + ": this trial is not the one the calibration shows next: give the same --curve, "
                              "--references, --reversals, --average-last and --seed as the run that wrote the log");
  c.answer(a.answered_left);
  return ok_status();
}

}  // namespace ps::calibrate
