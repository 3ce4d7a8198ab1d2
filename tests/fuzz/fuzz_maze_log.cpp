// libFuzzer target: a maze session log (JSON lines), read back by `maze summarize` and by
// `maze --resume`. Any input gives a summary / resume point or an error with a message.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_util.h"
#include "maze/maze_resume.h"
#include "maze/maze_summary.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = ps::fuzz::write_input(data, size, "session.jsonl");
  ps::fuzz::check(ps::maze::summarize_log(path));
  ps::fuzz::check(ps::maze::read_resume_point(path));
  return 0;
}
