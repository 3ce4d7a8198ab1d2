// libFuzzer target: a study plan CSV (`maze plan` writes it, `maze --plan FILE` reads a row).
// Any input gives rows or an error with a message; a row is then looked up as `maze` does.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_util.h"
#include "maze/maze_plan.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = ps::fuzz::write_input(data, size, "plan.csv");
  auto rows = ps::maze::read_plan(path);
  ps::fuzz::check(rows);
  if (rows.ok() && !rows->empty())
    ps::fuzz::check(ps::maze::find_plan_row(rows.value(), rows->front().participant, 1, path));
  return 0;
}
