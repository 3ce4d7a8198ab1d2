#include "haptics/effects/scene_effects.h"

namespace ps {

HapticEvent EffectTick::event(EventKind kind) const { return make_event(kind, state.tick, t); }

SceneEffects::SceneEffects(const Snapshot<LiveCharges>& live_charges, double coupling_n_per_mm)
    : fields_(live_charges), buttons_(coupling_n_per_mm) {}

void SceneEffects::restart(const world::HapticScene& scene, bool after_switch) {
  for (HapticEffect* e : on_probe_) e->restart(scene, after_switch);
  for (HapticEffect* e : on_hand_) e->restart(scene, after_switch);
  have_scene_ = true;
}

glm::dvec3 SceneEffects::on_probe(const EffectTick& tick) {
  // -0.0 is the exact identity of IEEE addition (+0.0 + -0.0 would give +0.0), so this sum has
  // the bits of one started at its first term.
  glm::dvec3 sum(-0.0);
  if (!have_scene_) return sum;
  glm::dvec3 f(0.0);
  for (HapticEffect* e : on_probe_)
    if (e->compute(tick, f)) sum += f;
  return sum;
}

void SceneEffects::on_hand(const EffectTick& tick, glm::dvec3& force_n) {
  glm::dvec3 f(0.0);
  for (HapticEffect* e : on_hand_)
    if (e->compute(tick, f)) force_n += f;
}

}  // namespace ps
