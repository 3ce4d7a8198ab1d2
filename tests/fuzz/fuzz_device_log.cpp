// libFuzzer target: device logs and trajectory files (the text format of recordings), then the
// device sanitizer. Whatever the file holds, what passes the sanitizer must be finite, in time
// order and within the jump bound - the guarantee that bad device data never reaches the proxy.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "devices/sample_log.h"
#include "devices/sanitizer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  auto samples = ps::parse_sample_log(text, "fuzz.log");
  if (!samples.ok()) {
    if (samples.error().message.empty()) __builtin_trap();
    return 0;
  }
  ps::SanitizerParams params;
  ps::DeviceSanitizer sanitizer(params);
  double last_time = -INFINITY;
  for (const ps::DeviceSample& s : samples.value()) {
    const auto out = sanitizer.filter(s);
    if (!out) continue;
    if (!std::isfinite(out->time_s) || out->time_s < last_time) __builtin_trap();
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(out->position_mm[i])) __builtin_trap();
    last_time = out->time_s;
  }
  return 0;
}
