// libFuzzer target: a maze description (`maze --maze FILE`, docs/maze.md). Any input gives a
// description or an error with a message.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_util.h"
#include "maze/maze.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto desc = ps::maze::parse_maze_desc(text, "fuzz.maze.toml");
  ps::fuzz::check(desc);
  return 0;
}
