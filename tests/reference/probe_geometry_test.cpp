// Probe geometry on the reference plane against closed forms (no GL).
#include <cmath>

#include <gtest/gtest.h>

#include "reference/probe_geometry.h"

namespace ps {
namespace {

TEST(ProbeGeometryTest, SphereLowestPointIsCentreMinusRadius) {
  Probe p;
  p.position = {3.0, -2.0, 10.0};
  p.radius_mm = 8.0;
  const PlaneFrame f = make_plane_frame({0, 0, 1});
  const CapsuleShape c = capsule_of(p);
  EXPECT_NEAR(capsule_lowest_height(c, f, 3.0, -2.0), 2.0, 1e-12);
  // Off centre by 4 mm: h = 10 - sqrt(64 - 16).
  EXPECT_NEAR(capsule_lowest_height(c, f, 7.0, -2.0), 10.0 - std::sqrt(48.0), 1e-12);
  EXPECT_EQ(capsule_lowest_height(c, f, 12.0, -2.0), kNoProbe);
}

TEST(ProbeGeometryTest, LyingCapsuleHasFlatBottomAlongItsAxis) {
  Probe p;
  p.shape = ProbeShape::kCapsule;
  p.position = {0.0, 0.0, 5.0};
  p.axis = {1.0, 0.0, 0.0};
  p.length_mm = 20.0;
  p.radius_mm = 4.0;
  const PlaneFrame f = make_plane_frame({0, 0, 1});
  const CapsuleShape c = capsule_of(p);
  for (double u : {0.0, 5.0, 10.0, 19.9}) EXPECT_NEAR(capsule_lowest_height(c, f, u, 0.0), 1.0, 1e-9);
  EXPECT_NEAR(capsule_lowest_height(c, f, 10.0, 2.0), 5.0 - std::sqrt(12.0), 1e-9);
  EXPECT_NEAR(capsule_lowest_height(c, f, -2.0, 0.0), 5.0 - std::sqrt(12.0), 1e-9);  // end cap
}

TEST(ProbeGeometryTest, TiltedPlaneMeasuresAlongNormal) {
  Probe p;
  p.position = {0.0, 0.0, 0.0};
  p.radius_mm = 2.0;
  const PlaneFrame f = make_plane_frame(glm::normalize(glm::dvec3(1, 1, 1)));
  const CapsuleShape c = capsule_of(p);
  EXPECT_NEAR(capsule_lowest_height(c, f, 0.0, 0.0), -2.0, 1e-12);
}

TEST(ProbeGeometryTest, BoundsOfCapsuleEncloseIt) {
  Probe p;
  p.shape = ProbeShape::kCapsule;
  p.position = {0, 0, 0};
  p.axis = {0, 0, 2};
  p.length_mm = 10;
  p.radius_mm = 3;
  const BoundingSphere b = probe_bounds(p);
  EXPECT_NEAR(b.center.z, 5.0, 1e-12);
  EXPECT_NEAR(b.radius, 8.0, 1e-12);
}

}  // namespace
}  // namespace ps
