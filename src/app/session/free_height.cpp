#include "app/session/free_height.h"

#include <algorithm>
#include <cmath>

namespace ps {

namespace {

// A lowered probe centred at p that sits in a button's pocket is lifted to rest on the face:
// hovering over a button must not press it (pressing is the height keys' job).
glm::dvec3 rest_on_buttons(const world::HapticScene& scene, glm::dvec3 p, const glm::dvec3& n, double r) {
  for (const world::ButtonShape& b : scene.button_shapes()) {
    const double facing = glm::dot(b.normal(), n);
    if (facing < 0.5) continue;  // a button in a wall is not under a pointer looking down n
    const double depth = b.press_depth_mm(p, r);
    if (depth > 0.0) p += n * (depth / facing);
  }
  return p;
}

// The ray's first meeting with a button's face (its rectangle) before `t_max`: the face is solid
// for pointing as for hovering, or a ray would go on into the pocket behind it and put the probe
// over the pocket's far wall (7.8 mm past Weight's button, seen from its camera).
double first_button_face(const world::HapticScene& scene, const glm::dvec3& from, const glm::dvec3& dir, double t_max) {
  double best = t_max;
  for (const world::ButtonShape& b : scene.button_shapes()) {
    const double facing = -glm::dot(dir, b.normal());
    if (facing <= 1e-9) continue;  // seen from behind or edge-on
    const double t = glm::dot(from - b.center, b.normal()) / facing;
    if (t >= 0.0 && t < best && b.over(b.to_local(from + t * dir))) best = t;
  }
  return best;
}

}  // namespace

double FreeHeight::lift_mm(const glm::dvec3& hit_mm, const glm::dvec3& n_ws, double r) const {
  last_normal_ = n_ws;
  if (!scene_) return 0.0;
  const glm::dvec3 n = rotation_ * n_ws;
  const glm::dvec3 hit = rotation_ * hit_mm + offset_mm_;
  const double top = std::max(top_mm_, 0.0);
  glm::dvec3 p = hit + (r + top) * n;
  // A start inside an object (a camera inside a room's walls): no free side to find from here.
  const world::Contact start = scene_->closest(p, params_.query_mm);
  if (start.hit && (start.distance_mm < r || glm::dot(p - start.point, start.normal) < 0.0)) return 0.0;
  double fallen = 0.0;
  const double longest = top + params_.below_plane_mm;
  for (int i = 0; i < params_.max_steps; ++i) {
    const world::Contact c = scene_->closest(p, params_.query_mm);
    const double gap = (c.hit ? c.distance_mm : params_.query_mm) - r;
    if (gap < params_.touch_epsilon_mm) {
      if (c.hit) last_normal_ = glm::transpose(rotation_) * c.normal;
      p = rest_on_buttons(*scene_, p, n, r);
      return glm::dot(p - hit, n) - r;
    }
    fallen += gap;
    if (fallen > longest) return 0.0;  // nothing under the pointer: the plane
    p -= gap * n;
  }
  return 0.0;
}

std::optional<glm::dvec3> FreeHeight::first_hit(const PointerRay& ray) const {
  if (!scene_) return std::nullopt;
  const glm::dvec3 from = rotation_ * ray.near_mm + offset_mm_;
  const glm::dvec3 along = rotation_ * (ray.far_mm - ray.near_mm);
  const double length = glm::length(along);
  if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
  const glm::dvec3 dir = along / length;
  const auto in_workspace = [&](double t) { return glm::transpose(rotation_) * (from + t * dir - offset_mm_); };
  double t = 0.0;
  for (int i = 0; i < params_.ray_max_steps && t <= length; ++i) {
    const world::Contact c = scene_->closest(from + t * dir, params_.ray_query_mm);
    if (c.hit && c.distance_mm < params_.touch_epsilon_mm) return in_workspace(first_button_face(*scene_, from, dir, t));
    t += c.hit ? c.distance_mm : params_.ray_query_mm;
  }
  return std::nullopt;  // past the far plane, or grazing a surface for every step: the plane
}

double buried_mm(const world::HapticScene& scene, const glm::dvec3& centre_mm) {
  // The overlap only: which side of a surface is inside is not known for an open mesh (Suzanne's
  // eyes) or a surface embedded in 4D (its sheets cross), so a centre deeper than R inside a
  // closed solid reads as free here (the drawn probe's penetration shows it).
  const double r = scene.probe_radius_mm();
  const world::Contact c = scene.closest(centre_mm, r);
  return c.hit ? std::max(0.0, r - c.distance_mm) : 0.0;
}

}  // namespace ps
