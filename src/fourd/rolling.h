// The 4D haptic rolling manifold (Hanson & Zhang §6, docs/fourd.md "Rolling manifold"): as the
// proxy walks from facet to facet of a surface embedded in 4D, the view turns so that the facet it
// touches faces the viewer and glides so that the contact point comes to the screen centre,
// graphics and haptics together; a rubber-band tether (§6.4, eq. 1 with beta = 3) pulls the
// hand back toward the line of sight through the screen centre.
//
// The surface stays where it is in the world; what moves is the *view*: the camera and the
// device's workspace together, by a rigid map world = R * workspace + t (ViewPose). Seen from
// the person (who sits with the camera and the device) the surface rolls. Every world quantity
// the loop computes stays in one fixed frame, and [navigation]'s box (a translation of the same
// map) composes with it.
//
// Plain maths, no allocation: the haptic thread steps it every tick.
#pragma once

#include <glm/glm.hpp>

namespace ps::fourd {

// The device's workspace (and the camera that looks into it) placed in the world:
// world = rotation * workspace + offset.
struct ViewPose {
  glm::dmat3 rotation{1.0};
  glm::dvec3 offset{0.0};
  glm::dvec3 to_world(const glm::dvec3& ws) const { return rotation * ws + offset; }
  glm::dvec3 to_workspace(const glm::dvec3& world) const { return glm::transpose(rotation) * (world - offset); }
};

// Hanson & Zhang §6.2: Rotate(theta, N) with N = T x T' / |T x T'| and cos theta = T . T' (T, T'
// any non-zero vectors; they are normalised): the rotation that takes T's direction to T''s. The
// identity when they are parallel; a half turn about an axis perpendicular to T when they are
// opposite.
glm::dmat3 rotate_between(const glm::dvec3& t, const glm::dvec3& t_prime);

// Shortest-arc interpolation between two rotations: s = 0 gives a, 1 gives b.
glm::dmat3 slerp_rotation(const glm::dmat3& a, const glm::dmat3& b, double s);

// Angle between two rotations, radians.
double rotation_angle_between(const glm::dmat3& a, const glm::dmat3& b);

struct RollParams {
  bool on = false;
  // Time constant of the turn toward the facet's target orientation, s; 0 = at once (the
  // seed: the view turns in one step at each facet crossing).
  double turn_s = 0.08;
  // Time constant of the glide that brings the contact point to the screen centre, s; 0 = no
  // glide (the view only turns, about the contact point).
  double centre_s = 0.5;
  // Eq. 1 with beta = 3: |f| = alpha r^4 toward the line of sight through the screen centre,
  // r the proxy's distance from it (mm), capped at tether_max_n. alpha 0 = no tether.
  double tether_alpha_n_per_mm4 = 1e-4;
  double tether_max_n = 2.0;
  bool operator==(const RollParams&) const = default;
};

// Where the screen centre is, in the workspace: the camera's target, and the unit direction
// from it toward the viewer (toward the camera's eye; for an orthographic camera the same).
struct ViewAxes {
  glm::dvec3 centre_ws{0.0};
  glm::dvec3 toward_viewer_ws{0.0, 0.0, 1.0};
};

// The proxy's contact on its sheet this tick, in the world.
struct RollContact {
  bool on_sheet = false;
  int facet = -1;
  glm::dvec3 point{0.0};                   // contact point on the sheet
  glm::dvec3 normal{0.0, 0.0, 1.0};        // the facet's unit normal, on the proxy's side
  // The hand has stopped (HapticState's filtered speed under kRollRestMmS): the view rolls only
  // with the hand, so no new turn and no glide; a turn under way ends about the contact point.
  bool hand_at_rest = false;
};

// Below this filtered hand speed the hand is at rest for the rolling manifold, mm/s: a hand
// pressed on the rolling torus and held still had kept it tumbling (61 to 130 degrees in 2 s),
// the glide moving the sheet under the held proxy onto the next facet, and on. 3 mm/s is under
// any deliberate stroke (the slowest walks move at 20 mm/s) and above the filter's tail a few
// hundred ms after a mouse stops.
inline constexpr double kRollRestMmS = 3.0;

class RollingManifold {
 public:
  // Forgets the interest facet (a new scene, a lifted proxy); the pose is left as it is.
  void reset() { facet_ = -1; }
  // One tick: when the proxy has crossed into another facet, the target orientation becomes
  // Hanson & Zhang's Rotate(theta, N) (T: the contact point's motion since the last tick, T': T
  // projected on the new facet), then made exact by the shortest turn that brings the new
  // facet's normal onto the direction toward the viewer (their rule alone leaves a tilt
  // when T crosses the shared edge obliquely; docs/fourd.md). The pose then turns toward the
  // target about the contact point (the contact stays where it is on screen and under the
  // hand) and glides so the contact point approaches the screen centre. Returns true when the
  // interest facet changed this tick (not before the contact has moved 0.2 mm from the last
  // change: no flapping on an edge).
  bool step(const RollParams& p, const ViewAxes& axes, const RollContact& c, double dt, ViewPose& pose);
  // Eq. 1 (beta = 3) of the rubber band from the proxy to the line of sight through the screen
  // centre, in the world, N.
  static glm::dvec3 tether_force(const RollParams& p, const ViewAxes& axes, const ViewPose& pose,
                                 const glm::dvec3& proxy_world);

  int facet() const { return facet_; }
  const glm::dmat3& target_rotation() const { return target_; }
  int turns() const { return turns_; }  // interest-facet changes so far

 private:
  // step()'s turn: a new target rotation when the touch starts or the proxy crosses onto
  // another facet (at least kMinTravelMm from the last turn); false when it keeps the target.
  bool retarget(const ViewAxes& axes, const RollContact& c, const glm::dvec3& n, const ViewPose& pose);
  int facet_ = -1;
  glm::dvec3 last_point_{0.0}, last_normal_{0.0, 0.0, 1.0};
  // Where the interest facet last changed. It changes again only after the contact point has
  // travelled kMinTravelMm from there: a proxy resting on an edge would otherwise flap between
  // its two facets (each turn, about the contact, nudges it onto the other), at 1 kHz.
  glm::dvec3 changed_at_{0.0};
  static constexpr double kMinTravelMm = 0.2;
  glm::dmat3 target_{1.0};
  int turns_ = 0;
};

}  // namespace ps::fourd
