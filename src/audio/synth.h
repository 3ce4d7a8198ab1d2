// The sound of one haptic event: a short mono clip, a pure function of the event and the
// parameters (same event -> the same samples, bit for bit). What each kind sounds like and the
// loudness curves are in docs/sound.md, "Sounds".
// Every clip starts at full envelope on its first sample (a cosine, not a sine): the onset of an
// event's sound is the sample of its time, with no attack ramp to blur it.
#pragma once

#include <vector>

#include "haptics/events.h"

namespace ps::audio {

struct SynthParams {
  int sample_rate_hz = 48000;
  // Contact click: gain = click_min + (click_max - click_min) * (1 - exp(-v / click_ref)),
  // v = approach speed (mm/s). A slow touch is still audible; a fast one saturates.
  double click_min_gain = 0.1, click_max_gain = 0.6, click_ref_speed_mm_s = 60.0;
  // Body impact (A Virtual Universe §4): gain = impact_max * (1 - exp(-v / impact_ref)), v = impact
  // speed (mm/s): monotone, 0 at rest, saturating at impact_max (63 % of it at v = impact_ref).
  double impact_max_gain = 0.9, impact_ref_speed_mm_s = 300.0;
};

// The loudness curves above (peak amplitude of the clip, full scale = 1).
double click_gain(double approach_speed_mm_s, const SynthParams& p = {});
double impact_gain(double impact_speed_mm_s, const SynthParams& p = {});

// The clip of `e` at p.sample_rate_hz, float samples in [-1, 1]; sample 0 plays at e.time_s.
std::vector<float> event_sound(const HapticEvent& e, const SynthParams& p = {});

}  // namespace ps::audio
