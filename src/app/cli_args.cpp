#include "app/cli_args.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace ps::cli {

namespace {
bool parse_double(std::string_view s, double& out) {
  if (s.empty()) return false;
  const std::string tmp(s);
  char* end = nullptr;
  out = std::strtod(tmp.c_str(), &end);
  return end == tmp.c_str() + tmp.size();
}
}  // namespace

Result<glm::dvec3> parse_vec3(std::string_view option, std::string_view text, std::string_view example) {
  glm::dvec3 v(0.0);
  size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const size_t comma = text.find(',', start);
    const bool last = i == 2;
    if ((comma == std::string_view::npos) != last)
      return make_error(std::string(option) + ": expected three comma-separated numbers, e.g. " +
                        std::string(option) + " " + std::string(example));
    const std::string_view part = text.substr(start, last ? std::string_view::npos : comma - start);
    if (!parse_double(part, v[i]))
      return make_error(std::string(option) + ": '" + std::string(part) + "' is not a number (e.g. " +
                        std::string(option) + " " + std::string(example) + ")");
    if (!std::isfinite(v[i]))
      return make_error(std::string(option) + ": component " + std::to_string(i + 1) + " is " +
                        std::string(part) + "; NaN and Inf are rejected (give finite numbers)");
    start = comma + 1;
  }
  return v;
}

Result<long long> parse_int(std::string_view option, std::string_view text, long long lo, long long hi) {
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size())
    return make_error(std::string(option) + ": '" + std::string(text) + "' is not a whole number");
  if (v < lo || v > hi)
    return make_error(std::string(option) + ": " + std::string(text) + " is outside [" +
                      std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

Result<glm::ivec2> parse_size(std::string_view text, int max_side, long long max_pixels) {
  const size_t x = text.find('x');
  if (x == std::string_view::npos)
    return make_error("--size: expected WIDTHxHEIGHT, e.g. --size 512x512");
  auto w = parse_int("--size width", text.substr(0, x), 1, 1LL << 40);
  auto h = parse_int("--size height", text.substr(x + 1), 1, 1LL << 40);
  if (!w) return w.error();
  if (!h) return h.error();
  if (w.value() > max_side || h.value() > max_side || w.value() * h.value() > max_pixels)
    return make_error("--size " + std::string(text) + " refused: the limit is " + std::to_string(max_side) +
                      " pixels per side and " + std::to_string(max_pixels) + " pixels in all");
  return glm::ivec2(static_cast<int>(w.value()), static_cast<int>(h.value()));
}

std::optional<Result<std::string>> ArgCursor::option(std::string_view name) {
  if (done()) return std::nullopt;
  const std::string_view a = args_[i_];
  if (a == name) {
    if (i_ + 1 >= args_.size()) return Result<std::string>(make_error(std::string(name) + " needs a value"));
    i_ += 2;
    return Result<std::string>(std::string(args_[i_ - 1]));
  }
  if (a.size() > name.size() && a.substr(0, name.size()) == name && a[name.size()] == '=') {
    ++i_;
    return Result<std::string>(std::string(a.substr(name.size() + 1)));
  }
  return std::nullopt;
}

bool ArgCursor::flag(std::string_view name) {
  if (done() || args_[i_] != name) return false;
  ++i_;
  return true;
}

}  // namespace ps::cli
