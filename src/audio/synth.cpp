#include "audio/synth.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ps::audio {

namespace {

// One partial of a clip: a cosine gliding exponentially from f0 to f1 over its length, under an
// exponential decay, faded linearly to zero over its last kFadeS (no click where it stops).
struct Tone {
  double start_s = 0.0, length_s = 0.01;
  double f0_hz = 1000.0, f1_hz = 1000.0;
  double gain = 0.5, decay_s = 1e9;
};

constexpr double kFadeS = 0.002;

std::size_t samples_of(double s, int rate) { return static_cast<std::size_t>(std::llround(s * rate)); }

void add_tone(std::vector<float>& out, const Tone& t, int rate) {
  const std::size_t begin = samples_of(t.start_s, rate), n = samples_of(t.length_s, rate);
  if (out.size() < begin + n) out.resize(begin + n, 0.0f);
  const double fade_n = std::max(1.0, kFadeS * rate);
  double phase = 0.0;  // radians; summed per sample so a glide has no phase jumps
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i) / static_cast<double>(n);  // 0 .. 1 along the tone
    const double f = t.f0_hz * std::pow(t.f1_hz / t.f0_hz, x);
    const double tail = std::min(1.0, static_cast<double>(n - i) / fade_n);
    const double env = t.gain * std::exp(-static_cast<double>(i) / rate / t.decay_s) * tail;
    out[begin + i] += static_cast<float>(env * std::cos(phase));
    phase += 2.0 * std::numbers::pi * f / rate;
  }
}

std::vector<float> render(std::initializer_list<Tone> tones, int rate) {
  std::vector<float> out;
  for (const Tone& t : tones) add_tone(out, t, rate);
  return out;
}

}  // namespace

double click_gain(double v, const SynthParams& p) {
  const double s = 1.0 - std::exp(-std::max(0.0, v) / p.click_ref_speed_mm_s);
  return p.click_min_gain + (p.click_max_gain - p.click_min_gain) * s;
}

double impact_gain(double v, const SynthParams& p) {
  return p.impact_max_gain * (1.0 - std::exp(-std::max(0.0, v) / p.impact_ref_speed_mm_s));
}

std::vector<float> event_sound(const HapticEvent& e, const SynthParams& p) {
  const int r = p.sample_rate_hz;
  switch (e.kind) {
    case EventKind::contact_start:  // a bright tick, louder the faster the approach
      return render({{0.0, 0.012, 2400.0, 2400.0, click_gain(e.value, p), 0.0025}}, r);
    case EventKind::contact_end:  // a faint, lower release tick
      return render({{0.0, 0.008, 1200.0, 1200.0, 0.06, 0.002}}, r);
    case EventKind::button_fired:  // two-tone click: low then high, 30 ms apart
      return render({{0.0, 0.025, 1000.0, 1000.0, 0.4, 0.01}, {0.03, 0.025, 1500.0, 1500.0, 0.4, 0.01}}, r);
    case EventKind::body_impact:  // a thud whose pitch sags; loudness follows the impact speed
      return render({{0.0, 0.18, 120.0, 60.0, impact_gain(e.value, p), 0.06}}, r);
    case EventKind::charge_added:  // up chirp
      return render({{0.0, 0.12, 400.0, 1600.0, 0.35, 0.2}}, r);
    case EventKind::charge_removed:  // down chirp
      return render({{0.0, 0.12, 1600.0, 400.0, 0.35, 0.2}}, r);
    case EventKind::scene_switched:  // a rising C-major arpeggio
      return render({{0.0, 0.06, 523.25, 523.25, 0.3, 0.05},
                     {0.06, 0.06, 659.26, 659.26, 0.3, 0.05},
                     {0.12, 0.08, 783.99, 783.99, 0.3, 0.05}},
                    r);
    case EventKind::flag_toggled:  // on: high blip; off: an octave lower
      return render({{0.0, 0.04, e.value >= 0.5 ? 1760.0 : 880.0, e.value >= 0.5 ? 1760.0 : 880.0, 0.3, 0.02}}, r);
    case EventKind::sheet_crossing:
      if (e.value >= 0.0)  // in front: two quick bright blips
        return render({{0.0, 0.02, 1320.0, 1320.0, 0.3, 0.01}, {0.025, 0.02, 1760.0, 1760.0, 0.3, 0.01}}, r);
      return render({{0.0, 0.08, 330.0, 330.0, 0.3, 0.04}}, r);  // behind: one low, longer hum
    case EventKind::tick_stall:  // silent: the machine's trouble, not the world's
      return {};
  }
  return {};
}

}  // namespace ps::audio
