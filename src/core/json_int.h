// Integers read from JSON without undefined behaviour. nlohmann::json's get<int>() (and value()
// with an int default) converts a JSON float with static_cast, which is undefined behaviour when
// the float is outside the integer's range (a log line with "seed": 7.7e47, found by fuzz_maze_log)
// and silently truncates 2.5 to 2. These accept a JSON integer in T's range, or a float that is
// a whole number in range (a log edited by hand may write 3.0), and throw std::runtime_error
// naming the key otherwise, which the readers turn into their file:line error.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace ps {

template <class T>
T json_int(const nlohmann::json& v, const std::string& key) {
  static_assert(std::numeric_limits<T>::is_integer);
  const auto bad = [&] { return std::runtime_error("'" + key + "' must be a whole number in range, got " + v.dump()); };
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(std::numeric_limits<T>::max())) throw bad();
    return static_cast<T>(u);
  }
  if (v.is_number_integer()) {
    const auto i = v.get<std::int64_t>();
    if (std::numeric_limits<T>::is_signed ? (i < static_cast<std::int64_t>(std::numeric_limits<T>::min()) ||
                                             (i > 0 && static_cast<std::uint64_t>(i) > static_cast<std::uint64_t>(std::numeric_limits<T>::max())))
                                          : (i < 0 || static_cast<std::uint64_t>(i) > static_cast<std::uint64_t>(std::numeric_limits<T>::max())))
      throw bad();
    return static_cast<T>(i);
  }
  if (v.is_number_float()) {
    const double d = v.get<double>();
    // Within T's range on both sides (2^64 and 2^63 are exact doubles; max() itself may not be).
    const double hi = std::ldexp(1.0, std::numeric_limits<T>::digits);
    const double lo = std::numeric_limits<T>::is_signed ? -hi : 0.0;
    if (!(std::isfinite(d) && d == std::floor(d) && d >= lo && d < hi)) throw bad();
    return static_cast<T>(d);
  }
  throw bad();
}

// j[key] as T, `fallback` when j has no such key.
template <class T>
T json_int_or(const nlohmann::json& j, const std::string& key, T fallback) {
  return j.contains(key) ? json_int<T>(j.at(key), key) : fallback;
}

}  // namespace ps
