#include "world/shapes.h"

#include <algorithm>
#include <cmath>

namespace ps::world {

glm::dvec3 unit_or(const glm::dvec3& v, const glm::dvec3& fallback) {
  const double len = glm::length(v);
  return len > 1e-12 ? v / len : fallback;
}

SurfacePoint closest_on_plane(const glm::dvec3& p, const glm::dvec2& size_mm) {
  const glm::dvec2 h = 0.5 * size_mm;
  SurfacePoint s;
  s.point = {std::clamp(p.x, -h.x, h.x), std::clamp(p.y, -h.y, h.y), 0.0};
  s.normal = {0.0, 0.0, p.z >= 0.0 ? 1.0 : -1.0};
  return s;
}

SurfacePoint closest_on_sphere(const glm::dvec3& p, double r) {
  SurfacePoint s;
  s.normal = unit_or(p, {0.0, 0.0, 1.0});
  s.point = r * s.normal;
  return s;
}

SurfacePoint closest_on_box(const glm::dvec3& p, const glm::dvec3& size_mm) {
  const glm::dvec3 h = 0.5 * size_mm;
  const glm::dvec3 clamped = glm::clamp(p, -h, h);
  SurfacePoint s;
  if (clamped != p) {  // outside: the clamped point is on the surface
    s.point = clamped;
    // Outward normal of the face (or edge/corner: the direction to the point, which is the
    // normal of the box's offset surface there).
    s.normal = unit_or(p - clamped, {0.0, 0.0, 1.0});
    return s;
  }
  // Inside: push out through the nearest face.
  int axis = 0;
  double best = h.x - std::abs(p.x);
  for (int i = 1; i < 3; ++i) {
    const double d = h[i] - std::abs(p[i]);
    if (d < best) { best = d; axis = i; }
  }
  s.point = p;
  s.point[axis] = p[axis] >= 0.0 ? h[axis] : -h[axis];
  s.normal = glm::dvec3(0.0);
  s.normal[axis] = p[axis] >= 0.0 ? 1.0 : -1.0;
  return s;
}

SurfacePoint closest_on_torus(const glm::dvec3& p, double major_r, double minor_r) {
  // Nearest point of the ring (the tube's centre circle), then out along the tube's radius.
  const glm::dvec3 radial = unit_or({p.x, p.y, 0.0}, {1.0, 0.0, 0.0});
  const glm::dvec3 ring = major_r * radial;
  SurfacePoint s;
  s.normal = unit_or(p - ring, radial);
  s.point = ring + minor_r * s.normal;
  return s;
}

TrianglePoint closest_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                  const glm::dvec3& c) {
  // Voronoi regions of the vertices, then edges, then the face.
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {a, {1.0, 0.0, 0.0}};
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return {b, {0.0, 1.0, 0.0}};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {a + v * ab, {1.0 - v, v, 0.0}};
  }
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return {c, {0.0, 0.0, 1.0}};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {a + w * ac, {1.0 - w, 0.0, w}};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + w * (c - b), {0.0, 1.0 - w, w}};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {a + v * ab + w * ac, {1.0 - v - w, v, w}};
}

}  // namespace ps::world
