// The scene's [[fields]] on the haptic side (docs/haptics.md, "Fields"): uniform forces with a
// fluctuating part, viscous regions and point charges act on the probe; gravity acts on the
// bodies. Built once from the Scene; force_n() is const, allocation-free and thread-safe.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ps::world {

class FieldSet {
 public:
  FieldSet() = default;
  explicit FieldSet(const std::vector<Field>& fields);

  // The force (N) the fields put on a probe at p (mm) moving at v (mm/s), at session time t (s).
  glm::dvec3 force_n(const glm::dvec3& p_mm, const glm::dvec3& v_mm_s, double time_s) const;
  // The sum of the gravity fields' accelerations (mm/s^2): what the bodies fall with.
  const glm::dvec3& gravity_mm_s2() const { return gravity_; }
  bool empty() const { return probe_fields_.empty(); }  // nothing acts on the probe

  // Single laws, public for the closed-form tests.
  static glm::dvec3 charge_force_n(const glm::dvec3& p_mm, const glm::dvec3& charge_mm, double q_n_mm2,
                                   double softening_mm);

 private:
  struct Entry {
    FieldType type;
    glm::dvec3 force, fluctuation;  // uniform
    double omega = 0.0;             // uniform: 2 pi f
    double b = 0.0;                 // viscous
    bool bounded = false;
    glm::dmat3 to_local{1.0};       // region: world -> box frame (rotation transposed)
    glm::dvec3 center{0.0}, half{0.0};
    glm::dvec3 position{0.0};       // charge
    double q = 0.0, softening = 0.0;
  };
  bool inside(const Entry& e, const glm::dvec3& p) const;

  std::vector<Entry> probe_fields_;
  glm::dvec3 gravity_{0.0};
};

}  // namespace ps::world
