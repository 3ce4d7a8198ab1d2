// Probe geometry on the reference plane: CPU twin of glsl/probe_depth_analytic.frag.
#pragma once

#include <limits>

#include <glm/glm.hpp>

#include "reference/basis.h"
#include "scene/scene.h"

namespace ps {

inline constexpr double kNoProbe = std::numeric_limits<double>::infinity();

// Capsule segment of a sphere/capsule probe (a == b for a sphere), world space, mm.
struct CapsuleShape {
  glm::dvec3 a{0.0}, b{0.0};
  double radius = 1.0;
};
CapsuleShape capsule_of(const Probe& probe);

// Lowest height h = dot(x, n) of the capsule surface above the plane point (u, v), i.e. the
// first hit of the ray (u, v, -inf) -> +n; kNoProbe where the ray misses.
double capsule_lowest_height(const CapsuleShape& c, const PlaneFrame& f, double u, double v);

// Distance along a ray to a sphere/capsule probe "with the column above its underside": the
// first s >= 0 where o + s d enters the set of points at or above the capsule along the
// reference normal f.n (the solid the probe depth map describes as a height field; thesis
// §4.3.1's depth map, read along the surface's own normal: render.shadow_distance =
// "surface_normal"). o: world point mm, d: unit direction. CPU twin of
// analytic_normal_distance() in glsl/surface.frag; kNoProbe where the ray misses. A ray that
// starts inside that set returns 0.
double capsule_column_distance(const CapsuleShape& c, const PlaneFrame& f, const glm::dvec3& o,
                               const glm::dvec3& d);

// Bounding sphere of the probe in world space (mesh probes: pass the mesh's AABB).
struct BoundingSphere {
  glm::dvec3 center{0.0};
  double radius = 0.0;
};
BoundingSphere probe_bounds(const Probe& probe, const glm::dvec3& mesh_min = glm::dvec3(0.0),
                            const glm::dvec3& mesh_max = glm::dvec3(0.0));

}  // namespace ps
