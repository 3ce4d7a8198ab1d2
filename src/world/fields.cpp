#include "world/fields.h"

#include <cmath>
#include <numbers>

#include "world/haptic_scene.h"  // euler_xyz_deg: the renderer's rotation convention

namespace ps::world {

FieldSet::FieldSet(const std::vector<Field>& fields) {
  for (const Field& f : fields) {
    if (f.type == FieldType::kGravity) {
      gravity_ += f.acceleration_mm_s2;
      continue;
    }
    Entry e;
    e.type = f.type;
    e.force = f.force_n;
    e.fluctuation = f.fluctuation_n;
    e.omega = 2.0 * std::numbers::pi * f.frequency_hz;
    e.b = f.viscosity_n_s_per_mm;
    e.bounded = f.bounded;
    e.to_local = glm::transpose(glm::dmat3(euler_xyz_deg(f.rotation_deg)));
    e.center = f.center;
    e.half = 0.5 * f.size_mm;
    e.position = f.position;
    e.q = f.charge_n_mm2;
    e.softening = f.softening_mm;
    probe_fields_.push_back(e);
  }
}

bool FieldSet::inside(const Entry& e, const glm::dvec3& p) const {
  if (!e.bounded) return true;
  const glm::dvec3 l = e.to_local * (p - e.center);
  return std::abs(l.x) <= e.half.x && std::abs(l.y) <= e.half.y && std::abs(l.z) <= e.half.z;
}

glm::dvec3 FieldSet::charge_force_n(const glm::dvec3& p_mm, const glm::dvec3& charge_mm, double q_n_mm2,
                                    double softening_mm) {
  const glm::dvec3 d = p_mm - charge_mm;
  const double r2 = glm::dot(d, d) + softening_mm * softening_mm;
  return q_n_mm2 * d / (r2 * std::sqrt(r2));
}

glm::dvec3 FieldSet::force_n(const glm::dvec3& p_mm, const glm::dvec3& v_mm_s, double time_s) const {
  glm::dvec3 f(0.0);
  for (const Entry& e : probe_fields_) {
    switch (e.type) {
      case FieldType::kUniform:
        if (inside(e, p_mm)) f += e.force + e.fluctuation * std::sin(e.omega * time_s);
        break;
      case FieldType::kViscous:
        if (inside(e, p_mm)) f -= e.b * v_mm_s;
        break;
      case FieldType::kCharge: f += charge_force_n(p_mm, e.position, e.q, e.softening); break;
      case FieldType::kGravity: break;
    }
  }
  return f;
}

}  // namespace ps::world
