// The live vibration (src/vibration/live.h): the option's values and errors; on OpenAL Soft's
// null device (ALSOFT_DRIVERS=null: it mixes in real time and plays nothing) ticks pushed at
// 1 kHz reach the sound channel and every queued tick's latency is measured. No timing is
// asserted here (speed is measured in bench-haptics --vibration-out, docs/vibration.md).
#include <gtest/gtest.h>

#include <cstdlib>
#include <thread>

#include "vibration/stroke.h"
#include "vibration/live.h"

namespace ps::vibration {
namespace {

TEST(VibrationOutChoice, ParsesEveryForm) {
  auto none = parse_output_choice("none");
  ASSERT_TRUE(none);
  EXPECT_FALSE(none->sound || none->gamepad);
  auto dev = parse_output_choice("sound:My Card");
  ASSERT_TRUE(dev);
  EXPECT_TRUE(dev->sound && !dev->gamepad);
  EXPECT_EQ(dev->sound_device, "My Card");
  auto both = parse_output_choice("both");
  ASSERT_TRUE(both);
  EXPECT_TRUE(both->sound && both->gamepad);
  auto pad = parse_output_choice("gamepad");
  ASSERT_TRUE(pad);
  EXPECT_TRUE(!pad->sound && pad->gamepad);
}

TEST(VibrationOutChoice, BadValuesNameTheValueAndTheChoices) {
  auto bad = parse_output_choice("speaker");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("'speaker'"), std::string::npos) << bad.error().message;
  EXPECT_NE(bad.error().message.find("sound:DEVICE"), std::string::npos) << bad.error().message;
  EXPECT_FALSE(parse_output_choice("gamepad:x"));
  EXPECT_FALSE(parse_output_choice("sound:"));
}

TEST(LiveVibration, NoDeviceIsOneWarningAndTheRestRuns) {
  setenv("ALSOFT_DRIVERS", "alsa", 1);
  LiveDesc d;
  d.out = parse_output_choice("sound:ps-no-such-device").value();
  auto v = LiveVibration::open(d, test::texture_scene(0.5, 0.0));
  EXPECT_FALSE(v->active());
  ASSERT_EQ(v->warnings().size(), 1u);
  EXPECT_NE(v->warnings()[0].find("no vibration sound"), std::string::npos);
  v->start();  // nothing to run: returns at once
  v->close();
}

TEST(LiveVibration, NullDeviceMeasuresEveryQueuedTick) {
  setenv("ALSOFT_DRIVERS", "null", 1);
  LiveDesc d;
  d.out = parse_output_choice("sound").value();
  auto v = LiveVibration::open(d, test::texture_scene(0.5, 0.0));
  if (!v->active()) GTEST_SKIP() << "OpenAL Soft's null device did not open: " << v->warnings()[0];
  v->start();
  const auto ticks = test::script({{0.6, 100.0, 0.0}});
  const auto t0 = std::chrono::steady_clock::now();
  for (TickSample s : ticks) {  // a 1 kHz producer on the steady clock, as the haptic thread
    const auto at = t0 + std::chrono::microseconds(static_cast<std::int64_t>(s.tick) * 1000);
    std::this_thread::sleep_until(at);
    s.clock_ns = at.time_since_epoch().count();
    v->feed().push(s);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // let the last chunks leave
  v->close();
  const Percentiles l = v->latency_ms();
  // 600 ms = 120 chunks of 5 ms; each queued one is measured once (some may be dropped under
  // load, and the last ones may still be queued).
  EXPECT_GT(l.count, 50u) << v->summary();
  EXPECT_GT(l.p50, 0.0) << v->summary();
  std::printf("%s\n", v->summary().c_str());
}

}  // namespace
}  // namespace ps::vibration
