// The event clips against closed forms: each starts at its full gain on sample 0 (cos 0 = 1,
// envelope e^0 = 1), the impact's loudness follows 0.9 (1 - e^(-v/300)), chirps go the way
// their names say, and the same event always gives the same samples.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "audio/synth.h"

namespace ps::audio {
namespace {

HapticEvent event(EventKind kind, double value = 0.0, double time_s = 0.0) {
  HapticEvent e;
  e.kind = kind;
  e.value = value;
  e.time_s = time_s;
  return e;
}

double peak(const std::vector<float>& x) {
  double p = 0.0;
  for (float v : x) p = std::max(p, std::abs(static_cast<double>(v)));
  return p;
}

int zero_crossings(const std::vector<float>& x, std::size_t from, std::size_t to) {
  int n = 0;
  for (std::size_t i = from + 1; i < to; ++i) n += (x[i - 1] < 0.0f) != (x[i] < 0.0f);
  return n;
}

constexpr EventKind kAllKinds[] = {EventKind::contact_start,  EventKind::contact_end,    EventKind::button_fired,
                                   EventKind::body_impact,    EventKind::charge_added,   EventKind::charge_removed,
                                   EventKind::scene_switched, EventKind::flag_toggled,   EventKind::sheet_crossing};

TEST(SynthTest, EveryKindHasAShortClipStartingOnItsFirstSample) {
  for (EventKind k : kAllKinds) {
    const std::vector<float> clip = event_sound(event(k, 200.0));
    SCOPED_TRACE(std::string(event_name(k)));
    ASSERT_FALSE(clip.empty());
    EXPECT_LE(clip.size(), 48000u / 4) << "a cue, not a tune: at most 0.25 s";
    // 0.05: the quietest clip (contact end) starts at 0.06; an onset detector at 0.01 sees it.
    EXPECT_GT(std::abs(clip[0]), 0.05f);
    EXPECT_LE(peak(clip), 1.0);
    // The fade's last step is 1/96 of the envelope (2 ms at 48 kHz) and every gain is <= 0.9.
    EXPECT_LT(std::abs(clip.back()), 0.01f) << "faded out: no click where it stops";
  }
}

TEST(SynthTest, ContactClickGainFollowsApproachSpeed) {
  for (double v : {0.0, 10.0, 60.0, 500.0}) {
    const double expected = 0.1 + 0.5 * (1.0 - std::exp(-v / 60.0));  // SynthParams defaults
    // float rounding of one sample: 2^-24 relative.
    EXPECT_NEAR(event_sound(event(EventKind::contact_start, v))[0], expected, 1e-6) << v;
  }
}

TEST(SynthTest, ImpactLoudnessRisesWithSpeedAndSaturates) {
  const double speeds[] = {25.0, 50.0, 100.0, 200.0, 400.0, 800.0, 1600.0, 6400.0};
  double last_peak = 0.0, last_energy = 0.0;
  EXPECT_EQ(peak(event_sound(event(EventKind::body_impact, 0.0))), 0.0) << "no speed, no sound";
  for (double v : speeds) {
    const std::vector<float> clip = event_sound(event(EventKind::body_impact, v));
    double energy = 0.0;
    for (float x : clip) energy += static_cast<double>(x) * x;
    const double p = peak(clip);
    // The envelope only decays and |cos| <= 1: the peak is sample 0, the gain itself.
    EXPECT_NEAR(p, 0.9 * (1.0 - std::exp(-v / 300.0)), 1e-6) << v;  // float rounding, 2^-24 relative
    EXPECT_GT(p, last_peak) << v;
    EXPECT_GT(energy, last_energy) << v;
    last_peak = p;
    last_energy = energy;
  }
  EXPECT_LT(last_peak, 0.9) << "saturates below the maximum gain";
  const double p1600 = peak(event_sound(event(EventKind::body_impact, 1600.0)));
  EXPECT_LT(last_peak - p1600, 0.005) << "4x the speed past 1600 mm/s adds < 0.5 % of full scale";
}

TEST(SynthTest, ChirpsGoUpAndDown) {
  const std::vector<float> up = event_sound(event(EventKind::charge_added)), down = event_sound(event(EventKind::charge_removed));
  ASSERT_EQ(up.size(), down.size());
  const std::size_t q = up.size() / 4;
  // 400 -> 1600 Hz exponentially: the last quarter has ~2.8x the crossings of the first.
  EXPECT_GT(zero_crossings(up, 3 * q, up.size()), 2 * zero_crossings(up, 0, q));
  EXPECT_GT(zero_crossings(down, 0, q), 2 * zero_crossings(down, 3 * q, down.size()));
}

TEST(SynthTest, SheetCrossingInFrontAndBehindSoundDifferent) {
  const std::vector<float> front = event_sound(event(EventKind::sheet_crossing, +1.0));
  const std::vector<float> behind = event_sound(event(EventKind::sheet_crossing, -1.0));
  // In front: 1320/1760 Hz blips over 45 ms; behind: 330 Hz over 80 ms (crossings per 20 ms:
  // 2 * f * 0.02 = 52.8 vs 13.2).
  EXPECT_NE(front.size(), behind.size());
  EXPECT_GT(zero_crossings(front, 0, 960), 3 * zero_crossings(behind, 0, 960));
}

TEST(SynthTest, FlagOnAndOffAreAnOctaveApart) {
  const std::vector<float> on = event_sound(event(EventKind::flag_toggled, 1.0));
  const std::vector<float> off = event_sound(event(EventKind::flag_toggled, 0.0));
  const int a = zero_crossings(on, 0, on.size()), b = zero_crossings(off, 0, off.size());
  EXPECT_NEAR(static_cast<double>(a) / b, 2.0, 0.05);  // +-1 crossing at each end of 70 / 140
}

TEST(SynthTest, SameEventSameSamplesByteForByte) {
  for (EventKind k : kAllKinds) {
    const HapticEvent e = event(k, 123.456, 0.5);
    const std::vector<float> a = event_sound(e), b = event_sound(e);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0) << event_name(k);
  }
}

}  // namespace
}  // namespace ps::audio
