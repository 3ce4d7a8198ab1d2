// CPU Gabor noise: the generator, the count rule and the analytic variance (no GL).
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "reference/gabor.h"

namespace ps {
namespace {

TEST(GaborTest, LcgIsTheThesisGenerator) {
  // r_{n+1} = 3039177861 r_n mod 2^32, checked with 64-bit arithmetic.
  std::uint32_t s = 12345u;
  const std::uint64_t expect = (3039177861ull * 12345ull) % 4294967296ull;
  const float u = lcg_uniform(s);
  EXPECT_EQ(s, static_cast<std::uint32_t>(expect));
  EXPECT_FLOAT_EQ(u, static_cast<float>(static_cast<double>(expect) / 4294967296.0));
}

TEST(GaborTest, SetupCellIsLargestTruncationRadius) {
  GaborParams g;
  g.lambda_min_mm = 0.5;
  g.lambda_max_mm = 2.0;
  g.kernel_periods = 1.0;
  g.truncation = 0.05;
  const GaborSetup s = make_gabor_setup(g);
  EXPECT_NEAR(s.cell_mm, 2.0 * std::sqrt(-std::log(0.05)), 1e-12);
  // A kernel at its truncation radius has decayed to the truncation threshold.
  EXPECT_NEAR(std::exp(-(s.cell_mm * s.cell_mm) / (2.0 * 2.0)), 0.05, 1e-12);
}

TEST(GaborTest, ImpulseCountMeanIsDensityOverPi) {
  GaborParams g;
  g.n_min = 20;
  g.n_max = 30;  // mean 25 per kernel footprint -> 25/pi per cell
  const GaborSetup s = make_gabor_setup(g);
  double total = 0.0;
  const int n = 200;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) total += gabor_cell_impulse_count(g, s, 7, x, y);
  EXPECT_NEAR(total / (n * n), 25.0 / std::numbers::pi, 0.05);  // sd of the mean ~0.005
}

TEST(GaborTest, ImpulseCountIsCapped) {
  GaborParams g;
  g.n_min = g.n_max = 1e6;
  g.max_impulses_per_cell = 64;
  const GaborSetup s = make_gabor_setup(g);
  EXPECT_EQ(gabor_cell_impulse_count(g, s, 1, 3, 4), 64);
}

TEST(GaborTest, ZeroAmplitudeGivesZero) {
  GaborParams g;
  g.a_min = g.a_max = 0.0;
  const GaborSetup s = make_gabor_setup(g);
  EXPECT_EQ(gabor_noise(g, s, 1, 1.3, -4.2), 0.0);
}

TEST(GaborTest, VarianceMatchesAnalyticSigma) {
  // Sample the noise on a grid much larger than the kernel; the sample variance of A == 1
  // noise must match sigma_unit^2 (random phase: mean 0). 40k samples spaced 0.37 mm over
  // ~74 mm: correlated over ~1 mm, so ~5000 independent samples -> ~2 % sd; allow 8 %.
  GaborParams g;
  g.lambda_min_mm = g.lambda_max_mm = 0.5;
  g.n_min = 20;
  g.n_max = 30;
  const GaborSetup s = make_gabor_setup(g);
  double sum = 0.0, sum2 = 0.0;
  const int n = 200;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double v = gabor_noise(g, s, 3, x * 0.37, y * 0.37);
      sum += v;
      sum2 += v * v;
    }
  const double mean = sum / (n * n), var = sum2 / (n * n) - mean * mean;
  EXPECT_NEAR(std::sqrt(var) / s.sigma_unit, 1.0, 0.08);
  EXPECT_NEAR(mean / s.sigma_unit, 0.0, 0.1);
}

}  // namespace
}  // namespace ps

