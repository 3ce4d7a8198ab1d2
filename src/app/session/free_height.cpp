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

FreeHeight::March FreeHeight::march(const glm::dvec3& from, const glm::dvec3& dir, double length, double r,
                                    double clearance, const MarchLimits& limits) const {
  double t = 0.0;
  for (int i = 0; i < limits.max_steps; ++i) {
    const double at = std::min(t, length);
    // The query reaches past the sphere, so a sphere bigger than the query radius still sees.
    const world::Contact c = scene_->closest(from + at * dir, r + limits.query_mm);
    const double gap = (c.hit ? c.distance_mm - r : limits.query_mm) - clearance;
    if (c.hit && gap < params_.touch_epsilon_mm) return {March::End::kMet, at, c};
    if (t >= length) return {March::End::kClear, length, {}};
    t += std::max(gap, limits.min_step);
  }
  return {March::End::kLost, t, {}};
}

std::optional<FreeHeight::Lowered> FreeHeight::lower(const glm::dvec3& over, const glm::dvec3& n, double r) const {
  const double top = std::max(top_mm_, 0.0);
  const glm::dvec3 start = over + (r + top) * n;
  // A start inside an object (a camera inside a room's walls): no free side to find from here.
  const world::Contact inside = scene_->closest(start, params_.query_mm);
  if (inside.hit && (inside.distance_mm < r || glm::dot(start - inside.point, inside.normal) < 0.0)) return std::nullopt;
  // Down to below_plane_mm under the plane; nothing met by then: the plane.
  const March m = march(start, -n, top + r + params_.below_plane_mm, r, 0.0, {params_.query_mm, params_.max_steps, 0.0});
  if (m.end != March::End::kMet) return std::nullopt;
  return Lowered{start - m.t * n, m.contact.point, m.contact.normal};
}

double FreeHeight::lift_mm(const glm::dvec3& hit_mm, const glm::dvec3& n_ws, double r) const {
  last_normal_ = n_ws;
  if (!scene_) return 0.0;
  const glm::dvec3 n = rotation_ * n_ws;
  const glm::dvec3 hit = rotation_ * hit_mm + offset_mm_;
  const std::optional<Lowered> down = lower(hit, n, r);
  if (!down) return 0.0;
  last_normal_ = glm::transpose(rotation_) * down->normal;
  const glm::dvec3 p = rest_on_buttons(*scene_, down->centre, n, r);
  return glm::dot(p - hit, n) - r;
}

FloorLowering FreeHeight::rested(const glm::dvec3& over_ws, const Lowered& down, const glm::dvec3& n, double r) const {
  last_normal_ = glm::transpose(rotation_) * down.normal;
  const glm::dvec3 p = rest_on_buttons(*scene_, down.centre, n, r);  // as lift_mm() rests it
  return {over_ws, glm::transpose(rotation_) * (p - offset_mm_)};
}

std::optional<glm::dvec3> FreeHeight::normal_at(const glm::dvec3& p, const glm::dvec3& eye) const {
  // Read from just in front of the point (a query on the surface itself has no side), twice: from
  // in front along the ray, then along that first normal (nearer p's own normal line).
  constexpr double kFrontMm = 0.5;
  glm::dvec3 m = eye;
  for (int i = 0; i < 2; ++i) {
    const world::Contact c = scene_->closest(p + kFrontMm * m, params_.query_mm);
    // The shading normal (a mesh's vertex normals interpolated; the normal itself on analytic
    // shapes): the facets' own normals jump at every edge, and the place beside the point with them.
    if (!c.hit || !(glm::length(c.shaded_normal) > 0.5)) return std::nullopt;
    m = glm::dot(c.shaded_normal, eye) >= 0.0 ? c.shaded_normal : -c.shaded_normal;  // an open mesh seen from behind
  }
  return m;
}

