#include "render/plan.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ps {

double distance_sphere_aabb(const BoundingSphere& s, const Aabb& box) {
  const glm::dvec3 closest = glm::clamp(s.center, box.min, box.max);
  return std::max(0.0, glm::length(s.center - closest) - s.radius);
}

namespace {
std::string surface_label(const Scene& scene, size_t i) {
  std::ostringstream o;
  o << "surface " << i << " (material '" << scene.surfaces[i].material << "')";
  return o.str();
}
bool has_texture(const Material& m) {
  return m.textured && (m.gabor.a_min != 0.0 || m.gabor.a_max != 0.0) &&
         m.gabor.max_impulses_per_cell > 0 && std::max(m.gabor.n_min, m.gabor.n_max) > 0.0;
}
// Distance is measured along the reference normal (d = h_probe - h_surface), so a probe that
// sank far below a surface is penetrating it (d << 0), even when its bounding sphere is
// farther than the influence distance from the surface's box. True when the probe's lowest
// height lies below the box's highest one and its footprint disc, on the plane, comes
// within `reach` of the box's projection.
bool sunk_below(const BoundingSphere& probe, const Aabb& box, const PlaneFrame& f, double reach) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                            (i & 4) ? box.max.z : box.min.z);
    const glm::dvec3 q = to_plane(f, corner);
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const glm::dvec3 c = to_plane(f, probe.center);
  if (!(c.z - probe.radius < hi.z)) return false;
  const double du = std::max({lo.x - c.x, 0.0, c.x - hi.x}), dv = std::max({lo.y - c.y, 0.0, c.y - hi.y});
  return std::hypot(du, dv) < probe.radius + reach;
}

}  // namespace

std::vector<SphereCaster> bodies_in_reach(std::span<const SphereCaster> bodies, const Aabb& bounds,
                                          double influence_mm) {
  std::vector<SphereCaster> out;
  for (const SphereCaster& b : bodies) {
    // A non-finite centre would reach the shader as NaN (distance_sphere_aabb reads it as 0).
    const bool finite = std::isfinite(b.centre.x) && std::isfinite(b.centre.y) && std::isfinite(b.centre.z) &&
                        std::isfinite(b.radius_mm);
    if (finite && distance_sphere_aabb({b.centre, b.radius_mm}, bounds) < influence_mm) out.push_back(b);
  }
  return out;
}

FramePlan make_plan(const Scene& scene, const std::vector<Aabb>& bounds,
                    const BoundingSphere& probe, const PlaneFrame& frame, int depth_map_size) {
  FramePlan plan;
  const size_t n = scene.surfaces.size();
  plan.surface_shadow.assign(n, false);
  plan.surface_textured.assign(n, false);
  plan.surface_distance_mm.assign(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const Material& m = scene.materials[static_cast<size_t>(scene.surfaces[i].material_index)];
    const double dist = distance_sphere_aabb(probe, bounds[i]);
    plan.surface_distance_mm[i] = dist;
    plan.surface_shadow[i] = dist < m.influence_distance_mm ||
                             sunk_below(probe, bounds[i], frame, m.influence_distance_mm);
    plan.surface_textured[i] = plan.surface_shadow[i] && has_texture(m);
    if (!plan.surface_shadow[i]) {
      plan.skipped.push_back(surface_label(scene, i) + ": pseudo-shadow and Gabor (probe beyond influence distance)");
    } else if (!plan.surface_textured[i]) {
      plan.skipped.push_back(surface_label(scene, i) + ": Gabor (material untextured)");
    }
    plan.shadow_active = plan.shadow_active || plan.surface_shadow[i];
  }
  if (!plan.shadow_active) {
    plan.skipped.push_back("probe_depth: probe beyond every surface's influence distance");
    plan.skipped.push_back("reductions: nothing to reduce (reference plane kept)");
  }
  const glm::dvec3 c = to_plane(frame, probe.center);
  plan.window.center_uv = {c.x, c.y};
  // One texel of margin so the silhouette's edge texels are inside the map.
  plan.window.half_size_mm = probe.radius * (1.0 + 2.0 / std::max(depth_map_size, 2)) + 1e-6;
  return plan;
}

}  // namespace ps
