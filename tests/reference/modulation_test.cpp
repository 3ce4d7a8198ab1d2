// Formulas of the method against the thesis's own numbers and closed forms (no GL).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "reference/modulation.h"

namespace ps {
namespace {

Material thesis_material() {
  Material m;  // defaults are the thesis constants: 0.1 + 0.9 / (d + 1.25)
  m.influence_distance_mm = 50.0;
  return m;
}

TEST(ShadowIntensityTest, MatchesThesisCurve) {
  const Material m = thesis_material();
  EXPECT_EQ(shadow_intensity(m, -3.0), 1.0);  // penetrating: opaque
  EXPECT_EQ(shadow_intensity(m, 0.0), 1.0);   // touching: opaque
  // Just above contact the curve drops to 0.1 + 0.9/1.25 = 0.82: the jump that tells
  // "touching" from "close" (thesis §4.3.2).
  EXPECT_NEAR(shadow_intensity(m, 1e-9), 0.82, 1e-9);
  // The jump sits exactly at d = 0: slightly below is still contact, slightly above is not
  // (a threshold moved by a hundredth of a millimetre either way shows here).
  EXPECT_EQ(shadow_intensity(m, -1e-9), 1.0);
  EXPECT_EQ(shadow_intensity(m, -0.005), 1.0);
  EXPECT_NEAR(shadow_intensity(m, 0.005), 0.1 + 0.9 / 1.255, 1e-15);
  EXPECT_EQ(shadow_intensity(m, -0.0), 1.0);
  EXPECT_NEAR(shadow_intensity(m, 2.0), 0.1 + 0.9 / 3.25, 1e-15);
  EXPECT_EQ(shadow_intensity(m, 50.0), 0.0);  // at the influence distance: gone
  EXPECT_EQ(shadow_intensity(m, std::nan("")), 0.0);
}

TEST(ShadowIntensityTest, DecreasesWithDistance) {
  const Material m = thesis_material();
  double prev = 2.0;
  for (double d = 0.01; d < 49.0; d += 0.37) {
    const double i = shadow_intensity(m, d);
    EXPECT_LT(i, prev);
    prev = i;
  }
}

TEST(SpeedModulationTest, FrequencyGapThreeCases) {
  // lambda in [0.5, 1] mm: optimal speeds [125, 250] mm/s give 250 Hz somewhere in the range.
  EXPECT_DOUBLE_EQ(frequency_gap_hz(50.0, 0.5, 1.0, 250.0), 150.0);   // f_max = 100 Hz
  EXPECT_DOUBLE_EQ(frequency_gap_hz(200.0, 0.5, 1.0, 250.0), 0.0);    // 200..400 Hz holds 250
  EXPECT_DOUBLE_EQ(frequency_gap_hz(400.0, 0.5, 1.0, 250.0), 150.0);  // f_min = 400 Hz
  EXPECT_DOUBLE_EQ(frequency_gap_hz(0.0, 0.5, 1.0, 250.0), 250.0);    // at rest
}

TEST(SpeedModulationTest, GainIsGaussianOfGap) {
  Material m = thesis_material();
  m.gabor.lambda_min_mm = m.gabor.lambda_max_mm = 0.5;
  m.bandwidth_hz = 100.0;
  EXPECT_DOUBLE_EQ(amplitude_gain(m, 125.0), 1.0);  // exactly 250 Hz
  EXPECT_NEAR(amplitude_gain(m, 75.0), std::exp(-1.0), 1e-15);  // 150 Hz: gap = bandwidth
  EXPECT_EQ(amplitude_gain(m, std::nan("")), 0.0);
  EXPECT_EQ(amplitude_gain(m, -1.0), 0.0);
}

TEST(SpeedModulationTest, AnisotropicUsesSpeedAlongTextureDirection) {
  Material m = thesis_material();
  m.gabor.lambda_min_mm = m.gabor.lambda_max_mm = 0.5;
  m.gabor.theta_min_rad = m.gabor.theta_max_rad = 0.0;  // fully anisotropic, waves along u
  const PlaneFrame f = make_plane_frame({0, 0, 1});
  // Moving across the waves at 125 mm/s: 250 Hz, full amplitude.
  EXPECT_NEAR(speed_gain(m, f, {125.0, 0.0, 0.0}), 1.0, 1e-12);
  // Moving along the ridges: no vibration, the same as at rest.
  EXPECT_NEAR(speed_gain(m, f, {0.0, 125.0, 0.0}), amplitude_gain(m, 0.0), 1e-12);
  // Motion along the normal is not in-plane and does not count.
  EXPECT_NEAR(speed_gain(m, f, {125.0, 0.0, 500.0}), 1.0, 1e-12);
}

TEST(SpeedModulationTest, IsotropicUsesInPlaneSpeed) {
  Material m = thesis_material();
  m.gabor.lambda_min_mm = m.gabor.lambda_max_mm = 0.5;
  m.gabor.theta_min_rad = 0.0;
  m.gabor.theta_max_rad = std::numbers::pi;
  const PlaneFrame f = make_plane_frame({0, 0, 1});
  EXPECT_NEAR(speed_gain(m, f, {0.0, 125.0, 0.0}), 1.0, 1e-12);
  EXPECT_NEAR(speed_gain(m, f, {125.0 / std::sqrt(2.0), 125.0 / std::sqrt(2.0), 0.0}), 1.0, 1e-12);
}

TEST(SpeedModulationTest, HalfAnisotropyBlendsLinearly) {
  Material m = thesis_material();
  m.gabor.lambda_min_mm = m.gabor.lambda_max_mm = 0.5;
  m.gabor.theta_min_rad = -std::numbers::pi / 4;
  m.gabor.theta_max_rad = std::numbers::pi / 4;  // blend 0.5, mean direction u
  const PlaneFrame f = make_plane_frame({0, 0, 1});
  const double g = speed_gain(m, f, {0.0, 125.0, 0.0});
  EXPECT_NEAR(g, 0.5 * amplitude_gain(m, 0.0) + 0.5 * 1.0, 1e-12);
}

TEST(DisplacementWeightTest, RescaledThesisWeight) {
  // (1 - d)^c / (1 + max)^c, computed in log space.
  EXPECT_NEAR(displacement_weight(-1.0, 20.0, 3.0), std::pow(2.0 / 4.0, 20.0), 1e-18);
  EXPECT_DOUBLE_EQ(displacement_weight(-3.0, 20.0, 3.0), 1.0);
  EXPECT_EQ(displacement_weight(0.5, 20.0, 3.0), 0.0);  // not penetrating: no weight
  // Penetration of 1000 mm with c = 40: (1001)^40 overflows double; the rescaled weight does not.
  EXPECT_DOUBLE_EQ(displacement_weight(-1000.0, 40.0, 1000.0), 1.0);
  EXPECT_TRUE(std::isfinite(displacement_weight(-500.0, 40.0, 1000.0)));
}

// The composite's four discounting properties (docs/architecture.md "Composite") on the twin,
// against hand values of the thesis curve (onset 5 mm: I(5) = 0.1 + 0.9 / 6.25 = 0.244;
// I(0+) = 0.1 + 0.9 / 1.25 = 0.82).
TEST(CompositeTest, TextureAddsDetailNotLight) {
  const Material m = thesis_material();
  for (double d : {0.5, 1.5, 3.0, 4.9, -0.5})
    for (double g : {0.0, 0.4, 1.0})
      for (double s : {0.3, 0.9, 2.0}) {  // +s and -s: a symmetric texture's pair
        const double mean = 0.5 * (pseudo_shadow_darkening(m, d, 1.0, g, s) +
                                   pseudo_shadow_darkening(m, d, 1.0, g, -s));
        const double untextured = d <= 0.0 ? 1.0 - g * 0.09 : shadow_intensity(m, d);
        EXPECT_NEAR(mean, untextured, 1e-12) << d << " " << g << " " << s;
      }
  EXPECT_NEAR(pseudo_shadow_darkening(m, 1.5, 1.0, 1.0, 0.0), 0.1 + 0.9 / 2.75, 1e-12);
  // d = 1.5: I = 0.42727, amplitude min(I - 0.244, 1 - I) = 0.18327; s = 1 and s = -1.
  EXPECT_NEAR(pseudo_shadow_darkening(m, 1.5, 1.0, 1.0, 1.0), 0.42727 + 0.18327, 1e-5);
  EXPECT_NEAR(pseudo_shadow_darkening(m, 1.5, 1.0, 1.0, -1.0), 0.244, 1e-5);
  // Contact: the mean jumps to 1 - 0.09 at full gain, the texture spans [0.82, 1].
  EXPECT_NEAR(pseudo_shadow_darkening(m, -1.0, 1.0, 1.0, -1.0), 0.82, 1e-12);
  EXPECT_NEAR(pseudo_shadow_darkening(m, -1.0, 1.0, 1.0, 1.0), 1.0, 1e-12);
}

TEST(CompositeTest, DarkerEverywhereAndMonotoneAsTheProbeApproaches) {
  const Material m = thesis_material();
  for (double g : {0.0, 0.5, 1.0})
    for (double s = -1.0; s <= 1.0; s += 0.25) {
      double prev = 0.0;
      for (double d = 12.0; d >= -1.0; d -= 0.01) {
        const double dark = pseudo_shadow_darkening(m, d, 1.0, g, s);
        EXPECT_GT(dark, 0.0);
        EXPECT_LE(dark, 1.0);
        EXPECT_GE(dark, prev - 1e-12) << "d " << d << " gain " << g << " s " << s;
        prev = dark;
      }
    }
}

TEST(CompositeTest, TextureFadesInAtTheOnset) {
  const Material m = thesis_material();
  // Just inside the onset distance the texture's swing is tiny (no ring where it appears):
  // the slope of I there is 0.9 / 6.25^2 = 0.023 per mm, so 0.01 mm in gives ~2.3e-4.
  const double in = 5.0 - 0.01;
  const double swing = pseudo_shadow_darkening(m, in, 1.0, 1.0, 1.0) -
                       pseudo_shadow_darkening(m, in, 1.0, 1.0, -1.0);
  EXPECT_NEAR(swing, 2.0 * 0.9 * (1.0 / 6.24 - 1.0 / 6.25), 1e-9);
  EXPECT_EQ(pseudo_shadow_darkening(m, 5.0, 1.0, 1.0, 1.0), shadow_intensity(m, 5.0));
  EXPECT_NEAR(pseudo_shadow_darkening(m, 3.0, 0.25, 1.0, 0.5), 0.25 * pseudo_shadow_darkening(m, 3.0, 1.0, 1.0, 0.5), 1e-15);
}

}  // namespace
}  // namespace ps
