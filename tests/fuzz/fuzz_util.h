// Shared by the fuzz targets whose parser reads a file by name: the input written to a scratch
// file of this process (removed at exit), and the one rule every target checks.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/result.h"

namespace ps::fuzz {

// A scratch directory of this process, removed when the process ends.
inline const std::filesystem::path& scratch_dir() {
  struct Dir {
    std::filesystem::path path;
    ~Dir() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Dir dir{[] {
    auto p = std::filesystem::temp_directory_path() / ("ps_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    return p;
  }()};
  return dir.path;
}

// The input as the file `name` in the scratch directory; returns its path.
inline std::string write_input(const std::uint8_t* data, std::size_t size, const std::string& name) {
  const std::filesystem::path p = scratch_dir() / name;
  std::ofstream(p, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                              static_cast<std::streamsize>(size));
  return p.string();
}

// Every error must say something: an empty message is a bug.
template <typename T>
void check(const Result<T>& r) {
  if (!r.ok() && r.error().message.empty()) __builtin_trap();
}

}  // namespace ps::fuzz
