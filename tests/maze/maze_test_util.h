// Helpers shared by the maze tests: the shipped description, a per-test temporary directory
// (unique per process and name: the suite runs tests in parallel), a file's lines (and a line
// without its wall-clock start), a child process running the real program.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <sys/types.h>
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

// A log line without session_start's wall-clock `started_at`: two runs of one session compare
// equal line for line apart from it.
inline std::string without_start_time(const std::string& line) {
  static const std::regex started_at(R"("started_at":"[^"]*",)");
  return std::regex_replace(line, started_at, "");
}

// Starts args[0] (an absolute path) with args in a child process; returns its pid. Its stdout
// and stderr go to the files named, if any.
inline pid_t spawn(const std::vector<std::string>& args, const std::string& out = "", const std::string& err = "") {
  const pid_t pid = fork();
  if (pid == 0) {
    if (!out.empty() && !std::freopen(out.c_str(), "w", stdout)) _exit(126);
    if (!err.empty() && !std::freopen(err.c_str(), "w", stderr)) _exit(126);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

}  // namespace ps::maze::test
