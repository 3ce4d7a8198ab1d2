// The headless sound track of a session: every event's clip (audio/synth.h) mixed in at its
// event time, sample-accurate, and written as a WAV (48 kHz mono, 16-bit PCM) with libsndfile.
// Deterministic: the same events give the same file, byte for byte (16-bit PCM has no PEAK
// chunk, whose timestamp would differ).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "audio/synth.h"
#include "core/result.h"

namespace ps::audio {

// The sample at which an event at `time_s` starts: round(time_s * rate).
std::size_t event_sample(double time_s, int sample_rate_hz);

// A track of `length` samples: each event's clip added at event_sample(e.time_s); clips running
// past the end are cut there. Not clipped (sums may exceed 1; to_pcm16 clips).
std::vector<float> mix_track(std::span<const HapticEvent> events, std::size_t length, const SynthParams& p = {});

// Samples for a session of `duration_s`: one for every sample time in [0, duration_s].
std::size_t track_length(double duration_s, int sample_rate_hz);

// round(clamp(x, -1, 1) * 32767) per sample.
std::vector<std::int16_t> to_pcm16(std::span<const float> samples);

// A 16-bit PCM mono WAV at `sample_rate_hz` (errors name the file and libsndfile's reason).
Status write_wav(const std::string& path, std::span<const float> samples, int sample_rate_hz);

}  // namespace ps::audio