FloorLowering FreeHeight::lowering_point(const glm::dvec3& surface_ws, const glm::dvec3& n_ws, double r,
                                         const glm::dvec3& toward_eye_ws) const {
  // A lowered sphere that touches within this of the pointed point touches it: the straight
  // lowering is not tried against it.
  constexpr double kOnPointMm = 0.05;
  const FloorLowering straight_over{surface_ws, std::nullopt};  // lowered by lift_mm() if at all
  if (!scene_) return straight_over;
  const glm::dvec3 p = rotation_ * surface_ws + offset_mm_;
  const glm::dvec3 n = rotation_ * n_ws;
  for (const world::ButtonShape& b : scene_->button_shapes())
    if (b.over(b.to_local(p))) return over_button(surface_ws, p, b.normal(), n, r);
  const std::optional<glm::dvec3> m = normal_at(p, rotation_ * toward_eye_ws);
  if (!m) return straight_over;
  // A sphere touching p from outside has its centre at p + R m: lowered along -n over the point
  // below that centre, it first touches p (on a surface whose curvature radius exceeds R).
  const glm::dvec3 shift = r * (*m - glm::dot(*m, n) * n);
  if (glm::length(shift) < 1e-6) return straight_over;
  const std::optional<Lowered> shifted = lower(p + shift, n, r);
  if (!shifted) return straight_over;
  const double off = glm::length(shifted->touched - p);
  if (off > kOnPointMm) {
    const std::optional<Lowered> straight = lower(p, n, r);
    if (straight && glm::length(straight->touched - p) <= off) return rested(surface_ws, *straight, n, r);
  }
  return rested(glm::transpose(rotation_) * (p + shift - offset_mm_), *shifted, n, r);
}

FloorLowering FreeHeight::over_button(const glm::dvec3& surface_ws, const glm::dvec3& p, const glm::dvec3& face,
                                      const glm::dvec3& n, double r) const {
  // The face is flat and solid (a hole in the geometry, closed by the button's plate): no
  // hollow to compare with, and lower() would fall into the pocket, so the plate's own normal
  // places the sphere and rest_on_buttons() sets it on the plate, as lift_mm() does.
  const FloorLowering straight_over{surface_ws, std::nullopt};
  const double facing = glm::dot(face, n);
  const glm::dvec3 shift = r * (face - facing * n);
  if (facing < 0.5 || glm::length(shift) < 1e-6) return straight_over;  // a face along n: as before
  const std::optional<Lowered> down = lower(p + shift, n, r);
  if (!down) return straight_over;
  return rested(glm::transpose(rotation_) * (p + shift - offset_mm_), *down, n, r);
}

std::optional<glm::dvec3> FreeHeight::first_hit(const PointerRay& ray) const {
  if (!scene_) return std::nullopt;
  const glm::dvec3 from = rotation_ * ray.near_mm + offset_mm_;
  const glm::dvec3 along = rotation_ * (ray.far_mm - ray.near_mm);
  const double length = glm::length(along);
  if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
  const glm::dvec3 dir = along / length;
  // Past the far plane, or grazing a surface for every step: none (the plane).
  const March m = march(from, dir, length, 0.0, 0.0, {params_.ray_query_mm, params_.ray_max_steps, 0.0});
  if (m.end != March::End::kMet) return std::nullopt;
  const double t = first_button_face(*scene_, from, dir, m.t);
  return glm::transpose(rotation_) * (from + t * dir - offset_mm_);
}

bool FreeHeight::path_clear(const glm::dvec3& from_mm, const glm::dvec3& to_mm, double r, double clearance_mm) const {
  constexpr double kMinStepMm = 0.05;  // a dip shorter than this between two steps is not looked for
  if (!scene_) return true;
  const glm::dvec3 along = rotation_ * (to_mm - from_mm);
  const double length = glm::length(along);
  if (!std::isfinite(length)) return false;
  const glm::dvec3 dir = length > 0.0 ? along / length : glm::dvec3(0.0);
  const glm::dvec3 from = rotation_ * from_mm + offset_mm_;
  return march(from, dir, length, r, clearance_mm, {params_.query_mm, params_.max_steps, kMinStepMm}).end ==
         March::End::kClear;
}

double buried_mm(const world::HapticScene& scene, const glm::dvec3& centre_mm) {
  // The overlap only: which side of a surface is inside is not known for an open mesh (Suzanne's
  // eyes) or a surface embedded in 4D (its sheets cross), so a centre deeper than R inside a
  // closed solid reads as free here (the drawn probe's penetration shows it).
  const double r = scene.probe_radius_mm();
  const world::Contact c = scene.closest(centre_mm, r);
  return c.hit ? std::max(0.0, r - c.distance_mm) : 0.0;
}

bool proxy_stranded(const FreeHeight& floor, const glm::dvec3& hand_mm, const glm::dvec3& proxy_mm, double reach_mm) {
  constexpr double kShortOfProxyMm = 1.0;  // the proxy itself touches a surface: stop before it
  const glm::dvec3 d = proxy_mm - hand_mm;
  const double length = glm::length(d);
  if (!(length > reach_mm) || !(length > kShortOfProxyMm)) return false;  // NaN: not stranded either
  return !floor.path_clear(hand_mm, hand_mm + d * ((length - kShortOfProxyMm) / length), 0.0, 0.0);  // a line
}

}  // namespace ps
