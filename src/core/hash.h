// FNV-1a, 64 bits: names for cached files (button pictures, field maps), not a security measure.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace ps {

inline constexpr std::uint64_t kFnv1aOffset = 14695981039346656037ull;

inline std::uint64_t fnv1a(const void* data, std::size_t n, std::uint64_t h = kFnv1aOffset) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}

inline std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = kFnv1aOffset) {
  return fnv1a(bytes.data(), bytes.size(), h);
}

}  // namespace ps
