// The surface under the pointer, on the haptic geometry (world::HapticScene): `run`'s mouse
// counts its hover height from it (devices/pointer_map.h, SurfaceFloor), so the hand - and the
// proxy placed at it after a scene switch, a 4D turn, a panel edit or a reload - is on the free
// side of whatever is under the pointer, and the height keys always free it (docs/window.md,
// "When the hand is inside geometry").
// The pointer's point is where its ray first meets the geometry (first_hit: sphere tracing, each
// step the distance to the nearest surface, so it cannot step through a thin shell), moved onto
// the plane (devices/pointer_map.h, pointer_hit).
// A probe sphere of radius R is lowered along -n over the pointer's point on the plane, from
// above everything (the camera's height over the plane), by conservative advancement (each step
// the gap to the nearest surface, so it cannot pass through a thin shell) until it touches; a
// button's face counts as solid (its pocket is for pressing, not for hovering).
// Main thread; HapticScene::closest() is const and thread-safe, so the scene may be the one the
// haptic thread uses.
#pragma once

#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "devices/pointer_map.h"
#include "world/haptic_scene.h"

namespace ps {

struct FreeHeightParams {
  double query_mm = 64.0;       // radius of one closest-point query (longer steps in free space)
  double below_plane_mm = 300.0;  // how far under the plane a surface is still "under the pointer"
  double touch_epsilon_mm = 0.01;  // gap at which the lowered sphere counts as touching
  int max_steps = 128;          // conservative-advancement steps (then: the plane, as without a floor)
  // The pointer's ray is marched the same way (each step the gap to the nearest surface), with
  // longer steps through free space: a camera's far plane can be metres away.
  double ray_query_mm = 256.0;
  int ray_max_steps = 512;  // a ray grazing a surface converges slowly; then the plane
};

class FreeHeight final : public SurfaceFloor {
 public:
  explicit FreeHeight(const FreeHeightParams& params = {}) : params_(params) {}
  // The geometry felt now (null: no floor, the plane).
  void set_scene(std::shared_ptr<const world::HapticScene> scene) { scene_ = std::move(scene); }
  const std::shared_ptr<const world::HapticScene>& scene() const { return scene_; }
  // Workspace -> world (a [navigation] box's offset, a rolling view's turn): the pointer moves
  // in the workspace, the geometry is in the world.
  void set_pose(const glm::dmat3& rotation, const glm::dvec3& offset_mm) {
    rotation_ = rotation;
    offset_mm_ = offset_mm;
  }
  // Where the lowering starts, mm above the plane (the camera's height over it: above what it sees).
  void set_top_mm(double top_mm) { top_mm_ = top_mm; }
  double lift_mm(const glm::dvec3& hit_mm, const glm::dvec3& n, double probe_radius_mm) const override;
  // Where the pointer's ray (workspace) first meets the haptic geometry, in the workspace: the
  // visible surface under the cursor (a button's pocket counts as the button's place).
  std::optional<glm::dvec3> first_hit(const PointerRay& ray) const override;
  // Over a slope, the point beside `surface_mm` (downhill, by R sin(slope)) where the probe is
  // lowered so that the surface point nearest to it is `surface_mm`: the shadow's dark core under
  // the pointer. The straight lowering is kept where it comes nearer (hollows narrower than the
  // probe, an overhang over the shifted point). Over a button's face whose normal is not n (a
  // pointer plane facing the camera, as Illusion's) the probe is placed beside the point alike,
  // along the face's normal, and pressed from there along n.
  // Where it lowered a sphere to decide, that sphere's rest comes with the point (the mapping
  // then needs no lift_mm() for this reading).
  FloorLowering lowering_point(const glm::dvec3& surface_mm, const glm::dvec3& n, double probe_radius_mm,
                               const glm::dvec3& toward_eye) const override;
  // Whether a probe sphere of radius r moved straight from `from_mm` to `to_mm` (workspace) stays
  // more than `clearance_mm` from every surface (sphere tracing along the segment; a segment
  // grazing that clearance for more than `max_steps` steps counts as not clear).
  bool path_clear(const glm::dvec3& from_mm, const glm::dvec3& to_mm, double r, double clearance_mm) const;
  // The outward normal of the surface the last lift_mm() or lowering_point() lowering found, in
  // the workspace (the plane's normal where nothing was under the pointer): the hand placed over
  // it coasts along it.
  const glm::dvec3& last_normal() const { return last_normal_; }

