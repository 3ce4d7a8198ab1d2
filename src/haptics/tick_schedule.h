// When the haptic loop's next tick runs, and what happens after it fell behind (docs/haptics.md,
// "Falling behind"). Ticks sit on a fixed grid, start + k * period, so the rate never drifts.
// A tick that wakes a whole period or more late does not run the missed ticks back to back (a
// burst of stale forces is a hazard on a force device): they are skipped, counted, and the next
// tick goes on from the grid point just passed. A wake-up later than `stall_ns` is a stall: the
// loop reports it and the force restarts from zero, ramping back to full over `ramp_ns`, so the
// hand is not kicked by a force computed from where it was before the stall.
#pragma once

#include <cstdint>

#include "haptics/clock.h"

namespace ps {

struct TickScheduleParams {
  // A wake-up this late is a stall: 5 periods at 1 kHz, beyond any scheduling jitter measured
  // on a loaded machine's p99.9 (docs/haptics.md), well below what a hand notices (~20 ms).
  Clock::Ns stall_ns{5'000'000};
  // The force's ramp after a stall: 50 ms, the time a hand needs to react to a force change.
  Clock::Ns ramp_ns{50'000'000};
};

class TickSchedule {
 public:
  TickSchedule(Clock::Ns period, const TickScheduleParams& params) : period_(period), params_(params) {}

  void start(Clock::Ns now) { deadline_ = now; }
  Clock::Ns deadline() const { return deadline_ + period_; }  // when the next tick is due

  // What waking at `now` for deadline() meant.
  struct Wake {
    std::uint64_t skipped = 0;  // whole ticks missed and not run
    Clock::Ns late{0};          // how late the wake-up was
    bool stall = false;         // late >= stall_ns
  };
  // Moves to the latest grid point <= now (the tick about to run), skipping missed ones.
  Wake woke(Clock::Ns now);

  // The force's scale at `now`: 1, or after a stall a linear ramp from 0 to 1 over ramp_ns.
  double force_scale(Clock::Ns now) const;

 private:
  Clock::Ns period_;
  TickScheduleParams params_;
  Clock::Ns deadline_{0};       // the grid point of the tick that ran last
  Clock::Ns ramp_start_{-1};    // the last stall's wake-up (-1: none)
};

}  // namespace ps
