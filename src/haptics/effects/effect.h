// An effect of the haptic scene on the probe (haptic thread), as CHAI3D's cGenericEffect is: one
// thing the scene does to the probe besides its surfaces, asked once per tick for its force.
// The loop asks two groups (effects/scene_effects.h): before the proxy moves, the ones that act
// on the probe (fields, buttons, bodies: their force couples into the god-object's goal); after
// it, the ones that follow the contact (sheet crossings, force suggestions: added to the hand's
// force). Viscosity stays in the force models (force_model.h): it is summed inside the contact
// force, so taking it out would change the force's rounding and every replay's bytes.
#pragma once

#include <glm/glm.hpp>

#include "haptics/events.h"

namespace ps {

struct ForceResult;
struct HapticState;
struct TickSample;
namespace world { class GodObject; class HapticScene; }

// What an effect sees of one tick.
struct EffectTick {
  // The proxy in the scene: last tick's before the step, this tick's after. Null with the plane
  // model, where only the effects after the proxy are asked (and find no sheet).
  const world::GodObject* god;
  HapticState& state;           // readouts the effects write (button, bodies, flags); state.tick numbers events
  TickSample& feed;             // this tick's record for the tick feeds (a button's click)
  EventQueue& events;
  double t = 0.0;   // session time, s
  double dt = 0.0;  // this tick's period, s
  const ForceResult* contact = nullptr;  // after the proxy moved: its step this tick

  HapticEvent event(EventKind kind) const;  // kind, tick and time filled in
};

class HapticEffect {
 public:
  virtual ~HapticEffect() = default;
  // A scene is adopted (`after_switch`: switched to, not the first): what the effect keeps of
  // the last one starts afresh.
  virtual void restart(const world::HapticScene& scene, bool after_switch) = 0;
  // This tick's force (N, world) into `force_n`; false when the effect does not act this tick
  // (then nothing is added: adding a zero would turn a -0.0 into +0.0 and change a log's bytes).
  virtual bool compute(const EffectTick& tick, glm::dvec3& force_n) = 0;
};

}  // namespace ps
