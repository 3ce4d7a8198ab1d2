// Kalman filter (Hanson & Zhang §4.3) on synthetic hand-like motion with measurement noise.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "haptics/kalman.h"

namespace ps {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Hand-like: a few slow sinusoids (0.3-2.5 Hz, 5-40 mm) like stroking a surface, as in Fig. 6.
struct Hand {
  double pos(double t) const {
    return 40.0 * std::sin(2 * kPi * 0.3 * t) + 15.0 * std::sin(2 * kPi * 1.1 * t + 0.7) +
           5.0 * std::sin(2 * kPi * 2.5 * t + 1.9);
  }
  double vel(double t) const {
    return 40.0 * 2 * kPi * 0.3 * std::cos(2 * kPi * 0.3 * t) +
           15.0 * 2 * kPi * 1.1 * std::cos(2 * kPi * 1.1 * t + 0.7) +
           5.0 * 2 * kPi * 2.5 * std::cos(2 * kPi * 2.5 * t + 1.9);
  }
};

struct Rmse {
  double kf = 0.0, fd = 0.0;
};

Rmse velocity_rmse(double noise_sd_mm, unsigned seed) {
  const double T = 1e-3;  // 1 kHz haptic loop
  KalmanParams params;
  params.measurement_sd_mm = noise_sd_mm;
  AxisKalman kf;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_sd_mm);
  const Hand hand;
  double prev_y = hand.pos(0.0) + noise(rng), se_kf = 0.0, se_fd = 0.0;
  kf.reset(prev_y, params);
  int n = 0;
  for (int k = 1; k <= 10'000; ++k) {  // 10 s
    const double t = k * T, y = hand.pos(t) + noise(rng);
    kf.step(T, y, params);
    const double fd = (y - prev_y) / T;
    prev_y = y;
    if (k < 500) continue;  // skip the filter's warm-up (0.5 s)
    se_kf += std::pow(kf.velocity() - hand.vel(t), 2);
    se_fd += std::pow(fd - hand.vel(t), 2);
    ++n;
  }
  return {std::sqrt(se_kf / n), std::sqrt(se_fd / n)};
}

TEST(KalmanTest, VelocityRmseAtMostHalfOfFiniteDifferences) {
  for (double noise : {0.02, 0.1, 0.3}) {
    const Rmse r = velocity_rmse(noise, 7);
    RecordProperty("noise_" + std::to_string(noise) + "_ratio", std::to_string(r.kf / r.fd));
    std::printf("noise sd %.2f mm: velocity RMSE KF %.2f mm/s, finite differences %.2f mm/s, ratio %.3f\n",
                noise, r.kf, r.fd, r.kf / r.fd);
    EXPECT_LE(r.kf, 0.5 * r.fd) << "noise sd " << noise << " mm";
  }
}

TEST(KalmanTest, TracksPositionOfConstantVelocityExactly) {
  KalmanParams params;
  AxisKalman kf;
  kf.reset(0.0, params);
  for (int k = 1; k <= 5000; ++k) kf.step(1e-3, 100.0 * k * 1e-3, params);  // 100 mm/s
  EXPECT_NEAR(kf.velocity(), 100.0, 1e-6);
  EXPECT_NEAR(kf.position(), 500.0, 1e-9);
}

// Pure arithmetic, ~0.1 s: the Joseph update must keep P symmetric positive definite.
TEST(KalmanTest, CovarianceStaysPositiveDefiniteOver1e7Steps) {
  KalmanParams params;
  AxisKalman kf;
  kf.reset(0.0, params);
  bool ok = true;
  double y = 0.0;
  for (long k = 0; k < 10'000'000; ++k) {
    y = y * 0.999 + ((k * 2654435761u) % 1000) * 1e-4;  // cheap deterministic pseudo-noise
    kf.step(1e-3, y, params);
    const double det = kf.p00() * kf.p11() - kf.p01() * kf.p01();
    ok = ok && kf.p00() > 0.0 && kf.p11() > 0.0 && det > 0.0 && std::isfinite(det);
    if (!ok) { ADD_FAILURE() << "P not SPD at step " << k; break; }
  }
  EXPECT_TRUE(ok);
  EXPECT_TRUE(std::isfinite(kf.position()) && std::isfinite(kf.velocity()));
}

}  // namespace
}  // namespace ps
