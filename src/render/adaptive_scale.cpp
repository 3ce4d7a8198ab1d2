#include "render/adaptive_scale.h"

#include <algorithm>
#include <cassert>
#include <utility>

namespace ps {

AdaptiveScale::AdaptiveScale(AdaptiveScaleParams params) : params_(std::move(params)) {
  assert(!params_.steps.empty() && params_.window > 0 && "AdaptiveScale: needs at least one step and a window");
}

// A redraw's cost is modelled as proportional to its pixels (scale squared). The fixed part of a
// frame (the probe depth pass, the reductions over the footprint, the present) does not shrink,
// so a reduced frame's normalised cost overestimates the full one: the controller errs towards
// the smaller scale, which is the side that keeps the budget.
void AdaptiveScale::frame(double now_ms, double frame_ms, double scale, bool view_moved, bool full_redraw) {
  if (view_moved) last_move_ms_ = now_ms;
  if (!full_redraw || !(scale > 0.0) || !(frame_ms >= 0.0)) return;
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

SurfaceScale AdaptiveScale::next(double now_ms) const {
  const double full = full_cost_ms();
  double moving = 1.0;
  if (full > 0.0) {
    moving = params_.steps.back();
    for (double s : params_.steps)
      if (full * s * s <= params_.budget_ms) {
        moving = s;
        break;
      }
  }
  const bool resting = now_ms - last_move_ms_ > params_.rest_ms;
  return {moving, resting ? 1.0 : moving};
}

}  // namespace ps
