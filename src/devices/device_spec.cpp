#include "devices/device_spec.h"

namespace ps {

namespace {

// The word of each kind, as written before a log's colon or alone.
const char* kind_word(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::kMouse: return "mouse";
    case DeviceKind::kGamepad: return "gamepad";
    case DeviceKind::kTrajectory: return "trajectory";
    case DeviceKind::kPlayback: return "playback";
    case DeviceKind::kPointer: return "pointer";
  }
  return "?";
}

bool is_log_kind(DeviceKind kind) { return DeviceSpec{kind, {}}.is_log(); }

// "a", "a or b", "a, b or c".
std::string forms_of(std::initializer_list<DeviceKind> kinds) {
  std::string s;
  std::size_t i = 0;
  for (DeviceKind k : kinds) {
    s += (i == 0 ? "" : i + 1 == kinds.size() ? " or " : ", ") + device_form(k);
    ++i;
  }
  return s;
}

}  // namespace

std::string device_form(DeviceKind kind) {
  return std::string(kind_word(kind)) + (is_log_kind(kind) ? ":FILE" : "");
}

std::string DeviceSpec::text() const { return is_log() ? std::string(kind_word(kind)) + ":" + file : kind_word(kind); }

Result<DeviceSpec> parse_device_spec(std::string_view text, std::initializer_list<DeviceKind> accepted) {
  const std::size_t colon = text.find(':');
  const std::string_view word = text.substr(0, colon);
  for (DeviceKind k : accepted) {
    if (word != kind_word(k)) continue;
    const bool has_file = colon != std::string_view::npos;
    DeviceSpec spec{k, has_file ? std::string(text.substr(colon + 1)) : std::string()};
    // A log needs its FILE; mouse and gamepad take none (not even an empty one).
    if (spec.is_log() ? !spec.file.empty() : !has_file) return spec;
  }
  return device_spec_error(text, accepted);
}

Error device_spec_error(std::string_view text, std::initializer_list<DeviceKind> accepted) {
  return make_error("device '" + std::string(text) + "': expected " + forms_of(accepted));
}

}  // namespace ps
