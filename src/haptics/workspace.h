// The device's workspace in the world (haptic thread): where the hand's box sits and how it is
// turned. [navigation] moves it by the hand's push past the box's walls (a rate control); a
// rolling fourd surface (fourd/rolling.h) turns it under a probe on its sheet. Without either
// (or without a haptic scene: the plane model) workspace = world.
// navigate() runs before the proxy (it moves the hand into the world); roll() after it, because
// the manifold rolls on the contact the proxy found this tick.
#pragma once

#include <glm/glm.hpp>

#include "core/snapshot.h"
#include "fourd/rolling.h"

namespace ps {

struct HapticState;
struct PublishedViewAxes;
namespace world { class GodObject; class HapticScene; }

class Workspace {
 public:
  // A new scene (null: the plane model) starts with its own view: workspace = world.
  void restart(const world::HapticScene* scene);
  void home();  // the view back where the scene started (run's Home key)
  // [navigation]: moves the view by the push of `device_mm` (the device's own position, in the
  // workspace) past the box's walls; then (with navigation or a rolling surface) turns the
  // hand's filtered position and velocity (s.position_mm, s.velocity_mm_s, workspace) and
  // `device_mm` into world ones in `s`. Returns the walls' force (world, N). Always writes the
  // view's pose into `s` (identity for a scene that does not move it). `travel` false: the view
  // holds still (the walls still push). A device over a button (its rectangle, at any height)
  // neither moves the view nor meets a wall: a button beyond the box can be reached and pressed.
  glm::dvec3 navigate(const glm::dvec3& device_mm, double dt, HapticState& s, bool travel = true);
  // After the proxy moved: the rolling manifold's step on the sheet contact of `god` (the proxy in
  // the scene; null with the plane model), with the
  // camera's axes (the render thread's, until it publishes them the scene file's); `tether_n`
  // gets its tether's force (world, N). False without a scene.
  bool roll(const world::GodObject* god, const Snapshot<PublishedViewAxes>& published, double dt, HapticState& s,
            glm::dvec3& tether_n);
  // A force in the world as the device feels it, in its own workspace.
  glm::dvec3 to_device(const glm::dvec3& force_n) const { return glm::transpose(view_.rotation) * force_n; }

 private:
  const world::HapticScene* scene_ = nullptr;
  fourd::ViewPose view_;         // workspace -> world (navigation's offset, rolling's turn)
  fourd::RollingManifold roll_;  // Hanson & Zhang §6 on a fourd surface with fourd_roll
};

}  // namespace ps
