// The haptic scene's effects (effects/effect.h), owned and asked in a fixed order: the order
// fixes the events' order in the log and the rounding of the summed force, so a replay's bytes.
//   on_probe (before the proxy moves): fields with live charges, buttons, bodies;
//   on_hand  (after it):               sheet crossings, force suggestions.
#pragma once

#include <array>

#include "haptics/effects/probe_effects.h"
#include "haptics/effects/sheet_effects.h"

namespace ps {

class SceneEffects {
 public:
  SceneEffects(const Snapshot<LiveCharges>& live_charges, double coupling_n_per_mm);
  SceneEffects(const SceneEffects&) = delete;  // holds pointers to its own members
  SceneEffects& operator=(const SceneEffects&) = delete;

  // A scene is adopted (`after_switch`: not the first): every effect restarts with it, and the
  // effects on the probe act from then on (the plane model has none).
  void restart(const world::HapticScene& scene, bool after_switch);
  // Before the proxy moves: the sum of the forces on the probe (N, world).
  glm::dvec3 on_probe(const EffectTick& tick);
  // After it: each acting effect's force added to `force_n`, the hand's.
  void on_hand(const EffectTick& tick, glm::dvec3& force_n);

 private:
  FieldEffect fields_;
  ButtonEffect buttons_;
  BodyEffect bodies_;
  CrossingEffect crossings_;
  SuggestionEffect suggestions_;
  std::array<HapticEffect*, 3> on_probe_{&fields_, &buttons_, &bodies_};
  std::array<HapticEffect*, 2> on_hand_{&crossings_, &suggestions_};
  bool have_scene_ = false;
};

}  // namespace ps
