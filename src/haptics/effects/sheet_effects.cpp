#include "haptics/effects/sheet_effects.h"

#include "haptics/force_model.h"
#include "haptics/haptic_state.h"
#include "world/god_object.h"

namespace ps {

bool CrossingEffect::compute(const EffectTick& tick, glm::dvec3&) {
  glm::dvec3 point(0.0);
  int surface = -1;
  double w = 0.0;
  const fourd::FourdTouch* touch = nullptr;
  if (tick.god != nullptr && tick.god->sheet(surface, w, &point)) touch = tick.god->scene().fourd_touch(surface);
  if (touch == nullptr) {
    crossing_.reset();
    return false;
  }
  const int c = crossing_.update(*touch, point, w, touch->window(w, w));
  if (c == 0) return false;
  HapticEvent e = tick.event(EventKind::sheet_crossing);
  e.surface = surface;
  e.value = c;
  e.position_mm = point;
  tick.events.push(e);
  return false;
}

bool SuggestionEffect::compute(const EffectTick& tick, glm::dvec3& force_n) {
  if (!tick.contact->in_contact) return false;
  force_n = glm::dvec3(0.0);
  glm::dvec3 point(0.0);
  int surface = -1;
  double w = 0.0;
  if (tick.god == nullptr || !tick.god->sheet(surface, w, &point)) {
    have_sheet_point_ = false;
    return true;
  }
  const fourd::SuggestionParams p = tick.god->scene().fourd_suggestion(surface);
  const double dt = tick.dt;
  const glm::dvec3 v = have_sheet_point_ && dt > 0.0 ? (point - last_sheet_point_) / dt : glm::dvec3(0.0);
  last_sheet_point_ = point;
  have_sheet_point_ = true;
  if (!p.on()) return true;
  const glm::dvec3 n = glm::normalize(tick.state.proxy_mm - point);  // the facet's normal on the proxy's side
  glm::dvec3 p_des, v_des;
  fourd::desired_state(p, point, tick.state.velocity_mm_s, n, p_des, v_des);
  force_n = fourd::force_suggestion_n(p, p_des, point, v_des, v, n);
  return true;
}

}  // namespace ps
