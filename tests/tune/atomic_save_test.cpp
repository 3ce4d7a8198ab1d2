// The override file is replaced atomically: a writer killed by SIGKILL in the middle of a
// huge write leaves the old file intact (and the new one complete or absent).
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <sstream>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>

#include "tune/overrides_file.h"

namespace ps {
namespace {

std::string read_all(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(AtomicSaveTest, KillDuringWriteKeepsTheOldFile) {
  const std::string path = testing::TempDir() + "/killed.overrides.toml";
  const std::string old_text = "probe.radius_mm = 3\n";
  ASSERT_TRUE(write_file_atomic(path, old_text));
  // 128 MiB: long enough (hundreds of ms) for the parent's SIGKILL to land mid-write.
  const std::string line = "materials.wood.lambda_min = 0.40000000000000000000000000\n";
  std::string huge;
  huge.reserve(128u << 20);
  while (huge.size() < (128u << 20)) huge += line;
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    (void)write_file_atomic(path, huge);
    _exit(0);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  kill(child, SIGKILL);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  const std::string now = read_all(path);
  // Either the child was killed first (old file) or it finished (complete new file).
  EXPECT_TRUE(now == old_text || now == huge) << "partial file of " << now.size() << " bytes";
  if (WIFSIGNALED(status)) {
    EXPECT_EQ(now, old_text);
  }
  unlink((path + "." + std::to_string(child) + ".tmp").c_str());  // the killed writer's leftover
}

}  // namespace
}  // namespace ps
