#include "render/world_markers.h"

#include <algorithm>
#include <cmath>

#include "scene/mesh.h"

namespace ps {

std::vector<WorldMarker> world_markers(const Scene& scene, const glm::dvec3& probe_mm,
                                       std::span<const glm::dvec3> bodies_mm,
                                       std::span<const ChargeMarker> extra_charges, const glm::dvec3& force_n) {
  std::vector<WorldMarker> out;
  const glm::dvec3 push(0.85, 0.2, 0.15), pull(0.15, 0.35, 0.9);
  auto charge = [&](const glm::dvec3& at, double q) {
    out.push_back({at, at, kChargeMarkerRadiusMm, q > 0.0 ? push : pull});
  };
  bool any_charge = !extra_charges.empty();
  for (const Field& f : scene.fields)
    if (f.type == FieldType::kCharge) {
      charge(f.position, f.charge_n_mm2);
      any_charge = true;
    }
  for (const ChargeMarker& c : extra_charges) charge(c.position, c.charge_n_mm2);
  for (const glm::dvec3& b : bodies_mm) out.push_back({probe_mm, b, kBandRadiusMm, glm::dvec3(0.55, 0.4, 0.25)});
  const double f = glm::length(force_n);
  if (any_charge && f > 0.01) {
    const glm::dvec3 tip = probe_mm + kArrowMmPerN * force_n;
    out.push_back({probe_mm, tip, 0.8, glm::dvec3(0.95, 0.85, 0.2)});
    out.push_back({tip, tip, 1.8, glm::dvec3(0.95, 0.85, 0.2)});  // the head
  }
  return out;
}

namespace {

// A bounding radius of the felt shape about its centre.
double felt_radius(const Surface& s) {
  switch (s.type) {
    case SurfaceType::kSphere: return s.radius_mm;
    case SurfaceType::kTorus: return s.radius_mm + s.minor_radius_mm;
    case SurfaceType::kBox: return 0.5 * glm::length(s.box_size_mm);
    case SurfaceType::kPlane:
    case SurfaceType::kHeightField: return 0.5 * glm::length(s.size_mm) + std::abs(s.height_mm);
    case SurfaceType::kMesh: return 100.0 * s.scale;  // unknown without loading it: generous
    case SurfaceType::kFourd: return 3.0 * s.scale;    // the shipped surfaces' images lie within ~2 units
  }
  return 0.0;
}

}  // namespace

glm::dvec3 visual_position(const Scene& scene, const glm::dvec3& felt_mm) {
  for (const Surface& s : scene.surfaces) {
    if (s.visual_stretch == glm::dvec3(1.0)) continue;
    const glm::dmat3 rot = euler_xyz_deg(s.rotation_deg);
    const glm::dvec3 q = glm::transpose(rot) * (felt_mm - s.center);
    const double reach = felt_radius(s) + scene.probe.radius_mm + kStretchReachMarginMm;
    const double w = std::clamp(1.0 - (glm::length(q) - reach) / kStretchFadeMm, 0.0, 1.0);
    if (w <= 0.0) continue;
    return s.center + rot * (q * (glm::dvec3(1.0) + w * (s.visual_stretch - glm::dvec3(1.0))));
  }
  return felt_mm;
}

std::vector<glm::dvec3> start_positions(const Scene& scene) {
  std::vector<glm::dvec3> out;
  for (const Body& b : scene.bodies) out.push_back(b.position);
  return out;
}

WorldMarker rubber_band_marker(const glm::dvec3& probe_mm, const Camera& camera) {
  glm::dvec3 axis = camera.position - camera.target;
  const double len = glm::length(axis);
  axis = len > 0.0 ? axis / len : glm::dvec3(0.0, 0.0, 1.0);
  const glm::dvec3 on_line = camera.target + glm::dot(probe_mm - camera.target, axis) * axis;
  return {probe_mm, on_line, kRubberBandRadiusMm, glm::dvec3(0.95, 0.85, 0.35)};
}

}  // namespace ps
