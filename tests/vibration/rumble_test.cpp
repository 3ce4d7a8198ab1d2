// The gamepad output (src/vibration/rumble.h) on SDL2's virtual joystick, headless: a scripted
// hover -> stroke -> rest -> lift goes through the signal, written as the WAV `replay
// --vibration` writes, and chunk by chunk to the rumble. The virtual joystick's Rumble callback
// records what the motors were told: they run only while in contact, and their strength follows
// the WAV's envelope. Unplugged while the live vibration runs, it is said once and the rest runs;
// a pad plugged in again rumbles again.
#include <gtest/gtest.h>

#include <SDL.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "vibration/live.h"
#include "vibration/live_feed.h"
#include "vibration/rumble.h"
#include "vibration/stroke.h"
#include "vibration/track.h"

namespace ps::vibration {
namespace {

struct Motors {  // written by SDL's Rumble callback on whichever thread rumbles
  std::atomic<std::uint16_t> low{0}, high{0};
  std::atomic<int> calls{0};
};

int SDLCALL record_rumble(void* userdata, Uint16 low, Uint16 high) {
  auto* m = static_cast<Motors*>(userdata);
  m->low = low;
  m->high = high;
  ++m->calls;
  return 0;
}

// The 16-bit samples of a PCM WAV, found by walking its RIFF chunks (not libsndfile, which
// wrote it).
std::vector<float> read_wav(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(f)), {});
  std::size_t at = 12;
  while (at + 8 <= bytes.size()) {
    const std::string id(bytes.data() + at, 4);
    std::uint32_t size = 0;
    std::memcpy(&size, bytes.data() + at + 4, 4);
    if (id == "data") {
      std::vector<float> out(size / 2);
      for (std::size_t i = 0; i < out.size(); ++i) {
        std::int16_t v = 0;
        std::memcpy(&v, bytes.data() + at + 8 + 2 * i, 2);
        out[i] = static_cast<float>(v) / 32767.0f;
      }
      return out;
    }
    at += 8 + size + (size & 1u);
  }
  return {};
}

// Plugs in a virtual gamepad with rumble motors recorded into `motors`; its device index.
int plug_pad(const char* name, Motors& motors) {
  SDL_VirtualJoystickDesc desc;
  SDL_zero(desc);
  desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
  desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
  desc.naxes = 2;
  desc.nbuttons = 4;
  desc.name = name;
  desc.userdata = &motors;
  desc.Rumble = record_rumble;
  return SDL_JoystickAttachVirtualEx(&desc);
}

class VirtualGamepad : public ::testing::Test {
 protected:
  void SetUp() override {
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    ASSERT_EQ(SDL_InitSubSystem(SDL_INIT_JOYSTICK), 0) << SDL_GetError();
    index_ = plug_pad("ps virtual pad", motors_);
    ASSERT_GE(index_, 0) << SDL_GetError();
  }
  void TearDown() override {
    if (index_ >= 0) SDL_JoystickDetachVirtual(index_);
    SDL_QuitSubSystem(SDL_INIT_JOYSTICK);
  }
  Motors motors_;
  int index_ = -1;
};

