// Record -> playback -> byte-identical images: a scripted session is replayed while its device
// stream is recorded; replaying the recording must give exactly the same frames.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "app/session/session.h"
#include "devices/sample_log.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"

namespace ps {
namespace {

class ReplayGLTest : public test::GlTest {};

std::vector<Image> replay_images(Device& device, const std::string& record_path) {
  auto scene = parse_scene(default_scene_text(), "<default>", default_scene_base_dir(),
                           {"render.size=[128,128]", "render.depth_map_size=64"});
  EXPECT_TRUE(scene.ok());
  auto renderer = Renderer::create(scene.value(), {});
  EXPECT_TRUE(renderer.ok()) << renderer.error().message;
  ReplayOptions opt;
  opt.fps = 20.0;
  opt.record_path = record_path;
  std::vector<Image> images;
  auto r = replay_session(*renderer.value(), device, opt, [&](int, double, const HapticState&, const Renderer& rr) {
    images.push_back(rr.read_color());
    return ok_status();
  });
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
  return images;
}

TEST_P(ReplayGLTest, RecordedSessionPlaysBackByteIdentical) {
  // A stroke that presses into the plank (z 14 -> 4 mm: the 8 mm probe penetrates) and slides.
  auto script = parse_sample_log("0 -20 0 14 0\n0.2 -10 0 4 0\n0.4 10 5 4 1\n0.5 20 5 9 0\n", "stroke");
  ASSERT_TRUE(script.ok());
  // One file per backend: ctest runs the egl and osmesa instances in parallel.
  const std::string log = testing::TempDir() + "ps_replay_record_" + gl::backend_name(GetParam()) + ".log";
  LogDevice traj(script.value(), true, "trajectory");
  const std::vector<Image> first = replay_images(traj, log);
  ASSERT_EQ(first.size(), 11u);  // 0.5 s at 20 fps, both ends
  auto recorded = load_sample_log(log);
  ASSERT_TRUE(recorded.ok()) << recorded.error().message;
  EXPECT_EQ(recorded->size(), 501u);  // one sample per 1 ms tick, 0 to 0.5 s
  LogDevice playback(recorded.value(), false, "playback");
  const std::vector<Image> second = replay_images(playback, "");
  ASSERT_EQ(second.size(), first.size());
  for (size_t i = 0; i < first.size(); ++i)
    EXPECT_TRUE(first[i].pixels == second[i].pixels) << "frame " << i << " differs";
  EXPECT_FALSE(first.front().pixels == first[6].pixels) << "the probe should have moved";
  std::filesystem::remove(log);
}

// The frame schedule: frame i shows the state after tick floor(i / fps * rate), never a later
// tick (docs/haptics.md, replay). At 30 fps and 1 kHz, i / fps * rate = 33.3 i: frames 2, 5, ...
// have a fraction >= 0.5, so a schedule that rounded would show them one tick late.
TEST_P(ReplayGLTest, FrameIShowsTheTickAtFloorOfIOverFpsTimesRate) {
  auto scene = parse_scene(default_scene_text(), "<default>", default_scene_base_dir(),
                           {"render.size=[32,32]", "render.depth_map_size=32"});
  ASSERT_TRUE(scene.ok());
  auto renderer = Renderer::create(scene.value(), {});
  ASSERT_TRUE(renderer.ok()) << renderer.error().message;
  auto script = parse_sample_log("0 -20 0 14 0\n0.3 20 0 14 0\n", "line");
  ASSERT_TRUE(script.ok());
  LogDevice device(script.value(), true, "line");
  ReplayOptions opt;
  opt.fps = 30.0;
  std::vector<double> times;
  auto r = replay_session(*renderer.value(), device, opt, [&](int, double, const HapticState& st, const Renderer&) {
    times.push_back(st.time_s);
    return ok_status();
  });
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(times.size(), 10u);  // 0.3 s at 30 fps, both ends
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double tick = std::floor(static_cast<double>(i) / opt.fps * opt.haptics.rate_hz + 1e-9);
    // A tick's time is k / rate in double: a ms tick index is exact after rounding to the nearest.
    EXPECT_EQ(std::llround(times[i] * opt.haptics.rate_hz), static_cast<long long>(tick)) << "frame " << i;
  }
}

PS_INSTANTIATE_HEADLESS_BACKENDS(ReplayGLTest);

}  // namespace
}  // namespace ps
