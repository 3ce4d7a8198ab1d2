// The haptic loop on a thread that cannot sleep: a web page's (WebAssembly on the page's own
// thread, called once per animation frame), or any caller that is handed the time now and then.
// CatchUpDriver runs, at each call, every tick whose deadline has passed, each at its own
// deadline on a FakeClock, through HapticLoop::run_ticks, the code `replay` runs: the same ticks
// at the same times as a loop on its own thread waking on time, so the same states bit for bit
// however the calls fall (CatchUpDriverTest). A caller more than `max_lag` behind (a hidden
// tab, a frame that took long) does not get the missed ticks in a burst: the clock jumps to now
// and the loop's schedule treats that as a late wake-up (haptics/tick_schedule.h): the ticks in
// between are skipped and counted, a tick_stall event is raised, and the force ramps back in.
// Desktop builds run the loop on its own thread (HapticLoop::start) and do not need this.
#pragma once

#include <cstdint>

#include "haptics/clock.h"
#include "haptics/haptic_loop.h"

namespace ps {

struct CatchUpParams {
  // Ticks due but further behind than this are skipped instead of run in a burst: 100 ms, six
  // frames at 60 Hz, 100 ticks of catch-up at 1 kHz in one call at most.
  Clock::Ns max_lag{100'000'000};
};

class CatchUpDriver {
 public:
  // `loop` must run on `clock` and not have ticked yet; both outlive the driver.
  CatchUpDriver(HapticLoop& loop, FakeClock& clock, CatchUpParams params = {});

  // Runs the ticks due at `now` (the caller's clock, e.g. performance.now(), any epoch; never
  // earlier than the last call's): the first call runs the first tick at `now`; later calls run
  // every tick whose deadline (first tick + k periods) is at or before `now`. Returns the ticks
  // run by this call.
  std::uint64_t advance_to(Clock::Ns now);

  std::uint64_t ticks() const { return ticks_; }  // run so far
  std::uint64_t jumps() const { return jumps_; }  // calls that were more than max_lag behind

 private:
  HapticLoop& loop_;
  FakeClock& clock_;
  CatchUpParams params_;
  Clock::Ns period_;
  Clock::Ns next_{0};  // the next tick's deadline
  bool started_ = false;
  std::uint64_t ticks_ = 0, jumps_ = 0;
};

}  // namespace ps
