#include "reference/probe_geometry.h"

#include <cmath>

namespace ps {

CapsuleShape capsule_of(const Probe& probe) {
  CapsuleShape c;
  c.a = probe.position;
  c.b = probe.position;
  if (probe.shape == ProbeShape::kCapsule) {
    const double len = glm::length(probe.axis);
    if (len > 0.0) c.b = probe.position + probe.axis / len * probe.length_mm;
  }
  c.radius = probe.radius_mm;
  return c;
}

namespace {

// Ray/sphere, ray origin o, unit direction d: nearest t or +inf.
double hit_sphere(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& c, double r) {
  const glm::dvec3 oc = o - c;
  const double b = glm::dot(oc, d);
  const double h = b * b - (glm::dot(oc, oc) - r * r);
  if (h < 0.0) return kNoProbe;
  return -b - std::sqrt(h);
}

}  // namespace

// Ray/capsule after Inigo Quilez's capIntersect (cylinder body, then the two end spheres).
double capsule_lowest_height(const CapsuleShape& c, const PlaneFrame& f, double u, double v) {
  // Work in plane coordinates so the ray is axis aligned: o = (u, v, h0), d = (0, 0, 1).
  const glm::dvec3 pa = to_plane(f, c.a), pb = to_plane(f, c.b);
  const double h0 = std::min(pa.z, pb.z) - 2.0 * c.radius - 1.0;
  const glm::dvec3 ro(u, v, h0), rd(0.0, 0.0, 1.0);
  const glm::dvec3 ba = pb - pa, oa = ro - pa;
  const double baba = glm::dot(ba, ba), bard = glm::dot(ba, rd), baoa = glm::dot(ba, oa);
  const double rdoa = glm::dot(rd, oa), oaoa = glm::dot(oa, oa);
  double best = kNoProbe;
  if (baba > 0.0) {
    const double a = baba - bard * bard;
    const double b = baba * rdoa - baoa * bard;
    const double cc = baba * oaoa - baoa * baoa - c.radius * c.radius * baba;
    const double h = b * b - a * cc;
    if (a > 0.0 && h >= 0.0) {
      const double t = (-b - std::sqrt(h)) / a;
      const double y = baoa + t * bard;
      if (y > 0.0 && y < baba) best = t;
    }
  }
  best = std::min(best, hit_sphere(ro, rd, pa, c.radius));
  best = std::min(best, hit_sphere(ro, rd, pb, c.radius));
  return best == kNoProbe ? kNoProbe : h0 + best;
}

BoundingSphere probe_bounds(const Probe& probe, const glm::dvec3& mesh_min,
                            const glm::dvec3& mesh_max) {
  if (probe.shape == ProbeShape::kMesh) {
    return {0.5 * (mesh_min + mesh_max), 0.5 * glm::length(mesh_max - mesh_min)};
  }
  const CapsuleShape c = capsule_of(probe);
  return {0.5 * (c.a + c.b), 0.5 * glm::length(c.b - c.a) + c.radius};
}

}  // namespace ps
