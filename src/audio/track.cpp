#include "audio/track.h"

#include <algorithm>
#include <cmath>

#include <sndfile.h>

namespace ps::audio {

std::size_t event_sample(double time_s, int rate) {
  return static_cast<std::size_t>(std::llround(std::max(0.0, time_s) * rate));
}

std::size_t track_length(double duration_s, int rate) {
  return static_cast<std::size_t>(std::floor(std::max(0.0, duration_s) * rate + 1e-6)) + 1;
}

std::vector<float> mix_track(std::span<const HapticEvent> events, std::size_t length, const SynthParams& p) {
  std::vector<float> track(length, 0.0f);
  for (const HapticEvent& e : events) {
    const std::size_t at = event_sample(e.time_s, p.sample_rate_hz);
    if (at >= length) continue;
    const std::vector<float> clip = event_sound(e, p);
    const std::size_t n = std::min(clip.size(), length - at);
    for (std::size_t i = 0; i < n; ++i) track[at + i] += clip[i];
  }
  return track;
}

std::vector<std::int16_t> to_pcm16(std::span<const float> samples) {
  std::vector<std::int16_t> out(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i)
    out[i] = static_cast<std::int16_t>(std::lround(std::clamp(static_cast<double>(samples[i]), -1.0, 1.0) * 32767.0));
  return out;
}

Status write_wav(const std::string& path, std::span<const float> samples, int rate) {
  SF_INFO info{};
  info.samplerate = rate;
  info.channels = 1;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  SNDFILE* f = sf_open(path.c_str(), SFM_WRITE, &info);
  if (f == nullptr) return make_error(path + ": cannot write WAV: " + sf_strerror(nullptr));
  const std::vector<std::int16_t> pcm = to_pcm16(samples);
  const sf_count_t n = sf_write_short(f, pcm.data(), static_cast<sf_count_t>(pcm.size()));
  const std::string why = n == static_cast<sf_count_t>(pcm.size()) ? "" : sf_strerror(f);
  if (sf_close(f) != 0 && why.empty()) return make_error(path + ": cannot write WAV: close failed");
  if (!why.empty()) return make_error(path + ": cannot write WAV: " + why);
  return ok_status();
}

}  // namespace ps::audio