namespace ps {
namespace {

GaborParams bench_like_material() {  // the bench scene's material (src/app/bench/bench_sweep.cpp)
  GaborParams g;
  g.lambda_min_mm = 0.8;
  g.lambda_max_mm = 2.0;
  g.theta_max_rad = 1.0;
  return g;
}

TEST(GaborBakedTest, DerivativesMatchCentralDifferences) {
  const GaborParams g = bench_like_material();
  const GaborSetup s = make_gabor_setup(g);
  const double h = 1e-4;  // central differences: error ~ h^2 f''' ~ 1e-8 * (2 pi / 0.8)^3 ~ 5e-6
  for (const auto& [u, v] : {std::pair{0.3, -1.7}, {5.1, 2.2}, {-7.9, 11.4}}) {
    const GaborSample x = gabor_noise_derivatives(g, s, 1, u, v, 0);
    const auto f = [&](double a, double b) { return gabor_noise_derivatives(g, s, 1, a, b, 0).f; };
    EXPECT_NEAR(x.f, gabor_noise(g, s, 1, u, v), 1e-12);
    // Skipped where a truncation circle passes within 2h (the noise jumps there).
    if (gabor_truncation_margin(g, s, 1, u, v) < 2 * h) continue;
    EXPECT_NEAR(x.fu, (f(u + h, v) - f(u - h, v)) / (2 * h), 1e-5);
    EXPECT_NEAR(x.fv, (f(u, v + h) - f(u, v - h)) / (2 * h), 1e-5);
    EXPECT_NEAR(x.fuv, (f(u + h, v + h) - f(u + h, v - h) - f(u - h, v + h) + f(u - h, v - h)) / (4 * h * h), 1e-3);
  }
}

TEST(GaborBakedTest, PeriodicTextureIsPeriodicAndNaiveInsideTheCentralPeriod) {
  const GaborParams g = bench_like_material();
  const GaborSetup s = make_gabor_setup(g);
  const GaborBakePlan plan = make_gabor_bake_plan(g, s);
  ASSERT_TRUE(plan.ok);
  EXPECT_EQ(plan.period_cells % 2, 0);
  EXPECT_LE(plan.texel_mm, g.lambda_min_mm / 8.0 + 1e-12);
  EXPECT_LE(plan.texels, kMaxBakeTexels);
  const double inner = 0.5 * plan.period_mm - s.cell_mm;  // 3x3 cells all inside the period
  for (double u = -inner; u < inner; u += 1.37)
    for (double v = -inner; v < inner; v += 2.11) {
      EXPECT_NEAR(gabor_noise_derivatives(g, s, 1, u, v, plan.period_cells).f, gabor_noise(g, s, 1, u, v), 1e-12);
      EXPECT_NEAR(gabor_noise_derivatives(g, s, 1, u + plan.period_mm, v - plan.period_mm, plan.period_cells).f,
                  gabor_noise(g, s, 1, u, v), 1e-9);
    }
}

TEST(GaborBakedTest, HermiteInterpolationErrorIsBelowOnePercentOfSigma) {
  const GaborParams g = bench_like_material();
  const GaborSetup s = make_gabor_setup(g);
  const GaborBakePlan plan = make_gabor_bake_plan(g, s);
  ASSERT_TRUE(plan.ok);
  double sum2 = 0.0, worst = 0.0;
  int n = 0;
  for (double u = -20.0; u < 20.0; u += 0.731)
    for (double v = -20.0; v < 20.0; v += 0.917) {
      const double e = (gabor_noise_baked(g, s, plan, 1, u, v) - gabor_noise(g, s, 1, u, v)) / s.sigma_unit;
      sum2 += e * e;
      worst = std::max(worst, std::abs(e));
      ++n;
    }
  // texel <= lambda_min / 8: a sinusoid's Hermite error is <= 1e-3 of its amplitude; the
  // truncation jumps (<= 5 % of one kernel's amplitude) add a little near the cut circles.
  EXPECT_LT(std::sqrt(sum2 / n), 0.01) << "worst " << worst;
  std::printf("baked vs naive: RMS %.4f sigma, worst %.4f sigma\n", std::sqrt(sum2 / n), worst);
}

}  // namespace
}  // namespace ps
