// The effects that follow the proxy's contact on a surface embedded in 4D (docs/fourd.md), asked
// after the proxy moved (effects/effect.h): sheet crossings (an event, no force) and the force
// suggestion toward the desired state (Hanson & Zhang, eq. 5).
#pragma once

#include "fourd/crossing.h"
#include "haptics/effects/effect.h"

namespace ps {

// Hanson & Zhang §5: a cue each time the proxy's contact point on a surface embedded in 4D passes
// through another sheet of it; sheet_crossing's value is +1 in front of it, -1 behind it.
class CrossingEffect final : public HapticEffect {
 public:
  void restart(const world::HapticScene&, bool) override { crossing_.reset(); }
  bool compute(const EffectTick& tick, glm::dvec3& force_n) override;  // never acts: an event only

 private:
  fourd::CrossingDetector crossing_;
};

// Eq. 5's force suggestion on a fourd sheet, in contact only (zero when off or off the sheet);
// keeps the contact point to difference its velocity, across scene switches too.
class SuggestionEffect final : public HapticEffect {
 public:
  void restart(const world::HapticScene&, bool) override {}
  bool compute(const EffectTick& tick, glm::dvec3& force_n) override;

 private:
  glm::dvec3 last_sheet_point_{0.0};
  bool have_sheet_point_ = false;
};

}  // namespace ps
