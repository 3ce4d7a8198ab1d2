#include "calibrate/staircase.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace ps::calibrate {

Staircase::Staircase(const StaircaseParams& params) : params_(params), delta_(params.start_delta) {
  assert(params.start_delta > 0.0 && params.coarse_factor > 1.0 && params.fine_factor > 1.0 &&
         "Staircase: start_delta > 0 and step factors > 1 (a factor of 1 never moves)");
}

bool Staircase::done() const {
  return reversal_count() >= params_.reversals || trials_ >= params_.max_trials;
}

void Staircase::step(int direction) {
  const bool reversal = direction_ != 0 && direction != direction_;
  if (reversal) reversal_deltas_.push_back(delta_);
  direction_ = direction;
  const double f = reversal_count() < params_.coarse_reversals ? params_.coarse_factor : params_.fine_factor;
  delta_ = std::clamp(direction < 0 ? delta_ / f : delta_ * f, params_.min_delta, params_.max_delta);
}

bool Staircase::record(bool correct) {
  ++trials_;
  const int before = reversal_count();
  if (!correct) {
    correct_run_ = 0;
    step(+1);
  } else if (++correct_run_ == 2) {
    correct_run_ = 0;
    step(-1);
  }
  return reversal_count() > before;
}

double Staircase::threshold() const {
  if (reversal_deltas_.empty()) return delta_;
  const int n = std::min<int>(params_.average_last, reversal_count());
  double log_sum = 0.0;
  for (int i = reversal_count() - n; i < reversal_count(); ++i) log_sum += std::log(reversal_deltas_[i]);
  return std::exp(log_sum / n);
}

}  // namespace ps::calibrate
