#include "world/buttons.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/mesh.h"

namespace ps::world {

namespace {

constexpr double kNotHeld = std::numeric_limits<double>::infinity();  // held_from_mm_ while not held

}  // namespace

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

ButtonSet::ButtonSet(const std::vector<ButtonShape>& shapes, double probe_radius_mm, double coupling_n_per_mm,
                     bool after_switch)
    : shapes_(shapes.begin(), shapes.begin() + std::min<std::size_t>(shapes.size(), kMaxButtons)),
      radius_mm_(probe_radius_mm), coupling_n_per_mm_(coupling_n_per_mm) {
  if (after_switch) phase_.fill(ButtonPhase::kLeaveFirst);
  held_from_mm_.fill(kNotHeld);
}

ButtonStepResult ButtonSet::step(const glm::dvec3& proxy_mm, const glm::dvec3& hand_mm) {
  ButtonStepResult r;
  for (std::size_t i = 0; i < shapes_.size(); ++i) step_button(i, proxy_mm, hand_mm, r);
  return r;
}

void ButtonSet::step_button(std::size_t i, const glm::dvec3& proxy_mm, const glm::dvec3& hand_mm, ButtonStepResult& r) {
  const ButtonShape& b = shapes_[i];
  ButtonPhase& phase = phase_[i];
  double& held_from = held_from_mm_[i];
  const glm::dvec3 q = b.to_local(proxy_mm), hq = b.to_local(hand_mm);
  // After a switch the proxy starts where the old scene left it: only the hand leaving counts.
  if (phase == ButtonPhase::kLeaveFirst && !b.over(hq)) phase = ButtonPhase::kIdle;
  if (!b.over(q)) {  // left sideways: ready for the next approach
    if (phase != ButtonPhase::kLeaveFirst) phase = ButtonPhase::kIdle;
    held_from = kNotHeld;
    return;
  }
  const double depth = radius_mm_ - q.z, hand_depth = radius_mm_ - hq.z;
  const bool waiting = phase == ButtonPhase::kIdle || phase == ButtonPhase::kLeaveFirst;
  // Clear of the face: approached. The hand too, over the button and clear, as it is when the
  // probe comes at the button freely: a proxy put above the face by a scene switch while the
  // hand is elsewhere or deep would otherwise count as an approach and fall into a press.
  if (phase != ButtonPhase::kLeaveFirst && depth <= -kButtonClearMm && b.over(hq) && hand_depth <= -kButtonClearMm)
    phase = ButtonPhase::kReady;
  if (depth <= 0.0 || phase == ButtonPhase::kFired) {
    if (depth <= 0.0 && !waiting) phase = ButtonPhase::kReady;  // out again: re-armed
    held_from = kNotHeld;
    return;
  }
  if ((phase == ButtonPhase::kIdle || phase == ButtonPhase::kLeaveFirst) && hold(i, hand_depth, hand_mm, r)) return;
  phase = ButtonPhase::kPressing;
  r.pressed = static_cast<int>(i);
  r.depth_mm = depth;
  if (depth >= b.travel_mm) {  // gives way: the force stops, the action fires
    phase = ButtonPhase::kFired;
    r.fired[static_cast<std::size_t>(r.fired_count++)] = static_cast<int>(i);
    return;
  }
  r.force_n += b.stiffness_n_per_mm * depth * b.normal();
}

bool ButtonSet::hold(std::size_t i, double hand_depth, const glm::dvec3& hand_mm, ButtonStepResult& r) {
  const ButtonShape& b = shapes_[i];
  double& from = held_from_mm_[i];
  from = std::min(from, hand_depth);
  // After a switch the hand never pushes on: PageDowns sent on from the old world (a person still
  // pressing for the button that switched) would press whatever the new one has under the pointer.
  if (phase_[i] == ButtonPhase::kIdle && hand_depth >= from + kHeldPushMm) {  // pushed on: a press from here
    from = kNotHeld;
    return false;
  }
  r.force_n += (1.0 - kHeldShare) * coupling_n_per_mm_ * std::max(0.0, b.press_depth_mm(hand_mm, radius_mm_)) * b.normal();
  return true;
}

double deepest_press_mm(const std::vector<ButtonShape>& shapes, double coupling_n_per_mm) {
  double deepest = 0.0;
  for (const ButtonShape& b : shapes)
    deepest = std::max(deepest, b.travel_mm * (coupling_n_per_mm + b.stiffness_n_per_mm) / coupling_n_per_mm);
  return deepest;
}

}  // namespace ps::world
