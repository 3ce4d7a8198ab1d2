// Pointer -> probe: where a pointer on the window puts the probe, without GL or GLFW, so the
// mouse of `run`, the scripted pointer device and the tests share one mapping.
//   absolute (the default): the pointer's ray through the scene camera (the same matrices the
//            renderer draws with, scene/camera.h) meets the reference plane at the hit point;
//            the probe hovers over it: centre = hit + (R + h) n, R the probe radius, h the
//            person-controlled height of the probe's lowest point. The pseudo-shadow is the
//            probe projected along n (passes/probe_depth.h), so its centre is the hit point:
//            the shadow sits under the pointer on any camera and zoom.
//            With view.floor set, h counts from the surface under the hit point instead
//            (centre = hit + (R + lift + h) n): the probe hovers over whatever is there, and
//            the hit point is where the pointer's ray first meets that surface (raised or
//            lowered parts too: a box's top, a button's plate, a face), moved along n onto the
//            plane; where the ray meets no surface, or meets it on the plane, the plane's hit as
//            without a floor. The probe is lifted along n, not back along the ray, because the
//            pseudo-shadow is the probe projected along n: lifted along n, the shadow's centre
//            is the surface point under the pointer (docs/window.md, "Pointing by ray"). Over a
//            slope the hit point moves downhill (SurfaceFloor::lowering_point) and the lift is a
//            sphere of R + h's, so the probe rests h from the pointed point along the slope's
//            normal and that point is the nearest to it: the shadow's dark core ("Over a slope").
//   relative (captured pointer): raw counts move the hit point along the plane, screen-aligned
//            (right on screen = right on the plane), at a fixed mm per count.
// Units: window positions in the units of the window size (GLFW screen coordinates, origin top
// left, y down, pixel i covering [i, i + 1)); everything else in mm.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ps {

struct PlaneAxes {  // where the device moves: origin and orthonormal tangents/normal (mm)
  glm::dvec3 origin{0.0}, t{1.0, 0.0, 0.0}, b{0.0, 1.0, 0.0}, n{0.0, 0.0, 1.0};
};

// A segment of the pointer's ray: from the near plane (t = 0) to the far plane (t = 1).
struct PointerRay {
  glm::dvec3 near_mm{0.0}, far_mm{0.0};
};

// The surface under the pointer, for a mapping whose height is relative to it (`run`'s mouse):
// how far along the plane's normal n the centre of a probe sphere of radius R, lowered along
// -n over `hit_mm` (a point on the plane), first touches a surface, minus R; 0 where nothing is
// under it. The hover height h is then counted from that surface, not from the plane, so a
// probe hovering at h > 0 is never inside geometry (world/free_height.h).
// SurfaceFloor::lowering_point's answer: the point to lower the probe over and, where the floor
// lowered a sphere there to decide, where it came to rest, so one reading lowers once.
struct FloorLowering {
  glm::dvec3 point{0.0};  // workspace: the pointed surface point, or the place beside it
  // Workspace: the centre of the sphere of that radius lowered over `point` until it touches (a
  // button's pocket counts as its face, as lift_mm's); none where the floor did not lower one.
  std::optional<glm::dvec3> centre;
};

class SurfaceFloor {
 public:
  virtual ~SurfaceFloor() = default;
  virtual double lift_mm(const glm::dvec3& hit_mm, const glm::dvec3& n, double probe_radius_mm) const = 0;
  // The first surface point the pointer's ray meets (the visible surface under the cursor), or
  // none where it meets nothing between the near and far planes.
  virtual std::optional<glm::dvec3> first_hit(const PointerRay& ray) const = 0;
  // Where, over a surface point the ray met (`surface_mm`, not on a button), the probe is to be
  // lowered along -n so that the surface point nearest to it - where its shadow's dark core lies -
  // is `surface_mm` itself: on a slope that is R sin(slope) downhill of it. The same height over
  // the plane as `surface_mm`. The default: `surface_mm` (lowered straight over it).
  virtual FloorLowering lowering_point(const glm::dvec3& surface_mm, const glm::dvec3& /*n*/,
                                       double /*probe_radius_mm*/, const glm::dvec3& /*toward_eye*/) const {
    return {surface_mm, std::nullopt};
  }
};

// Everything the mapping needs, taken from the render thread's current state at every poll
// (the camera orbits and zooms in `run`). Trivially copyable: it crosses threads in a Snapshot.
struct PointerView {
  Camera camera;
  double aspect = 1.0;                  // the renderer's width / height (the image is stretched to the window)
  glm::dvec2 window_size{512.0, 512.0}; // in the pointer's units
  PlaneAxes plane;
  double probe_radius_mm = 8.0;         // R: sphere/capsule radius (mesh probes: an approximation)
  // Null: the height counts from the plane. Not owned; it must outlive the view's use.
  const SurfaceFloor* floor = nullptr;
};

