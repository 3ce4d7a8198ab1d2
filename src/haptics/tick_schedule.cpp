#include "haptics/tick_schedule.h"

#include <algorithm>

namespace ps {

TickSchedule::Wake TickSchedule::woke(Clock::Ns now) {
  Wake w;
  const Clock::Ns due = deadline();
  w.late = std::max(now - due, Clock::Ns{0});
  w.skipped = static_cast<std::uint64_t>(w.late / period_);
  deadline_ = due + period_ * static_cast<std::int64_t>(w.skipped);
  w.stall = w.late >= params_.stall_ns;
  if (w.stall) ramp_start_ = now;
  return w;
}

double TickSchedule::force_scale(Clock::Ns now) const {
  if (ramp_start_.count() < 0 || params_.ramp_ns.count() <= 0) return 1.0;
  const double f = static_cast<double>((now - ramp_start_).count()) / static_cast<double>(params_.ramp_ns.count());
  return std::clamp(f, 0.0, 1.0);
}

}  // namespace ps
