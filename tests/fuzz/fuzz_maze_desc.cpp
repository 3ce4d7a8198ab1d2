// libFuzzer target: a maze description (`maze --maze FILE`, docs/maze.md). Any input gives a
// description or an error with a message; one that parses also builds its route and the scene
// of its first pass, so the checked values must be usable.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_util.h"
#include "maze/maze.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto desc = ps::maze::parse_maze_desc(text, "fuzz.maze.toml");
  ps::fuzz::check(desc);
  if (!desc.ok()) return 0;
  const ps::maze::Route route = ps::maze::draw_route(desc->seed);
  (void)route.order(0);
  return 0;
}
