#include "fourd/crossing.h"

namespace ps::fourd {

int CrossingDetector::update(const FourdTouch& touch, const glm::dvec3& contact_mm, double w, const WWindow& window) {
  const FourdTouch::OtherSheet o = touch.other_sheet(contact_mm, reach_mm_, window);
  if (!o.hit) {
    have_ = false;
    return 0;
  }
  int crossing = 0;
  if (crossed_ && glm::length(contact_mm - crossed_at_) > rearm_mm_) crossed_ = false;
  // A sign change against the same other sheet (its facet or one touching it): the contact
  // point went through it. Its w against ours says in front (+1: ours nearer the 4D eye) or behind.
  if (have_ && !crossed_ && (last_signed_mm_ < 0.0) != (o.signed_mm < 0.0) && touch.facets_touch(last_facet_, o.facet)) {
    crossing = w > o.w ? 1 : -1;
    other_w_ = o.w;
    crossed_ = true;
    crossed_at_ = contact_mm;
  }
  have_ = true;
  last_signed_mm_ = o.signed_mm;
  last_facet_ = o.facet;
  return crossing;
}

}  // namespace ps::fourd
