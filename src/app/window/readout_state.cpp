#include "app/window/readout_state.h"

#include <algorithm>
#include <cstdio>

namespace ps {

ProbeReadout probe_readout(const ProbeReadoutInput& in) {
  // The proxy held this far from where the hand and the fields put it is held by a surface (a button's face, an edge the
  // contact test left): touching, whatever the contact flag said. 0.05 mm: 0.025 N through the
  // default 0.5 N/mm coupling, below any force a person feels, above the filter's rounding.
  constexpr double kHeldMm = 0.05;
  ProbeReadout r;
  const double hold_mm = glm::length(in.hand_mm + in.field_offset_mm - in.proxy_mm);
  const bool held = !in.catching_up && hold_mm > kHeldMm;
  if (in.in_contact || held) {
    r.state = ProbeState::kTouching;
    r.pressed_mm = glm::length(in.hand_mm - in.proxy_mm);
    r.held_mm = hold_mm;
  } else if (in.distance_mm) {
    // The drawn probe may graze a surface the proxy does not touch (the shadow's distance is
    // measured on the render mesh, the proxy on the haptic geometry): still hovering, at 0.
    r.state = ProbeState::kHovering;
    r.hover_mm = std::max(0.0, *in.distance_mm);
  }
  return r;
}

std::string probe_distance_text(const ProbeReadout& r) {
  if (r.state == ProbeState::kOutOfReach) return "out of reach";
  if (r.state == ProbeState::kTouching) return "touching";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f mm", r.hover_mm);
  return buf;
}

const char* probe_state_name(ProbeState s) {
  switch (s) {
    case ProbeState::kOutOfReach: return "out of reach";
    case ProbeState::kHovering: return "hovering";
    case ProbeState::kTouching: return "touching";
  }
  return "?";
}

}  // namespace ps
