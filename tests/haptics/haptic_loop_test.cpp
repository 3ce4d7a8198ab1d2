// The haptic loop under a fake clock, device logs and the sanitizer. No GL.
#include <gtest/gtest.h>

#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "devices/sample_log.h"
#include "devices/sanitizer.h"
#include "haptics/haptic_loop.h"

namespace ps {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<DeviceSample> line_samples() {  // 0 -> 100 mm along x in 1 s
  return {{0.0, {0, 0, 20}, 0, true}, {1.0, {100, 0, 20}, 1, true}};
}

TEST(HapticLoopTest, FakeClockGivesDeterministicTicks) {
  std::vector<HapticState> runs[2];
  for (auto& run : runs) {
    LogDevice device(line_samples(), true, "line");
    FakeClock clock;
    HapticLoop loop(device, clock, HapticLoopParams{});
    for (int i = 0; i < 20; ++i) {
      loop.run_ticks(50);
      run.push_back(loop.state().read());
    }
    const Percentiles p = loop.period_stats();
    EXPECT_EQ(p.p50, 1000.0);  // exactly 1 ms: the fake clock wakes on time
    EXPECT_EQ(p.max, 1000.0);
    loop.run_ticks(1);  // tick 1000 closes the first 1 s rate window
    EXPECT_DOUBLE_EQ(loop.state().read().rate_hz, 1000.0);
  }
  for (size_t i = 0; i < runs[0].size(); ++i)
    for (auto f : {&HapticState::device_mm, &HapticState::position_mm, &HapticState::velocity_mm_s,
                   &HapticState::proxy_mm, &HapticState::force_n})
      EXPECT_EQ(runs[0][i].*f, runs[1][i].*f) << "state " << i;
  const HapticState& last = runs[0].back();
  EXPECT_EQ(last.tick, 1000u);
  EXPECT_DOUBLE_EQ(last.time_s, 0.999);
  EXPECT_NEAR(last.device_mm.x, 99.9, 1e-9);
  EXPECT_NEAR(last.velocity_mm_s.x, 100.0, 2.0);  // Kalman velocity of a 100 mm/s ramp
}

// A mouse is polled once per rendered frame and the haptic thread holds that sample for the
// ~50 ticks until the next one. A stroke at a steady 34 mm/s (400 px/s on the default camera)
// seen at 20 Hz must read as 34 mm/s between polls too, or the texture amplitude, which
// follows this speed, collapses between frames. Bounds: +-25 %, the gain of the shipped speed
// curves stays above 0.5 within +-0.3 x the peak speed (docs/scene-format.md), so +-25 % keeps
// the texture up; the filter's own ripple at 20 Hz samples is a few percent.
TEST(HapticLoopTest, HeldSamplesKeepTheStrokeSpeedBetweenPolls) {
  std::vector<DeviceSample> polls;
  for (int i = 0; i <= 40; ++i) polls.push_back({0.05 * i, {34.0 * 0.05 * i, 0, 20}, 0, true});
  LogDevice device(polls, false, "mouse at 20 Hz");  // sample-and-hold, like the mouse device
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{});
  loop.run_ticks(1000);  // settle over 20 polls
  double lo = 1e9, hi = 0.0;
  for (int i = 0; i < 500; ++i) {
    loop.run_ticks(1);
    const double v = loop.state().read().velocity_mm_s.x;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_GT(lo, 0.75 * 34.0);
  EXPECT_LT(hi, 1.25 * 34.0);
}

// The loop's logs are allocated at construction: logging past the old 100 k reservation, and a
// stall whose missed ticks run back to back inside one HUD window, must not grow either (a
// reallocation on the 1 kHz thread copies megabytes mid-tick).
TEST(HapticLoopTest, LogsNeverReallocateWhileLogging) {
  LogDevice device(line_samples(), true, "line");
  FakeClock clock;
  const HapticLoopParams params;
  HapticLoop loop(device, clock, params);
  const std::size_t period_capacity = loop.period_log_capacity();
  const std::size_t window_capacity = loop.jitter_window_capacity();
  EXPECT_GE(period_capacity, params.keep_periods);
  const double* storage = loop.periods_us().data();
  loop.run_ticks(130'000);
  clock.advance(std::chrono::seconds(5));  // 5000 missed ticks, then caught up at once
  loop.run_ticks(6'000);
  EXPECT_EQ(loop.periods_us().size(), 135'999u);  // every period of 136 000 ticks so far
  EXPECT_EQ(loop.period_log_capacity(), period_capacity);
  EXPECT_EQ(loop.periods_us().data(), storage);
  EXPECT_EQ(loop.jitter_window_capacity(), window_capacity);
  EXPECT_GT(loop.state().read().rate_hz, 0.0);
}

// The period log's storage is resident from construction (BoundedLog writes it once): the haptic
// thread never takes a page fault appending, and a soak's RSS does not climb for the ten minutes
// the 600 000-period log takes to fill (it did: 4.6 MiB over the first 10 minutes). mincore(2)
// says which pages are in memory; with the storage only reserved (std::vector::reserve, as
// before) none of them are.
TEST(HapticLoopTest, ThePeriodLogIsInMemoryBeforeTheFirstTick) {
  const BoundedLog log(HapticLoopParams{}.keep_periods);
  const long page = sysconf(_SC_PAGESIZE);
  const auto begin = reinterpret_cast<std::uintptr_t>(log.values().data()) / page * page;
  const auto end = reinterpret_cast<std::uintptr_t>(log.values().data() + log.capacity());
  std::vector<unsigned char> resident((end - begin + page - 1) / page);
  ASSERT_EQ(mincore(reinterpret_cast<void*>(begin), end - begin, resident.data()), 0) << std::strerror(errno);
  std::size_t in = 0;
  for (unsigned char r : resident) in += r & 1u;
  EXPECT_EQ(in, resident.size()) << "pages of the log not in memory";
  EXPECT_GE(resident.size(), 1000u);  // 600 000 doubles: ~1170 pages
}

// run's frame times and latencies over hours, in fixed memory (StreamingPercentiles): against
// the exact nearest-rank percentiles of 200 000 values spread over six decades, each percentile
// is within half a bin (0.05 %, plus rounding) of the exact one; the count and the max are
// exact and the mean is the exact sum's. Values beyond the scale count in its end bins (the
// max stays exact), and NaN is not counted.
TEST(StreamingPercentilesTest, MatchesTheExactPercentilesWithinHalfABin) {
  std::vector<double> values;
  std::uint64_t x = 88172645463325252ull;  // xorshift64: any spread will do, a fixed one
  StreamingPercentiles s;
  double sum = 0.0;
  for (int i = 0; i < 200'000; ++i) {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    const double v = 0.01 * std::pow(10.0, 6.0 * static_cast<double>(x >> 11) / 9007199254740992.0);
    values.push_back(v);
    s.add(v);
    sum += v;
  }
  const Percentiles exact = percentiles(values), got = s.percentiles();
  const double half_bin = std::sqrt(StreamingPercentiles::kRatio) - 1.0 + 1e-12;
  EXPECT_EQ(got.count, exact.count);
  EXPECT_EQ(got.max, exact.max);
  EXPECT_DOUBLE_EQ(got.mean, sum / 200'000.0);
  EXPECT_NEAR(got.p50 / exact.p50, 1.0, half_bin) << got.p50 << " vs " << exact.p50;
  EXPECT_NEAR(got.p99 / exact.p99, 1.0, half_bin) << got.p99 << " vs " << exact.p99;
  EXPECT_NEAR(got.p999 / exact.p999, 1.0, half_bin) << got.p999 << " vs " << exact.p999;

  StreamingPercentiles edges;
  EXPECT_EQ(edges.percentiles().count, 0u);
  edges.add(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(edges.count(), 0u);
  edges.add(-1.0);  // below kMin: the first bin
  edges.add(1e9);   // above kMax: the last bin, and the max
  const Percentiles e = edges.percentiles();
  EXPECT_EQ(e.count, 2u);
  EXPECT_NEAR(e.p50, StreamingPercentiles::kMin, StreamingPercentiles::kMin * half_bin);
  EXPECT_EQ(e.max, 1e9);
  EXPECT_GT(e.p99, StreamingPercentiles::kMax / StreamingPercentiles::kRatio);
  EXPECT_LE(e.p99, e.max);
}

TEST(HapticLoopTest, PeriodLogKeepsAtMostKeepPeriods) {
  LogDevice device(line_samples(), true, "line");
  FakeClock clock;
  HapticLoopParams params;
  params.keep_periods = 500;
  HapticLoop loop(device, clock, params);
  const std::size_t capacity = loop.period_log_capacity();
  loop.run_ticks(2'000);
  EXPECT_EQ(loop.periods_us().size(), 500u);  // the first 500 periods; later ones dropped
  EXPECT_EQ(loop.period_log_capacity(), capacity);
  EXPECT_EQ(loop.period_stats().p50, 1000.0);  // exactly 1 ms: the fake clock wakes on time
}

TEST(HapticLoopTest, ProxyStaysOnSurfacePublishedByRenderThread) {
  std::vector<DeviceSample> s = {{0.0, {0, 0, 20}, 0, true}, {1.0, {0, 0, -10}, 0, true}};
  LogDevice device(s, true, "press");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{});
  SurfaceModel floor;
  floor.valid = true;
  floor.probe_radius_mm = 8.0;
  loop.surface().publish(floor);
  loop.run_ticks(1001);
  const HapticState st = loop.state().read();
  EXPECT_TRUE(st.in_contact);
  EXPECT_NEAR(st.proxy_mm.z, 8.0, 1e-9);           // sphere resting on z = 0
  EXPECT_GT(st.force_n.z, 0.0);                    // pushes the hand out
  EXPECT_LE(glm::length(st.force_n), 8.0 + 1e-12); // clamped
}

// A press onto the floor and back up: exactly one contact_start and one contact_end, at the
// ticks where in_contact flips, with the approach speed of the press (30 mm/s downward ramp;
// the Kalman velocity has settled long before contact, so within 5 %).
TEST(HapticLoopTest, ContactStartAndEndAreQueuedOnceAtTheFlip) {
  std::vector<DeviceSample> s = {{0.0, {0, 0, 20}, 0, true}, {1.0, {0, 0, -10}, 0, true},
                                 {2.0, {0, 0, 20}, 0, true}};
  LogDevice device(s, true, "press and lift");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{});
  SurfaceModel floor;
  floor.valid = true;
  floor.probe_radius_mm = 8.0;
  loop.surface().publish(floor);
  std::vector<HapticEvent> events;
  std::vector<std::uint64_t> flips;
  bool was = false;
  for (int i = 0; i < 2000; ++i) {
    loop.run_ticks(1);
    const HapticState st = loop.state().read();
    if (st.in_contact != was) flips.push_back(st.tick - 1);
    was = st.in_contact;
    loop.events().drain([&](const HapticEvent& e) { events.push_back(e); });
  }
  ASSERT_EQ(flips.size(), 2u);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, EventKind::contact_start);
  EXPECT_EQ(events[1].kind, EventKind::contact_end);
  EXPECT_EQ(events[0].tick, flips[0]);
  EXPECT_EQ(events[1].tick, flips[1]);
  EXPECT_NEAR(events[0].time_s, 0.001 * static_cast<double>(flips[0]), 1e-12);
  EXPECT_NEAR(events[0].value, 30.0, 1.5);
  EXPECT_EQ(loop.events().dropped(), 0u);
}

TEST(EventQueueTest, KeepsOrderDropsWhenFullAndCounts) {
  EventQueue q(4);
  for (int i = 0; i < 6; ++i) {
    HapticEvent e;
    e.tick = static_cast<std::uint64_t>(i);
    EXPECT_EQ(q.push(e), i < 4);
  }
  EXPECT_EQ(q.dropped(), 2u);
  std::vector<std::uint64_t> ticks;
  EXPECT_EQ(q.drain([&](const HapticEvent& e) { ticks.push_back(e.tick); }), 4u);
  EXPECT_EQ(ticks, (std::vector<std::uint64_t>{0, 1, 2, 3}));
  HapticEvent e;
  e.tick = 9;
  EXPECT_TRUE(q.push(e));  // room again after the drain
  EXPECT_EQ(q.drain([&](const HapticEvent& x) { EXPECT_EQ(x.tick, 9u); }), 1u);
}

TEST(EventQueueTest, JsonLineHasFixedFieldsAndEscapes) {
  HapticEvent e;
  e.kind = EventKind::button_fired;
  e.tick = 250;
  e.time_s = 0.25;
  e.surface = 2;
  e.index = 1;
  e.value = 0.5;
  e.position_mm = {1.0, -2.0, 8.0};
  e.set_label("scene \"b\".toml");
  EXPECT_EQ(event_json(e),
            "{\"t\":0.25,\"tick\":250,\"event\":\"button_fired\",\"surface\":2,\"index\":1,"
            "\"value\":0.5,\"pos\":[1,-2,8],\"label\":\"scene \\\"b\\\".toml\"}");
  e.set_label(std::string(100, 'x'));
  EXPECT_EQ(e.label_view().size(), 47u);  // truncated to the fixed buffer, NUL kept
}

TEST(DeviceSanitizerTest, NanJumpsAndBackwardTimeNeverReachTheProxy) {
  const std::string log =
      "# bad data on purpose\n"
      "0.000 0 0 20 0\n"
      "0.010 1 0 20 0\n"
      "0.020 nan 0 20 0\n"
      "0.030 2 inf 20 0\n"
      "0.040 500 0 20 0   # a 499 mm jump\n"
      "0.060 4 0 20 0\n";
  auto samples = parse_sample_log(log, "bad.log");
  ASSERT_TRUE(samples.ok()) << samples.error().message;
  LogDevice device(samples.value(), false, "bad");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{});
  double max_x = 0.0;
  for (int i = 0; i < 60; ++i) {
    loop.run_ticks(1);
    const HapticState st = loop.state().read();
    for (const glm::dvec3& v : {st.device_mm, st.position_mm, st.velocity_mm_s, st.proxy_mm, st.force_n})
      ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) << "tick " << i;
    max_x = std::max(max_x, st.device_mm.x);
  }
  const SanitizerCounts c = loop.state().read().rejected;
  EXPECT_EQ(c.non_finite, 20u);     // two bad lines, each held for 10 ticks
  EXPECT_EQ(c.jumps_clamped, 20u);  // ticks 40..59 each move 5 mm toward x = 500
  EXPECT_DOUBLE_EQ(max_x, 1.0 + 5.0 * 20);
}

TEST(DeviceSanitizerTest, CountsEachKind) {
  DeviceSanitizer s({5.0});
  EXPECT_TRUE(s.filter({0.0, {0, 0, 0}, 0, true}));
  EXPECT_FALSE(s.filter({0.001, {kNaN, 0, 0}, 0, true}));
  EXPECT_FALSE(s.filter({-1.0, {0, 0, 0}, 0, true}));
  EXPECT_FALSE(s.filter({0.002, {0, 0, 0}, 0, false}));
  auto clamped = s.filter({0.003, {100, 0, 0}, 0, true});
  ASSERT_TRUE(clamped);
  EXPECT_DOUBLE_EQ(clamped->position_mm.x, 5.0);
  EXPECT_EQ(s.counts().non_finite, 1u);
  EXPECT_EQ(s.counts().time_backwards, 1u);
  EXPECT_EQ(s.counts().invalid, 1u);
  EXPECT_EQ(s.counts().jumps_clamped, 1u);
}

TEST(SampleLogTest, ErrorsNameFileAndLine) {
  auto r = parse_sample_log("0 0 0 0 0\n# ok\n0.1 1 2\n", "t.log");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "t.log:3: expected 5 fields 'time_s x y z buttons', got 3");
  r = parse_sample_log("0 0 zero 0 0\n", "t.log");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "t.log:1: y: not a number: 'zero'");
  r = parse_sample_log("0 0 0 0 -1\n", "t.log");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("t.log:1: buttons"), std::string::npos);
  EXPECT_FALSE(parse_sample_log("# nothing\n", "e.log").ok());
}

TEST(SampleLogTest, FormatRoundTripsExactly) {
  const DeviceSample s{0.1 + 0.2, {1.0 / 3.0, -2e-300, 12345.678901234567}, 5, true};
  auto r = parse_sample_log(format_sample(s), "x");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value()[0].time_s, s.time_s);
  EXPECT_EQ(r.value()[0].position_mm, s.position_mm);
  EXPECT_EQ(r.value()[0].buttons, 5u);
}

TEST(SampleLogTest, TrajectoryInterpolatesPlaybackHolds) {
  LogDevice traj(line_samples(), true, "t"), play(line_samples(), false, "p");
  EXPECT_DOUBLE_EQ(traj.read(0.25).position_mm.x, 25.0);
  EXPECT_DOUBLE_EQ(play.read(0.25).position_mm.x, 0.0);
  EXPECT_DOUBLE_EQ(play.read(1.5).position_mm.x, 100.0);
  EXPECT_DOUBLE_EQ(traj.duration_s(), 1.0);
}

}  // namespace
}  // namespace ps
