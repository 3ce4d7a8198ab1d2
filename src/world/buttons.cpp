#include "world/buttons.h"

#include <algorithm>
#include <cmath>

#include "scene/mesh.h"

namespace ps::world {

ButtonShape ButtonShape::make(const Button& b, int plate_surface) {
  ButtonShape s;
  s.rotation = euler_xyz_deg(b.rotation_deg);
  s.center = b.center;
  s.half = 0.5 * b.size_mm;
  s.pocket_mm = kPocketDepthPerTravel * b.travel_mm;
  s.stiffness_n_per_mm = b.stiffness_n_per_mm;
  s.travel_mm = b.travel_mm;
  s.surface = plate_surface;
  return s;
}

bool ButtonShape::in_hole(const glm::dvec3& q) const {
  constexpr double kEps = 1e-6;
  return std::abs(q.z) <= kEps && std::abs(q.x) <= half.x + kEps && std::abs(q.y) <= half.y + kEps;
}

SurfacePoint ButtonShape::pocket_closest(const glm::dvec3& q) const {
  // The walls run from the face (z = 0) down to the bottom (z = -pocket): their nearest point
  // has z clamped to that range (above the face that is the hole's rim).
  const double z = std::clamp(q.z, -pocket_mm, 0.0);
  SurfacePoint best;
  best.point = {q.x, q.y, -pocket_mm};
  best.normal = {0.0, 0.0, 1.0};
  double best_d = std::abs(q.z + pocket_mm);
  auto wall = [&](const glm::dvec3& point, const glm::dvec3& inward) {
    const double d = glm::length(q - point);
    if (d < best_d) {
      best_d = d;
      best.point = point;
      best.normal = inward;
    }
  };
  wall({half.x, q.y, z}, {-1.0, 0.0, 0.0});
  wall({-half.x, q.y, z}, {1.0, 0.0, 0.0});
  wall({q.x, half.y, z}, {0.0, -1.0, 0.0});
  wall({q.x, -half.y, z}, {0.0, 1.0, 0.0});
  return best;
}

double ButtonShape::press_depth_mm(const glm::dvec3& p, double r) const {
  const glm::dvec3 q = to_local(p);
  return over(q) ? r - q.z : 0.0;
}

ButtonSet::ButtonSet(const std::vector<ButtonShape>& shapes, double probe_radius_mm)
    : shapes_(shapes.begin(), shapes.begin() + std::min<std::size_t>(shapes.size(), kMaxButtons)),
      radius_mm_(probe_radius_mm) {
  armed_.fill(true);
}

ButtonStepResult ButtonSet::step(const glm::dvec3& proxy_mm) {
  ButtonStepResult r;
  for (std::size_t i = 0; i < shapes_.size(); ++i) {
    const ButtonShape& b = shapes_[i];
    const double depth = b.press_depth_mm(proxy_mm, radius_mm_);
    if (!armed_[i]) {
      if (depth <= 0.0) armed_[i] = true;  // the probe left it: the next push fires again
      continue;
    }
    if (depth <= 0.0) continue;
    r.pressed = static_cast<int>(i);
    r.depth_mm = depth;
    if (depth >= b.travel_mm) {  // gives way: the force stops, the action fires
      armed_[i] = false;
      r.fired[static_cast<std::size_t>(r.fired_count++)] = static_cast<int>(i);
      continue;
    }
    r.force_n += b.stiffness_n_per_mm * depth * b.normal();
  }
  return r;
}

}  // namespace ps::world
