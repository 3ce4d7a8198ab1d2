// The vibration on a gamepad's rumble motors, through SDL2's joystick API (libsdl2-dev). A
// gamepad has two motors, a heavy low-frequency one and a light high-frequency one; they take a
// strength, not a waveform. Each chunk of the signal (vibration/signal.h) sets them: the low
// motor from the chunk's RMS below split_hz (a one-pole low-pass), the high motor from the RMS
// above it, each full_scale_rms -> full strength, held for hold_ms (refreshed every chunk, so
// a stalled program stops rumbling by itself). A silent chunk stops both motors.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "core/result.h"

namespace ps::vibration {

struct RumbleDesc {
  int sample_rate_hz = 48000;
  double split_hz = 150.0;       // low motor below, high motor above
  double full_scale_rms = 0.25;  // RMS that drives a motor at full strength
  std::uint32_t hold_ms = 100;   // each setting lasts this long unless renewed
};

struct RumbleLevels {
  std::uint16_t low = 0, high = 0;  // SDL's motor strengths, 0 .. 65535
  bool operator==(const RumbleLevels&) const = default;
};

// The band split of one chunk, a pure function of the chunk and the low-pass state carried
// from the previous chunk (tests compute the WAV's envelope with it).
class RumbleEnvelope {
 public:
  explicit RumbleEnvelope(const RumbleDesc& desc) : desc_(desc) {}
  RumbleLevels next(std::span<const float> chunk);

 private:
  RumbleDesc desc_;
  double low_state_ = 0.0;
};

class RumbleOut {
 public:
  // The first joystick SDL finds that can rumble (SDL_Init(SDL_INIT_JOYSTICK)). Errors: SDL
  // fails to start, no joystick, none with rumble.
  static Result<std::unique_ptr<RumbleOut>> open(const RumbleDesc& desc);
  ~RumbleOut();
  RumbleOut(const RumbleOut&) = delete;
  RumbleOut& operator=(const RumbleOut&) = delete;

  void write(std::span<const float> chunk);  // any one thread
  // False once the gamepad is unplugged (SDL's joystick state, updated here: nothing else pumps
  // SDL's events). The same thread as write().
  bool attached();
  // After attached() said false: opens the first joystick with rumble SDL finds now (the same
  // pad plugged back, or another); true if one was found. The same thread as write().
  bool reattach();
  const std::string& name() const { return name_; }
  RumbleLevels last() const { return last_; }

 private:
  RumbleOut(const RumbleDesc& desc) : envelope_(desc), desc_(desc) {}
  int open_first();  // opens the first joystick with rumble into joystick_; returns the count seen
  void* joystick_ = nullptr;  // SDL_Joystick*, kept out of this header
  RumbleEnvelope envelope_;
  RumbleDesc desc_;
  RumbleLevels last_;
  std::string name_;
};

}  // namespace ps::vibration