 private:
  struct Lowered {
    glm::dvec3 centre{0.0}, touched{0.0}, normal{0.0};  // world; touched: the surface point nearest the centre
  };
  // Sphere tracing, the one loop behind first_hit (a ray: radius 0), lower and path_clear: a
  // sphere of radius r moved from `from` along the unit `dir`, each step the gap to the nearest
  // surface beyond `clearance` (so it cannot step through a thin shell, nor past a place that
  // comes within `clearance`), at least `min_step`. It meets a surface where the gap is within
  // touch_epsilon_mm of `clearance`; it is clear where it reaches `length` first (checked there
  // too); it is lost after `max_steps` (a path grazing the clearance converges slowly).
  struct March {
    enum class End { kMet, kClear, kLost } end = End::kLost;
    double t = 0.0;          // how far along dir it went
    world::Contact contact;  // the nearest surface where it stopped (kMet)
  };
  struct MarchLimits {
    double query_mm = 64.0;  // beyond the sphere: the longest step through free space
    int max_steps = 128;
    double min_step = 0.0;
  };
  March march(const glm::dvec3& from, const glm::dvec3& dir, double length, double r, double clearance,
              const MarchLimits& limits) const;
  // A probe sphere of radius r lowered along -n (world) over `over` from the camera's height
  // (top_mm_ above it) until it touches; none where it starts inside or nothing is under it.
  std::optional<Lowered> lower(const glm::dvec3& over, const glm::dvec3& n, double r) const;
  // A lowering_point() answer over `over_ws` (workspace) from the sphere lowered there (world),
  // rested on buttons as lift_mm() rests it; its surface normal becomes last_normal().
  FloorLowering rested(const glm::dvec3& over_ws, const Lowered& down, const glm::dvec3& n, double r) const;
  // lowering_point() over a button's face (normal `face`, world) at p (world).
  FloorLowering over_button(const glm::dvec3& surface_ws, const glm::dvec3& p, const glm::dvec3& face,
                            const glm::dvec3& n, double r) const;
  // The outward surface normal at a surface point p (world), on the side facing `eye`.
  std::optional<glm::dvec3> normal_at(const glm::dvec3& p, const glm::dvec3& eye) const;

  FreeHeightParams params_;
  std::shared_ptr<const world::HapticScene> scene_;
  glm::dmat3 rotation_{1.0};
  glm::dvec3 offset_mm_{0.0};
  double top_mm_ = 200.0;
  mutable glm::dvec3 last_normal_{0.0, 0.0, 1.0};  // main thread only, like every call here
};

// How far a probe sphere (the scene's probe radius) centred at `centre_mm` overlaps the haptic
// geometry, mm: R - the distance to the nearest surface; 0 when free.
double buried_mm(const world::HapticScene& scene, const glm::dvec3& centre_mm);

// A hovering hand's proxy left behind a raised surface: further than `reach_mm` from the hand,
// with a surface between their centres (the straight line from the hand to 1 mm short of the
// proxy passes through one). A mouse read by slow frames (4-10 a second: a dense texture, a
// loaded machine) can skip the readings over a raised part's top: the hand then goes from one
// side to the other below the top, and the proxy, which cannot pass through, stays pressed
// against the side while the pointer points elsewhere. Both positions in the workspace, as
// path_clear's.
bool proxy_stranded(const FreeHeight& floor, const glm::dvec3& hand_mm, const glm::dvec3& proxy_mm, double reach_mm);

}  // namespace ps
