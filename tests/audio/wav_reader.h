// A WAV reader written from the RIFF layout, independent of libsndfile (which wrote the files
// under test): the "fmt " fields and the 16-bit samples of the "data" chunk.
#pragma once

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace ps::test {

struct Wav {
  bool ok = false;
  int format = 0, channels = 0, rate = 0, bits = 0;
  std::vector<std::int16_t> samples;
};

inline std::string read_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

inline Wav read_wav(const std::string& path) {
  const std::string b = read_bytes(path);
  auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[at + i]);
    return v;
  };
  auto u16 = [&](std::size_t at) {
    return static_cast<std::uint16_t>(static_cast<unsigned char>(b[at]) | static_cast<unsigned char>(b[at + 1]) << 8);
  };
  Wav w;
  if (b.size() < 12 || b.compare(0, 4, "RIFF") != 0 || b.compare(8, 4, "WAVE") != 0) return w;
  bool have_fmt = false;
  for (std::size_t at = 12; at + 8 <= b.size();) {
    const std::string id = b.substr(at, 4);
    const std::uint32_t size = u32(at + 4);
    if (at + 8 + size > b.size()) return w;
    if (id == "fmt ") {
      w.format = u16(at + 8);
      w.channels = u16(at + 10);
      w.rate = static_cast<int>(u32(at + 12));
      w.bits = u16(at + 22);
      have_fmt = true;
    } else if (id == "data") {
      w.samples.resize(size / 2);
      for (std::size_t i = 0; i < w.samples.size(); ++i) w.samples[i] = static_cast<std::int16_t>(u16(at + 8 + 2 * i));
      w.ok = have_fmt;
    }
    at += 8 + size + (size & 1);
  }
  return w;
}

// Onsets: the first sample whose |amplitude| exceeds `threshold` after at least `quiet`
// samples at or below it (the start of the track counts as quiet).
template <class T>
std::vector<std::size_t> detect_onsets(const std::vector<T>& x, double threshold, std::size_t quiet) {
  std::vector<std::size_t> onsets;
  std::size_t below = quiet;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (std::abs(static_cast<double>(x[i])) > threshold) {
      if (below >= quiet) onsets.push_back(i);
      below = 0;
    } else {
      ++below;
    }
  }
  return onsets;
}

}  // namespace ps::test
