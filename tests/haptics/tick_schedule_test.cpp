// Falling behind (haptics/tick_schedule.h, docs/haptics.md "Falling behind"): missed ticks are
// skipped, never run back to back; a stall is reported and the force ramps back in. No GL.
#include <gtest/gtest.h>

#include <chrono>
#include <vector>

#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "haptics/tick_schedule.h"

namespace ps {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;

TEST(TickScheduleTest, OnTimeAndSlightlyLateWakeUpsKeepTheGrid) {
  TickSchedule s(milliseconds(1), {});
  s.start(milliseconds(0));
  EXPECT_EQ(s.deadline(), milliseconds(1));
  TickSchedule::Wake w = s.woke(milliseconds(1));
  EXPECT_EQ(w.skipped, 0u);
  EXPECT_EQ(w.late, milliseconds(0));
  w = s.woke(microseconds(2300));  // 0.3 ms late: the tick runs, the grid stays
  EXPECT_EQ(w.skipped, 0u);
  EXPECT_EQ(w.late, microseconds(300));
  EXPECT_FALSE(w.stall);
  EXPECT_EQ(s.deadline(), milliseconds(3));
  EXPECT_EQ(s.force_scale(milliseconds(3)), 1.0);
}

TEST(TickScheduleTest, AStallSkipsTheMissedTicksAndRampsTheForce) {
  TickSchedule s(milliseconds(1), {});  // stall at 5 ms late, ramp over 50 ms
  s.start(milliseconds(0));
  const TickSchedule::Wake w = s.woke(microseconds(8500));  // due at 1 ms
  EXPECT_EQ(w.late, microseconds(7500));
  EXPECT_EQ(w.skipped, 7u);  // 1..7 ms missed; this tick stands for 8 ms
  EXPECT_TRUE(w.stall);
  EXPECT_EQ(s.deadline(), milliseconds(9));
  EXPECT_EQ(s.force_scale(microseconds(8500)), 0.0);
  EXPECT_DOUBLE_EQ(s.force_scale(microseconds(33500)), 0.5);
  EXPECT_EQ(s.force_scale(microseconds(58500)), 1.0);
  EXPECT_FALSE(s.woke(milliseconds(9)).stall);
}

TEST(TickScheduleTest, LateButUnderTheThresholdIsNoStall) {
  TickSchedule s(milliseconds(1), {});
  s.start(milliseconds(0));
  const TickSchedule::Wake w = s.woke(microseconds(4900));
  EXPECT_EQ(w.skipped, 3u);
  EXPECT_FALSE(w.stall);
  EXPECT_EQ(s.force_scale(microseconds(4900)), 1.0);
}

// The loop itself: a 30 ms stall in the middle of a press. Before, the 29 missed ticks ran back
// to back (periods of 0 us, 29 force updates from stale samples in a burst); now none does, the
// stall is one event and one count, and the force restarts from zero and ramps up: against a
// twin loop without the ramp, exactly scale x its force.
struct StalledPress {
  explicit StalledPress(Clock::Ns ramp) : device(samples(), true, "press"), loop(device, clock, params(ramp)) {
    SurfaceModel floor;
    floor.valid = true;
    floor.probe_radius_mm = 8.0;
    loop.surface().publish(floor);
    loop.run_ticks(400);  // pressed 3 mm into the floor since 0.3 s
    clock.advance(milliseconds(30));
  }
  static std::vector<DeviceSample> samples() { return {{0.0, {0, 0, 20}, 0, true}, {0.3, {0, 0, 5}, 0, true}}; }
  static HapticLoopParams params(Clock::Ns ramp) {
    HapticLoopParams p;
    p.schedule.ramp_ns = ramp;
    return p;
  }
  LogDevice device;
  FakeClock clock;
  HapticLoop loop;
};

TEST(TickScheduleTest, TheLoopNeverBurstsAfterAStall) {
  StalledPress ramped(milliseconds(50)), twin(Clock::Ns{0});
  ASSERT_GT(glm::length(ramped.loop.state().read().force_n), 1.0);
  ramped.loop.run_ticks(1);
  twin.loop.run_ticks(1);
  HapticState st = ramped.loop.state().read();
  EXPECT_EQ(st.stalls, 1u);
  EXPECT_EQ(st.skipped_ticks, 29u);
  EXPECT_DOUBLE_EQ(st.last_stall_ms, 29.0);
  EXPECT_EQ(glm::length(st.force_n), 0.0);  // restarts from zero
  EXPECT_GT(glm::length(twin.loop.state().read().force_n), 1.0);
  ramped.loop.run_ticks(25);
  twin.loop.run_ticks(25);
  st = ramped.loop.state().read();
  EXPECT_DOUBLE_EQ(st.force_scale, 0.5);  // 25 ms into the 50 ms ramp
  EXPECT_NEAR(glm::length(st.force_n), 0.5 * glm::length(twin.loop.state().read().force_n), 1e-12);
  EXPECT_EQ(st.proxy_mm, twin.loop.state().read().proxy_mm);  // the ramp scales the force only
  ramped.loop.run_ticks(100);
  EXPECT_EQ(ramped.loop.state().read().force_scale, 1.0);
  for (double p : ramped.loop.periods_us()) EXPECT_GE(p, 1000.0) << "a tick ran early: a burst";
  int stalls = 0;
  ramped.loop.events().drain([&](const HapticEvent& e) {
    if (e.kind != EventKind::tick_stall) return;
    ++stalls;
    EXPECT_EQ(e.index, 29);
    EXPECT_DOUBLE_EQ(e.value, 29.0);
  });
  EXPECT_EQ(stalls, 1);
}

}  // namespace
}  // namespace ps
