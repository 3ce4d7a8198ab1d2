// The bodies' pseudo-shadow law (reference/body_shadow.h) at closed-form points: the intensity
// curve at the foot, the disc's radius at the influence distance and below the receiver, the
// filtered rim, monotone in the body's height and in the distance from the foot, and the
// multiplicative combination.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "reference/body_shadow.h"
#include "reference/modulation.h"

namespace ps {
namespace {

const glm::dvec3 kUp{0.0, 0.0, 1.0};
constexpr double kR = 6.0, kEdge = 0.3125;

SphereCaster ball(double gap_mm) { return {{0.0, 0.0, kR + gap_mm}, kR}; }

TEST(BodyShadowTest, FootFollowsTheIntensityCurve) {
  const Material m;
  for (double gap : {0.01, 0.5, 1.25, 5.0, 20.0, 49.0})
    EXPECT_DOUBLE_EQ(body_shadow_darkening(m, ball(gap), {0, 0, 0}, kUp, kEdge), shadow_intensity(m, gap)) << gap;
  EXPECT_EQ(body_shadow_darkening(m, ball(0.0), {0, 0, 0}, kUp, kEdge), 1.0);   // contact
  EXPECT_EQ(body_shadow_darkening(m, ball(-2.0), {0, 0, 0}, kUp, kEdge), 1.0);  // through the receiver
  // Off the foot the distance is the sphere's lower surface: d = gap + r - sqrt(r^2 - rho^2).
  const double rho = 4.0, d = 1.0 + kR - std::sqrt(kR * kR - rho * rho);
  EXPECT_DOUBLE_EQ(body_shadow_darkening(m, ball(1.0), {rho, 0, 0}, kUp, kEdge), shadow_intensity(m, d));
}

TEST(BodyShadowTest, DiscEndsAtTheInfluenceDistanceAndBelowTheReceiver) {
  const Material m;  // influence 50 mm
  EXPECT_EQ(body_shadow_radius_mm(kR + 10.0, kR, 50.0), kR);
  EXPECT_EQ(body_shadow_radius_mm(kR + 50.0 - kR, kR, 50.0), kR);  // centre at the influence distance
  EXPECT_NEAR(body_shadow_radius_mm(kR + 49.99, kR, 50.0), std::sqrt(2.0 * kR * 0.01 - 1e-4), 1e-12);
  EXPECT_EQ(body_shadow_radius_mm(kR + 50.01, kR, 50.0), 0.0);
  EXPECT_NEAR(body_shadow_radius_mm(-3.0, kR, 50.0), std::sqrt(kR * kR - 9.0), 1e-12);  // centre 3 mm below
  EXPECT_EQ(body_shadow_radius_mm(-kR - 0.01, kR, 50.0), 0.0);  // wholly below: hidden by the receiver
  for (double x = -10.0; x <= 10.0; x += 0.05) {
    EXPECT_EQ(body_shadow_darkening(m, ball(50.01), {x, 0.3, 0}, kUp, kEdge), 0.0) << x;
    EXPECT_EQ(body_shadow_darkening(m, ball(-2.0 * kR - 0.01), {x, 0.3, 0}, kUp, kEdge), 0.0) << x;
  }
  EXPECT_GT(body_shadow_darkening(m, ball(49.99), {0, 0, 0}, kUp, kEdge), 0.1);
  // A material's own shorter influence distance.
  Material near;
  near.influence_distance_mm = 10.0;
  EXPECT_EQ(body_shadow_darkening(near, ball(10.01), {0, 0, 0}, kUp, kEdge), 0.0);
  EXPECT_GT(body_shadow_darkening(near, ball(9.99), {0, 0, 0}, kUp, kEdge), 0.1);
}

// The rim is a ramp one pixel wide centred on the disc's edge: half covered on the edge, empty
// half a pixel outside; a disc narrower than a pixel covers at most 2R / pixel.
TEST(BodyShadowTest, RimIsFilteredOverOnePixel) {
  const Material m;
  const double edge_i = shadow_intensity(m, 1.0 + kR);  // at rho = r: d = gap + r
  EXPECT_NEAR(body_shadow_darkening(m, ball(1.0), {kR, 0, 0}, kUp, kEdge), 0.5 * edge_i, 1e-12);
  EXPECT_NEAR(body_shadow_darkening(m, ball(1.0), {kR + 0.25 * kEdge, 0, 0}, kUp, kEdge), 0.25 * edge_i, 1e-12);
  EXPECT_EQ(body_shadow_darkening(m, ball(1.0), {kR + 0.5 * kEdge, 0, 0}, kUp, kEdge), 0.0);
  const double disc = body_shadow_radius_mm(kR + 49.999, kR, 50.0);  // 0.11 mm
  EXPECT_NEAR(body_shadow_darkening(m, ball(49.999), {0, 0, 0}, kUp, kEdge),
              2.0 * disc / kEdge * shadow_intensity(m, 49.999), 1e-9);
}

// Darker as the body comes down, at every point, and never darker away from the foot.
TEST(BodyShadowTest, MonotoneInHeightAndInDistanceFromTheFoot) {
  const Material m;
  for (double x = 0.0; x <= kR + kEdge; x += 0.01) {
    double prev = 0.0;
    for (double gap = 52.0; gap >= -kR; gap -= 0.01) {
      const double dk = body_shadow_darkening(m, ball(gap), {x, 0, 0}, kUp, kEdge);
      ASSERT_GE(dk, prev) << "x " << x << " gap " << gap;
      ASSERT_LE(dk, 1.0);
      prev = dk;
    }
  }
  for (double gap : {0.0, 0.1, 2.0, 30.0, 49.9}) {
    double prev = 1.0;
    for (double x = 0.0; x <= kR + kEdge; x += 0.001) {
      const double dk = body_shadow_darkening(m, ball(gap), {x, 0, 0}, kUp, kEdge);
      ASSERT_LE(dk, prev) << "x " << x << " gap " << gap;
      prev = dk;
    }
  }
}

TEST(BodyShadowTest, CastersCombineAsIndependentAbsorbers) {
  const Material m;
  const std::vector<SphereCaster> two{ball(1.0), {{1.0, 0.0, kR + 3.0}, kR}};
  const glm::dvec3 x{0.5, 0.2, 0.0};
  const double a = body_shadow_darkening(m, two[0], x, kUp, kEdge), b = body_shadow_darkening(m, two[1], x, kUp, kEdge);
  EXPECT_DOUBLE_EQ(body_shadows_darkening(m, two, x, kUp, kEdge), 1.0 - (1.0 - a) * (1.0 - b));
  EXPECT_GE(combine_darkening(a, b), std::max(a, b));
  EXPECT_LE(combine_darkening(a, b), 1.0);
  EXPECT_EQ(combine_darkening(a, 0.0), a);
  EXPECT_EQ(body_shadows_darkening(m, {}, x, kUp, kEdge), 0.0);
}

// Along any reference normal, not only +Z: the law depends on heights and lateral distances.
TEST(BodyShadowTest, TiltedReferenceNormal) {
  const Material m;
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.4, 1.0));
  const glm::dvec3 x{2.0, -1.0, 0.5};
  const SphereCaster tilted{x + (kR + 1.5) * n, kR};
  EXPECT_NEAR(body_shadow_darkening(m, tilted, x, n, kEdge), shadow_intensity(m, 1.5), 1e-12);
}

}  // namespace
}  // namespace ps
