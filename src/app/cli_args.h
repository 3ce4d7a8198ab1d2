// Small helpers for the CLI's hand-written argument parsing (no exceptions, clear messages).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"

namespace ps::cli {

// "1,2,3" -> three finite doubles; the message names the option and shows an example.
Result<glm::dvec3> parse_vec3(std::string_view option, std::string_view text, std::string_view example);
// "512x384" -> (512, 384), each in [1, max_side] and w*h <= max_pixels.
Result<glm::ivec2> parse_size(std::string_view text, int max_side, long long max_pixels);
// Whole positive number in [lo, hi].
Result<long long> parse_int(std::string_view option, std::string_view text, long long lo, long long hi);

// Walks argv: `take(value)` for options with a value (supports "--opt value" and "--opt=value").
class ArgCursor {
 public:
  ArgCursor(int argc, char** argv, int first) : args_(argv + first, argv + argc) {}
  bool done() const { return i_ >= args_.size(); }
  std::string_view peek() const { return args_[i_]; }
  // If the current argument is `name` (or `name=...`), consumes it and its value.
  // Returns nullopt if it is not this option; an Error if the value is missing.
  std::optional<Result<std::string>> option(std::string_view name);
  bool flag(std::string_view name);
  std::string_view next() { return args_[i_++]; }

 private:
  std::vector<std::string_view> args_;
  size_t i_ = 0;
};

}  // namespace ps::cli
