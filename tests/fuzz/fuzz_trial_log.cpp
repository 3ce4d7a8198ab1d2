// libFuzzer target: a calibration trial log (`calibrate --resume LOG.csv`). Any input gives
// answers or an error with a message; the answers are then replayed into a calibration as
// --resume does, each giving ok or an error naming its row.
#include <cstddef>
#include <cstdint>
#include <string>

#include "calibrate/calibration.h"
#include "fuzz_util.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto answers = ps::calibrate::parse_trial_log(text, "fuzz.trials.csv");
  ps::fuzz::check(answers);
  if (!answers.ok()) return 0;
  ps::calibrate::Spec spec;
  spec.references = {1.0, 2.0, 4.0, 8.0};
  ps::calibrate::Calibration cal(spec);
  for (const auto& a : answers.value()) {
    if (cal.done()) break;
    const ps::Status s = ps::calibrate::replay_answer(cal, a, "fuzz.trials.csv:row");
    ps::fuzz::check(s);
    if (!s.ok()) break;
  }
  return 0;
}
