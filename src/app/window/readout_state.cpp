#include "app/window/readout_state.h"

#include <algorithm>
#include <cstdio>

namespace ps {

ProbeReadout probe_readout(const ProbeReadoutInput& in) {
  ProbeReadout r;
  if (in.in_contact) {
    r.state = ProbeState::kTouching;
    r.pressed_mm = glm::length(in.hand_mm - in.proxy_mm);
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
