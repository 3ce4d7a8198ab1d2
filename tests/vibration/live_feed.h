// Test helper: ticks pushed into a LiveVibration's feed at 1 kHz on the steady clock, as the
// haptic thread pushes them, with an optional action before a given tick (unplug a device, plug
// one in) on the producing thread.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <thread>
#include <vector>

#include "vibration/live.h"

namespace ps::vibration::test {

inline void feed_live(LiveVibration& v, const std::vector<TickSample>& ticks,
                      const std::function<void(std::uint64_t tick)>& before_tick = {}) {
  const auto t0 = std::chrono::steady_clock::now();
  for (TickSample s : ticks) {
    const auto at = t0 + std::chrono::microseconds(static_cast<std::int64_t>(s.tick) * 1000);
    std::this_thread::sleep_until(at);
    if (before_tick) before_tick(s.tick);
    s.clock_ns = at.time_since_epoch().count();
    v.feed().push(s);
  }
}

}  // namespace ps::vibration::test
