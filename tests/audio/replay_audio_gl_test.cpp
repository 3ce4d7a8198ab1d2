// End to end: the scripted stroke (tests/haptics/data/stroke.traj) replayed on the default
// scene, as `replay --events --audio` does it. The probe (radius 8 mm) touches the plank (top
// at z = 0) when the device, coming down linearly from z = 16 to 6 mm over 0.3 s, passes
// z = 8 mm: t = 0.3 * 8 / 10 = 0.24 s; it lifts off on the way up from z = 6 (t = 1.3 s) to 16
// (t = 1.6 s) at t = 1.3 + 0.3 * 2 / 10 = 1.36 s.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/session/replay_events.h"
#include "app/session/session.h"
#include "audio/wav_reader.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"
#include "world/haptic_scene.h"

namespace ps {
namespace {

class ReplayAudioGLTest : public test::GlTest {};

struct Outputs {
  std::string log_text, wav_bytes;
  std::vector<nlohmann::json> events;
  test::Wav wav;
};

Outputs replay_stroke(const std::string& dir) {
  std::filesystem::create_directories(dir);
  auto scene = parse_scene(default_scene_text(), "<default>", default_scene_base_dir(),
                           {"render.size=[64,64]", "render.depth_map_size=64"});
  EXPECT_TRUE(scene.ok());
  auto renderer = Renderer::create(scene.value(), {});
  EXPECT_TRUE(renderer.ok()) << renderer.error().message;
  auto haptic_scene = world::HapticScene::build(scene.value());
  EXPECT_TRUE(haptic_scene.ok());
  auto device = open_log_device("trajectory:" PS_SOURCE_DIR "/tests/haptics/data/stroke.traj");
  EXPECT_TRUE(device.ok()) << device.error().message;
  ReplayEventsDesc desc;
  desc.log_path = dir + "/events.jsonl";
  desc.audio_path = dir + "/sound.wav";
  desc.duration_s = device.value()->duration_s();
  auto events = ReplayEvents::open(desc);
  EXPECT_TRUE(events.ok());
  ReplayOptions opt;
  opt.fps = 10.0;
  opt.haptic_scene = &haptic_scene.value();
  opt.on_event = [&](const HapticEvent& e) { events.value()->dispatcher().dispatch(e); };
  auto r = replay_session(*renderer.value(), *device.value(), opt,
                          [](int, double, const HapticState&, const Renderer&) { return ok_status(); });
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
  OutputSet out;
  EXPECT_TRUE(events.value()->finish(out).ok());
  EXPECT_TRUE(out.publish().ok());
  Outputs o;
  o.log_text = test::read_bytes(desc.log_path);
  o.wav_bytes = test::read_bytes(desc.audio_path);
  std::istringstream lines(o.log_text);
  for (std::string line; std::getline(lines, line);) o.events.push_back(nlohmann::json::parse(line));
  o.wav = test::read_wav(desc.audio_path);
  return o;
}

TEST_P(ReplayAudioGLTest, StrokeGivesContactEventsAndClicksAtTheirTimes) {
  const std::string dir = testing::TempDir() + "ps_replay_audio_" + gl::backend_name(GetParam());
  const Outputs o = replay_stroke(dir);
  ASSERT_EQ(o.events.size(), 2u) << o.log_text;
  EXPECT_EQ(o.events[0]["event"], "contact_start");
  EXPECT_EQ(o.events[1]["event"], "contact_end");
  // 5 ms: the Kalman filter's position lags the device by a tick or two at these speeds
  // (33 mm/s down, 33 mm/s up); 5 ticks is a generous bound that still pins the right pass.
  EXPECT_NEAR(o.events[0]["t"].get<double>(), 0.24, 0.005);
  EXPECT_NEAR(o.events[1]["t"].get<double>(), 1.36, 0.005);
  EXPECT_GT(o.events[0]["value"].get<double>(), 20.0) << "approach speed: the stroke comes down at 33 mm/s";
  for (const auto& e : o.events)  // the event time is its tick's time on the 1 kHz loop
    EXPECT_NEAR(e["t"].get<double>(), e["tick"].get<double>() * 1e-3, 1e-12) << e;  // ns -> s rounding
  ASSERT_TRUE(o.wav.ok);
  EXPECT_EQ(o.wav.rate, 48000);
  EXPECT_EQ(o.wav.samples.size(), 76801u) << "1.6 s at 48 kHz, both ends: the whole replay";
  // Threshold 327 counts (0.01 of full scale): the contact-end tick starts at 0.06, silence is 0.
  const std::vector<std::size_t> onsets = test::detect_onsets(o.wav.samples, 327.0, 480);
  ASSERT_EQ(onsets.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i)  // sample-accurate: tick k starts at sample 48 k, exactly
    EXPECT_EQ(onsets[i], o.events[i]["tick"].get<std::size_t>() * 48);
  std::filesystem::remove_all(dir);
}

TEST_P(ReplayAudioGLTest, TwoReplaysGiveByteIdenticalLogAndWav) {
  const std::string dir = testing::TempDir() + "ps_replay_audio_twice_" + gl::backend_name(GetParam());
  const Outputs a = replay_stroke(dir + "/a"), b = replay_stroke(dir + "/b");
  EXPECT_FALSE(a.log_text.empty());
  EXPECT_TRUE(a.log_text == b.log_text);
  EXPECT_GT(a.wav_bytes.size(), 2u * 76801u);
  EXPECT_TRUE(a.wav_bytes == b.wav_bytes);
  std::filesystem::remove_all(dir);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(ReplayAudioGLTest);

}  // namespace
}  // namespace ps
