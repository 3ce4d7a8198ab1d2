// Analytic filtering of the Gabor texture (Lagae et al. 2009 §5), CPU twin: the filtered kernel
// is the convolution of the kernel with the footprint's Gaussian, computed here by quadrature.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "reference/gabor.h"

namespace ps {
namespace {

// (k * G_S)(dx, dy) by the trapezoidal rule over +-8 sd of S's widest axis. The integrand is
// smooth and decays like a Gaussian, so the rule converges geometrically: with a step of
// min(sd_min, lambda) / 8 its error is far below the 1e-9 asked below.
double numeric_convolution(const GaborKernelShape& k, double dx, double dy, const Cov2& S) {
  const double det = S.xx * S.yy - S.xy * S.xy;
  const double m = 0.5 * (S.xx + S.yy), rad = std::sqrt(0.25 * (S.xx - S.yy) * (S.xx - S.yy) + S.xy * S.xy);
  const double sd_max = std::sqrt(m + rad), sd_min = std::sqrt(m - rad);
  const double step = std::min(sd_min, k.lambda) / 8.0, half = 8.0 * sd_max;
  const int n = static_cast<int>(std::ceil(half / step));
  const double ixx = S.yy / det, ixy = -S.xy / det, iyy = S.xx / det;
  const double norm = 1.0 / (2.0 * std::numbers::pi * std::sqrt(det));
  double sum = 0.0;
  for (int j = -n; j <= n; ++j)
    for (int i = -n; i <= n; ++i) {
      const double yx = i * step, yy = j * step;
      const double q = ixx * yx * yx + 2.0 * ixy * yx * yy + iyy * yy * yy;
      sum += norm * std::exp(-0.5 * q) * gabor_kernel(k, dx - yx, dy - yy);
    }
  return sum * step * step;
}

TEST(GaborFilterTest, FilteredKernelIsTheKernelConvolvedWithTheFootprint) {
  const GaborKernelShape kernels[] = {{1.0, 1.0, 0.0, 0.0, 1.0},
                                      {0.7, 0.5, 0.6, 1.3, 0.5},
                                      {1.3, 2.0, 2.2, 4.0, 3.0}};  // W = 1.5 lambda
  for (const GaborKernelShape& k : kernels) {
    const double l2 = k.lambda * k.lambda;
    // Isotropic, axis-aligned anisotropic, rotated anisotropic (a grazing view's stretch);
    // from a tenth of lambda (little attenuation) to half of it (most of it).
    const Cov2 footprints[] = {{0.01 * l2, 0.0, 0.01 * l2},
                               {0.09 * l2, 0.0, 0.01 * l2},
                               {0.10 * l2, 0.06 * l2, 0.05 * l2},
                               {0.25 * l2, -0.05 * l2, 0.04 * l2}};
    for (const Cov2& S : footprints)
      for (const auto& [dx, dy] : {std::pair{0.0, 0.0}, {0.3 * k.lambda, -0.2 * k.lambda}, {-1.1 * k.w, 0.7 * k.w}}) {
        const double analytic = gabor_kernel_filtered(k, dx, dy, S);
        const double numeric = numeric_convolution(k, dx, dy, S);
        // Quadrature error (see numeric_convolution) and double rounding over ~1e5 terms.
        EXPECT_NEAR(analytic, numeric, 1e-9 * k.amp)
            << "lambda " << k.lambda << " theta " << k.theta << " S (" << S.xx << ", " << S.xy << ", " << S.yy
            << ") at (" << dx << ", " << dy << ")";
      }
  }
}

TEST(GaborFilterTest, ZeroFootprintGivesTheUnfilteredKernelAndNoise) {
  const GaborKernelShape k{0.9, 0.8, 0.4, 2.0, 0.8};
  for (double d = -1.0; d <= 1.0; d += 0.125)
    EXPECT_NEAR(gabor_kernel_filtered(k, d, 0.3 * d, {}), gabor_kernel(k, d, 0.3 * d), 1e-14);
  GaborParams g;
  g.lambda_min_mm = 0.8, g.lambda_max_mm = 2.0, g.theta_max_rad = 1.0;
  const GaborSetup s = make_gabor_setup(g);
  double worst = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double u = 0.731 * i - 40.0, v = 0.377 * i - 20.0;
    // Same kernels, same cut (q >= 2 trunc_factor is r^2 >= W^2 trunc_factor at S = 0).
    worst = std::max(worst, std::abs(gabor_noise_filtered(g, s, 7, u, v, {}) - gabor_noise(g, s, 7, u, v)));
  }
  EXPECT_LT(worst / s.sigma_unit, 1e-12) << "double rounding of the same sum";
}

TEST(GaborFilterTest, FilteredNoiseLosesTheVarianceTheSpectrumPredicts) {
  // One wavelength, all orientations: the filtered noise's variance is the unfiltered one times
  // E_theta[ energy of the filtered kernel / energy of the kernel ], the energy of
  // a exp(-d^T Q d / 2) being a^2 pi / sqrt|Q|. Isotropic S = s2 I: the factor is
  // c / (c + s2) * exp(-|k0|^2 c s2 / (c + s2)) with c = W^2 / 2.
  GaborParams g;
  g.lambda_min_mm = g.lambda_max_mm = 1.0, g.theta_min_rad = 0.0, g.theta_max_rad = std::numbers::pi;
  const GaborSetup s = make_gabor_setup(g);
  for (const double sd_in_lambda : {0.1, 0.2}) {
    const double s2 = sd_in_lambda * sd_in_lambda, c = 0.5, k0 = 2.0 * std::numbers::pi;
    const double predicted = c / (c + s2) * std::exp(-k0 * k0 * c * s2 / (c + s2));
    double sum2 = 0.0, sum2_raw = 0.0;
    constexpr int kN = 160;  // 160^2 points 0.6 lambda apart: ~1 % sd of a variance estimate
    for (int j = 0; j < kN; ++j)
      for (int i = 0; i < kN; ++i) {
        const double u = 0.6 * i - 48.0, v = 0.6 * j - 48.0;
        const double f = gabor_noise_filtered(g, s, 3, u, v, {s2, 0.0, s2}), r = gabor_noise(g, s, 3, u, v);
        sum2 += f * f, sum2_raw += r * r;
      }
    // Ratio on the same points, so the texture's own sampling scatter mostly cancels; the rest
    // (and the truncation's 0.25 % of the energy) stays within 3 %.
    EXPECT_NEAR(sum2 / sum2_raw, predicted, 0.03 * predicted) << "footprint sd " << sd_in_lambda << " lambda";
  }
}

TEST(GaborFilterTest, CapKeepsTheAxesAndLimitsTheVariances) {
  const Cov2 c{5.0, 2.0, 1.0};  // eigenvalues 3 +- sqrt(8)
  const Cov2 same = cap_footprint(c, 10.0);
  EXPECT_EQ(same.xx, c.xx);
  EXPECT_EQ(same.xy, c.xy);
  EXPECT_EQ(same.yy, c.yy);
  const Cov2 capped = cap_footprint(c, 2.0);  // major 5.83 -> 2, minor 0.17 kept
  const double m = 0.5 * (capped.xx + capped.yy);
  const double rad = std::sqrt(0.25 * (capped.xx - capped.yy) * (capped.xx - capped.yy) + capped.xy * capped.xy);
  EXPECT_NEAR(m + rad, 2.0, 1e-12);
  EXPECT_NEAR(m - rad, 3.0 - std::sqrt(8.0), 1e-12);
  // Major axis unchanged: (xy, l1 - xx) of the original is still an eigenvector.
  const double l1 = 3.0 + std::sqrt(8.0), ex = c.xy, ey = l1 - c.xx;
  EXPECT_NEAR(capped.xx * ex + capped.xy * ey, 2.0 * ex, 1e-12);
  const Cov2 fp = footprint_from_derivatives(0.5, 0.0, 0.0, 2.0, 1.0 / 12.0);
  EXPECT_DOUBLE_EQ(fp.xx, 0.25 / 12.0);
  EXPECT_DOUBLE_EQ(fp.yy, 4.0 / 12.0);
  EXPECT_DOUBLE_EQ(fp.xy, 0.0);
}

TEST(GaborFilterTest, FilteredTileLevelsSampleTheFilteredNoiseAndItsDerivatives) {
  // The bake's filtered levels (gabor_noise_derivatives with sigma2) against
  // gabor_noise_filtered and its central differences.
  GaborParams g;
  g.lambda_min_mm = 0.8, g.lambda_max_mm = 2.0, g.theta_max_rad = 1.0;
  const GaborSetup s = make_gabor_setup(g);
  const double s2 = 0.04, e = 1e-4;
  const Cov2 S{s2, 0.0, s2};
  for (int i = 0; i < 40; ++i) {
    const double u = 0.913 * i - 17.0, v = -0.417 * i + 5.0;
    const GaborSample d = gabor_noise_derivatives(g, s, 5, u, v, 0, s2);
    const auto f = [&](double du, double dv) { return gabor_noise_filtered(g, s, 5, u + du, v + dv, S); };
    EXPECT_NEAR(d.f, f(0, 0), 1e-12);
    // Central differences err by f''' e^2 / 6 ~ (2 pi / 0.8)^3 1e-8 / 6 ~ 1e-6 of A; where a
    // kernel's cut falls within e the difference jumps by up to 5 % A / e: such points are rare
    // (none on this path; the margin would show in the message).
    EXPECT_NEAR(d.fu, (f(e, 0) - f(-e, 0)) / (2 * e), 1e-4) << u << " " << v;
    EXPECT_NEAR(d.fv, (f(0, e) - f(0, -e)) / (2 * e), 1e-4) << u << " " << v;
    EXPECT_NEAR(d.fuv, (f(e, e) - f(e, -e) - f(-e, e) + f(-e, -e)) / (4 * e * e), 1e-2) << u << " " << v;
  }
}

TEST(GaborFilterTest, AnalyticFilterGivesTilesFilteredLevels) {
  GaborParams g;
  g.lambda_min_mm = g.lambda_max_mm = 0.5;
  g.bake_samples_per_lambda = 24;
  const GaborSetup s = make_gabor_setup(g);
  g.filter = GaborParams::Filter::kNone;
  EXPECT_EQ(make_gabor_bake_plan(g, s).filtered_levels, 0);
  g.filter = GaborParams::Filter::kAnalytic;
  const GaborBakePlan p = make_gabor_bake_plan(g, s);
  ASSERT_TRUE(p.ok);
  ASSERT_GT(p.filtered_levels, 2);
  for (int l = 1; l <= p.filtered_levels; ++l) {
    EXPECT_GE(p.level_texels(l), 16);
    EXPECT_NEAR(std::sqrt(p.level_sigma2_mm2(l)), p.level_sigma_texels() * p.period_mm / (p.texels >> l), 1e-12);
  }
  // The last level's filter reaches lambda (the texture is then gone, exp(-2 pi^2)) or the
  // tile's smallest size.
  EXPECT_TRUE(p.level_sigma2_mm2(p.filtered_levels) >= 0.25 || p.level_texels(p.filtered_levels + 1) < 16);
}

}  // namespace
}  // namespace ps
