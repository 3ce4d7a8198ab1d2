// Closest point and outward normal on the analytic haptic shapes and on one triangle, in the
// shape's local frame (HapticScene moves the query point into it). Pure functions, double
// precision, no allocation: they run on the 1 kHz haptic thread.
// Units: mm. Distances are unsigned (a point inside a sphere or box gets the nearest point on
// its surface); `normal` is the surface's outward normal at `point` (for the two-sided finite
// plane: the side the query point is on).
#pragma once

#include <glm/glm.hpp>

namespace ps::world {

// Unit vector along v, or `fallback` when v is (numerically) zero: a query point on a symmetry
// centre (every direction equally close) or a proxy exactly on a surface.
glm::dvec3 unit_or(const glm::dvec3& v, const glm::dvec3& fallback);

struct SurfacePoint {
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0, 0.0, 1.0};
};

// Finite plane: size_mm.x by size_mm.y in local XY, centred at the origin, normal +Z.
SurfacePoint closest_on_plane(const glm::dvec3& p, const glm::dvec2& size_mm);
// Sphere of radius r at the origin.
SurfacePoint closest_on_sphere(const glm::dvec3& p, double r);
// Box centred at the origin with full edge lengths `size_mm` along X, Y, Z.
SurfacePoint closest_on_box(const glm::dvec3& p, const glm::dvec3& size_mm);
// Ring torus around local Z: major radius R (ring), minor radius r (tube).
SurfacePoint closest_on_torus(const glm::dvec3& p, double major_r, double minor_r);

// Closest point on triangle abc (Ericson, Real-Time Collision Detection §5.1.5) and its
// barycentric coordinates (u, v, w) with point = u a + v b + w c.
struct TrianglePoint {
  glm::dvec3 point{0.0};
  glm::dvec3 barycentric{1.0, 0.0, 0.0};
};
TrianglePoint closest_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                  const glm::dvec3& c);

}  // namespace ps::world
