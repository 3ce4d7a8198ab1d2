// A maze session killed mid-way (SIGKILL: no destructor, no flush at exit) leaves a session log
// of complete lines up to the last one written, and they are exactly the first lines of the
// same session run to its end; the device stream's ".partial" holds whole samples up to its last
// flush and replays. Runs the real `pseudoshadow maze` in a child process (no GL: no frames).
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "devices/sample_log.h"
#include "maze/maze_script.h"
#include "maze/maze_summary.h"
#include "maze_test_util.h"

namespace ps::maze {
namespace {

std::vector<std::string> session_args(const std::string& traj, const std::string& out, bool paced) {
  std::vector<std::string> a = {std::string(PS_BINARY_DIR) + "/pseudoshadow", "maze", "--maze", test::maze_file(),
                                "--participant", "K1", "--seed", "9", "--cues", "on",
                                "--device", "trajectory:" + traj, "--out", out, "-q",
                                "--force"};  // the same participant twice in one folder, on purpose
  if (paced) a.insert(a.end(), {"--pace", "4"});  // ~4 x real time: slow enough to be killed mid-way
  return a;
}

int wait_exit(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

TEST(MazeKillTest, KilledSessionLeavesACompleteLogUpToTheLastLine) {
  const std::string dir = test::temp_dir("kill");
  auto d = load_maze_desc(test::maze_file());
  ASSERT_TRUE(d) << d.error().message;
  const Route route = draw_route(9);
  const std::string traj = dir + "/k1.traj";
  std::ofstream(traj) << script_trajectory(d.value(), {choices_with_errors(route, 0, 2), correct_choices(route, 1)}, 100.0);
  // The whole session, unpaced, for reference.
  ASSERT_EQ(wait_exit(test::spawn(session_args(traj, dir + "/full", false))), 0);
  const auto full = test::read_lines(dir + "/full/session.jsonl");
  ASSERT_GT(full.size(), 20u);
  // The same session paced, killed once its log has 10 lines (about 8 s of session, 2 s of wall
  // time: rooms 1 to 4 of pass 1).
  const std::string cut = dir + "/cut";
  const pid_t pid = test::spawn(session_args(traj, cut, true));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (test::read_lines(cut + "/session.jsonl").size() < 10 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // past a device-stream flush or two
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  const int status = wait_exit(pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the session ended before it was killed: make it longer";
  std::ifstream in(cut + "/session.jsonl", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(bytes.empty());
  EXPECT_EQ(bytes.back(), '\n') << "the last line is whole";
  const auto lines = test::read_lines(cut + "/session.jsonl");
  ASSERT_GE(lines.size(), 10u);
  ASSERT_LT(lines.size(), full.size()) << "killed before the end";
  for (std::size_t i = 0; i < lines.size(); ++i) {
    EXPECT_TRUE(nlohmann::json::accept(lines[i])) << "line " << i + 1;
    EXPECT_EQ(test::without_start_time(lines[i]), test::without_start_time(full[i]))
        << "line " << i + 1 << " differs from the uninterrupted session's";
  }
  EXPECT_NE(nlohmann::json::parse(lines.back())["type"], "session_end");
  auto summary = summarize_log(cut + "/session.jsonl");
  ASSERT_TRUE(summary) << summary.error().message;
  EXPECT_FALSE(summary->ended);
  // The device stream: not published (no rename), its partial file whole samples up to a flush.
  EXPECT_FALSE(std::filesystem::exists(cut + "/device.log"));
  auto samples = load_sample_log(cut + "/device.log.partial");
  ASSERT_TRUE(samples) << samples.error().message;
  EXPECT_GE(samples->size(), 1000u);  // at least one flush: 1 s of session at 1 kHz
  EXPECT_EQ(samples->size() % 1000, 0u) << "flushed once per second of session time, whole seconds only";
}

}  // namespace
}  // namespace ps::maze
