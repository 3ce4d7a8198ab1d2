// The live vibration (src/vibration/live.h): the option's values and errors; on OpenAL Soft's
// null device (ALSOFT_DRIVERS=null: it mixes in real time and plays nothing) ticks pushed at
// 1 kHz reach the sound channel and every queued tick's latency is measured. No timing is
// asserted here (speed is measured in bench-haptics --vibration-out, docs/vibration.md). The
// audio output lost while vibrating is one notice, and the rest runs.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "vibration/live.h"
#include "vibration/live_feed.h"
#include "vibration/stroke.h"

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
  test::feed_live(*v, test::script({{0.6, 100.0, 0.0}}));
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // let the last chunks leave
  v->close();
  const Percentiles l = v->latency_ms();
  // 600 ms = 120 chunks of 5 ms; each queued one is measured once (some may be dropped under
  // load, and the last ones may still be queued).
  EXPECT_GT(l.count, 50u) << v->summary();
  EXPECT_GT(l.p50, 0.0) << v->summary();
  std::printf("%s\n", v->summary().c_str());
}

// The audio output lost while vibrating (a USB card unplugged, the sound server ended): OpenAL
// Soft's wave writer on /dev/full, where every write fails (ENOSPC). The device opens, then OpenAL
// reports it disconnected (ALC_EXT_disconnect) at its first mix, as it does for a card that goes
// away. Said once, the sound stops, and the thread goes on taking every tick from the haptic
// loop's feed (the rumble, had there been one, would go on).
TEST(LiveVibration, AudioOutputGoneIsOneNoticeAndTheRestRuns) {
  const std::filesystem::path conf = std::filesystem::temp_directory_path() / "ps_live_vibration_full.conf";
  std::ofstream(conf) << "drivers = wave\n[wave]\nfile = /dev/full\n";
  setenv("ALSOFT_CONF", conf.c_str(), 1);
  unsetenv("ALSOFT_DRIVERS");
  LiveDesc d;
  d.out = parse_output_choice("sound").value();
  std::mutex m;
  std::vector<std::string> said;
  d.notice = [&](const std::string& line) {
    std::lock_guard<std::mutex> lock(m);
    said.push_back(line);
  };
  auto v = LiveVibration::open(d, test::texture_scene(0.5, 0.0));
  ASSERT_TRUE(v->active()) << v->warnings()[0];
  v->start();
  const auto ticks = test::script({{1.5, 100.0, 0.0}});
  test::feed_live(*v, ticks);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the last ticks drained
  v->close();
  const std::vector<std::string> notices = v->notices();
  ASSERT_EQ(notices.size(), 1u) << v->summary();
  EXPECT_NE(notices[0].find("audio output"), std::string::npos) << notices[0];
  EXPECT_NE(notices[0].find("went away"), std::string::npos) << notices[0];
  EXPECT_EQ(said, notices);
  EXPECT_NE(v->summary().find("(lost)"), std::string::npos) << v->summary();
  // The rest runs: every tick was taken from the feed, none dropped.
  EXPECT_EQ(v->ticks_seen(), ticks.size()) << v->summary();
  EXPECT_EQ(v->feed().dropped(), 0u);
  std::filesystem::remove(conf);
}

}  // namespace
}  // namespace ps::vibration
