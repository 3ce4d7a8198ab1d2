// How a surface feels: the haptic half of a material (docs/scene-format.md, [materials.NAME]
// haptic keys; docs/haptics.md has the force laws). Plain data, parsed with the scene and read
// by the haptic thread; the defaults are the device-side values the loop used before materials
// carried a feel (a desktop 3-DOF device, Falcon-class, ~9 N peak).
// Units: mm, mm/s, s, newtons (N).
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace ps {

// Limits shared by the scene reader and the force code (src/haptics/material_forces.h): the
// friction history is a fixed ring buffer of this many ticks, and a texture sums at most this
// many waves, so the haptic thread never allocates.
inline constexpr int kMaxFrictionHistoryTicks = 32;
inline constexpr int kMaxHapticWaves = 16;

// One term of a haptic texture along the surface (A Virtual Universe §3): a sine or square wave of
// the surface coordinate along `direction` (a unit tangent direction in the surface's local frame,
// normalised by the scene reader),
// pushing along the surface normal with amplitude `amplitude_n`.
struct HapticWave {
  enum class Shape { kSine, kSquare };
  Shape shape = Shape::kSine;
  double amplitude_n = 0.0;
  double period_mm = 1.0;
  glm::dvec2 direction{1.0, 0.0};
  bool operator==(const HapticWave&) const = default;
};

struct HapticMaterial {
  double stiffness_n_per_mm = 0.5;      // alpha (beta = 0: 500 N/m linear spring)
  double stiffness_exponent = 0.0;      // beta in f = alpha r^(1+beta)
  double damping_n_s_per_mm = 0.002;    // K_d on the normal velocity
  double static_friction = 0.3;         // mu_s
  double dynamic_friction = 0.2;        // mu_d <= mu_s
  int friction_history_ticks = 8;       // friction direction averaged over this many ticks
  // Below this tangential speed friction ramps linearly from 0 (a hand at rest feels no
  // chatter) to its static peak mu_s; at and above it, it slides at mu_d (the break-away).
  double stick_speed_mm_s = 2.0;
  // Penetrable medium (water, thick fluid): no surface spring, only F = -b v inside.
  bool penetrable = false;
  double viscosity_n_s_per_mm = 0.0;    // b inside a penetrable material
  // Magnetic attraction toward the surface within `magnetic_range_mm`, zero at contact.
  double magnetic_force_n = 0.0;
  double magnetic_range_mm = 0.0;
  double stickiness_n = 0.0;            // inward radial friction (resists pulling away)
  double restitution = 0.0;             // elastic restitution in [0, 1] on impact
  std::vector<HapticWave> texture;      // haptic texture, summed
  bool operator==(const HapticMaterial&) const = default;
};

}  // namespace ps
