// Snapshot exchange between two threads: a reader must never see a torn value. Run under
// ThreadSanitizer with the `tsan` build (docs/haptics.md).
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "core/snapshot.h"
#include "haptics/haptic_loop.h"

namespace ps {
namespace {

struct Wide {  // every field equal: a torn copy mixes two writes and shows up as unequal fields
  std::uint64_t a[13];
};

TEST(SnapshotTest, ReaderNeverSeesTornWrites) {
  Snapshot<Wide> snap;
  std::atomic<bool> done{false};
  std::uint64_t torn = 0, reads = 0, last = 0, backwards = 0;
  std::thread writer([&] {
    for (std::uint64_t i = 1; i <= 300'000; ++i) {
      Wide w;
      for (auto& x : w.a) x = i;
      snap.publish(w);
    }
    done.store(true);
  });
  while (!done.load()) {
    const Wide w = snap.read();
    for (auto x : w.a) torn += x != w.a[0];
    backwards += w.a[0] < last;
    last = w.a[0];
    ++reads;
  }
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

}  // namespace
}  // namespace ps
