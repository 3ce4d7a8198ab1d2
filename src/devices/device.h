// Haptic/pointing input devices behind one interface. read() runs on the haptic thread at
// 1 kHz; write_force() hands back the force (devices without actuators ignore it).
// Units: positions in mm (scene space), time in s since the start of the session.
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace ps {

struct DeviceSample {
  double time_s = 0.0;             // session time of the sample
  glm::dvec3 position_mm{0.0};
  std::uint32_t buttons = 0;       // bit i = button i held
  bool valid = false;              // false: the device has nothing (yet)
  // How many times the device has put its hand somewhere new itself, no motion of the person's
  // (the maze window's clutch puts the mouse's hand back under the probe): the haptic loop
  // restarts its filter at the first sample with a new count, so the jump is not taken for a
  // motion and carried on past the new place (HapticLoop::read_device).
  std::uint32_t placements = 0;
};

class Device {
 public:
  virtual ~Device() = default;
  // Haptic thread: the newest sample at session time now_s.
  virtual DeviceSample read(double now_s) = 0;
  // Haptic thread: force on the user's hand, N.
  virtual void write_force(const glm::dvec3& force_n) {}
  // Length of a scripted/recorded session in s; < 0 for live devices.
  virtual double duration_s() const { return -1.0; }
  virtual std::string name() const = 0;
};

}  // namespace ps
