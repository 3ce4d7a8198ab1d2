#include "vibration/track.h"

#include "audio/track.h"

namespace ps::vibration {

std::vector<float> SignalTrack::samples(double duration_s, int sample_rate_hz) const {
  std::vector<float> out = samples_;
  out.resize(audio::track_length(duration_s, sample_rate_hz), 0.0f);
  return out;
}

Status write_track_wav(const std::string& path, const SignalTrack& track, double duration_s, int sample_rate_hz) {
  return audio::write_wav(path, track.samples(duration_s, sample_rate_hz), sample_rate_hz);
}

}  // namespace ps::vibration
