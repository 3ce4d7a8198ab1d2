// The god-object proxy (Zilles & Salisbury 1995) for a sphere probe of radius R: a point that
// follows the device in free space and stays on the surface when the device goes into it.
// Every shape is seen through HapticScene::closest(), so analytic shapes and meshes behave
// alike. One update, from the last proxy p toward the goal g (the device position):
//   1. target = the point nearest g on the side of every active constraint plane
//      (n_i . x >= d_i, up to 3 planes, solved by trying each active set: Lagrange
//      multipliers >= 0 and all other planes satisfied);
//   2. approach the target by conservative advancement: each step is at most (distance to the
//      nearest surface - R), so the proxy sphere cannot cross a surface, however thin;
//   3. once touching (gap < contact_epsilon_mm), that surface's tangent plane, offset by R,
//      becomes a constraint (normal = from the contact point to the proxy centre); the proxy
//      then slides toward the new target in steps shorter than R, pushed back out of anything
//      it enters, and back to 1. A step that cannot be made safe is not taken.
// Each closest-point query is limited to R + the remaining step (+ a margin): only facets near
// the proxy are examined, the local model (Hanson & Zhang §4.2); Step::facets_visited counts them.
// No allocation: the haptic thread calls update() and move_to() every tick.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "world/haptic_scene.h"

namespace ps::world {

struct GodObjectParams {
  double contact_epsilon_mm = 1e-3;  // gap under which the proxy counts as touching
  int max_iterations = 24;           // approach / slide steps per move (then it stops, safely)
  double slide_step_fraction = 0.25; // longest step along a surface, in units of R (< 1: see slide())
  double query_margin_mm = 0.5;      // extra query radius beyond R + step
};

struct ProxyStep {
  glm::dvec3 proxy_mm{0.0};
  bool in_contact = false;           // a surface stopped the proxy short of the goal
  int surface = -1;                  // the surface touched (last constraint)
  glm::dvec3 contact_point{0.0};     // closest surface point to the proxy
  glm::dvec3 contact_normal{0.0, 0.0, 1.0};  // unit, contact point -> proxy centre
  glm::dvec3 shaded_normal{0.0, 0.0, 1.0};   // force-shading normal there, on the proxy's side
  int planes = 0;                    // constraint planes used (0..3)
  // Touching nothing, yet short of the goal: the hand moved farther in one tick than the
  // approach's steps reach (each step is the gap to the nearest surface, so a sphere gliding 1 mm
  // over a floor covers ~max_iterations mm a tick; a mouse read after a stalled frame can jump
  // 100 mm). The proxy catches up over the next ticks; nothing holds it.
  bool short_of_goal = false;
  std::uint32_t facets_visited = 0;  // mesh triangles examined over the whole update
};

class GodObject {
 public:
  GodObject(const HapticScene& scene, const GodObjectParams& params = {});

  // Places the proxy at `device_mm`, pushed out along the outward normal if that is within R
  // of a surface (a device that starts inside an object).
  void reset(const glm::dvec3& device_mm);
  // Frictionless god-object move toward the goal (the device; or friction's stick point).
  ProxyStep move(const glm::dvec3& goal_mm);

  const glm::dvec3& proxy() const { return proxy_; }
  const HapticScene& scene() const { return scene_; }
  bool initialized() const { return initialized_; }
  double radius_mm() const { return radius_; }
  // The sheet of a surface embedded in 4D the proxy keeps to (docs/fourd.md): false when it
  // touches none; else its surface index and the 4D depth w at the last contact.
  // `point`: if given, the contact point on that sheet, mm.
  bool sheet(int& surface, double& w4, glm::dvec3* point = nullptr) const {
    if (!hint_.has_w4) return false;
    surface = hint_.surface;
    w4 = hint_.w4;
    if (point != nullptr) *point = hint_.point;
    return true;
  }
  // That sheet's last contact (point, facet normal turned toward the proxy, fourd_facet), or
  // null when the proxy keeps to no sheet.
  const Contact* sheet_contact() const { return hint_.has_w4 ? &hint_ : nullptr; }

 private:
  struct Plane {
    glm::dvec3 n;
    double d;  // n . x >= d
  };
  double gap(const glm::dvec3& p, double limit, Contact& c, std::uint32_t& facets);
  bool slide(glm::dvec3& p, const glm::dvec3& target, std::uint32_t& facets);
  glm::dvec3 constrained_target(const glm::dvec3& goal, const Plane* planes, int count,
                                const glm::dvec3& fallback) const;
  // move(), in three steps: the constraint solve (approach, touch, slide) from p toward the goal,
  // returning the last surface touched with `count` planes in use; a plane kept among the (at
  // most 3) constraints; the contact reported where the proxy rests.
  Contact constrain(const glm::dvec3& goal_mm, glm::dvec3& p, int& count, std::uint32_t& facets);
  static void keep_plane(Plane* planes, int& count, const Plane& plane);
  void settle(ProxyStep& out, const glm::dvec3& goal_mm, const glm::dvec3& p, Contact touched);

  const HapticScene& scene_;
  GodObjectParams params_;
  double radius_ = 0.0;
  glm::dvec3 proxy_{0.0};
  bool initialized_ = false;
  Contact hint_;  // last mesh hit: starts the next query's search radius (local model)
};

}  // namespace ps::world
