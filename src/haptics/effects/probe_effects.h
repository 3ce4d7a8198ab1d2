// The effects that act on the probe before the proxy moves (effects/effect.h): the scene's fields
// with the live charges, its buttons, its bodies. Their forces are summed in this order and
// couple into the god-object's goal (docs/haptics.md, "Pseudo-haptic coupling").
#pragma once

#include "core/snapshot.h"
#include "haptics/effects/effect.h"
#include "haptics/haptic_state.h"
#include "world/bodies.h"
#include "world/buttons.h"

namespace ps {

// The scene's fields at the probe (last tick's proxy: the probe that is in the field) and the
// live charges a person adds (run's C / Shift+C); a charge that came or went is an event.
class FieldEffect final : public HapticEffect {
 public:
  explicit FieldEffect(const Snapshot<LiveCharges>& published) : published_(published) {}
  void restart(const world::HapticScene& scene, bool) override { scene_ = &scene; }
  bool compute(const EffectTick& tick, glm::dvec3& force_n) override;

 private:
  void adopt_live_charges(const EffectTick& tick);
  const world::HapticScene* scene_ = nullptr;
  const Snapshot<LiveCharges>& published_;  // written by the render thread
  LiveCharges adopted_;  // the set in force, to diff the next one against (kept across scenes)
};

// The buttons under the probe: their springs push it; a button that gives way raises
// button_fired and, for a flag action, toggles the flag (HapticState::flags) and raises
// flag_toggled. A scene action is carried out by the event's consumer.
class ButtonEffect final : public HapticEffect {
 public:
  explicit ButtonEffect(double coupling_n_per_mm) : coupling_n_per_mm_(coupling_n_per_mm) {}
  void restart(const world::HapticScene& scene, bool after_switch) override;
  bool compute(const EffectTick& tick, glm::dvec3& force_n) override;

 private:
  const world::HapticScene* scene_ = nullptr;
  double coupling_n_per_mm_;
  world::ButtonSet buttons_;
};

// The scene's bodies on their springs, stepped one tick; floor impacts become events.
class BodyEffect final : public HapticEffect {
 public:
  void restart(const world::HapticScene& scene, bool) override;
  bool compute(const EffectTick& tick, glm::dvec3& force_n) override;

 private:
  world::BodySet bodies_;
};

}  // namespace ps
