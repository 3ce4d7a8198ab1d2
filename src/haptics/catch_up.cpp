#include "haptics/catch_up.h"

#include <cmath>

namespace ps {

CatchUpDriver::CatchUpDriver(HapticLoop& loop, FakeClock& clock, CatchUpParams params)
    : loop_(loop),
      clock_(clock),
      params_(params),
      period_(static_cast<Clock::Ns::rep>(std::llround(1e9 / loop.params().rate_hz))) {}

// The clock is moved only to a tick's time: run_ticks' sleep_until(deadline) takes the fake
// clock to each deadline itself, so every tick runs exactly at its own time.
std::uint64_t CatchUpDriver::advance_to(Clock::Ns now) {
  if (!started_) {
    if (now > clock_.now()) clock_.advance(now - clock_.now());
    loop_.run_ticks(1);  // the first tick at now: the loop's schedule starts there
    started_ = true;
    next_ = clock_.now() + period_;
    ++ticks_;
    return 1;
  }
  std::uint64_t run = 0;
  if (now - next_ > params_.max_lag) {
    // Too far behind: the clock goes to now, and the loop's schedule, waking that late, runs one
    // tick at the grid point just passed, skips the ones before it and counts a stall.
    clock_.advance(now - clock_.now());
    loop_.run_ticks(1);
    ++run, ++jumps_;
    next_ += ((now - next_) / period_ + 1) * period_;
  }
  for (; next_ <= now; next_ += period_) {
    loop_.run_ticks(1);
    ++run;
  }
  ticks_ += run;
  return run;
}

}  // namespace ps
