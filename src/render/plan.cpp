#include "render/plan.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "scene/camera.h"

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

// The range of heights along f.n of the shadowed surfaces' boxes (their corners bound it).
void shadowed_height_range(std::span<const Aabb> bounds, const std::vector<SurfacePlan>& surfaces,
                           const PlaneFrame& f, double& lo, double& hi) {
  lo = 1e300;
  hi = -1e300;
  for (size_t i = 0; i < bounds.size(); ++i) {
    if (!surfaces[i].shadow) continue;
    for (int k = 0; k < 8; ++k) {
      const glm::dvec3 corner((k & 1) ? bounds[i].max.x : bounds[i].min.x, (k & 2) ? bounds[i].max.y : bounds[i].min.y,
                              (k & 4) ? bounds[i].max.z : bounds[i].min.z);
      const double h = glm::dot(corner, f.n);
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
  }
}

}  // namespace

bool has_texture(const Material& m) {
  return m.textured && (m.gabor.a_min != 0.0 || m.gabor.a_max != 0.0) &&
         m.gabor.max_impulses_per_cell > 0 && std::max(m.gabor.n_min, m.gabor.n_max) > 0.0;
}

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

PixelRect footprint_screen_rect(const Camera& camera, int width, int height, const PlaneFrame& f,
                                const DepthWindow& window, int depth_map_size, double height_lo,
                                double height_hi) {
  const PixelRect image = PixelRect::whole(width, height);
  if (!(height_lo <= height_hi) || !std::isfinite(height_lo) || !std::isfinite(height_hi)) return image;
  // The shader reads texels within half a texel outside the window; one texel of margin covers
  // that. Heights get 1e-3 mm + 1e-6 relative for the float vertex positions.
  const double half = window.half_size_mm * (1.0 + 2.0 / std::max(depth_map_size, 2));
  const double pad = 1e-3 + 1e-6 * std::max(std::abs(height_lo), std::abs(height_hi));
  const glm::dmat4 vp = view_projection(camera, static_cast<double>(width) / height);
  double x_lo = 1e300, x_hi = -1e300, y_lo = 1e300, y_hi = -1e300;
  for (int k = 0; k < 8; ++k) {
    const double u = window.center_uv.x + ((k & 1) ? half : -half);
    const double v = window.center_uv.y + ((k & 2) ? half : -half);
    const double h = (k & 4) ? height_hi + pad : height_lo - pad;
    const glm::dvec4 clip = vp * glm::dvec4(u * f.t + v * f.b + h * f.n, 1.0);
    // w is linear: all corners in front means the whole box is, and its projection is the hull
    // of the corners' projections. 1e-6: w of a corner on the eye plane.
    if (!(clip.w > 1e-6)) return image;
    const double x = (clip.x / clip.w * 0.5 + 0.5) * width, y = (clip.y / clip.w * 0.5 + 0.5) * height;
    if (!std::isfinite(x) || !std::isfinite(y)) return image;  // a NaN or huge probe: no bound
    x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x), y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
  }
  // Pixel (i, j) is drawn when its centre (i + 0.5, j + 0.5) is inside a triangle; two pixels of
  // margin. Clamped first: a corner near the eye plane projects to huge coordinates.
  const auto lo_px = [](double c, int n) { return static_cast<int>(std::floor(std::clamp(c, -4.0, n + 4.0))) - 2; };
  const auto hi_px = [](double c, int n) { return static_cast<int>(std::ceil(std::clamp(c, -4.0, n + 4.0))) + 2; };
  return PixelRect{lo_px(x_lo, width), lo_px(y_lo, height), hi_px(x_hi, width), hi_px(y_hi, height)}.clipped_to(image);
}

FramePlan make_plan(const Scene& scene, std::span<const Aabb> bounds,
                    const BoundingSphere& probe, const PlaneFrame& frame, int depth_map_size) {
  return make_plan(scene, scene.camera, bounds, probe, frame, depth_map_size);
}

FramePlan make_plan(const Scene& scene, const Camera& camera, std::span<const Aabb> bounds,
                    const BoundingSphere& probe, const PlaneFrame& frame, int depth_map_size) {
  FramePlan plan;
  const size_t n = scene.surfaces.size();
  plan.surfaces.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const Material& m = scene.materials[static_cast<size_t>(scene.surfaces[i].material_index)];
    SurfacePlan& sp = plan.surfaces[i];
    sp.distance_mm = distance_sphere_aabb(probe, bounds[i]);
    sp.shadow = sp.distance_mm < m.influence_distance_mm || sunk_below(probe, bounds[i], frame, m.influence_distance_mm);
    sp.textured = sp.shadow && has_texture(m);
    if (!sp.shadow) {
      plan.skipped.push_back(surface_label(scene, i) + ": pseudo-shadow and Gabor (probe beyond influence distance)");
    } else if (!sp.textured) {
      plan.skipped.push_back(surface_label(scene, i) + ": Gabor (material untextured)");
    }
    plan.shadow_active = plan.shadow_active || sp.shadow;
  }
  if (!plan.shadow_active) {
    plan.skipped.push_back("probe_depth: probe beyond every surface's influence distance");
    plan.skipped.push_back("reductions: nothing to reduce (reference plane kept)");
  }
  const glm::dvec3 c = to_plane(frame, probe.center);
  plan.window.center_uv = {c.x, c.y};
  // One texel of margin so the silhouette's edge texels are inside the map.
  plan.window.half_size_mm = probe.radius * (1.0 + 2.0 / std::max(depth_map_size, 2)) + 1e-6;
  if (plan.shadow_active) {
    double lo = 0.0, hi = 0.0;
    shadowed_height_range(bounds, plan.surfaces, frame, lo, hi);
    plan.shadow_rect = footprint_screen_rect(camera, scene.render.width, scene.render.height, frame,
                                             plan.window, depth_map_size, lo, hi);
  }
  return plan;
}

}  // namespace ps