PointerRay pointer_ray(const PointerView& view, const glm::dvec2& pointer);
// The ray's point on the plane, or none when the ray is parallel to it or meets it outside the
// near..far segment (behind the camera, or past what the camera draws).
std::optional<glm::dvec3> intersect_plane(const PointerRay& ray, const PlaneAxes& plane);
// Where a world point lands in the window (the inverse of pointer_ray for points in view).
glm::dvec2 project_to_window(const PointerView& view, const glm::dvec3& p_mm);
// The absolute mapping's hit point: with a floor, the surface point the ray meets first, moved
// along n onto the plane (the plane's own hit where that point lies within 0.01 mm of the plane,
// so a flat scene maps exactly as without a floor); without one, or where the ray meets no
// surface, the plane's hit. None where neither is met.
// `hover_mm`: the probe's height h; on a slope the point is moved downhill so that a probe
// hovering h above the surface (a sphere of R + h lowered along -n) is nearest the pointed point.
struct PointerHits {
  std::optional<glm::dvec3> hit;       // as above
  std::optional<glm::dvec3> on_plane;  // the ray's own point on the plane (intersect_plane)
  // Over a surface off the plane: the probe's centre (a sphere of R + max(h, 0)) lowered over
  // `hit` already (FloorLowering::centre); none where it is still to be lowered (lift_mm).
  std::optional<glm::dvec3> rest_centre;
};
PointerHits pointer_hits(const PointerView& view, const glm::dvec2& pointer, double hover_mm = 0.0);
inline std::optional<glm::dvec3> pointer_hit(const PointerView& view, const glm::dvec2& pointer, double hover_mm = 0.0) {
  return pointer_hits(view, pointer, hover_mm).hit;
}

// The person-controlled height h of the probe's lowest point above the hit point, mm.
struct HeightParams {
  // 1 mm: the default 8 mm probe's shadow shows a dark core (at 4 mm only a faint grey disc is
  // left), yet the probe is out of contact, so nothing pushes back until the person lowers it
  // (two key presses).
  double start_mm = 1.0;
  double step_mm = 0.5;     // per key press (and per key repeat while held)
  double scroll_mm = 0.5;   // per scroll notch
  double min_mm = -4.0;     // pressing in: half the default probe's radius (2 N at 0.5 N/mm)
  double max_mm = 60.0;     // a cap that keeps the probe within reach of the scene
};

class HeightControl {
 public:
  explicit HeightControl(const HeightParams& params) : params_(params), mm_(params.start_mm) {}
  double mm() const { return mm_; }
  void step(int presses) { set(mm_ + presses * params_.step_mm); }
  void scroll(double notches) { set(mm_ + notches * params_.scroll_mm); }
  void add_mm(double dmm) { set(mm_ + dmm); }
  void set(double mm);  // clamped to [min_mm, max_mm]; NaN is ignored
  // The scene needs the probe to go at least `depth_mm` in (its buttons' full travel through
  // the coupling, world::deepest_press_mm): min_mm becomes -max(depth_mm, the params' own).
  void reach_depth(double depth_mm);
  const HeightParams& params() const { return params_; }

 private:
  HeightParams params_;
  double base_min_mm_ = params_.min_mm;
  double mm_;
};

// Keeps the last good hit point, so a pointer whose ray misses the plane (parallel, pointing
// away, outside the window far beyond the horizon) leaves the probe where it was: never NaN.
class PointerMap {
 public:
  // Absolute mapping: the probe centre over the pointer at height_mm.
  glm::dvec3 absolute(const PointerView& view, const glm::dvec2& pointer, double height_mm);
  // Relative mapping: moves the hit point by `counts` (x right, y down) at mm_per_count.
  glm::dvec3 relative(const PointerView& view, const glm::dvec2& counts, double mm_per_count, double height_mm);
  // The current hit point (the shadow's centre); the plane origin before the first hit.
  glm::dvec3 hit(const PointerView& view) const { return have_hit_ ? hit_ : view.plane.origin; }
  bool have_hit() const { return have_hit_; }
  // Puts the hit point at `hit_mm` (a point on the plane): where a relative pointer starts, or
  // where a clutch re-centres it. Non-finite points are ignored.
  void set_hit(const glm::dvec3& hit_mm);
  // How far the last absolute() call moved the hit point off the plane's own hit, beyond how far
  // the previous call had it (mm): the surface's parallax jumps where the pointer crosses a
  // silhouette (off a bump onto the ground behind it) and is smooth elsewhere.
  double parallax_jump_mm() const { return parallax_jump_mm_; }

 private:
  // The probe's centre over the hit point at height_mm; `rest`: the sphere of R + max(h, 0) this
  // reading lowered over it already (absolute()), so it is not lowered again.
  glm::dvec3 centre(const PointerView& view, double height_mm, const std::optional<glm::dvec3>& rest = std::nullopt) const;
  glm::dvec3 hit_{0.0};
  glm::dvec3 parallax_{0.0};  // hit_ minus the plane's own hit (0 on the plane)
  double parallax_jump_mm_ = 0.0;
  bool have_hit_ = false;
};

}  // namespace ps
