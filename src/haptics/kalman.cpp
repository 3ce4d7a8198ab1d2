#include "haptics/kalman.h"

namespace ps {

void AxisKalman::reset(double position_mm, const KalmanParams& params) {
  p_ = position_mm;
  v_ = 0.0;
  p00_ = params.measurement_sd_mm * params.measurement_sd_mm;
  p01_ = 0.0;
  p11_ = params.initial_velocity_sd_mm_s * params.initial_velocity_sd_mm_s;
}

void AxisKalman::predict(double dt_s, const KalmanParams& params) {
  const double t = dt_s, q = params.accel_sd_mm_s2 * params.accel_sd_mm_s2;
  p_ += t * v_;
  const double a00 = p00_ + 2.0 * t * p01_ + t * t * p11_ + q * t * t * t * t / 4.0;
  const double a01 = p01_ + t * p11_ + q * t * t * t / 2.0;
  p11_ += q * t * t;
  p00_ = a00;
  p01_ = a01;
}

void AxisKalman::step(double dt_s, double measured_mm, const KalmanParams& params) {
  const double r = params.measurement_sd_mm * params.measurement_sd_mm;
  predict(dt_s, params);  // x = A x, P = A P A^T + S_w
  const double a00 = p00_, a01 = p01_, a11 = p11_;
  // Update with y: K = P C^T / (C P C^T + S_z).
  const double s = a00 + r;
  const double k0 = a00 / s, k1 = a01 / s;
  const double innovation = measured_mm - p_;
  p_ += k0 * innovation;
  v_ += k1 * innovation;
  // Joseph form, written out for C = [1 0]: M = (I - K C) P; P = M (I - K C)^T + K r K^T.
  const double m00 = (1.0 - k0) * a00, m01 = (1.0 - k0) * a01;
  const double m10 = a01 - k1 * a00, m11 = a11 - k1 * a01;
  p00_ = m00 * (1.0 - k0) + r * k0 * k0;
  p01_ = m01 - k1 * m00 + r * k0 * k1;
  p11_ = m11 - k1 * m10 + r * k1 * k1;
}

void Kalman3::step(double dt_s, const glm::dvec3& measured_mm) {
  for (int i = 0; i < 3; ++i) {
    auto& a = axes_[static_cast<std::size_t>(i)];
    if (!initialized_) a.reset(measured_mm[i], params_);
    else a.step(dt_s, measured_mm[i], params_);
  }
  initialized_ = true;
}

void Kalman3::predict(double dt_s) {
  if (!initialized_) return;
  for (AxisKalman& a : axes_) a.predict(dt_s, params_);
}

glm::dvec3 Kalman3::position() const {
  return {axes_[0].position(), axes_[1].position(), axes_[2].position()};
}

glm::dvec3 Kalman3::velocity() const {
  return {axes_[0].velocity(), axes_[1].velocity(), axes_[2].velocity()};
}

}  // namespace ps
