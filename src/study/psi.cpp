#include "study/psi.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace ps::study {
namespace {

// -sum q log2 q of the unnormalised weights w (sum `total`).
double entropy_bits(const std::vector<double>& w, double total) {
  double h = 0.0;
  for (double v : w)
    if (v > 0.0) {
      const double q = v / total;
      h -= q * std::log2(q);
    }
  return h;
}

}  // namespace

std::vector<double> log_spaced(double lo, double hi, int n) {
  assert(lo > 0.0 && hi > lo && n >= 2 && "log_spaced: 0 < lo < hi, n >= 2");
  std::vector<double> out(n);
  for (int i = 0; i < n; ++i) out[i] = lo * std::pow(hi / lo, static_cast<double>(i) / (n - 1));
  return out;
}

std::vector<double> lin_spaced(double lo, double hi, int n) {
  assert(hi > lo && n >= 2 && "lin_spaced: lo < hi, n >= 2");
  std::vector<double> out(n);
  for (int i = 0; i < n; ++i) out[i] = lo + (hi - lo) * static_cast<double>(i) / (n - 1);
  return out;
}

PsiMethod::PsiMethod(PsiGrid grid) : grid_(std::move(grid)) {
  assert(!grid_.levels.empty() && !grid_.thresholds.empty() && !grid_.slopes.empty() && !grid_.lapses.empty() &&
         "PsiMethod: every grid needs at least one value");
  const std::size_t K = grid_.thresholds.size() * grid_.slopes.size() * grid_.lapses.size();
  posterior_.assign(K, 1.0 / static_cast<double>(K));
  table_.resize(grid_.levels.size() * K);
  for (std::size_t i = 0; i < grid_.levels.size(); ++i)
    for (std::size_t k = 0; k < K; ++k) table_[i * K + k] = psi(grid_.shape, params_at(k), grid_.levels[i]);
}

PsychometricParams PsiMethod::params_at(std::size_t k) const {
  const std::size_t nl = grid_.lapses.size(), ns = grid_.slopes.size();
  PsychometricParams p;
  p.lapse = grid_.lapses[k % nl];
  p.slope = grid_.slopes[(k / nl) % ns];
  p.threshold = grid_.thresholds[k / (nl * ns)];
  p.guess = grid_.guess;
  return p;
}

double PsiMethod::expected_entropy(std::vector<double>& right, std::vector<double>& wrong, double p_right) const {
  const double p_wrong = 1.0 - p_right;
  if (grid_.threshold_only) {  // sum each outcome's weights over slope and lapse first
    const std::size_t per_threshold = grid_.slopes.size() * grid_.lapses.size();
    for (std::size_t a = 0; a < grid_.thresholds.size(); ++a) {
      double r = 0.0, w = 0.0;
      for (std::size_t k = a * per_threshold; k < (a + 1) * per_threshold; ++k) r += right[k], w += wrong[k];
      right[a] = r, wrong[a] = w;
    }
    right.resize(grid_.thresholds.size());
    wrong.resize(grid_.thresholds.size());
  }
  return (p_right > 0.0 ? p_right * entropy_bits(right, p_right) : 0.0) +
         (p_wrong > 0.0 ? p_wrong * entropy_bits(wrong, p_wrong) : 0.0);
}

double PsiMethod::next_level() {
  if (cached_for_ == trials_) return cached_level_;
  const std::size_t K = posterior_.size();
  std::vector<double> right(K), wrong(K);
  double best = INFINITY;
  std::size_t best_i = 0;
  for (std::size_t i = 0; i < grid_.levels.size(); ++i) {
    right.resize(K), wrong.resize(K);
    double p_right = 0.0;
    for (std::size_t k = 0; k < K; ++k) {
      right[k] = posterior_[k] * table_[i * K + k];
      wrong[k] = posterior_[k] - right[k];
      p_right += right[k];
    }
    const double expected = expected_entropy(right, wrong, p_right);
    if (expected < best) best = expected, best_i = i;
  }
  cached_for_ = trials_;
  cached_level_ = grid_.levels[best_i];
  return cached_level_;
}

void PsiMethod::update(double level, bool correct) {
  std::vector<double> next(posterior_.size());
  double total = 0.0;
  for (std::size_t k = 0; k < posterior_.size(); ++k) {
    const double p = psi(grid_.shape, params_at(k), level);
    next[k] = posterior_[k] * (correct ? p : 1.0 - p);
    total += next[k];
  }
  ++trials_;
  // An answer no grid point allows (a wrong one where every function of a lapse-free grid is
  // 1, a person's lapse): Bayes' rule would divide by 0. The posterior stays as it was, and the
  // trial is counted so the caller can report it.
  if (!(total > 0.0)) {
    ++impossible_;
    return;
  }
  for (std::size_t k = 0; k < next.size(); ++k) posterior_[k] = next[k] / total;
}

PsiEstimate PsiMethod::estimate() const {
  double m_a = 0, m_b = 0, m_l = 0, s_a = 0, s_b = 0;
  for (std::size_t k = 0; k < posterior_.size(); ++k) {
    const PsychometricParams p = params_at(k);
    const double w = posterior_[k];
    m_a += w * p.threshold, s_a += w * p.threshold * p.threshold;
    m_b += w * p.slope, s_b += w * p.slope * p.slope;
    m_l += w * p.lapse;
  }
  PsiEstimate e;
  e.threshold = m_a, e.threshold_sd = std::sqrt(std::max(0.0, s_a - m_a * m_a));
  e.slope = m_b, e.slope_sd = std::sqrt(std::max(0.0, s_b - m_b * m_b));
  e.lapse = m_l;
  e.entropy_bits = entropy_bits(posterior_, 1.0);
  return e;
}

double PsiMethod::threshold_at_criterion(double criterion) const {
  double mean = 0.0, weight = 0.0;
  for (std::size_t k = 0; k < posterior_.size(); ++k) {
    const double x = threshold_at(grid_.shape, params_at(k), criterion);
    if (std::isfinite(x)) mean += posterior_[k] * x, weight += posterior_[k];
  }
  return mean / weight;
}

}  // namespace ps::study
