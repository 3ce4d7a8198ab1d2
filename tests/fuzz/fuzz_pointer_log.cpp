// libFuzzer target: a scripted pointer log (`--device pointer:FILE`), then the device sanitizer
// as the haptic loop runs it. Any input gives samples or an error with a message; whatever the
// sanitizer passes on is finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "devices/sample_log.h"
#include "devices/sanitizer.h"
#include "fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto samples = ps::parse_pointer_log(text, "fuzz.ptr");
  ps::fuzz::check(samples);
  if (!samples.ok()) return 0;
  ps::DeviceSanitizer sanitizer;
  for (const ps::DeviceSample& s : samples.value()) {
    const auto out = sanitizer.filter(s);
    if (out && (!std::isfinite(out->time_s) || !std::isfinite(out->position_mm.x) ||
                !std::isfinite(out->position_mm.y) || !std::isfinite(out->position_mm.z)))
      __builtin_trap();
  }
  return 0;
}
