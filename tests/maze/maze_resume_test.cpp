// `maze --resume DIR` after SIGKILL at random moments: the resumed session's summary equals the
// uninterrupted session's apart from the resumed marker, and its log is the killed log's lines,
// one `resumed` line, then the rest of the session. Runs the real `pseudoshadow maze` in child
// processes (no GL).
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <random>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "maze/maze_script.h"
#include "maze/maze_summary.h"
#include "maze_test_util.h"

namespace ps::maze {
namespace {

int run_child(const std::vector<std::string>& args, double kill_after_s = -1.0, bool* killed = nullptr) {
  const pid_t pid = test::spawn(args);
  if (kill_after_s >= 0.0) {
    std::this_thread::sleep_for(std::chrono::duration<double>(kill_after_s));
    kill(pid, SIGKILL);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (killed) *killed = WIFSIGNALED(status);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<std::string> maze_args(std::vector<std::string> rest) {
  std::vector<std::string> a = {std::string(PS_BINARY_DIR) + "/pseudoshadow", "maze", "-q"};
  a.insert(a.end(), rest.begin(), rest.end());
  return a;
}

// Two participants' summaries are the same session: every count equal, every time within 1e-9 s.
// The resumed loop's clock counts on from the session time it stopped at (T + k ms against
// k' ms): the same ticks, rounded differently in the last bits (seen: a few 1e-15 s); a door
// crossed one tick apart would be 1e-3 s and fail.
void expect_same_session(const ParticipantSummary& a, const ParticipantSummary& b) {
  EXPECT_EQ(a.ended, b.ended);
  EXPECT_EQ(a.end_reason, b.end_reason);
  EXPECT_EQ(a.passes, b.passes);
  EXPECT_EQ(a.trials_to_criterion, b.trials_to_criterion);
  EXPECT_EQ(a.trials, b.trials);
  EXPECT_EQ(a.errors, b.errors);
  EXPECT_EQ(a.pass_correct, b.pass_correct);
  EXPECT_NEAR(a.total_time_s, b.total_time_s, 1e-9);
  ASSERT_EQ(a.pass_time_s.size(), b.pass_time_s.size());
  for (std::size_t i = 0; i < a.pass_time_s.size(); ++i) EXPECT_NEAR(a.pass_time_s[i], b.pass_time_s[i], 1e-9) << "pass " << i + 1;
  for (int c = 0; c < kCueCount; ++c) EXPECT_NEAR(a.mean_room_time_s(c), b.mean_room_time_s(c), 1e-9) << cue_name(static_cast<Cue>(c));
}

TEST(MazeResumeTest, KilledAtRandomMomentsThenResumedSummarizesAsTheUninterruptedSession) {
  const std::string dir = test::temp_dir("resume");
  auto d = load_maze_desc(test::maze_file());
  ASSERT_TRUE(d) << d.error().message;
  const Route route = draw_route(9);
  const std::string traj = dir + "/r1.traj";
  std::ofstream(traj) << script_trajectory(d.value(), {choices_with_errors(route, 0, 2), correct_choices(route, 1)}, 100.0);
  const std::vector<std::string> who = {"--maze", test::maze_file(), "--participant", "R1", "--seed", "9", "--cues", "on",
                                        "--device", "trajectory:" + traj,
                                        "--force"};  // the same participant several times in one folder, on purpose
  auto with = [&](std::vector<std::string> more) {
    std::vector<std::string> a = who;
    a.insert(a.end(), more.begin(), more.end());
    return maze_args(a);
  };
  ASSERT_EQ(run_child(with({"--out", dir + "/full"})), 0);
  auto full = summarize_log(dir + "/full/session.jsonl");
  ASSERT_TRUE(full) << full.error().message;
  ASSERT_EQ(full->passes, 2);
  const auto full_lines = test::read_lines(dir + "/full/session.jsonl");
  // Paced at 16x, the ~40 s session takes ~2.5 s of wall time; kills fall anywhere in it.
  std::mt19937 rng(20261126);
  std::uniform_real_distribution<double> when(0.3, 2.3);
  int resumed = 0;
  for (int k = 0; k < 4; ++k) {
    const double after = when(rng);
    const std::string cut = dir + "/cut" + std::to_string(k);
    bool killed = false;
    run_child(with({"--out", cut, "--pace", "16"}), after, &killed);
    if (!killed) continue;  // it finished first: nothing to resume
    const auto before = test::read_lines(cut + "/session.jsonl");
    ASSERT_EQ(run_child(maze_args({"--resume", cut})), 0) << "killed after " << after << " s";
    ++resumed;
    const auto lines = test::read_lines(cut + "/session.jsonl");
    ASSERT_GT(lines.size(), before.size());
    for (std::size_t i = 0; i < before.size(); ++i)
      EXPECT_EQ(test::without_start_time(lines[i]), test::without_start_time(full_lines[i])) << "line " << i + 1;
    EXPECT_EQ(nlohmann::json::parse(lines[before.size()])["type"], "resumed") << "killed after " << after << " s";
    auto again = summarize_log(cut + "/session.jsonl");
    ASSERT_TRUE(again) << again.error().message;
    SCOPED_TRACE("killed after " + std::to_string(after) + " s, at line " + std::to_string(before.size()));
    EXPECT_EQ(again->resumed, 1);
    EXPECT_EQ(full->resumed, 0);
    expect_same_session(again.value(), full.value());
  }
  EXPECT_GE(resumed, 3) << "most kills must land inside the session";
}

TEST(MazeResumeTest, AFinishedSessionHasNothingToResume) {
  const std::string dir = test::temp_dir("resume_done");
  auto d = load_maze_desc(test::maze_file());
  ASSERT_TRUE(d) << d.error().message;
  const std::string traj = dir + "/ok.traj";
  std::ofstream(traj) << script_trajectory(d.value(), {correct_choices(draw_route(4), 0)}, 200.0);
  ASSERT_EQ(run_child(maze_args({"--maze", test::maze_file(), "--participant", "D", "--seed", "4", "--cues", "off",
                                 "--device", "trajectory:" + traj, "--out", dir + "/s"})),
            0);
  const auto before = test::read_lines(dir + "/s/session.jsonl");
  EXPECT_EQ(run_child(maze_args({"--resume", dir + "/s"})), 1);
  EXPECT_EQ(test::read_lines(dir + "/s/session.jsonl"), before) << "a refused resume writes nothing";
}

}  // namespace
}  // namespace ps::maze
