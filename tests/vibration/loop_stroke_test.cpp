// The signal from the real haptic loop (fake clock) on the default scene's scripted stroke
// (tests/haptics/data/stroke.traj: down onto the plank, 1 s along x at 33.8 mm/s, up): silent
// before the touch (0.24 s), the contact transient at the touch, the texture while it slides
// (the friction model moves the proxy in stick-slip steps; the signal follows the hand's smooth
// velocity), silent again once lifted.
#include <gtest/gtest.h>

#include "app/session/session.h"
#include "haptics/haptic_loop.h"
#include "scene/scene_io.h"
#include "vibration/signal.h"
#include "vibration/stroke.h"
#include "world/haptic_scene.h"

namespace ps {
namespace {

TEST(VibrationLoop, DefaultSceneStrokeFromTheHapticLoop) {
  auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/default.toml");
  ASSERT_TRUE(scene) << scene.error().message;
  auto haptic = world::HapticScene::build(scene.value());
  ASSERT_TRUE(haptic) << haptic.error().message;
  auto dev = open_device_log(std::string("trajectory:") + PS_SOURCE_DIR + "/tests/haptics/data/stroke.traj");
  ASSERT_TRUE(dev) << dev.error().message;
  FakeClock clock;
  HapticLoop loop(*dev->device, clock, HapticLoopParams{}, &haptic.value());
  TickFeed feed(2048);
  loop.add_tick_feed(&feed);
  vibration::SignalSynth synth(std::make_shared<const vibration::SignalModel>(scene.value()));
  std::vector<float> x;
  for (int block = 0; block < 2; ++block) {  // 1.601 s of ticks, drained before the feed fills
    loop.run_ticks(block == 0 ? 1000 : 601);
    feed.drain([&](const TickSample& s) { synth.add_tick(s, x); });
  }
  ASSERT_EQ(x.size(), 48u * 1600 + 1);
  EXPECT_EQ(vibration::test::rms(x, 0, 48 * 230), 0.0) << "before the touch";
  EXPECT_GT(vibration::test::rms(x, 48 * 235, 48 * 270), 0.02) << "the contact transient";
  const double slide = vibration::test::rms(x, 48 * 400, 48 * 1250);
  EXPECT_GT(slide, 0.05) << "sliding over the plank's texture";
  EXPECT_LT(vibration::test::rms(x, 48 * 1450, x.size()), 0.01 * slide) << "lifted";
}

}  // namespace
}  // namespace ps
