// The session log's durability, seen through its system calls (maze/maze_log.h LogSyscalls):
// every line is one write and is synced before append returns. A kill test cannot see a missing
// fsync (the page cache keeps the data), so the calls are counted instead.
#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

#include "maze/maze_log.h"

namespace ps::maze {
namespace {

// Forwards to the real calls and records them in order: "w" per write, "s" per fsync of the
// descriptor that was written.
struct CallTrace {
  std::vector<std::string> calls;
  int written_fd = -1;
  LogSyscalls syscalls() {
    return {[this](int fd, const char* data, std::size_t size) {
              calls.push_back("w");
              written_fd = fd;
              return static_cast<long>(::write(fd, data, size));
            },
            [this](int fd) {
              calls.push_back(fd == written_fd ? "s" : "s(other fd)");
              return ::fsync(fd);
            }};
  }
};

std::string fresh_log(const std::string& name) {
  const std::string path = testing::TempDir() + "/" + name;
  std::filesystem::remove(path);
  return path;
}

TEST(MazeLogTest, EveryLineIsWrittenOnceAndSyncedBeforeAppendReturns) {
  CallTrace trace;
  const std::string path = fresh_log("synced.maze.jsonl");
  auto log = SessionLog::open(path, trace.syscalls());
  ASSERT_TRUE(log) << log.error().message;
  ASSERT_TRUE(log->pass_start(0, {}, 0.0));
  EXPECT_EQ(trace.calls, (std::vector<std::string>{"w", "s"}));  // synced before the next line
  ASSERT_TRUE(log->clutch(1.5, 3.0, {1, 2, 0}, {1, 0, 0}));
  ASSERT_TRUE(log->session_end(EndReason::kQuit, 1, 0, 2.0));
  EXPECT_EQ(trace.calls, (std::vector<std::string>{"w", "s", "w", "s", "w", "s"}));
  EXPECT_EQ(log->lines(), 3);
}

TEST(MazeLogTest, ResumedLogSyncsEveryLineToo) {
  const std::string path = fresh_log("resumed.maze.jsonl");
  { ASSERT_TRUE(SessionLog::open(path)); }
  CallTrace trace;
  auto log = SessionLog::open_existing(path, trace.syscalls());
  ASSERT_TRUE(log) << log.error().message;
  ASSERT_TRUE(log->resumed(1, 0, 0, 0.5, "mouse", "resume1.log"));
  EXPECT_EQ(trace.calls, (std::vector<std::string>{"w", "s"}));
}

// A failed sync is the caller's error, naming the file: the line may not be on disk.
TEST(MazeLogTest, FailedSyncIsReported) {
  CallTrace trace;
  LogSyscalls sys = trace.syscalls();
  sys.fsync = [](int) {
    errno = EIO;
    return -1;
  };
  const std::string path = fresh_log("unsynced.maze.jsonl");
  auto log = SessionLog::open(path, sys);
  ASSERT_TRUE(log);
  const Status s = log->session_end(EndReason::kQuit, 0, 0, 0.0);
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("unsynced.maze.jsonl: cannot sync the session log"), std::string::npos)
      << s.error().message;
}

}  // namespace
}  // namespace ps::maze
