// The web core probe (tools/web_core_probe.sh): the default scene's haptic side, driven the way a
// web page would drive it (CatchUpDriver, 90 animation frames of 16.7 ms), prints the final
// state with every digit. Built twice, natively and with Emscripten to WebAssembly run by node;
// the two outputs must be equal. The scene's albedo texture is left out: the probe has no image
// reader (images would be decoded by the page).
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "devices/sample_log.h"
#include "haptics/catch_up.h"
#include "haptics/haptic_loop.h"
#include "scene/lut.h"
#include "scene/scene_io.h"
#include "world/haptic_scene.h"

using namespace ps;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: probe SCENES_DIR\n");
    return 2;
  }
  std::string text(default_scene_text()), kept;
  for (size_t at = 0; at < text.size();) {
    size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(at, end - at);
    if (line.rfind("albedo_texture", 0) != 0) kept += line + "\n";
    at = end + 1;
  }
  auto scene = parse_scene(kept, "<default, untextured>", argv[1], {});
  if (!scene) {
    std::printf("scene: %s\n", scene.error().message.c_str());
    return 1;
  }
  auto haptic = world::HapticScene::build(scene.value());
  if (!haptic) {
    std::printf("haptic scene: %s\n", haptic.error().message.c_str());
    return 1;
  }
  // Down onto the plank, pressing 1 mm into it, then a stroke along x.
  const std::vector<DeviceSample> stroke = {{0.0, {0, 0, 12}, 0, true}, {0.5, {5, 0, 6}, 0, true}, {1.5, {25, 3, 6}, 1, true}};
  LogDevice device(stroke, true, "stroke");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, std::make_shared<const world::HapticScene>(std::move(haptic.value())));
  CatchUpDriver driver(loop, clock);
  for (int i = 0; i < 90; ++i) driver.advance_to(std::chrono::nanoseconds(16'666'667LL * i));
  const HapticState s = loop.state().read();
  std::printf("tick %llu time %.17g proxy %.17g %.17g %.17g force %.17g %.17g %.17g\n",
              static_cast<unsigned long long>(s.tick), s.time_s, s.proxy_mm.x, s.proxy_mm.y, s.proxy_mm.z, s.force_n.x,
              s.force_n.y, s.force_n.z);
  // A lookup table read and evaluated: the number parser differs in WebAssembly (scene/lut.cpp).
  auto lut = read_lut(std::string(argv[1]) + "/../textures/intensity_thesis.lut", LutAxis::kDistanceMm);
  if (!lut) {
    std::printf("lut: %s\n", lut.error().message.c_str());
    return 1;
  }
  std::uint64_t hash = 1469598103934665603ull;  // FNV-1a over every point's bits
  for (const LutPoint& p : lut->points)
    for (double v : {p.x, p.y}) {
      std::uint64_t bits;
      std::memcpy(&bits, &v, sizeof bits);
      for (int b = 0; b < 8; ++b) hash = (hash ^ ((bits >> (8 * b)) & 0xffu)) * 1099511628211ull;
    }
  std::printf("lut %zu points, bits hash %016llx, at 0.37 mm %.17g\n", lut->points.size(),
              static_cast<unsigned long long>(hash), lut_eval(lut.value(), 0.37));
  return 0;
}
