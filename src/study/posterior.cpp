#include "study/posterior.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace ps::study {
namespace {

// The q-quantile of a weighted sample sorted by value: the first value whose cumulative weight
// reaches q (weights summing to 1). The grid is fine enough that interpolating would not move
// an end by more than a grid step (~4 % of the threshold, an interval spans ~100 %).
double weighted_quantile(const std::vector<std::pair<double, double>>& sorted, double q) {
  double acc = 0.0;
  for (const auto& [value, weight] : sorted) {
    acc += weight;
    if (acc >= q) return value;
  }
  return sorted.back().first;
}

}  // namespace

PosteriorResult posterior_intervals(std::span<const LevelCounts> data, const FitOptions& options,
                                    const PosteriorOptions& o) {
  FitBox box = fit_box(data, options);
  if (o.slope_min > 0.0) box.b_lo = std::log(o.slope_min);
  if (o.slope_max > 0.0) box.b_hi = std::log(o.slope_max);
  const int nl = options.fit_lapse ? o.lapses : 1;
  struct Point {
    double threshold, slope, log_likelihood;
  };
  std::vector<Point> points;
  points.reserve(static_cast<std::size_t>(o.thresholds) * o.slopes * nl);
  double best = -INFINITY;
  for (int i = 0; i < o.thresholds; ++i)
    for (int j = 0; j < o.slopes; ++j)
      for (int l = 0; l < nl; ++l) {
        // Cell centres, so that neither bound of the box (a slope of 50) weighs double.
        const double a = box.a_lo + (box.a_hi - box.a_lo) * (i + 0.5) / o.thresholds;
        const double b = box.b_lo + (box.b_hi - box.b_lo) * (j + 0.5) / o.slopes;
        PsychometricParams p;
        p.threshold = options.shape == Shape::kWeibull ? std::exp(a) : a;
        p.slope = std::exp(b);
        p.guess = options.guess;
        p.lapse = options.fit_lapse ? options.lapse_max * (nl > 1 ? l / (nl - 1.0) : 0.0) : options.fixed_lapse;
        const double th = threshold_at(options.shape, p, o.criterion);
        if (!std::isfinite(th)) continue;
        const double ll = log_likelihood(options.shape, p, data);
        points.push_back({th, slope_at(options.shape, p, th), ll});
        best = std::max(best, ll);
      }
  PosteriorResult out;
  if (points.empty()) return out;
  std::vector<std::pair<double, double>> thresholds, slopes;
  double total = 0.0;
  for (const Point& p : points) {
    const double w = std::exp(p.log_likelihood - best);  // normalised below, once the total is known
    total += w;
    thresholds.emplace_back(p.threshold, w);
    slopes.emplace_back(p.slope, w);
  }
  for (auto* v : {&thresholds, &slopes})
    for (auto& [value, w] : *v) w /= total;
  std::sort(thresholds.begin(), thresholds.end());
  std::sort(slopes.begin(), slopes.end());
  const double lo = (1.0 - o.confidence) / 2.0, hi = (1.0 + o.confidence) / 2.0;
  out.threshold_ci = {weighted_quantile(thresholds, lo), weighted_quantile(thresholds, hi)};
  out.slope_ci = {weighted_quantile(slopes, lo), weighted_quantile(slopes, hi)};
  out.threshold_median = weighted_quantile(thresholds, 0.5);
  return out;
}

}  // namespace ps::study
