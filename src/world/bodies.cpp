#include "world/bodies.h"

#include <algorithm>
#include <cmath>

namespace ps::world {

BodySet::BodySet(const std::vector<Body>& bodies, const glm::dvec3& gravity_mm_s2)
    : specs_(bodies.begin(), bodies.begin() + std::min<std::size_t>(bodies.size(), kMaxBodies)),
      gravity_(gravity_mm_s2) {
  for (const Body& b : specs_) state_.push_back({b.position, glm::dvec3(0.0)});
}

glm::dvec3 BodySet::spring_force_n(std::size_t i, const glm::dvec3& anchor_mm, const glm::dvec3& x_mm,
                                   const glm::dvec3& v_mm_s) const {
  const Body& b = specs_[i];
  const glm::dvec3 d = x_mm - anchor_mm;
  const double len = glm::length(d);
  if (len < 1e-12) return glm::dvec3(0.0);
  const glm::dvec3 u = d / len;
  return -(b.spring_n_per_mm * (len - b.rest_length_mm) + b.damping_n_s_per_mm * glm::dot(v_mm_s, u)) * u;
}

namespace {

// A band stretched to its limit is a string: the body goes back onto the sphere of that radius
// around the anchor and keeps only the part of its velocity that does not stretch it further.
template <typename State>
void hold_within(State& s, const glm::dvec3& anchor, double max_length_mm) {
  const glm::dvec3 d = s.x - anchor;
  const double len = glm::length(d);
  if (len <= max_length_mm) return;
  const glm::dvec3 u = d / len;
  s.x = anchor + max_length_mm * u;
  const double out = glm::dot(s.v, u);
  if (out > 0.0) s.v -= out * u;
}

}  // namespace

// a (mm/s^2) = F (N) / m (kg) in m/s^2, x 1000 mm/m; m (kg) = mass_g / 1000: F x 1e6 / mass_g.
glm::dvec3 BodySet::acceleration(std::size_t i, const glm::dvec3& anchor, const glm::dvec3& x,
                                 const glm::dvec3& v) const {
  return spring_force_n(i, anchor, x, v) * (1e6 / specs_[i].mass_g) + gravity_ - specs_[i].air_damping_per_s * v;
}

BodyStepResult BodySet::step(const glm::dvec3& proxy_mm, double dt_s) {
  BodyStepResult out;
  for (std::size_t i = 0; i < state_.size(); ++i) {
    const Body& b = specs_[i];
    State& s = state_[i];
    const double h = dt_s * b.time_scale / b.substeps;
    for (int k = 0; k < b.substeps; ++k) {
      // Velocity Verlet (kick-drift-kick); the damping term sees the half-step velocity.
      const glm::dvec3 v_half = s.v + 0.5 * h * acceleration(i, proxy_mm, s.x, s.v);
      s.x += h * v_half;
      s.v = v_half + 0.5 * h * acceleration(i, proxy_mm, s.x, v_half);
      if (b.max_length_mm > 0.0) hold_within(s, proxy_mm, b.max_length_mm);
      const double floor_z = b.floor_z_mm + b.radius_mm;
      if (b.floor && s.x.z < floor_z) {
        s.x.z = floor_z;
        if (s.v.z < -kRestingSpeedMmS) {  // an impact: bounce, and say so
          if (out.impact_count < kMaxBodies) out.impacts[out.impact_count++] = {static_cast<int>(i), -s.v.z, s.x};
          s.v.z = -b.restitution * s.v.z;
        } else if (s.v.z < 0.0) {  // resting on the floor: the contact absorbs the step's fall
          s.v.z = 0.0;
        }
      }
    }
    out.force_on_proxy_n -= spring_force_n(i, proxy_mm, s.x, s.v);  // reaction on the anchor
  }
  return out;
}

}  // namespace ps::world
