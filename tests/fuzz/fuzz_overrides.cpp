// libFuzzer target: an override file (`--overrides FILE`, saved by `run` and `tune`). Any input
// gives KEY=VALUE lines or an error with a message; the lines are then applied to the default
// scene as the CLI does, which must give a scene or an error with a message.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_util.h"
#include "scene/scene_io.h"
#include "tune/overrides_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = ps::fuzz::write_input(data, size, "fuzz.overrides.toml");
  auto lines = ps::read_overrides(path);
  ps::fuzz::check(lines);
  if (!lines.ok()) return 0;
  ps::fuzz::check(ps::parse_scene(ps::default_scene_text(), "default.toml", PS_FUZZ_SCENES_DIR, lines.value()));
  return 0;
}