TEST_F(VirtualGamepad, RumblesOnlyInContactFollowingTheWavEnvelope) {
  auto out = RumbleOut::open({});
  ASSERT_TRUE(out) << out.error().message;
  EXPECT_EQ(out.value()->name(), "ps virtual pad");
  const Scene scene = test::texture_scene(0.5, 0.0);
  const auto ticks = test::script({{0.3, 100.0, 0.0, 0.0, false}, {1.0, 120.0, 0.0, 1.0},
                                   {0.3, 0.0, 0.0}, {0.4, 100.0, 0.0, 0.0, false}});
  SignalTrack track(std::make_shared<const SignalModel>(scene));
  for (const TickSample& t : ticks) track.add_tick(t);
  const double duration = ticks.back().time_s;
  const std::string wav = std::string(PS_BINARY_DIR) + "/tests/vibration/rumble_test.wav";
  std::filesystem::create_directories(std::filesystem::path(wav).parent_path());
  ASSERT_TRUE(write_track_wav(wav, track, duration, 48000));
  const std::vector<float> x = read_wav(wav);
  ASSERT_EQ(x.size(), static_cast<std::size_t>(duration * 48000 + 0.5) + 1);
  const std::size_t chunk = 240;  // 5 ms, as live
  std::vector<double> wav_rms, motor;
  for (std::size_t c = 0; (c + 1) * chunk <= x.size(); ++c) {
    out.value()->write(std::span<const float>(x.data() + c * chunk, chunk));
    const double t0 = static_cast<double>(c * chunk) / 48000.0, t1 = static_cast<double>((c + 1) * chunk) / 48000.0;
    const double strength = std::hypot(motors_.low.load(), motors_.high.load()) / 65535.0;
    // Contact is [0.3, 1.6) s; a chunk after it may still carry the low-pass's tail (e^-4.7 of
    // it per chunk), so the one right after the contact is not judged.
    if (t1 <= 0.3 || t0 >= 1.605) {
      EXPECT_EQ(strength, 0.0) << "out of contact, chunk at " << t0 << " s";
    }
    if (t0 >= 0.35 && t1 <= 1.3) {
      EXPECT_GT(strength, 0.0) << "stroking, chunk at " << t0 << " s";
    }
    if (t0 >= 1.35 && t1 <= 1.6) {
      EXPECT_EQ(strength, 0.0) << "at rest in contact, chunk at " << t0 << " s";
    }
    wav_rms.push_back(test::rms(x, c * chunk, (c + 1) * chunk));
    motor.push_back(strength);
  }
  EXPECT_GT(motors_.calls.load(), 10);
  // The envelope: correlation of motor strength with the WAV's chunk RMS over the whole script
  // (the motors saturate at full_scale_rms and split the band, so not equal; 0.9 says they
  // follow it).
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < motor.size(); ++i) mx += wav_rms[i], my += motor[i];
  mx /= motor.size(), my /= motor.size();
  double sxy = 0, sxx = 0, syy = 0;
  for (std::size_t i = 0; i < motor.size(); ++i) {
    sxy += (wav_rms[i] - mx) * (motor[i] - my);
    sxx += (wav_rms[i] - mx) * (wav_rms[i] - mx);
    syy += (motor[i] - my) * (motor[i] - my);
  }
  EXPECT_GT(sxy / std::sqrt(sxx * syy), 0.9);
}

// The gamepad unplugged while the live vibration rumbles it, then a pad plugged in: one notice
// each way; between them nothing rumbles and the vibration thread goes on taking every tick.
TEST_F(VirtualGamepad, UnpluggedIsOneNoticeAndAPadPluggedInRumblesAgain) {
  Motors second;  // outlives the vibration, whose close stops the motors it holds
  LiveDesc d;
  d.out = parse_output_choice("gamepad").value();
  auto v = LiveVibration::open(d, test::texture_scene(0.5, 0.0));
  ASSERT_TRUE(v->active()) << v->warnings()[0];
  v->start();
  int calls_unplugged = -1, second_index = -1;
  const auto ticks = test::script({{2.4, 120.0, 0.0, 1.0}});  // stroking in contact throughout
  test::feed_live(*v, ticks, [&](std::uint64_t tick) {
    if (tick == 600) {  // unplugged after 0.6 s of rumble
      EXPECT_GT(motors_.calls.load(), 0);
      SDL_JoystickDetachVirtual(index_);
      index_ = -1;
      calls_unplugged = motors_.calls.load();
    }
    if (tick == 1200) second_index = plug_pad("ps second pad", second);  // 0.6 s without a pad
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  v->close();
  index_ = second_index;  // TearDown unplugs it
  const std::vector<std::string> n = v->notices();
  ASSERT_EQ(n.size(), 2u) << v->summary();
  EXPECT_NE(n[0].find("the gamepad 'ps virtual pad' went away"), std::string::npos) << n[0];
  EXPECT_NE(n[1].find("rumble back on 'ps second pad'"), std::string::npos) << n[1];
  EXPECT_EQ(motors_.calls.load(), calls_unplugged);  // nothing reached the unplugged pad
  EXPECT_GT(second.calls.load(), 0);                 // the new pad rumbles
  EXPECT_EQ(v->ticks_seen(), ticks.size()) << v->summary();
  EXPECT_EQ(v->feed().dropped(), 0u);
}

}  // namespace
}  // namespace ps::vibration
