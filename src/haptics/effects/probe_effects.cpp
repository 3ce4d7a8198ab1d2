#include "haptics/effects/probe_effects.h"

#include "haptics/tick_feed.h"
#include "world/god_object.h"

namespace ps {

namespace {

// Where the effects act: the proxy (last tick's), the hand before the proxy has a position.
glm::dvec3 anchor_mm(const EffectTick& tick) {
  return tick.god->initialized() ? tick.god->proxy() : tick.state.position_mm;
}

}  // namespace

bool FieldEffect::compute(const EffectTick& tick, glm::dvec3& force_n) {
  const glm::dvec3 anchor = anchor_mm(tick);
  const world::FieldSet& fields = scene_->fields();
  force_n = fields.empty() ? glm::dvec3(0.0) : fields.force_n(anchor, tick.state.velocity_mm_s, tick.t);
  adopt_live_charges(tick);
  for (int i = 0; i < adopted_.count; ++i)
    force_n += world::FieldSet::charge_force_n(anchor, adopted_.position[i], adopted_.charge_n_mm2[i],
                                               adopted_.softening_mm);
  return true;
}

// Compares the published live charges with the adopted ones by id: one charge_added or
// charge_removed event per difference, with this tick's time.
void FieldEffect::adopt_live_charges(const EffectTick& tick) {
  const LiveCharges now = published_.read();
  auto has = [](const LiveCharges& set, std::uint32_t id) {
    for (int i = 0; i < set.count; ++i)
      if (set.id[i] == id) return i;
    return -1;
  };
  auto raise = [&](EventKind kind, const LiveCharges& set, int i) {
    HapticEvent e = tick.event(kind);
    e.index = static_cast<int>(set.id[i]);
    e.value = set.charge_n_mm2[i];
    e.position_mm = set.position[i];
    tick.events.push(e);
  };
  for (int i = 0; i < adopted_.count; ++i)
    if (has(now, adopted_.id[i]) < 0) raise(EventKind::charge_removed, adopted_, i);
  for (int i = 0; i < now.count; ++i)
    if (has(adopted_, now.id[i]) < 0) raise(EventKind::charge_added, now, i);
  adopted_ = now;
}

void ButtonEffect::restart(const world::HapticScene& scene, bool after_switch) {
  scene_ = &scene;
  // After a switch nothing fires until the probe has left (a rare event: the old storage is freed here).
  buttons_ = world::ButtonSet(scene.button_shapes(), scene.probe_radius_mm(), coupling_n_per_mm_, after_switch);
}

bool ButtonEffect::compute(const EffectTick& tick, glm::dvec3& force_n) {
  if (buttons_.size() == 0) return false;
  const glm::dvec3 anchor = anchor_mm(tick);
  HapticState& s = tick.state;
  // The hand as the device gives it, not the Kalman estimate: after a scene switch the filter
  // sweeps from the old scene's mapping of the pointer to the new one over some ticks, and that
  // sweep can pass over a button clear of its face like an approach (run fired the panel's
  // Weight button 20 ms after a Backspace). The raw position jumps instead.
  const world::ButtonStepResult r = buttons_.step(anchor, s.device_mm);
  force_n = r.force_n;
  s.button_pressed = r.pressed;
  s.button_depth_mm = r.depth_mm;
  for (int k = 0; k < r.fired_count; ++k) {
    const std::size_t i = static_cast<std::size_t>(r.fired[static_cast<std::size_t>(k)]);
    const Button& b = scene_->buttons()[i];
    HapticEvent e = tick.event(EventKind::button_fired);
    e.surface = scene_->button_shapes()[i].surface;
    e.index = static_cast<int>(i);
    e.value = b.travel_mm;
    e.position_mm = anchor;
    e.set_label(b.action);
    tick.events.push(e);
    tick.feed.click = true;
    if (b.action_kind != ButtonActionKind::kFlag || b.flag < 0) continue;
    s.flags ^= 1u << static_cast<unsigned>(b.flag);
    e.kind = EventKind::flag_toggled;
    e.value = (s.flags >> static_cast<unsigned>(b.flag)) & 1u;
    e.set_label(b.action_target);
    tick.events.push(e);
  }
  return true;
}

void BodyEffect::restart(const world::HapticScene& scene, bool) {
  // The new scene's bodies start afresh (a rare event: the vectors' old storage is freed here).
  bodies_ = world::BodySet(scene.bodies(), scene.fields().gravity_mm_s2());
}

bool BodyEffect::compute(const EffectTick& tick, glm::dvec3& force_n) {
  tick.state.body_count = static_cast<int>(bodies_.size());
  if (bodies_.size() == 0) return false;
  const world::BodyStepResult r = bodies_.step(anchor_mm(tick), tick.dt);
  force_n = r.force_on_proxy_n;
  for (std::size_t i = 0; i < bodies_.size(); ++i) tick.state.body_mm[i] = bodies_.position(i);
  for (int k = 0; k < r.impact_count; ++k) {
    HapticEvent e = tick.event(EventKind::body_impact);
    e.index = r.impacts[k].body;
    e.value = r.impacts[k].speed_mm_s;
    e.position_mm = r.impacts[k].position_mm;
    tick.events.push(e);
  }
  return true;
}

}  // namespace ps
