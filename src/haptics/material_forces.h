// How a material feels: the force laws of a HapticMaterial (scene/haptic_material.h) at one
// contact. Pure functions of the material and a contact description, plus a fixed-size
// friction history the caller owns (one per touched surface); no GL, no allocation, so the
// haptic thread calls them at 1 kHz. docs/haptics.md ("Materials: how they feel") has the laws.
// Units: mm, mm/s, N.
//
// Use: the haptic geometry finds the closest surface point and fills a MaterialContact,
// pushes the contact point into that surface's FrictionHistory, then calls material_forces()
// (or the single laws) and adds the total to the force it sends to the device.
//
//   penetration   r = -distance (> 0 inside)
//   spring        alpha r^(1+beta) n                    (not penetrable; r > 0)
//   damping       -K_d (n.v) n                          (not penetrable; r > 0)
//   viscosity     -b v                                  (penetrable; r > 0: inside the medium)
//   friction      -mu(|Qv|) N d_avg                     (N: the normal push; d_avg: averaged
//                 mu(s) = mu_s s / v0 (s < v0), mu_d (s >= v0)   direction of motion)
//   magnetic      -F_m 16 s^2 (1 - s)^2 n, s = distance / range   (0 < distance < range)
//   stickiness    -S min(1, (n.v) / v0) n               (r > 0, moving outward n.v > 0)
//   texture       n sum_i a_i w_i(d_i . uv / p_i)       (r > 0; w = sin 2 pi x or its sign)
//   restitution   v' = v - (1 + e) (n.v) n              (impact: n.v < 0)
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "scene/haptic_material.h"

namespace ps {

// The probe and one surface at this tick, as the haptic geometry sees them.
struct MaterialContact {
  // Signed distance from the probe's surface to the material's surface: > 0 a gap,
  // < 0 penetrating by -distance_mm.
  double distance_mm = 0.0;
  glm::dvec3 normal{0.0, 0.0, 1.0};     // unit outward normal at the closest point
  glm::dvec3 tangent_u{1.0, 0.0, 0.0};  // unit tangents, u x v = normal: the surface frame
  glm::dvec3 tangent_v{0.0, 1.0, 0.0};
  glm::dvec2 surface_mm{0.0};           // closest point in that frame (texture coordinates)
  glm::dvec3 velocity_mm_s{0.0};        // probe velocity (filtered)

  bool penetrating() const { return distance_mm < 0.0; }
  double depth_mm() const { return distance_mm < 0.0 ? -distance_mm : 0.0; }
};

// Each law's contribution, on the user's hand, in N.
struct MaterialForces {
  glm::dvec3 spring_n{0.0};
  glm::dvec3 damping_n{0.0};
  glm::dvec3 viscosity_n{0.0};
  glm::dvec3 friction_n{0.0};
  glm::dvec3 magnetic_n{0.0};
  glm::dvec3 stickiness_n{0.0};
  glm::dvec3 texture_n{0.0};
  glm::dvec3 total() const {
    return spring_n + damping_n + viscosity_n + friction_n + magnetic_n + stickiness_n + texture_n;
  }
};

// The contact point's last kMaxFrictionHistoryTicks steps in a ring buffer (A Virtual Universe §3:
// the friction direction is the step between the projected previous and current points,
// averaged over a history for stability). reset() when contact is lost.
class FrictionHistory {
 public:
  void reset() { count_ = 0; next_ = 0; has_point_ = false; }
  // The contact point on the surface this tick; from the second call on, a step is stored.
  void push(const glm::dvec3& point_mm);
  // Unit mean of the newest `ticks` steps projected onto the plane of `normal`; zero when
  // there are none or they cancel.
  glm::dvec3 direction(int ticks, const glm::dvec3& normal) const;
  int steps() const { return count_; }

 private:
  std::array<glm::dvec3, kMaxFrictionHistoryTicks> steps_{};
  glm::dvec3 last_point_{0.0};
  int count_ = 0;  // stored steps, <= kMaxFrictionHistoryTicks
  int next_ = 0;   // where the next step goes
  bool has_point_ = false;
};

// alpha r^(1+beta) for depth r > 0; 0 outside and for penetrable materials.
double spring_force_magnitude_n(const HapticMaterial& m, double depth_mm);
// -K_d (n.v) n while penetrating a solid material.
glm::dvec3 damping_force_n(const HapticMaterial& m, const MaterialContact& c);
// -b v inside a penetrable material (water, thick fluid); zero elsewhere.
glm::dvec3 viscosity_force_n(const HapticMaterial& m, const MaterialContact& c);
// mu(s): mu_s s / v0 below the stick speed v0, mu_d from v0 on.
double friction_coefficient(const HapticMaterial& m, double tangential_speed_mm_s);
// Coulomb friction of normal force `normal_force_n` against the history's direction of
// motion (the tangential velocity's when the history has none). Zero when penetrable.
glm::dvec3 friction_force_n(const HapticMaterial& m, const MaterialContact& c,
                            double normal_force_n, const FrictionHistory& history);
// F_m 16 s^2 (1 - s)^2, s = distance / range: 0 at contact and at the range, F_m at range/2.
double magnetic_force_magnitude_n(const HapticMaterial& m, double distance_mm);
glm::dvec3 magnetic_force_n(const HapticMaterial& m, const MaterialContact& c);
// Inward radial friction: resists leaving the surface, up to stickiness_n.
glm::dvec3 stickiness_force_n(const HapticMaterial& m, const MaterialContact& c);
// sum_i a_i w_i(d_i . uv / p_i) (N, signed): the texture's push along the normal.
double texture_value_n(const HapticMaterial& m, const glm::dvec2& surface_mm);
glm::dvec3 texture_force_n(const HapticMaterial& m, const MaterialContact& c);
// Velocity after an impact: v - (1 + e)(n.v) n when approaching (n.v < 0), else v.
glm::dvec3 restitution_velocity_mm_s(const HapticMaterial& m, const glm::dvec3& normal,
                                     const glm::dvec3& velocity_mm_s);

// Every law at once. The normal push (spring + damping + texture) is clamped at >= 0 (a
// surface never pulls: damping and texture are cut first), and friction uses that push as N.
MaterialForces material_forces(const HapticMaterial& m, const MaterialContact& c,
                               const FrictionHistory& history);

}  // namespace ps
