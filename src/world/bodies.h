// The scene's [[bodies]] on the haptic side (docs/haptics.md, "Bodies"; A Virtual Universe §4):
// each a mass on a spring hanging from the proxy, falling with the scene's gravity fields and
// bouncing on its floor. Integrated by velocity Verlet (symplectic: an undamped spring keeps its
// energy) in `substeps` steps per haptic tick of simulated time tick x time_scale. The hand
// feels each spring's pull. No allocation after construction.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ps::world {

inline constexpr int kMaxBodies = kMaxSceneBodies;  // the scene parser's limit; HapticState carries this many

// Slower than this into the floor is resting contact, not an impact (no bounce, no event): a
// body lying on its floor gains g x substep = 2.5 mm/s of fall per 0.25 ms substep; 20 mm/s is
// a drop of 0.02 mm.
inline constexpr double kRestingSpeedMmS = 20.0;

struct BodyImpact {
  int body = -1;
  double speed_mm_s = 0.0;  // normal speed into the floor just before the bounce
  glm::dvec3 position_mm{0.0};
};

struct BodyStepResult {
  glm::dvec3 force_on_proxy_n{0.0};  // what the springs pull the proxy (and the hand) with
  std::array<BodyImpact, kMaxBodies> impacts{};
  int impact_count = 0;
};

class BodySet {
 public:
  BodySet() = default;
  BodySet(const std::vector<Body>& bodies, const glm::dvec3& gravity_mm_s2);

  // Advances every body by one haptic tick of dt_s real seconds, the spring anchored at proxy_mm.
  BodyStepResult step(const glm::dvec3& proxy_mm, double dt_s);

  std::size_t size() const { return state_.size(); }
  const glm::dvec3& position(std::size_t i) const { return state_[i].x; }
  const glm::dvec3& velocity(std::size_t i) const { return state_[i].v; }
  const Body& spec(std::size_t i) const { return specs_[i]; }
  // Spring force on body i (N) for a proxy at anchor_mm: -k (|d| - L) d/|d|, d = body - anchor,
  // plus damping along the spring.
  glm::dvec3 spring_force_n(std::size_t i, const glm::dvec3& anchor_mm, const glm::dvec3& x_mm,
                            const glm::dvec3& v_mm_s) const;

 private:
  struct State {
    glm::dvec3 x{0.0}, v{0.0};
  };
  glm::dvec3 acceleration(std::size_t i, const glm::dvec3& anchor, const glm::dvec3& x, const glm::dvec3& v) const;

  std::vector<Body> specs_;
  std::vector<State> state_;
  glm::dvec3 gravity_{0.0};
};

}  // namespace ps::world
