// A device read once a frame (the mouse and the gamepad, devices/glfw_input.h) as the haptic loop
// sees it at 1 kHz: between two readings the hand goes straight from where it was to the newest
// one, at an even pace over as long as the last frame took (at most `max_s`), then waits there.
// The hand follows the readings' polyline one frame behind and never passes a reading.
// Held readings instead (the newest one repeated each tick until the next frame) make the haptic
// loop's filter coast on its velocity past each reading and swing back after it (its velocity
// gain after a long gap is about 1.5 / gap: half a frame's motion and more each way). At 4-10
// frames a second (a heavy scene, a loaded machine) that carried a hovering hand under the flank
// of a hill it passed (docs/window.md, "Between two frames").
#pragma once

#include <glm/glm.hpp>

#include "devices/device.h"

namespace ps {

struct PollStroke {
  DeviceSample to;  // the newest reading (time_s: when it was polled)
  glm::dvec3 from_mm{0.0};
  double from_s = 0.0, to_s = 0.0;  // from_s = to_s: the hand is at the reading

  // Where the hand is at time t (session time, the poll's clock).
  glm::dvec3 at(double t) const;
  // The sample the haptic loop reads at t: the reading, at its place on the way, time t (a new
  // measurement each tick, never before the poll).
  DeviceSample read(double t) const;
  // The hand is at the reading from now on (the app placed it there: HapticLoop::place_hand).
  void snap() {
    from_mm = to.position_mm;
    from_s = to_s;
  }
};

// The way after the reading `s`, polled at now_s; `last` is the way before it, polled at
// last_poll_s. It starts where the hand is on `last` at now_s and lasts now_s - last_poll_s, at
// most max_s. The first reading, a new placement (a clutch: DeviceSample::placements) or no
// time since the last poll: the hand is at the reading.
PollStroke next_stroke(const PollStroke& last, const DeviceSample& s, double now_s, double last_poll_s, double max_s);

}  // namespace ps
