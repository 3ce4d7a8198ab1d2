#include "devices/poll_stroke.h"

#include <algorithm>

namespace ps {

glm::dvec3 PollStroke::at(double t) const {
  if (!(to_s > from_s)) return to.position_mm;
  const double a = std::clamp((t - from_s) / (to_s - from_s), 0.0, 1.0);
  return from_mm + a * (to.position_mm - from_mm);
}

DeviceSample PollStroke::read(double t) const {
  DeviceSample s = to;
  s.position_mm = at(t);
  s.time_s = std::max(t, to.time_s);
  return s;
}

PollStroke next_stroke(const PollStroke& last, const DeviceSample& s, double now_s, double last_poll_s, double max_s) {
  PollStroke k{s, s.position_mm, now_s, now_s};
  if (last.to.valid && s.valid && last.to.placements == s.placements && now_s > last_poll_s) {
    k.from_mm = last.at(now_s);
    k.to_s = now_s + std::min(now_s - last_poll_s, max_s);
  }
  return k;
}

}  // namespace ps
