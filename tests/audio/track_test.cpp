// The mixed track and its WAV: onsets, found by an independent detector, at the event times;
// the WAV's bytes read back without libsndfile; two writes byte-identical.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "audio/track.h"
#include "audio/wav_reader.h"

namespace ps::audio {
namespace {

HapticEvent at_tick(EventKind kind, std::uint64_t tick, double value = 0.0) {
  HapticEvent e;
  e.kind = kind;
  e.tick = tick;
  e.time_s = static_cast<double>(tick) * 1e-3;  // the 1 kHz loop's session time
  e.value = value;
  return e;
}

// One of every kind, 0.3 s apart (the longest clip is 0.2 s), at ticks that are not multiples
// of the frame or of 10 ms.
std::vector<HapticEvent> all_kinds() {
  return {at_tick(EventKind::contact_start, 137, 40.0), at_tick(EventKind::contact_end, 437),
          at_tick(EventKind::button_fired, 741),        at_tick(EventKind::body_impact, 1043, 20.0),
          at_tick(EventKind::charge_added, 1349),       at_tick(EventKind::charge_removed, 1651),
          at_tick(EventKind::scene_switched, 1953),     at_tick(EventKind::flag_toggled, 2257, 1.0),
          at_tick(EventKind::sheet_crossing, 2561, -1.0), at_tick(EventKind::sheet_crossing, 2863, 1.0)};
}

// 0.01: every clip's first sample is >= 0.05 (synth_test) and silence is exactly 0.
constexpr double kThreshold = 0.01;
// 10 ms of quiet before an onset: longer than any gap inside a clip (5 ms in the button's
// two-tone click), shorter than the 0.1 s between the clips here.
constexpr std::size_t kQuiet = 480;

TEST(TrackTest, OnsetsSitAtTheEventSamples) {
  const std::vector<HapticEvent> events = all_kinds();
  const std::vector<float> track = mix_track(events, track_length(3.2, 48000));
  ASSERT_EQ(track.size(), 153601u);  // 3.2 s at 48 kHz, both ends
  const std::vector<std::size_t> onsets = test::detect_onsets(track, kThreshold, kQuiet);
  ASSERT_EQ(onsets.size(), events.size());
  for (std::size_t i = 0; i < events.size(); ++i)  // tick k at 48 k samples: exact, tolerance 0
    EXPECT_EQ(onsets[i], events[i].tick * 48) << event_name(events[i].kind);
}

TEST(TrackTest, ClipsPastTheEndAreCutAndLateEventsIgnored) {
  const std::vector<HapticEvent> events = {at_tick(EventKind::body_impact, 990, 500.0),
                                           at_tick(EventKind::contact_start, 1200, 10.0)};
  const std::vector<float> track = mix_track(events, track_length(1.0, 48000));
  ASSERT_EQ(track.size(), 48001u);
  EXPECT_NE(track[990 * 48], 0.0f);
  EXPECT_EQ(test::detect_onsets(track, kThreshold, kQuiet).size(), 1u);
}

TEST(TrackTest, OverlappingClipsAdd) {
  const HapticEvent a = at_tick(EventKind::charge_added, 10), b = at_tick(EventKind::body_impact, 30, 300.0);
  const std::vector<float> both = mix_track(std::vector<HapticEvent>{a, b}, 48000);
  const std::vector<float> ca = event_sound(a), cb = event_sound(b);
  for (std::size_t i : {std::size_t{0}, std::size_t{100}, std::size_t{2000}}) {
    const std::size_t s = 30 * 48 + i;
    // float sum of two floats, each exact: one rounding, 2^-24 relative.
    EXPECT_NEAR(both[s], ca[s - 10 * 48] + cb[i], 1e-6);
  }
}

TEST(TrackTest, WavIs48kMono16BitWithTheQuantisedSamples) {
  const std::vector<float> track = mix_track(all_kinds(), track_length(3.2, 48000));
  const std::string path = testing::TempDir() + "ps_track_test.wav";
  ASSERT_TRUE(write_wav(path, track, 48000).ok());
  const test::Wav w = test::read_wav(path);
  ASSERT_TRUE(w.ok);
  EXPECT_EQ(w.format, 1);  // WAVE_FORMAT_PCM
  EXPECT_EQ(w.channels, 1);
  EXPECT_EQ(w.rate, 48000);
  EXPECT_EQ(w.bits, 16);
  ASSERT_EQ(w.samples.size(), track.size());
  for (std::size_t i = 0; i < track.size(); i += 97)
    EXPECT_EQ(w.samples[i], static_cast<int>(std::lround(std::clamp(track[i], -1.0f, 1.0f) * 32767.0))) << i;
  // Onsets in the file itself: 0.01 of full scale = 327.67 counts.
  const std::vector<std::size_t> onsets = test::detect_onsets(w.samples, kThreshold * 32767.0, kQuiet);
  ASSERT_EQ(onsets.size(), all_kinds().size());
  for (std::size_t i = 0; i < onsets.size(); ++i) EXPECT_EQ(onsets[i], all_kinds()[i].tick * 48);
  std::filesystem::remove(path);
}

TEST(TrackTest, TwoWritesAreByteIdentical) {
  const std::string a = testing::TempDir() + "ps_track_a.wav", b = testing::TempDir() + "ps_track_b.wav";
  ASSERT_TRUE(write_wav(a, mix_track(all_kinds(), 153601), 48000).ok());
  ASSERT_TRUE(write_wav(b, mix_track(all_kinds(), 153601), 48000).ok());
  const std::string ba = test::read_bytes(a), bb = test::read_bytes(b);
  EXPECT_GT(ba.size(), 2u * 153601u);
  EXPECT_TRUE(ba == bb);
  std::filesystem::remove(a);
  std::filesystem::remove(b);
}

TEST(TrackTest, ClippingAndBadPath) {
  const std::vector<std::int16_t> q = to_pcm16(std::vector<float>{2.0f, -3.0f, 0.5f, -0.5f});
  EXPECT_EQ(q, (std::vector<std::int16_t>{32767, -32767, 16384, -16384}));  // 16383.5 rounds away from 0
  const Status s = write_wav("/nonexistent-dir/x.wav", std::vector<float>{0.0f}, 48000);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find("/nonexistent-dir/x.wav: cannot write WAV"), std::string::npos) << s.error().message;
}

}  // namespace
}  // namespace ps::audio
