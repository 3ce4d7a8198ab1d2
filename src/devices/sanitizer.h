// Guards the haptic loop against bad device data: NaN/Inf, timestamps going backwards and jumps
// larger than max_jump_mm between consecutive samples. Bad samples are dropped (the loop holds
// the last good one) or clamped, and counted; none reaches the filter or the proxy.
#pragma once

#include <cstdint>
#include <optional>

#include "devices/device.h"

namespace ps {

struct SanitizerParams {
  double max_jump_mm = 5.0;  // per sample (1 ms): 5 m/s, faster than any hand
};

struct SanitizerCounts {
  std::uint64_t non_finite = 0;      // dropped: NaN/Inf time or position
  std::uint64_t time_backwards = 0;  // dropped: time earlier than the last good sample
  std::uint64_t jumps_clamped = 0;   // kept, moved max_jump_mm toward the reported position
  std::uint64_t invalid = 0;         // dropped: device said valid = false
  std::uint64_t total() const { return non_finite + time_backwards + jumps_clamped + invalid; }
};

class DeviceSanitizer {
 public:
  explicit DeviceSanitizer(const SanitizerParams& params = {}) : params_(params) {}
  // The sample to use, or nullopt to hold the previous one.
  std::optional<DeviceSample> filter(const DeviceSample& in);
  const SanitizerCounts& counts() const { return counts_; }
  // Forgets the last good sample (counts kept): the device was put somewhere on purpose (a
  // placement, HapticLoop::place_hand), so the next sample is no jump to clamp.
  void restart() { last_.reset(); }

 private:
  SanitizerParams params_;
  SanitizerCounts counts_;
  std::optional<DeviceSample> last_;
};

}  // namespace ps
