// Sheet crossings (Hanson & Zhang §5): the moments the proxy passes a place where another sheet of
// its surface crosses its own in the 3D image, and whether it passes in front of that sheet
// (its own sheet nearer the 4D eye: larger w) or behind it. Fed the proxy's contact point on
// its sheet every haptic tick; reports a crossing when the point's signed distance from the
// nearest other-sheet facet (outside the sheet's w window, within reach_mm) changes sign.
// No allocation: it runs on the haptic thread.
#pragma once

#include <glm/glm.hpp>

#include "fourd/touch.h"

namespace ps::fourd {

class CrossingDetector {
 public:
  // Half-width of the neighbourhood searched for another sheet, mm: a crossing is only seen
  // while the other sheet is this near the contact point on both ticks of the sign change.
  // After a crossing, the next one counts only once the contact point has moved rearm_mm away
  // from it: a proxy that chatters on a crease (its contact point hopping to and fro across
  // the other sheet, tick after tick) gives one cue, not dozens.
  explicit CrossingDetector(double reach_mm = 2.0, double rearm_mm = 1.5) : reach_mm_(reach_mm), rearm_mm_(rearm_mm) {}
  // +1: passed in front of another sheet this tick; -1: behind it; 0: no crossing. `window`:
  // the proxy's sheet (facets within it are its own). Call reset() when the proxy leaves.
  int update(const FourdTouch& touch, const glm::dvec3& contact_mm, double w, const WWindow& window);
  void reset() { have_ = false, crossed_ = false; }
  double other_w() const { return other_w_; }  // w of the other sheet at the last crossing

 private:
  double reach_mm_, rearm_mm_;
  bool have_ = false;
  bool crossed_ = false;            // a crossing at crossed_at_ not yet re-armed
  glm::dvec3 crossed_at_{0.0};
  double last_signed_mm_ = 0.0;
  int last_facet_ = -1;
  double other_w_ = 0.0;
};

}  // namespace ps::fourd
