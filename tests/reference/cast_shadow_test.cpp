// The probe's cast shadow's CPU twin (reference/cast_shadow.h) against closed forms: no GL.
#include <gtest/gtest.h>

#include "reference/cast_shadow.h"

namespace ps {
namespace {

const SphereCaster kProbe{{0.0, 0.0, 10.0}, 4.0};
const glm::dvec3 kDown{0.0, 0.0, -1.0};

// Straight down: the shadow is the disc of radius 4 under the centre; its edge, filtered over
// one pixel, is half covered exactly on the circle. 1e-12: double rounding only.
TEST(CastShadowTest, DiscUnderAVerticalLight) {
  EXPECT_DOUBLE_EQ(cast_shadow_coverage(kProbe, {0.0, 0.0, 0.0}, kDown, 0.3), 1.0);
  EXPECT_NEAR(cast_shadow_coverage(kProbe, {4.0, 0.0, 0.0}, kDown, 0.3), 0.5, 1e-12);
  EXPECT_NEAR(cast_shadow_coverage(kProbe, {4.0 + 0.075, 0.0, 0.0}, kDown, 0.3), 0.25, 1e-12);
  EXPECT_DOUBLE_EQ(cast_shadow_coverage(kProbe, {4.15, 0.0, 0.0}, kDown, 0.3), 0.0);
  EXPECT_DOUBLE_EQ(cast_shadow_coverage(kProbe, {6.0, 0.0, 0.0}, kDown, 0.3), 0.0);
}

// The sphere between the point and the light shadows it; beyond the point (the light behind
// it) it does not; a point inside the sphere is in its shadow.
TEST(CastShadowTest, OnlyTowardTheLight) {
  EXPECT_DOUBLE_EQ(cast_shadow_coverage(kProbe, {0.0, 0.0, 20.0}, kDown, 0.3), 0.0);
  EXPECT_DOUBLE_EQ(cast_shadow_coverage(kProbe, {0.0, 0.0, 20.0}, -kDown, 0.3), 1.0);
  EXPECT_DOUBLE_EQ(cast_shadow_coverage(kProbe, {1.0, 0.0, 9.0}, -kDown, 0.3), 1.0);
}

// A slanted light moves the shadow by height x slant: its centre on z = 0 is at (5, 2.5) for a
// light going 0.5 along x and 0.25 along y per unit down, and covered; the foot is not.
TEST(CastShadowTest, SlantedLightMovesTheShadow) {
  const glm::dvec3 light{0.5, 0.25, -1.0};
  const glm::dvec3 c = cast_shadow_centre(kProbe.centre, light, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0});
  EXPECT_NEAR(c.x, 5.0, 1e-12);
  EXPECT_NEAR(c.y, 2.5, 1e-12);
  EXPECT_NEAR(c.z, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(cast_shadow_coverage(kProbe, c, light, 0.3), 1.0);
  EXPECT_DOUBLE_EQ(cast_shadow_coverage(kProbe, {0.0, 0.0, 0.0}, light, 0.3), 0.0);
}

// In shadow only the ambient part of the light is left; lit, surface.frag's factor.
TEST(CastShadowTest, ShadowKeepsTheAmbientLight) {
  EXPECT_DOUBLE_EQ(cast_shadow_light(0.25, 0.8, 1.0), 0.25);
  EXPECT_DOUBLE_EQ(cast_shadow_light(0.25, 0.8, 0.0), 0.25 + 0.75 * 0.8);
  EXPECT_DOUBLE_EQ(cast_shadow_light(0.25, 0.8, 0.5), 0.25 + 0.75 * 0.8 * 0.5);
}

// The pixel's extent across the light: a step along the light does not count.
TEST(CastShadowTest, ExtentAcrossTheLight) {
  EXPECT_DOUBLE_EQ(extent_across({0.3, 0.0, 0.0}, {0.0, 0.0, 0.5}, kDown), 0.3);
  EXPECT_NEAR(extent_across({0.3, 0.0, 0.0}, {0.0, 0.3, 0.0}, {1.0, 0.0, -1.0}), 0.3, 1e-12);
}

}  // namespace
}  // namespace ps
