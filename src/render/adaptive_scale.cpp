#include "render/adaptive_scale.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace ps {

AdaptiveScale::AdaptiveScale(AdaptiveScaleParams params)
    : params_(std::move(params)), step_costs_(params_.steps.size()) {
  assert(!params_.steps.empty() && params_.window > 0 && "AdaptiveScale: needs at least one step and a window");
}

// Each full redraw is kept twice: as its step's own cost, and divided by its scale squared as an
// estimate of the whole frame's, for the steps not measured lately. The fixed part of a frame
// (the probe depth pass, the reductions over the footprint, the upsample) does not shrink, so a
// reduced frame's normalised cost overestimates the whole one: the estimate errs towards the
// smaller scale, the side that keeps the budget, and the steps' own costs (with the tries up,
// next()) correct it.
void AdaptiveScale::frame(double now_ms, double frame_ms, double scale, bool view_moved, bool full_redraw) {
  if (view_moved) last_move_ms_ = now_ms;
  if (!full_redraw || !(scale > 0.0) || !(frame_ms >= 0.0)) return;
  for (std::size_t i = 0; i < params_.steps.size(); ++i) {
    if (std::abs(params_.steps[i] - scale) > 1e-9) continue;
    std::vector<Measured>& m = step_costs_[i];
    if (m.size() == params_.window) m.erase(m.begin());
    m.push_back({now_ms, frame_ms});
  }
  const double normalised = frame_ms / (scale * scale);
  if (full_costs_.size() < params_.window) {
    full_costs_.push_back(normalised);
  } else {
    full_costs_[next_slot_] = normalised;
    next_slot_ = (next_slot_ + 1) % params_.window;
  }
}

// The median, so that one frame delayed by something else (a shader built, the cores shared)
// does not halve the resolution of the frames after it.
double AdaptiveScale::full_cost_ms() const {
  if (full_costs_.empty()) return 0.0;
  std::vector<double> sorted = full_costs_;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
  return sorted[sorted.size() / 2];
}

double AdaptiveScale::step_cost_ms(std::size_t i, double now_ms) const {
  std::vector<double> recent;
  for (const Measured& m : step_costs_[i])
    if (now_ms - m.at_ms <= params_.memory_ms) recent.push_back(m.cost_ms);
  if (recent.empty()) return -1.0;
  std::nth_element(recent.begin(), recent.begin() + static_cast<long>(recent.size() / 2), recent.end());
  return recent[recent.size() / 2];
}

SurfaceScale AdaptiveScale::next(double now_ms) const {
  const double full = full_cost_ms();
  double moving = 1.0;
  if (full > 0.0) {
    const std::size_t n = params_.steps.size();
    std::size_t chosen = n - 1;
    for (std::size_t i = 0; i < n; ++i) {
      const double own = step_cost_ms(i, now_ms), s = params_.steps[i];
      if ((own >= 0.0 ? own : full * s * s) <= params_.budget_ms) {
        chosen = i;
        break;
      }
    }
    // The way back up: a step with room to spare tries the whole frame, which has no upsample
    // and may cost less than any reduced step, then the step above it; a step measured lately
    // is not tried (its own cost decided above).
    const double own = step_cost_ms(chosen, now_ms);
    if (chosen > 0 && own >= 0.0 && own <= params_.probe_fraction * params_.budget_ms) {
      if (step_cost_ms(0, now_ms) < 0.0)
        chosen = 0;
      else if (step_cost_ms(chosen - 1, now_ms) < 0.0)
        --chosen;
    }
    moving = params_.steps[chosen];
  }
  const bool resting = now_ms - last_move_ms_ > params_.rest_ms;
  return {moving, resting ? 1.0 : moving};
}

}  // namespace ps
