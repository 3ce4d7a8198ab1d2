// Helpers shared by the maze tests: the shipped description, a per-test temporary directory
// (unique per process and name: the suite runs tests in parallel), a file's lines.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace ps::maze::test {

inline std::string maze_file() { return std::string(PS_SOURCE_DIR) + "/scenes/maze/maze.toml"; }

inline std::string temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("ps_maze_test_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

inline std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

}  // namespace ps::maze::test
