#include "devices/pointer_map.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/camera.h"

namespace ps {

namespace {

glm::dvec3 unproject(const glm::dmat4& inv_vp, const glm::dvec2& ndc, double z) {
  const glm::dvec4 p = inv_vp * glm::dvec4(ndc, z, 1.0);
  return glm::dvec3(p) / p.w;
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The screen's right and up directions laid onto the plane (the relative mapping's axes).
void screen_axes_on_plane(const PointerView& view, glm::dvec3& right, glm::dvec3& up) {
  const Camera& c = view.camera;
  const glm::dmat4 v = glm::lookAt(c.position, c.target, c.up);
  const glm::dvec3 screen_right(v[0][0], v[1][0], v[2][0]);  // first row: the camera's x axis
  const glm::dvec3& n = view.plane.n;
  right = screen_right - glm::dot(screen_right, n) * n;
  const double len = glm::length(right);
  // The screen's right runs along the normal only when the plane is seen edge-on.
  right = len > 1e-9 ? right / len : view.plane.t;
  up = glm::cross(n, right);
}

}  // namespace

PointerRay pointer_ray(const PointerView& view, const glm::dvec2& pointer) {
  const glm::dmat4 inv_vp = glm::inverse(view_projection(view.camera, view.aspect));
  // Window y grows downwards, NDC y upwards.
  const glm::dvec2 ndc(2.0 * pointer.x / view.window_size.x - 1.0, 1.0 - 2.0 * pointer.y / view.window_size.y);
  return {unproject(inv_vp, ndc, -1.0), unproject(inv_vp, ndc, 1.0)};
}

std::optional<glm::dvec3> intersect_plane(const PointerRay& ray, const PlaneAxes& plane) {
  const glm::dvec3 d = ray.far_mm - ray.near_mm;
  const double denom = glm::dot(d, plane.n);
  const double num = glm::dot(plane.origin - ray.near_mm, plane.n);
  // Parallel within 1e-12 of the segment's length (a grazing ray's hit is not a usable place).
  if (!(std::abs(denom) > 1e-12 * glm::length(d))) return std::nullopt;
  const double t = num / denom;
  if (!(t >= 0.0 && t <= 1.0)) return std::nullopt;  // behind the eye or past the far plane
  const glm::dvec3 hit = ray.near_mm + t * d;
  if (!finite(hit)) return std::nullopt;
  return hit;
}

glm::dvec2 project_to_window(const PointerView& view, const glm::dvec3& p_mm) {
  const glm::dvec4 clip = view_projection(view.camera, view.aspect) * glm::dvec4(p_mm, 1.0);
  const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
  return {(ndc.x + 1.0) * 0.5 * view.window_size.x, (1.0 - ndc.y) * 0.5 * view.window_size.y};
}

PointerHits pointer_hits(const PointerView& view, const glm::dvec2& pointer, double hover_mm) {
  // A surface point within this of the plane is on it: the plane's closed-form hit is used, so a
  // pointer over a flat scene maps exactly as without a floor (the surface search stops within
  // 0.01 mm of a surface, FreeHeightParams::touch_epsilon_mm).
  constexpr double kOnPlaneMm = 0.02;
  const PointerRay ray = pointer_ray(view, pointer);
  const std::optional<glm::dvec3> on_plane = intersect_plane(ray, view.plane);
  const std::optional<glm::dvec3> surface = view.floor ? view.floor->first_hit(ray) : std::nullopt;
  if (!surface || !finite(*surface)) return {on_plane, on_plane, std::nullopt};
  const double above = glm::dot(*surface - view.plane.origin, view.plane.n);
  if (on_plane && std::abs(above) <= kOnPlaneMm) return {on_plane, on_plane, std::nullopt};
  const glm::dvec3 toward_eye = glm::normalize(ray.near_mm - ray.far_mm);
  const FloorLowering lowered = view.floor->lowering_point(*surface, view.plane.n, view.probe_radius_mm + std::max(hover_mm, 0.0), toward_eye);
  const bool moved = finite(lowered.point);
  const glm::dvec3 over = moved ? lowered.point : *surface;
  const std::optional<glm::dvec3> rest = moved && lowered.centre && finite(*lowered.centre) ? lowered.centre : std::nullopt;
  return {over - glm::dot(over - view.plane.origin, view.plane.n) * view.plane.n, on_plane, rest};
}

void HeightControl::set(double mm) {
  if (std::isnan(mm)) return;
  mm_ = std::clamp(mm, params_.min_mm, params_.max_mm);
}

void HeightControl::reach_depth(double depth_mm) {
  if (!std::isfinite(depth_mm)) return;
  params_.min_mm = std::min(base_min_mm_, -depth_mm);
  set(mm_);
}

glm::dvec3 PointerMap::centre(const PointerView& view, double height_mm, const std::optional<glm::dvec3>& rest) const {
  const glm::dvec3 at = hit(view);
  // Hovering, the probe keeps h from every surface: lowered as a sphere of R + h, it rests h
  // above what it would touch (on a slope along the slope's normal, as lowering_point places it).
  // Pressing in (h < 0) goes on along n from the touching place.
  // `rest`: this reading's sphere of R + h, lowered over `at` already (PointerHits::rest_centre).
  const double hover = std::max(height_mm, 0.0);
  const double r = view.probe_radius_mm + hover;
  double lift = 0.0;
  if (rest)
    lift = glm::dot(*rest - at, view.plane.n) - r;
  else if (view.floor)
    lift = view.floor->lift_mm(at, view.plane.n, r);
  return at + (view.probe_radius_mm + (std::isfinite(lift) ? lift : 0.0) + height_mm) * view.plane.n;
}

void PointerMap::set_hit(const glm::dvec3& hit_mm) {
  if (!finite(hit_mm)) return;
  hit_ = hit_mm;
  have_hit_ = true;
}

glm::dvec3 PointerMap::absolute(const PointerView& view, const glm::dvec2& pointer, double height_mm) {
  std::optional<glm::dvec3> rest;  // lowered already by this reading, over the new hit
  if (std::isfinite(pointer.x) && std::isfinite(pointer.y) && view.window_size.x > 0.0 && view.window_size.y > 0.0)
    if (const PointerHits h = pointer_hits(view, pointer, height_mm); h.hit) {
      rest = h.rest_centre;
      const glm::dvec3 parallax = h.on_plane ? *h.hit - *h.on_plane : glm::dvec3(0.0);
      parallax_jump_mm_ = have_hit_ ? glm::length(parallax - parallax_) : 0.0;
      parallax_ = parallax;
      hit_ = *h.hit;
      have_hit_ = true;
    }
  return centre(view, height_mm, rest);
}

glm::dvec3 PointerMap::relative(const PointerView& view, const glm::dvec2& counts, double mm_per_count,
                                double height_mm) {
  glm::dvec3 right, up;
  screen_axes_on_plane(view, right, up);
  const glm::dvec3 moved = hit(view) + mm_per_count * (counts.x * right - counts.y * up);  // y down on screen
  if (finite(moved)) {
    hit_ = moved;
    have_hit_ = true;
  }
  return centre(view, height_mm);
}

}  // namespace ps
