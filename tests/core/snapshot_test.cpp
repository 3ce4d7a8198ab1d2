// Snapshot exchange between two threads: a reader must never see a torn value. Run under
// ThreadSanitizer with the `tsan` build (docs/haptics.md).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>

#include "core/snapshot.h"
#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"

namespace ps {
namespace {

struct Wide {  // every field equal: a torn copy mixes two writes and shows up as unequal fields
  std::uint64_t a[13];
};

TEST(SnapshotTest, ReaderNeverSeesTornWrites) {
  Snapshot<Wide> snap;
  std::atomic<bool> done{false}, reading{false};
  std::uint64_t torn = 0, reads = 0, last = 0, backwards = 0;
  std::thread writer([&] {
    // Start writing once the reader reads: on a loaded machine the writer could otherwise finish
    // all its writes before the reader's first look (no read at all, nothing tested).
    while (!reading.load()) std::this_thread::yield();
    for (std::uint64_t i = 1; i <= 300'000; ++i) {
      Wide w;
      for (auto& x : w.a) x = i;
      snap.publish(w);
    }
    done.store(true);
  });
  do {
    const Wide w = snap.read();
    reading.store(true);
    for (auto x : w.a) torn += x != w.a[0];
    backwards += w.a[0] < last;
    last = w.a[0];
    ++reads;
  } while (!done.load());
  writer.join();
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(backwards, 0u);
  EXPECT_EQ(snap.read().a[0], 300'000u);
  EXPECT_GT(reads, 0u);
}

// The real loop on its real thread and clock for 0.2 s, with a render-side writer.
TEST(SnapshotTest, HapticThreadAndRenderThreadExchange) {
  LogDevice device({{0.0, {0, 0, 20}, 0, true}, {1.0, {50, 0, 0}, 0, true}}, true, "t");
  SteadyClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{});
  loop.start();
  std::uint64_t last_tick = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
  for (std::uint64_t frame = 1; std::chrono::steady_clock::now() < end; ++frame) {
    SurfaceModel m;
    m.valid = true;
    m.probe_radius_mm = 8.0;
    m.frame = frame;
    loop.surface().publish(m);
    const HapticState st = loop.state().read();
    EXPECT_GE(st.tick, last_tick);
    last_tick = st.tick;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  loop.stop();
  EXPECT_GT(last_tick, 100u);  // ~200 at 1 kHz; generous for a loaded 2-core machine
}

// The time-keeping settings reach the real thread: the slice request is a raw syscall with the
// kernel's struct layout, which a wrong size or field order makes fail (E2BIG / EINVAL); the
// summary line names each setting. (How well it keeps time is measured in bench-haptics.)
TEST(HapticLoopTimingTest, SliceSlackAndSpinAreAppliedOnTheHapticThread) {
  LogDevice device({{0.0, {0, 0, 20}, 0, true}, {1.0, {50, 0, 0}, 0, true}}, true, "t");
  SteadyClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{});
  loop.start();
  while (loop.state().read().tick < 5) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  loop.stop();
  const std::string s = loop.scheduling();
  EXPECT_NE(s.find("slice 100 us"), std::string::npos) << s;
  EXPECT_NE(s.find("timer slack 1000 ns"), std::string::npos) << s;
  EXPECT_NE(s.find("wake spin 50 us"), std::string::npos) << s;
}

// With a wake spin the clock still never returns early (the spin polls up to the deadline).
TEST(HapticLoopTimingTest, SpinningClockNeverWakesEarly) {
  SteadyClock clock;
  clock.set_wake_spin(std::chrono::microseconds(200));
  for (int i = 0; i < 50; ++i) {
    const Clock::Ns when = clock.now() + std::chrono::microseconds(300 + 20 * i);
    clock.sleep_until(when);
    EXPECT_GE(clock.now(), when);
  }
}

// The event queue between the haptic thread (producer) and the render thread (consumer): every
// pushed event arrives once, in order, whole (label and tick written together), or is counted as
// dropped; never torn, never twice. Under TSan this also checks the ring's memory ordering.
TEST(EventQueueThreadsTest, ProducerAndConsumerOnTwoThreads) {
  EventQueue q(64);  // small: the producer outruns the consumer and some pushes are dropped
  constexpr std::uint64_t kEvents = 200'000;
  std::uint64_t accepted = 0;
  std::thread producer([&] {
    for (std::uint64_t i = 0; i < kEvents; ++i) {
      HapticEvent e;
      e.tick = i;
      e.value = static_cast<double>(i);
      e.set_label(std::to_string(i));
      if (q.push(e)) ++accepted;
    }
  });
  std::uint64_t received = 0, last = 0;
  bool first = true, whole = true;
  auto consume = [&](const HapticEvent& e) {
    whole = whole && e.value == static_cast<double>(e.tick) && e.label_view() == std::to_string(e.tick);
    if (!first) {
      EXPECT_GT(e.tick, last);
    }
    first = false;
    last = e.tick;
    ++received;
  };
  while (received + q.dropped() < kEvents) q.drain(consume);
  producer.join();
  q.drain(consume);
  EXPECT_TRUE(whole);
  EXPECT_EQ(received, accepted);
  EXPECT_EQ(received + q.dropped(), kEvents);
}

}  // namespace
}  // namespace ps
