#include "haptics/material_forces.h"

#include <algorithm>
#include <cmath>

namespace ps {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

glm::dvec3 tangential(const glm::dvec3& v, const glm::dvec3& n) { return v - glm::dot(n, v) * n; }

bool touching_solid(const HapticMaterial& m, const MaterialContact& c) {
  return !m.penetrable && c.penetrating();
}

}  // namespace

void FrictionHistory::push(const glm::dvec3& point_mm) {
  if (has_point_) {
    steps_[static_cast<std::size_t>(next_)] = point_mm - last_point_;
    next_ = (next_ + 1) % kMaxFrictionHistoryTicks;
    count_ = std::min(count_ + 1, kMaxFrictionHistoryTicks);
  }
  last_point_ = point_mm;
  has_point_ = true;
}

glm::dvec3 FrictionHistory::direction(int ticks, const glm::dvec3& normal) const {
  const int n = std::clamp(ticks, 0, count_);
  glm::dvec3 sum(0.0);
  for (int i = 1; i <= n; ++i) {
    sum += steps_[static_cast<std::size_t>((next_ - i + kMaxFrictionHistoryTicks) %
                                           kMaxFrictionHistoryTicks)];
  }
  const glm::dvec3 t = tangential(sum, normal);
  const double len = glm::length(t);
  // 1e-9 mm over a few ticks is below any device's resolution: no motion, no direction.
  return len > 1e-9 ? t / len : glm::dvec3(0.0);
}

double spring_force_magnitude_n(const HapticMaterial& m, double depth_mm) {
  if (m.penetrable || !(depth_mm > 0.0)) return 0.0;
  return m.stiffness_n_per_mm * std::pow(depth_mm, 1.0 + m.stiffness_exponent);
}

glm::dvec3 damping_force_n(const HapticMaterial& m, const MaterialContact& c) {
  if (!touching_solid(m, c)) return glm::dvec3(0.0);
  return -m.damping_n_s_per_mm * glm::dot(c.normal, c.velocity_mm_s) * c.normal;
}

glm::dvec3 viscosity_force_n(const HapticMaterial& m, const MaterialContact& c) {
  if (!m.penetrable || !c.penetrating()) return glm::dvec3(0.0);
  return -m.viscosity_n_s_per_mm * c.velocity_mm_s;
}

double friction_coefficient(const HapticMaterial& m, double tangential_speed_mm_s) {
  const double s = std::abs(tangential_speed_mm_s);
  if (s < m.stick_speed_mm_s) return m.static_friction * s / m.stick_speed_mm_s;
  return m.dynamic_friction;
}

glm::dvec3 friction_force_n(const HapticMaterial& m, const MaterialContact& c,
                            double normal_force_n, const FrictionHistory& history) {
  if (!touching_solid(m, c) || !(normal_force_n > 0.0)) return glm::dvec3(0.0);
  const glm::dvec3 vt = tangential(c.velocity_mm_s, c.normal);
  const double speed = glm::length(vt);
  glm::dvec3 dir = history.direction(m.friction_history_ticks, c.normal);
  if (dir == glm::dvec3(0.0) && speed > 0.0) dir = vt / speed;
  return -friction_coefficient(m, speed) * normal_force_n * dir;
}

double magnetic_force_magnitude_n(const HapticMaterial& m, double distance_mm) {
  if (!(m.magnetic_range_mm > 0.0) || !(distance_mm > 0.0) || distance_mm >= m.magnetic_range_mm)
    return 0.0;
  const double s = distance_mm / m.magnetic_range_mm;
  return m.magnetic_force_n * 16.0 * s * s * (1.0 - s) * (1.0 - s);
}

glm::dvec3 magnetic_force_n(const HapticMaterial& m, const MaterialContact& c) {
  return -magnetic_force_magnitude_n(m, c.distance_mm) * c.normal;
}

glm::dvec3 stickiness_force_n(const HapticMaterial& m, const MaterialContact& c) {
  const double outward = glm::dot(c.normal, c.velocity_mm_s);
  if (!touching_solid(m, c) || !(outward > 0.0)) return glm::dvec3(0.0);
  return -m.stickiness_n * std::min(1.0, outward / m.stick_speed_mm_s) * c.normal;
}

double texture_value_n(const HapticMaterial& m, const glm::dvec2& surface_mm) {
  double sum = 0.0;
  const std::size_t waves = std::min(m.texture.size(), static_cast<std::size_t>(kMaxHapticWaves));
  for (std::size_t i = 0; i < waves; ++i) {
    const HapticWave& w = m.texture[i];
    const double phase = std::sin(kTwoPi * glm::dot(w.direction, surface_mm) / w.period_mm);
    const double shape = w.shape == HapticWave::Shape::kSine ? phase : (phase >= 0.0 ? 1.0 : -1.0);
    sum += w.amplitude_n * shape;
  }
  return sum;
}

glm::dvec3 texture_force_n(const HapticMaterial& m, const MaterialContact& c) {
  if (!touching_solid(m, c)) return glm::dvec3(0.0);
  return texture_value_n(m, c.surface_mm) * c.normal;
}

glm::dvec3 restitution_velocity_mm_s(const HapticMaterial& m, const glm::dvec3& normal,
                                     const glm::dvec3& velocity_mm_s) {
  const double vn = glm::dot(normal, velocity_mm_s);
  if (!(vn < 0.0)) return velocity_mm_s;
  return velocity_mm_s - (1.0 + m.restitution) * vn * normal;
}

MaterialForces material_forces(const HapticMaterial& m, const MaterialContact& c,
                               const FrictionHistory& history) {
  MaterialForces f;
  const glm::dvec3& n = c.normal;
  const double spring = spring_force_magnitude_n(m, c.depth_mm());
  // A surface pushes, it never pulls (pulling is stickiness's and magnetism's job): the
  // damping may at most cancel the spring, the texture at most what is left.
  const double damping = std::max(glm::dot(n, damping_force_n(m, c)), -spring);
  const double texture = std::max(glm::dot(n, texture_force_n(m, c)), -(spring + damping));
  f.spring_n = spring * n;
  f.damping_n = damping * n;
  f.texture_n = texture * n;
  f.viscosity_n = viscosity_force_n(m, c);
  f.friction_n = friction_force_n(m, c, spring + damping + texture, history);
  f.magnetic_n = magnetic_force_n(m, c);
  f.stickiness_n = stickiness_force_n(m, c);
  return f;
}

}  // namespace ps
