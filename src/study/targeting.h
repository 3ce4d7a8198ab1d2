// The targeting task's geometry (docs/study.md, "Targeting"): ISO 9241-9's multidirectional
// ring. `targets` round targets of diameter W sit evenly on a ring of diameter D lying on a plane
// of the scene (TargetingSpec: its centre and normal); the participant selects them across the
// ring, target 0 first, then the one (targets + 1) / 2 steps on, and so on, which with an odd
// count visits every target once a sequence and makes every movement the same chord,
// D sin(pi (targets - 1) / (2 targets)): 0.985 D for 9 targets.
#pragma once

#include <array>

#include "study/experiment.h"
#include "study/fitts.h"

namespace ps::study {

struct Ring {
  Point3 centre;
  std::array<double, 3> u{1.0, 0.0, 0.0}, v{0.0, 1.0, 0.0}, normal{0.0, 0.0, 1.0};  // orthonormal; u, v span the plane
  double diameter = 0.0;
  int targets = 9;
};

// The ring of diameter `diameter` on the spec's plane. u is the plane's direction nearest world
// +x (world +y when the normal is along x), so target 0 lies on the ring's +x side.
Ring make_ring(const TargetingSpec& spec, double diameter);
// Target `index`'s centre: at angle 2 pi index / targets from u towards v.
Point3 target_centre(const Ring& ring, int index);
// The target selected at `step` of a sequence (from 0): step (targets + 1) / 2 mod targets.
int target_at_step(int targets, int step);
// Every movement's centre-to-centre distance on a ring: D sin(pi (targets - 1) / (2 targets)).
double movement_distance(double diameter, int targets);

// Selections made by touching (the targeting task in the window, docs/study.md, "Targeting in
// the window"): a selection is the haptic tick on which the probe comes into contact; the next
// one counts only after the probe has been lifted more than `rearm_mm` off the plane for
// `rearm_s` without a break. So contact that flickers at the surface (a probe resting on it)
// selects once, and so does the hand filter's ringing when the height steps: lifted through
// the contact height, the filtered probe was seen to rise 0.29 mm for 7 ms and fall back into
// contact (a second selection without the time condition). A person's lift between two touches
// lasts far longer than 60 ms.
// It starts unarmed: a probe already down when a ring appears selects nothing until lifted.
class TouchSelector {
 public:
  explicit TouchSelector(double rearm_mm = 0.25, double rearm_s = 0.06) : rearm_mm_(rearm_mm), rearm_s_(rearm_s) {}
  // One tick at `time_s`: in contact or not, and the gap between the probe and the plane (mm;
  // <= 0 pressed in). True: this tick is a selection.
  bool tick(double time_s, bool in_contact, double gap_mm);
  bool armed() const { return armed_; }

 private:
  double rearm_mm_, rearm_s_;
  bool armed_ = false;
  double lifted_since_ = -1.0;  // < 0: not lifted past rearm_mm now
};

// Whether a sphere (`centre`, `radius`) hides point `p` from `eye`: the segment between them
// passes through it, or `p` is inside it. The window draws the targets over the picture; where
// the probe is drawn opaque they are cut where it stands in front of them (docs/study.md,
// "Targeting in the window").
bool hidden_by_sphere(const Point3& eye, const Point3& p, const Point3& centre, double radius);

// A point `along` the task axis from `from` towards `to` and `aside` across it in the plane.
Point3 on_axis(const Ring& ring, const Point3& from, const Point3& to, double along, double aside);
// The distance between two points.
double distance(const Point3& a, const Point3& b);

}  // namespace ps::study
