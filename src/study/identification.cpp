#include "study/identification.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace ps::study {
namespace {

// -sum (n / N) log2(n / N) over the counts, and how many of them are non-zero.
struct Entropy {
  double bits = 0.0;
  int occupied = 0;
};
Entropy entropy(const std::vector<int>& counts, int total) {
  Entropy e;
  for (int n : counts)
    if (n > 0) {
      const double p = static_cast<double>(n) / total;
      e.bits -= p * std::log2(p);
      ++e.occupied;
    }
  return e;
}

}  // namespace

ConfusionMatrix::ConfusionMatrix(int stimuli, int responses)
    : counts_(static_cast<std::size_t>(stimuli), std::vector<int>(static_cast<std::size_t>(responses), 0)) {
  assert(stimuli > 0 && responses > 0 && "ConfusionMatrix: at least one stimulus and one response");
}

ConfusionMatrix::ConfusionMatrix(std::vector<std::vector<int>> counts) : counts_(std::move(counts)) {
  for ([[maybe_unused]] const auto& row : counts_)
    assert(row.size() == counts_[0].size() && "ConfusionMatrix: every row needs the same number of columns");
}

void ConfusionMatrix::add(int shown, int answered, int count) {
  assert(shown >= 0 && shown < stimuli() && answered >= 0 && answered < responses() &&
         "ConfusionMatrix::add: stimulus or response out of range");
  counts_[shown][answered] += count;
}

int ConfusionMatrix::total() const {
  int n = 0;
  for (const auto& row : counts_)
    for (int c : row) n += c;
  return n;
}

IdentificationStats identification_stats(const ConfusionMatrix& m) {
  IdentificationStats s;
  s.trials = m.total();
  if (s.trials == 0) return s;
  std::vector<int> rows(m.stimuli(), 0), cols(m.responses(), 0), all;
  int diagonal = 0;
  for (int i = 0; i < m.stimuli(); ++i)
    for (int j = 0; j < m.responses(); ++j) {
      const int n = m.count(i, j);
      rows[i] += n, cols[j] += n;
      all.push_back(n);
      if (i == j) diagonal += n;
    }
  s.percent_correct = 100.0 * diagonal / s.trials;
  const Entropy hr = entropy(rows, s.trials), hc = entropy(cols, s.trials), hx = entropy(all, s.trials);
  s.information_bits = std::max(0.0, hr.bits + hc.bits - hx.bits);  // >= 0 up to rounding
  const int cells = hr.occupied * hc.occupied;
  s.miller_madow_bits = (hr.occupied + hc.occupied - cells - 1) / (2.0 * s.trials * std::numbers::ln2);
  const double cap = std::log2(static_cast<double>(std::min(hr.occupied, hc.occupied)));
  s.corrected_bits = std::clamp(s.information_bits + s.miller_madow_bits, 0.0, cap);
  s.distinguishable = std::exp2(s.corrected_bits);
  return s;
}

}  // namespace ps::study
