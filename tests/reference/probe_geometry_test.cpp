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


// capsule_column_distance against an independent oracle: a point is in the column above the
// probe's underside exactly when the probe's lowest height above its plane point
// (capsule_lowest_height, the depth map's own CPU twin) is at or below it. The first such point
// along each ray is found by stepping 0.01 mm and bisecting to 1e-10 mm; 1e-6 mm covers the
// step's bisection and the closed forms' rounding (doubles, lengths of tens of mm).
double first_entry_by_search(const CapsuleShape& c, const PlaneFrame& f, const glm::dvec3& o,
                             const glm::dvec3& d, double s_max) {
  const auto inside = [&](double s) {
    const glm::dvec3 q = o + s * d;
    const glm::dvec3 pq = to_plane(f, q);
    const double h = capsule_lowest_height(c, f, pq.x, pq.y);
    return h != kNoProbe && h <= pq.z;
  };
  if (inside(0.0)) return 0.0;
  for (double s = 0.01; s <= s_max; s += 0.01) {
    if (!inside(s)) continue;
    double a = s - 0.01, b = s;
    while (b - a > 1e-10) (inside(0.5 * (a + b)) ? b : a) = 0.5 * (a + b);
    return b;
  }
  return kNoProbe;
}

TEST(ProbeGeometryTest, ColumnDistanceMatchesASearchAlongTheRay) {
  struct Shape {
    const char* name;
    ProbeShape shape;
    glm::dvec3 axis;
  };
  const glm::dvec3 centre{1.0, -2.0, 12.0};
  int hits = 0, side_entries = 0, misses = 0;
  for (const Shape& sh : {Shape{"sphere", ProbeShape::kSphere, {0, 0, 1}},
                          Shape{"upright capsule", ProbeShape::kCapsule, {0, 0, 1}},
                          Shape{"tilted capsule", ProbeShape::kCapsule, {0.0, -0.5, 0.866}},
                          Shape{"lying capsule", ProbeShape::kCapsule, {1, 0, 0}}}) {
    Probe p;
    p.shape = sh.shape;
    p.position = centre;
    p.radius_mm = 5.0;
    p.length_mm = 12.0;
    p.axis = sh.axis;
    const CapsuleShape c = capsule_of(p);
    for (const glm::dvec3 n : {glm::dvec3(0, 0, 1), glm::normalize(glm::dvec3(0.2, -0.1, 1.0))}) {
      const PlaneFrame f = make_plane_frame(n);
      // A fan of rays from points under and beside the probe, tilted up to 60 deg off n.
      for (int i = 0; i < 400; ++i) {
        const double a = 0.7 * i, tilt = 1.05 * ((i * 37) % 100) / 100.0;
        const glm::dvec3 o = centre + glm::dvec3(9.0 * std::cos(a), 9.0 * std::sin(1.3 * a), -9.0 - 0.02 * i);
        const glm::dvec3 d = glm::normalize(n * std::cos(tilt) + f.t * (std::sin(tilt) * std::cos(2.1 * a)) +
                                            f.b * (std::sin(tilt) * std::sin(2.1 * a)));
        const double got = capsule_column_distance(c, f, o, d);
        const double want = first_entry_by_search(c, f, o, d, 60.0);
        if (want == kNoProbe) {  // no entry within the 60 mm searched
          EXPECT_TRUE(got == kNoProbe || got > 60.0) << sh.name << " ray " << i << ": " << got;
          ++misses;
          continue;
        }
        ASSERT_NE(got, kNoProbe) << sh.name << " ray " << i << " expected " << want;
        EXPECT_NEAR(got, want, 1e-6) << sh.name << " ray " << i;
        ++hits;
        const glm::dvec3 q = o + got * d;
        // Entered through the column's side, not through the probe itself.
        const glm::dvec3 pq = to_plane(f, q);
        side_entries += capsule_lowest_height(c, f, pq.x, pq.y) < pq.z - 1e-3;
      }
    }
  }
  // The fan has to exercise every branch: hits through the underside, through the side, misses.
  EXPECT_GT(hits, 500);
  EXPECT_GT(side_entries, 50);
  EXPECT_GT(misses, 200);
  RecordProperty("hits", hits);
  RecordProperty("side_entries", side_entries);
  RecordProperty("misses", misses);
}

TEST(ProbeGeometryTest, ColumnDistanceOfAPointInsideOrAboveTheProbeIsZero) {
  Probe p;
  p.position = {0.0, 0.0, 10.0};
  p.radius_mm = 4.0;
  const PlaneFrame f = make_plane_frame({0, 0, 1});
  const CapsuleShape c = capsule_of(p);
  EXPECT_EQ(capsule_column_distance(c, f, {0.0, 0.0, 9.0}, {0, 0, 1}), 0.0);   // inside
  EXPECT_EQ(capsule_column_distance(c, f, {1.0, 0.0, 30.0}, {0, 0, 1}), 0.0);  // above
  // Straight up from under the centre: the lowest point, 6 mm from z = 0.
  EXPECT_NEAR(capsule_column_distance(c, f, {0.0, 0.0, 0.0}, {0, 0, 1}), 6.0, 1e-12);
  // Straight up beside it: a miss.
  EXPECT_EQ(capsule_column_distance(c, f, {4.5, 0.0, 0.0}, {0, 0, 1}), kNoProbe);
}

}  // namespace
}  // namespace ps
