// The probe's state as the window's readouts, its title and `run --readouts-log` say it: one
// state machine, so no two of them can disagree (docs/window.md, "Readouts").
//   out of reach   no contact and no shadowed pixel (beyond the influence distance, off screen)
//   hovering d mm  no contact; d = the smallest probe-surface distance over the shadow (>= 0)
//   touching       the haptic proxy is in contact; pressed p mm = how far the hand is past the
//                  proxy (|hand - proxy|): the pseudo-haptic depth the person pushed in
// Contact decides first, so "out of reach" never comes with contact. Contact is the proxy's: in
// contact, or held away from where the hand (and the fields' pull) would put it: a surface's push
// never reads as hovering.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace ps {

enum class ProbeState { kOutOfReach, kHovering, kTouching };

struct ProbeReadoutInput {
  std::optional<double> distance_mm;  // the frame's smallest shadowed distance; none: no shadow
  bool in_contact = false;            // the haptic proxy touches a surface
  glm::dvec3 hand_mm{0.0};            // the filtered device position (world)
  glm::dvec3 proxy_mm{0.0};           // the proxy (world)
  // Where fields, bodies and walls alone put the proxy from the hand (their force through the
  // coupling: HapticState::field_force_n / k): that offset is no surface's hold.
  glm::dvec3 field_offset_mm{0.0};
  // The proxy is catching up with a hand that jumped (HapticState::proxy_catching_up): held by
  // nothing, so its distance from the hand is no touch.
  bool catching_up = false;
};

struct ProbeReadout {
  ProbeState state = ProbeState::kOutOfReach;
  double hover_mm = 0.0;    // kHovering: distance to the surface, >= 0
  double pressed_mm = 0.0;  // kTouching: the hand's depth past the proxy, >= 0
  // kTouching: the part of pressed_mm the surface holds, |hand + field offset - proxy|: what the
  // hand pushed in. A field that pushes a hovering proxy onto the floor (Field, under a repelling
  // charge) presses it by the field's offset with the hand pushing nothing: held ~0. Equal to
  // pressed_mm in a scene without fields, bodies or walls.
  double held_mm = 0.0;
};

ProbeReadout probe_readout(const ProbeReadoutInput& in);

// "out of reach", "1.2 mm", "touching": the distance line and the window title.
std::string probe_distance_text(const ProbeReadout& r);
// "out of reach", "hovering", "touching": the readouts log's `state`.
const char* probe_state_name(ProbeState s);

}  // namespace ps
