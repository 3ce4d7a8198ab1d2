// libFuzzer target: a lookup table (materials.NAME.intensity_lut / speed_gain_lut). Any input
// gives a table or an error with a message; a table's rows must be finite, in range and
// increasing in x, as the format promises (scene/lut.h), and evaluate to a value in [0, 1].
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_util.h"
#include "scene/lut.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto lut = ps::parse_lut(text, "fuzz.lut");
  ps::fuzz::check(lut);
  if (!lut.ok()) return 0;
  double last = -1.0;
  for (const ps::LutPoint& p : lut->points) {
    if (!std::isfinite(p.x) || !(p.x > last) || !(p.y >= 0.0 && p.y <= 1.0)) __builtin_trap();
    last = p.x;
  }
  return 0;
}
