#include "reference/probe_geometry.h"

#include <algorithm>
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

namespace {

// First s >= 0 where o + s w meets the capsule (segment 0 -> e, radius r) of the same dimension
// (2: its disc-swept outline on the plane, 3: the solid), o outside it; kNoProbe on a miss. The
// quadratics are those of capsule_lowest_height for a direction w of any length.
template <typename V>
double ray_capsule(const V& o, const V& w, const V& e, double r) {
  const double ww = glm::dot(w, w), ee = glm::dot(e, e);
  double best = kNoProbe;
  if (ww <= 0.0) return best;
  if (ee > 0.0) {
    const double ew = glm::dot(e, w), eo = glm::dot(e, o);
    const double a = ee * ww - ew * ew;
    const double b = ee * glm::dot(w, o) - eo * ew;
    const double c = ee * glm::dot(o, o) - eo * eo - r * r * ee;
    const double h = b * b - a * c;
    if (a > 0.0 && h >= 0.0) {
      const double s = (-b - std::sqrt(h)) / a;
      const double y = eo + s * ew;
      if (s >= 0.0 && y > 0.0 && y < ee) best = s;
    }
  }
  for (const V& centre : {V(0.0), e}) {
    const V oc = o - centre;
    const double b = glm::dot(oc, w), h = b * b - ww * (glm::dot(oc, oc) - r * r);
    if (h < 0.0) continue;
    const double s = (-b - std::sqrt(h)) / ww;
    if (s >= 0.0) best = std::min(best, s);
  }
  return best;
}

// Where the closest point of the segment 0 -> e to x lies, in [0, 1].
template <typename V>
double segment_param(const V& x, const V& e) {
  const double ee = glm::dot(e, e);
  return ee > 0.0 ? std::clamp(glm::dot(x, e) / ee, 0.0, 1.0) : 0.0;
}

}  // namespace

// In plane coordinates relative to end a: the ray enters the column above the probe's underside
// either through the underside (it meets the capsule itself: s_k) or through the column's side
// above the silhouette: where its trace on the plane enters the probe's outline F (s_f) at a
// height at or above the silhouette there. The silhouette's height at an outline point is the
// axis's height at the nearest point of the projected axis (the lower end for an upright axis).
double capsule_column_distance(const CapsuleShape& c, const PlaneFrame& f, const glm::dvec3& o,
                               const glm::dvec3& d) {
  const glm::dvec3 e = to_plane(f, c.b) - to_plane(f, c.a);
  const glm::dvec3 p = to_plane(f, o) - to_plane(f, c.a);
  const glm::dvec3 w(glm::dot(d, f.t), glm::dot(d, f.b), glm::dot(d, f.n));
  const double r = c.radius;
  const glm::dvec2 e2(e), p2(p), w2(w);
  const auto silhouette_height = [&](const glm::dvec2& x) {
    if (glm::dot(e2, e2) <= 0.0) return std::min(0.0, e.z);
    return segment_param(x, e2) * e.z;
  };
  const glm::dvec2 near2 = segment_param(p2, e2) * e2;
  const bool in_outline = glm::dot(p2 - near2, p2 - near2) <= r * r;
  const glm::dvec3 near3 = segment_param(p, e) * e;
  if (glm::dot(p - near3, p - near3) <= r * r) return 0.0;               // inside the probe
  if (in_outline && p.z >= silhouette_height(p2)) return 0.0;             // above it
  const double s_f = in_outline ? 0.0 : ray_capsule(p2, w2, e2, r);
  if (s_f == kNoProbe) return kNoProbe;
  const glm::dvec3 q = p + s_f * w;
  if (s_f > 0.0 && q.z >= silhouette_height(glm::dvec2(q))) return s_f;  // through the side
  return ray_capsule(p, w, e, r);
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
