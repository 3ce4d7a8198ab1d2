// The haptic loop's tick feed (haptics/tick_feed.h) on a fake clock: one record per tick, in
// order; in contact with the plane z = 0 the record carries the contact point on the surface
// (proxy centre less the probe radius: z = 0), the normal +z, a positive normal force, and the
// approach speed on the tick the contact starts only. The feed drops (and counts) when full.
#include <gtest/gtest.h>

#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "vibration/stroke.h"
#include "world/haptic_scene.h"

namespace ps {
namespace {

TEST(TickFeed, OneRecordPerTickWithTheContactPointOnTheSurface) {
  Scene scene = vibration::test::texture_scene(0.5, 0.0);
  scene.probe.radius_mm = 8.0;
  auto haptic = world::HapticScene::build(scene);
  ASSERT_TRUE(haptic) << haptic.error().message;
  // Down from 20 mm to 6 mm (2 mm into the 8 mm probe's reach) in 0.3 s, then 0.3 s along x.
  LogDevice device({{0.0, {0, 0, 20}, 0, true}, {0.3, {0, 0, 6}, 0, true}, {0.6, {15, 0, 6}, 0, true}}, true, "t");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &haptic.value());
  TickFeed feed(1024);
  loop.add_tick_feed(&feed);
  loop.run_ticks(600);
  std::vector<TickSample> got;
  feed.drain([&](const TickSample& s) { got.push_back(s); });
  ASSERT_EQ(got.size(), 600u);
  int starts = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const TickSample& s = got[i];
    EXPECT_EQ(s.tick, i);
    EXPECT_DOUBLE_EQ(s.time_s, static_cast<double>(i) * 1e-3);
    if (s.impact_mm_s > 0.0) ++starts;
    if (!s.in_contact) {
      EXPECT_EQ(s.surface, -1);
      EXPECT_EQ(s.normal_force_n, 0.0);
      continue;
    }
    EXPECT_EQ(s.surface, 0);
    EXPECT_NEAR(s.proxy_mm.z, 0.0, 1e-3);  // the god-object's contact epsilon, 1e-3 mm
    EXPECT_NEAR(s.normal.z, 1.0, 1e-9);
    EXPECT_GE(s.normal_force_n, 0.0);
  }
  EXPECT_EQ(starts, 1);
  EXPECT_TRUE(got.back().in_contact);
  EXPECT_GT(got.back().normal_force_n, 0.1);  // ~2 mm into a 0.5 N/mm spring
  EXPECT_GT(got.back().proxy_mm.x, 10.0);     // it slid along
}

TEST(TickFeed, AFullFeedDropsAndCounts) {
  TickFeed feed(4);
  for (int i = 0; i < 6; ++i) feed.push(TickSample{});
  EXPECT_EQ(feed.dropped(), 2u);
  EXPECT_EQ(feed.drain([](const TickSample&) {}), 4u);
  EXPECT_TRUE(feed.push(TickSample{}));
}

}  // namespace
}  // namespace ps
