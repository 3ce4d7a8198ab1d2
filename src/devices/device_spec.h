// A device as the command line names it (`run --device`, `maze --device`, `replay --log`),
// parsed once: "mouse", "gamepad", or a log, "trajectory:FILE", "playback:FILE" or
// "pointer:FILE" (docs/haptics.md, "Devices"). What each command does with a kind is its own
// (which kinds it takes, what it opens); the kind is compared as this enum, never as text.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

#include "core/result.h"

namespace ps {

enum class DeviceKind {
  kMouse,       // the window's mouse (GLFW)
  kGamepad,     // the window's gamepad (GLFW)
  kTrajectory,  // a scripted log, positions interpolated between its lines
  kPlayback,    // a recorded log, sample-and-hold
  kPointer,     // a scripted pointer in pixels, mapped through the camera like the mouse
};

struct DeviceSpec {
  DeviceKind kind = DeviceKind::kMouse;
  std::string file;  // the log of trajectory, playback and pointer (never empty); "" for mouse and gamepad

  // A log played by the session (trajectory, playback, pointer), not a device at the window.
  bool is_log() const { return kind != DeviceKind::kMouse && kind != DeviceKind::kGamepad; }
  // The text it was parsed from: "mouse", "trajectory:FILE", ...
  std::string text() const;
};

// "mouse", "gamepad", "trajectory:FILE" (a log's word, as in "trajectory:FILE").
std::string device_form(DeviceKind kind);

inline constexpr std::initializer_list<DeviceKind> kAllDeviceKinds = {
    DeviceKind::kMouse, DeviceKind::kGamepad, DeviceKind::kTrajectory, DeviceKind::kPlayback, DeviceKind::kPointer};
inline constexpr std::initializer_list<DeviceKind> kLogDeviceKinds = {DeviceKind::kTrajectory, DeviceKind::kPlayback,
                                                                      DeviceKind::kPointer};

// `text` as one of the kinds `accepted`; otherwise the error names `text` and the accepted forms:
// "device 'foo': expected mouse, gamepad, trajectory:FILE, playback:FILE or pointer:FILE".
// A log's FILE must not be empty.
Result<DeviceSpec> parse_device_spec(std::string_view text,
                                     std::initializer_list<DeviceKind> accepted = kAllDeviceKinds);
// That error, for a device parsed before and not one of the kinds `accepted` here.
Error device_spec_error(std::string_view text, std::initializer_list<DeviceKind> accepted);

}  // namespace ps
