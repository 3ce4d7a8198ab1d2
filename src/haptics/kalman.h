// Kalman filter for device position -> filtered position and velocity (Hanson & Zhang §4.3):
//   state x = [P, V] per axis,  x_{k+1} = A x_k + B u_k,  y_k = C x_k + z_k,
//   A = [[1, T], [0, 1]],  B = [T^2/2, T],  C = [1, 0],
// with u_k a white random acceleration (sd accel_sd_mm_s2), so the process noise is
//   S_w = accel_sd^2 * B B^T = accel_sd^2 * [[T^4/4, T^3/2], [T^3/2, T^2]],
// and z_k white measurement noise (sd measurement_sd_mm). The paper writes the one-step
// predictor form; we use the equivalent predict/update form with the Joseph covariance update
// (P = (I-KC) P (I-KC)^T + K S_z K^T), which keeps P symmetric positive definite in floating
// point over arbitrarily many steps. Each axis is filtered independently.
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace ps {

struct KalmanParams {
  double accel_sd_mm_s2 = 3000.0;   // hand accelerations: a few m/s^2
  double measurement_sd_mm = 0.1;   // sensor + tremor noise on position
  double initial_velocity_sd_mm_s = 500.0;
};

class AxisKalman {
 public:
  void reset(double position_mm, const KalmanParams& params);
  void step(double dt_s, double measured_mm, const KalmanParams& params);
  // Predict only (no measurement this tick): x = A x, P = A P A^T + S_w.
  void predict(double dt_s, const KalmanParams& params);
  double position() const { return p_; }
  double velocity() const { return v_; }
  // Moves the state (a device put somewhere on purpose), keeping the covariance.
  void place(double position_mm, double velocity_mm_s) {
    p_ = position_mm;
    v_ = velocity_mm_s;
  }
  // Covariance [[p00, p01], [p01, p11]] (mm^2, mm^2/s, mm^2/s^2).
  double p00() const { return p00_; }
  double p01() const { return p01_; }
  double p11() const { return p11_; }

 private:
  double p_ = 0.0, v_ = 0.0;
  double p00_ = 1.0, p01_ = 0.0, p11_ = 1.0;
};

class Kalman3 {
 public:
  explicit Kalman3(const KalmanParams& params = {}) : params_(params) {}
  // First call only initialises the state at the measurement (velocity 0).
  void step(double dt_s, const glm::dvec3& measured_mm);
  // A tick without a new measurement (the device repeats its last sample): the state moves on
  // at its velocity and the covariance grows, so the next real sample gets its full weight.
  void predict(double dt_s);
  bool initialized() const { return initialized_; }
  // Moves an initialised state to position/velocity, covariance kept (HapticLoop::place_hand).
  void place(const glm::dvec3& position_mm, const glm::dvec3& velocity_mm_s) {
    for (int i = 0; i < 3; ++i) axes_[static_cast<std::size_t>(i)].place(position_mm[i], velocity_mm_s[i]);
  }
  glm::dvec3 position() const;
  glm::dvec3 velocity() const;
  const AxisKalman& axis(int i) const { return axes_[static_cast<std::size_t>(i)]; }

 private:
  KalmanParams params_;
  std::array<AxisKalman, 3> axes_;
  bool initialized_ = false;
};

}  // namespace ps
