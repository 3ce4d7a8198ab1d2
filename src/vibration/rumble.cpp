#include "vibration/rumble.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <SDL.h>

namespace ps::vibration {

namespace {

std::uint16_t strength(double rms, double full_scale) {
  const double s = std::clamp(rms / full_scale, 0.0, 1.0);
  return static_cast<std::uint16_t>(std::lround(s * 65535.0));
}

}  // namespace

RumbleLevels RumbleEnvelope::next(std::span<const float> chunk) {
  if (chunk.empty()) return {};
  // One-pole low-pass at split_hz (impulse-invariant: a = exp(-2 pi fc / rate)).
  const double a = std::exp(-2.0 * std::numbers::pi * desc_.split_hz / desc_.sample_rate_hz);
  double low2 = 0.0, high2 = 0.0;
  for (float x : chunk) {
    low_state_ = (1.0 - a) * x + a * low_state_;
    const double high = x - low_state_;
    low2 += low_state_ * low_state_;
    high2 += high * high;
  }
  const double n = static_cast<double>(chunk.size());
  return {strength(std::sqrt(low2 / n), desc_.full_scale_rms), strength(std::sqrt(high2 / n), desc_.full_scale_rms)};
}

Result<std::unique_ptr<RumbleOut>> RumbleOut::open(const RumbleDesc& desc) {
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");  // Ctrl+C stays the program's
  if (SDL_InitSubSystem(SDL_INIT_JOYSTICK) != 0) return make_error(std::string("SDL could not start its joysticks: ") + SDL_GetError());
  std::unique_ptr<RumbleOut> out(new RumbleOut(desc));
  const int count = out->open_first();
  if (out->joystick_ == nullptr) {  // the destructor quits the subsystem
    return make_error(count == 0 ? "no gamepad found" : "no gamepad with rumble motors among " + std::to_string(count) + " joystick(s)");
  }
  return out;
}

int RumbleOut::open_first() {
  const int count = SDL_NumJoysticks();
  for (int i = 0; i < count && joystick_ == nullptr; ++i) {
    SDL_Joystick* j = SDL_JoystickOpen(i);
    if (j == nullptr) continue;
    if (SDL_JoystickHasRumble(j) == SDL_TRUE) {
      joystick_ = j;
      const char* name = SDL_JoystickName(j);
      name_ = name != nullptr ? name : "joystick " + std::to_string(i);
    } else {
      SDL_JoystickClose(j);
    }
  }
  return count;
}

bool RumbleOut::attached() {
  SDL_JoystickUpdate();  // notices a pad unplugged (SDL's event loop would, but none runs)
  return joystick_ != nullptr && SDL_JoystickGetAttached(static_cast<SDL_Joystick*>(joystick_)) == SDL_TRUE;
}

bool RumbleOut::reattach() {
  SDL_JoystickUpdate();  // and one plugged in
  if (joystick_ != nullptr) SDL_JoystickClose(static_cast<SDL_Joystick*>(joystick_));
  joystick_ = nullptr;
  last_ = {};
  open_first();
  return joystick_ != nullptr;
}

RumbleOut::~RumbleOut() {  // once per successful SDL_InitSubSystem in open()
  if (joystick_ != nullptr) {
    auto* j = static_cast<SDL_Joystick*>(joystick_);
    SDL_JoystickRumble(j, 0, 0, 0);
    SDL_JoystickClose(j);
  }
  SDL_QuitSubSystem(SDL_INIT_JOYSTICK);
}

void RumbleOut::write(std::span<const float> chunk) {
  const RumbleLevels l = envelope_.next(chunk);
  // Not on a pad that went away (SDL would only answer with an error).
  if (joystick_ == nullptr || SDL_JoystickGetAttached(static_cast<SDL_Joystick*>(joystick_)) != SDL_TRUE) return;
  const bool silent = l.low == 0 && l.high == 0;
  if (silent && last_ == RumbleLevels{}) return;  // already stopped: nothing to renew
  SDL_JoystickRumble(static_cast<SDL_Joystick*>(joystick_), l.low, l.high, silent ? 0 : desc_.hold_ms);
  last_ = l;
}

}  // namespace ps::vibration
