#include "fourd/rolling.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace ps::fourd {

glm::dmat3 rotate_between(const glm::dvec3& t, const glm::dvec3& t_prime) {
  const double lt = glm::length(t), lp = glm::length(t_prime);
  if (!(lt > 0.0) || !(lp > 0.0)) return glm::dmat3(1.0);
  const glm::dvec3 a = t / lt, b = t_prime / lp;
  const glm::dvec3 cross = glm::cross(a, b);
  const double s = glm::length(cross), c = glm::dot(a, b);
  glm::dvec3 axis;
  if (s < 1e-12) {
    if (c > 0.0) return glm::dmat3(1.0);
    // Opposite: half a turn about any axis perpendicular to a.
    const glm::dvec3 other = std::abs(a.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
    axis = glm::normalize(glm::cross(a, other));
  } else {
    axis = cross / s;
  }
  const double theta = std::atan2(s, c);
  // Rodrigues: R = cos(theta) I + sin(theta) [N]x + (1 - cos(theta)) N N^T (column-major glm).
  const double ct = std::cos(theta), st = std::sin(theta), vt = 1.0 - ct;
  glm::dmat3 r;
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) r[col][row] = vt * axis[row] * axis[col] + (row == col ? ct : 0.0);
  r[1][0] -= st * axis.z;
  r[0][1] += st * axis.z;
  r[2][0] += st * axis.y;
  r[0][2] -= st * axis.y;
  r[2][1] -= st * axis.x;
  r[1][2] += st * axis.x;
  return r;
}

glm::dmat3 slerp_rotation(const glm::dmat3& a, const glm::dmat3& b, double s) {
  if (s >= 1.0) return b;
  if (s <= 0.0) return a;
  const glm::dquat qa = glm::quat_cast(a);
  glm::dquat qb = glm::quat_cast(b);
  if (glm::dot(qa, qb) < 0.0) qb = -qb;  // the shorter of the two arcs
  return glm::mat3_cast(glm::normalize(glm::slerp(qa, qb, s)));
}

double rotation_angle_between(const glm::dmat3& a, const glm::dmat3& b) {
  const glm::dmat3 d = glm::transpose(a) * b;
  const double c = 0.5 * (d[0][0] + d[1][1] + d[2][2] - 1.0);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

bool RollingManifold::retarget(const ViewAxes& axes, const RollContact& c, const glm::dvec3& n,
                               const ViewPose& pose) {
  if (facet_ < 0) {
    // The first facet of a touch: it turns to face the viewer (Hanson & Zhang §6.1).
    target_ = rotate_between(pose.rotation * axes.toward_viewer_ws, n) * pose.rotation;
    return true;
  }
  if (c.facet == facet_ || !(glm::length(c.point - changed_at_) >= kMinTravelMm)) return false;
  // Hanson & Zhang §6.2: T the proxy's incremental motion on the facet it leaves (this tick's step
  // crosses the edge, so it is taken in that facet's plane), T' its projection on the new
  // facet; the view turns as the path turns (the surface, seen from the person, the other way).
  const glm::dvec3 step = c.point - last_point_;
  const glm::dvec3 t = step - glm::dot(step, last_normal_) * last_normal_;
  const glm::dvec3 t_prime = t - glm::dot(t, n) * n;
  glm::dmat3 r = target_;
  if (glm::length(t_prime) > 1e-12 * (1.0 + glm::length(t))) r = rotate_between(t, t_prime) * r;
  // What their rule leaves (T oblique to the shared edge): the shortest turn that puts
  // the new facet's normal exactly toward the viewer.
  target_ = rotate_between(r * axes.toward_viewer_ws, n) * r;
  return true;
}

bool RollingManifold::step(const RollParams& p, const ViewAxes& axes, const RollContact& c, double dt,
                           ViewPose& pose) {
  if (!p.on || !c.on_sheet || c.facet < 0) {
    facet_ = -1;
    return false;
  }
  if (c.hand_at_rest && facet_ < 0) return false;  // a touch that starts at rest waits for motion
  const glm::dvec3 n = glm::normalize(c.normal);
  const bool changed = !c.hand_at_rest && retarget(axes, c, n, pose);
  if (changed) {
    ++turns_;
    changed_at_ = c.point;
  }
  if (changed) facet_ = c.facet;
  last_point_ = c.point;
  last_normal_ = n;
  // Turn toward the target about the contact point: the contact keeps its place in the
  // workspace (on screen and under the hand).
  const glm::dvec3 contact_ws = pose.to_workspace(c.point);
  const double s = p.turn_s > 0.0 ? 1.0 - std::exp(-dt / p.turn_s) : 1.0;
  pose.rotation = slerp_rotation(pose.rotation, target_, s);
  pose.offset = c.point - pose.rotation * contact_ws;
  // Glide: the screen centre approaches the contact point.
  if (p.centre_s > 0.0 && !c.hand_at_rest) {
    const glm::dvec3 centre = pose.to_world(axes.centre_ws);
    pose.offset += (c.point - centre) * (1.0 - std::exp(-dt / p.centre_s));
  }
  return changed;
}

glm::dvec3 RollingManifold::tether_force(const RollParams& p, const ViewAxes& axes, const ViewPose& pose,
                                         const glm::dvec3& proxy_world) {
  if (!p.on || !(p.tether_alpha_n_per_mm4 > 0.0)) return glm::dvec3(0.0);
  const glm::dvec3 centre = pose.to_world(axes.centre_ws);
  const glm::dvec3 axis = glm::normalize(pose.rotation * axes.toward_viewer_ws);
  const glm::dvec3 d = proxy_world - centre;
  const glm::dvec3 perp = d - glm::dot(d, axis) * axis;
  const double r = glm::length(perp);
  if (!(r > 0.0)) return glm::dvec3(0.0);
  const double r2 = r * r;
  const double magnitude = std::min(p.tether_alpha_n_per_mm4 * r2 * r2, p.tether_max_n);
  return -magnitude / r * perp;
}

}  // namespace ps::fourd
