// The headless vibration track (`replay --vibration FILE.wav`): every tick of a session through
// the signal (vibration/signal.h), written as a WAV of the same format as the event sounds'
// track (audio/track.h: 48 kHz mono 16-bit PCM, round(clamp(x, -1, 1) * 32767), libsndfile),
// as long as the replay: one sample for every sample time in [0, duration]. Deterministic: the
// same ticks give the same bytes.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/result.h"
#include "vibration/signal.h"

namespace ps::vibration {

class SignalTrack {
 public:
  explicit SignalTrack(std::shared_ptr<const SignalModel> model) : synth_(std::move(model)) {}
  void add_tick(const TickSample& s) { synth_.add_tick(s, samples_); }
  void set_model(std::shared_ptr<const SignalModel> model) { synth_.set_model(std::move(model)); }
  // The track of a session of duration_s: audio::track_length samples, silent past the last
  // tick, cut at the end.
  std::vector<float> samples(double duration_s, int sample_rate_hz) const;
  const std::vector<float>& raw() const { return samples_; }

 private:
  SignalSynth synth_;
  std::vector<float> samples_;
};

Status write_track_wav(const std::string& path, const SignalTrack& track, double duration_s, int sample_rate_hz);

}  // namespace ps::vibration
