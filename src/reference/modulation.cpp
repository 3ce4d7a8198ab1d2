#include "reference/modulation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ps {

double intensity_curve(const Material& m, double d) {
  if (!m.intensity_lut.empty()) return std::clamp(lut_eval(m.intensity_lut, d), 0.0, 1.0);
  return std::clamp(m.intensity_floor + m.intensity_scale / (d + m.intensity_offset_mm), 0.0, 1.0);
}

double shadow_intensity(const Material& m, double d) {
  if (!(d < m.influence_distance_mm)) return 0.0;  // also catches NaN
  if (d <= 0.0) return 1.0;
  return intensity_curve(m, d);
}

double pseudo_shadow_darkening(const Material& m, double d, double coverage, double gain,
                               double s) {
  double i = shadow_intensity(m, d);
  if (i <= 0.0) return 0.0;
  double amp = 0.0;
  if (d <= 0.0) {
    const double i_near = intensity_curve(m, 0.0);
    const double half_gap = 0.5 * (1.0 - i_near);
    i = 1.0 - gain * half_gap;
    amp = gain * half_gap;
  } else if (d < m.onset_distance_mm) {
    amp = gain * std::max(std::min(i - shadow_intensity(m, m.onset_distance_mm), 1.0 - i), 0.0);
  }
  return coverage * (i + amp * std::clamp(s, -1.0, 1.0));
}

double frequency_gap_hz(double speed, double lambda_min, double lambda_max, double peak_hz) {
  const double lo = std::min(lambda_min, lambda_max), hi = std::max(lambda_min, lambda_max);
  const double f_max = speed / lo;  // shortest wavelength gives the highest frequency
  const double f_min = speed / hi;
  if (f_max <= peak_hz) return peak_hz - f_max;
  if (f_min <= peak_hz) return 0.0;
  return f_min - peak_hz;
}

double amplitude_gain(const Material& m, double speed) {
  const GaborParams& g = m.gabor;
  if (!(speed >= 0.0) || !std::isfinite(speed)) return 0.0;
  if (!m.speed_gain_lut.empty()) return lut_eval(m.speed_gain_lut, speed);
  const double gap = frequency_gap_hz(speed, g.lambda_min_mm, g.lambda_max_mm, m.peak_hz);
  if (m.bandwidth_hz <= 0.0) return gap == 0.0 ? 1.0 : 0.0;
  const double x = gap / m.bandwidth_hz;
  return std::exp(-x * x);
}

double speed_gain(const Material& m, const PlaneFrame& f, const glm::dvec3& velocity) {
  const GaborParams& g = m.gabor;
  const double vu = glm::dot(velocity, f.t), vv = glm::dot(velocity, f.b);
  const double theta_mean = 0.5 * (g.theta_min_rad + g.theta_max_rad);
  const double along = std::abs(vu * std::cos(theta_mean) + vv * std::sin(theta_mean));
  const double in_plane = std::hypot(vu, vv);
  const double blend =
      std::clamp(std::abs(g.theta_max_rad - g.theta_min_rad) / std::numbers::pi, 0.0, 1.0);
  return (1.0 - blend) * amplitude_gain(m, along) + blend * amplitude_gain(m, in_plane);
}

double displacement_weight(double d, double c, double max_pen) {
  if (!(d <= 0.0)) return 0.0;
  const double pen = std::min(-d, max_pen);
  return std::exp(c * (std::log1p(pen) - std::log1p(max_pen)));
}

}  // namespace ps
