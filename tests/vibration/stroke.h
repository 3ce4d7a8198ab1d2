// Test helpers for the vibration signal: a one-plane scene with a chosen Gabor texture, scripted
// strokes as the haptic loop would report them (one TickSample per 1 kHz tick), and spectra.
#pragma once

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "haptics/tick_feed.h"
#include "scene/scene.h"

namespace ps::vibration::test {

// The plane z = 0, facing +Z, its material's stripes' normal at theta_deg (lambda_min = max).
inline Scene texture_scene(double lambda_mm, double theta_deg, double kernel_periods = 2.0) {
  Scene s;
  Material m;
  m.name = "t";
  m.gabor.lambda_min_mm = m.gabor.lambda_max_mm = lambda_mm;
  m.gabor.theta_min_rad = m.gabor.theta_max_rad = theta_deg * std::numbers::pi / 180.0;
  m.gabor.kernel_periods = kernel_periods;
  m.gabor.strategy = GaborParams::Strategy::kNaive;
  s.materials.push_back(m);
  Surface p;
  p.material = "t";
  s.surfaces.push_back(p);
  return s;
}

// A segment of a script: `seconds` of ticks moving the contact point at `speed` along the
// in-plane direction `dir_deg`, in contact (pressing with force_n) or lifted.
struct Leg {
  double seconds = 1.0, speed_mm_s = 0.0, dir_deg = 0.0, force_n = 1.0;
  bool contact = true;
};

inline std::vector<TickSample> script(const std::vector<Leg>& legs, glm::dvec3 start = glm::dvec3(3.1, -2.7, 0.0)) {
  std::vector<TickSample> out;
  glm::dvec3 p = start;
  std::uint64_t tick = 0;
  bool was_in = false;
  for (const Leg& leg : legs) {
    const double a = leg.dir_deg * std::numbers::pi / 180.0;
    const glm::dvec3 v = leg.speed_mm_s * glm::dvec3(std::cos(a), std::sin(a), 0.0);
    const auto n = static_cast<std::uint64_t>(std::llround(leg.seconds * 1000.0));
    for (std::uint64_t i = 0; i < n; ++i, ++tick) {
      TickSample s;
      s.tick = tick;
      s.time_s = static_cast<double>(tick) * 1e-3;
      s.clock_ns = static_cast<std::int64_t>(tick) * 1'000'000;
      s.proxy_mm = p;
      s.velocity_mm_s = v;
      s.in_contact = leg.contact;
      s.surface = leg.contact ? 0 : -1;
      s.normal_force_n = leg.contact ? leg.force_n : 0.0;
      if (leg.contact && !was_in) s.impact_mm_s = 20.0;
      was_in = leg.contact;
      out.push_back(s);
      p += v * 1e-3;
    }
  }
  return out;
}

inline void fft(std::vector<std::complex<double>>& a) {
  const std::size_t n = a.size();
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const std::complex<double> w = std::polar(1.0, -2.0 * std::numbers::pi / static_cast<double>(len));
    for (std::size_t i = 0; i < n; i += len) {
      std::complex<double> wk = 1.0;
      for (std::size_t k = 0; k < len / 2; ++k, wk *= w) {
        const auto u = a[i + k], t = a[i + k + len / 2] * wk;
        a[i + k] = u + t;
        a[i + k + len / 2] = u - t;
      }
    }
  }
}

// Welch's power spectrum: Hann-windowed segments of `n` samples, half overlapping, averaged.
inline std::vector<double> welch(const std::vector<float>& x, std::size_t first, std::size_t last, std::size_t n) {
  std::vector<double> psd(n / 2 + 1, 0.0);
  int segments = 0;
  for (std::size_t s = first; s + n <= last; s += n / 2, ++segments) {
    std::vector<std::complex<double>> a(n);
    for (std::size_t i = 0; i < n; ++i)
      a[i] = x[s + i] * 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n)));
    fft(a);
    for (std::size_t k = 0; k < psd.size(); ++k) psd[k] += std::norm(a[k]);
  }
  for (double& v : psd) v /= std::max(1, segments);
  return psd;
}

// The peak of a power spectrum (Hz): a parabola least-squares fitted to log power over the
// contiguous bins around the largest one that hold at least a third of it. A Gabor texture's
// spectrum along a line is a Gaussian, whose log is exactly a parabola; the fit averages the
// bin-to-bin scatter that picking the largest bin would keep.
inline double spectral_peak_hz(const std::vector<double>& psd, double bin_hz) {
  std::size_t top = 1;
  for (std::size_t k = 1; k < psd.size(); ++k)
    if (psd[k] > psd[top]) top = k;
  std::size_t lo = top, hi = top;
  while (lo > 1 && psd[lo - 1] >= psd[top] / 3.0) --lo;
  while (hi + 1 < psd.size() && psd[hi + 1] >= psd[top] / 3.0) ++hi;
  if (hi - lo < 2) return static_cast<double>(top) * bin_hz;
  // Normal equations of y = c0 + c1 x + c2 x^2, x = k - top.
  double s[5] = {0, 0, 0, 0, 0}, t[3] = {0, 0, 0};
  for (std::size_t k = lo; k <= hi; ++k) {
    const double x = static_cast<double>(k) - static_cast<double>(top), y = std::log(psd[k]);
    double xp = 1.0;
    for (int p = 0; p < 5; ++p, xp *= x) {
      s[p] += xp;
      if (p < 3) t[p] += xp * y;
    }
  }
  // Cramer's rule on the 3x3 system [s0 s1 s2; s1 s2 s3; s2 s3 s4] c = t.
  auto det3 = [](double a, double b, double c, double d, double e, double f, double g, double h, double i) {
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g);
  };
  const double d = det3(s[0], s[1], s[2], s[1], s[2], s[3], s[2], s[3], s[4]);
  const double c1 = det3(s[0], t[0], s[2], s[1], t[1], s[3], s[2], t[2], s[4]) / d;
  const double c2 = det3(s[0], s[1], t[0], s[1], s[2], t[1], s[2], s[3], t[2]) / d;
  if (!(c2 < 0.0)) return static_cast<double>(top) * bin_hz;
  return (static_cast<double>(top) - c1 / (2.0 * c2)) * bin_hz;
}

inline double rms(const std::vector<float>& x, std::size_t first, std::size_t last) {
  double s = 0.0;
  for (std::size_t i = first; i < last; ++i) s += static_cast<double>(x[i]) * x[i];
  return last > first ? std::sqrt(s / static_cast<double>(last - first)) : 0.0;
}

}  // namespace ps::vibration::test
