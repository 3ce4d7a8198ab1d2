// CatchUpDriver (haptics/catch_up.h): the haptic loop driven by a caller that is handed the time
// now and then (a web page's animation frames) must give the states a loop waking on time gives,
// bit for bit, however the calls fall; and a caller far behind must not get the missed ticks
// in a burst. No GL.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <vector>

#include "devices/sample_log.h"
#include "haptics/catch_up.h"
#include "haptics/haptic_loop.h"

namespace ps {
namespace {

using std::chrono::milliseconds;
using std::chrono::nanoseconds;
using std::chrono::seconds;

std::vector<DeviceSample> stroke() {  // 0 -> 60 mm along x in 1.5 s, pressing 1 mm into z = 0
  return {{0.0, {0, 0, 5}, 0, true}, {0.5, {10, 0, -1}, 0, true}, {2.0, {60, 0, -1}, 1, true}};
}

// The reference: the loop ticked one by one on a fake clock (a thread waking on time, `replay`).
std::vector<HapticState> on_time(std::uint64_t ticks) {
  LogDevice device(stroke(), true, "stroke");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{});
  std::vector<HapticState> states;
  for (std::uint64_t i = 0; i < ticks; ++i) {
    loop.run_ticks(1);
    states.push_back(loop.state().read());
  }
  return states;
}

void expect_same_state(const HapticState& a, const HapticState& b, const std::string& where) {
  EXPECT_EQ(a.tick, b.tick) << where;
  EXPECT_EQ(a.time_s, b.time_s) << where;
  for (auto f : {&HapticState::device_mm, &HapticState::position_mm, &HapticState::velocity_mm_s,
                 &HapticState::proxy_mm, &HapticState::force_n})
    EXPECT_EQ(a.*f, b.*f) << where;
}

// Calls every ~16.7 ms with up to 9 ms of jitter, some twice at the same time, one 90 ms late
// (under max_lag: caught up), from an epoch of 5 s (performance.now() of a page open a while).
TEST(CatchUpDriverTest, IrregularCallsGiveTheStatesOfALoopWakingOnTime) {
  const std::vector<HapticState> reference = on_time(1600);
  LogDevice device(stroke(), true, "stroke");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{});
  CatchUpDriver driver(loop, clock);
  const nanoseconds epoch = seconds(5);
  std::uint64_t x = 0x9E3779B97F4A7C15ull;  // xorshift: a fixed jitter sequence
  nanoseconds t = epoch;
  int calls = 0, checked = 0;
  while (t < epoch + milliseconds(1500)) {
    const std::uint64_t ran = driver.advance_to(t);
    ++calls;
    const HapticState s = loop.state().read();
    ASSERT_EQ(s.tick, driver.ticks()) << "call " << calls;  // the state's tick counts the ticks run
    if (calls == 1) EXPECT_EQ(ran, 1u);
    // Every tick due and none more: tick k (from 1) is due at epoch + (k - 1) ms; the last one
    // run was due at or before t, the next is due after it.
    EXPECT_LE(epoch + nanoseconds(static_cast<std::int64_t>(s.tick - 1) * 1'000'000), t);
    EXPECT_GT(epoch + nanoseconds(static_cast<std::int64_t>(s.tick) * 1'000'000), t);
    if (s.tick <= reference.size()) {
      expect_same_state(s, reference[s.tick - 1], "call " + std::to_string(calls));
      ++checked;
    }
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    const int jitter_us = static_cast<int>(x % 9000);
    if (calls % 17 == 5) continue;                                   // the same time again
    t += (calls == 40 ? milliseconds(90) : nanoseconds(16'666'667)) + std::chrono::microseconds(jitter_us);
  }
  EXPECT_GT(checked, 70);
  EXPECT_EQ(driver.jumps(), 0u);
  EXPECT_EQ(loop.state().read().stalls, 0u);
  EXPECT_EQ(loop.state().read().skipped_ticks, 0u);
}

// A caller 2 s behind (a hidden tab) gets one tick now, not 2000 in a burst: the loop's schedule
// counts the skipped ticks and a stall, raises tick_stall, and goes on on the same grid.
TEST(CatchUpDriverTest, FarBehindSkipsTheMissedTicksAsAStallInsteadOfABurst) {
  LogDevice device(stroke(), true, "stroke");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{});
  CatchUpDriver driver(loop, clock);
  for (int i = 0; i <= 10; ++i) driver.advance_to(milliseconds(10 * i));  // ticks due at 0..100 ms
  ASSERT_EQ(driver.ticks(), 101u);
  const std::uint64_t ran = driver.advance_to(milliseconds(2100) + std::chrono::microseconds(400));
  EXPECT_EQ(ran, 1u);
  EXPECT_EQ(driver.jumps(), 1u);
  const HapticState s = loop.state().read();
  EXPECT_EQ(s.stalls, 1u);
  EXPECT_EQ(s.skipped_ticks, 1999u);  // the ticks due at 101..2099 ms skipped, 2100's ran
  EXPECT_EQ(s.tick, 102u);            // the 102nd tick run
  // It ran when it was called, as a thread waking late does (the session's time follows the
  // caller's clock); the grid stays: the next tick is due at 2101 ms.
  EXPECT_NEAR(s.time_s, 2.1004, 1e-9);
  int stalls = 0;
  loop.events().drain([&](const HapticEvent& e) {
    if (e.kind == EventKind::tick_stall) {
      ++stalls;
      EXPECT_EQ(e.index, 1999);
    }
  });
  EXPECT_EQ(stalls, 1);
  // On from the grid point it ran at: 2101 .. 2116 ms are due at 2116.4 ms.
  EXPECT_EQ(driver.advance_to(milliseconds(2116) + std::chrono::microseconds(400)), 16u);
  EXPECT_NEAR(loop.state().read().time_s, 2.116, 1e-9);
  EXPECT_EQ(loop.state().read().stalls, 1u);
}

}  // namespace
}  // namespace ps
