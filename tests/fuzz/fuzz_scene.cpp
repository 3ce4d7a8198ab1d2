// libFuzzer target: scene files and --set overrides. Lines of the input that start with
// "#set " are also passed as --set KEY=VALUE overrides, so the fuzzer explores both parsers.
// Any input must give a Scene or an Error with a message - never a crash, hang or leak.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "scene/mesh.h"
#include "scene/scene_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> overrides;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("#set ", 0) == 0) overrides.push_back(line.substr(5));
  auto scene = ps::parse_scene(text, "fuzz.toml", PS_FUZZ_SCENES_DIR, overrides);
  if (!scene.ok()) {
    if (scene.error().message.empty()) __builtin_trap();  // every error must say something
    return 0;
  }
  // Tessellate the cheap procedural surfaces too: the converter's values must be usable.
  for (const ps::Surface& s : scene->surfaces) {
    if (s.type == ps::SurfaceType::kMesh || s.resolution > 64) continue;
    auto mesh = ps::build_surface_mesh(s);
    if (!mesh.ok() && mesh.error().message.empty()) __builtin_trap();
  }
  return 0;
}
