// Nothing lost (docs/hardening.md): a writer killed mid-way (SIGKILL, no chance to clean up)
// leaves the previous file intact, and the target is either the old complete file or the new
// complete one - never a torn mix. Same for device recordings, whose ".partial" file keeps
// everything up to the last flush.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "devices/sample_log.h"
#include "image/image.h"

namespace ps {
namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::path(PS_BINARY_DIR) / "test_scratch" / "hardening" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

Image constant_image(int size, float value) {
  Image im;
  im.width = im.height = size;
  im.channels = 3;
  im.pixels.assign(static_cast<size_t>(size) * size * 3, value);
  return im;
}

// Forks a child that runs `work` forever, lets it run `ms`, then SIGKILLs it.
template <class Work>
void kill_mid_way(Work work, int ms) {
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    for (;;) work();
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(ms));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
}

TEST(AtomicWriteTest, KilledImageWriterLeavesACompleteFile) {
  const auto dir = scratch("image");
  const std::string path = (dir / "out.exr").string();
  ASSERT_TRUE(write_image(path, constant_image(64, 0.25f)).ok());
  // 1024^2 float EXR takes tens of ms to write: the kill lands inside a write most times.
  const Image big = constant_image(1024, 0.75f);
  for (int round = 0; round < 5; ++round) {
    kill_mid_way([&] { (void)write_image(path, big); }, 40 + 17 * round);
    auto back = read_image(path);
    ASSERT_TRUE(back.ok()) << back.error().message;
    const bool old_file = back->width == 64 && back->pixels.front() == 0.25f;
    const bool new_file = back->width == 1024 && back->pixels.back() == 0.75f;
    EXPECT_TRUE(old_file || new_file) << "round " << round;
  }
}

TEST(AtomicWriteTest, KilledRecorderKeepsPreviousLogAndFlushedSamples) {
  const auto dir = scratch("recorder");
  const std::string path = (dir / "session.log").string();
  {
    std::ofstream(path) << "0 1 2 3 0\n";  // a previous recording
  }
  kill_mid_way(
      [&] {
        SampleRecorder rec(path);
        for (int i = 0;; ++i) {
          DeviceSample s;
          s.valid = true;
          s.time_s = i * 1e-3;
          s.position_mm = {i * 0.1, 0.0, 5.0};
          rec.append(s);
          if (i % 100 == 99) (void)rec.flush();  // the run loop flushes about once a second
        }
      },
      300);
  auto old_log = load_sample_log(path);
  ASSERT_TRUE(old_log.ok()) << old_log.error().message;
  ASSERT_EQ(old_log->size(), 1u);  // never replaced by a half-written recording
  EXPECT_EQ(old_log->front().position_mm.y, 2.0);
  // The partial file holds whole flushed lines (each flush writes complete lines).
  std::ifstream partial(path + ".partial");
  ASSERT_TRUE(partial.good());
  std::string text((std::istreambuf_iterator<char>(partial)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(text.empty());
  const size_t last_newline = text.rfind('\n');
  auto flushed = parse_sample_log(text.substr(0, last_newline + 1), "partial");
  ASSERT_TRUE(flushed.ok()) << flushed.error().message;
  EXPECT_GE(flushed->size(), 100u);
}

}  // namespace
}  // namespace ps
