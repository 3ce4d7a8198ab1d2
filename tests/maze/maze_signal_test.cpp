// `pseudoshadow maze` stopped by a signal (docs/maze.md, "A signal"): SIGTERM, SIGINT or SIGHUP
// ends the session through its normal end: the log's last line is session_end with reason
// `terminated`, the device stream is closed (device.log, no .partial), one line on stderr says
// where the log is and how to resume, the exit status is 128 + the signal's number, and
// `maze --resume` goes on from there to the same session as an uninterrupted run. Runs the real
// program in child processes (headless, paced; no GL).
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <sstream>
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

std::vector<std::string> maze_args(const std::vector<std::string>& rest) {
  std::vector<std::string> a = {std::string(PS_BINARY_DIR) + "/pseudoshadow", "maze"};
  a.insert(a.end(), rest.begin(), rest.end());
  return a;
}

int wait_status(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Fixture {
  std::string dir, traj;
  std::vector<std::string> who;
};

// A scripted participant of seed 9 (pass 1 with two wrong rooms, pass 2 right: ~40 s of session).
Fixture make_fixture(const std::string& name) {
  Fixture f;
  f.dir = test::temp_dir(name);
  auto d = load_maze_desc(test::maze_file());
  EXPECT_TRUE(d) << d.error().message;
  const Route route = draw_route(9);
  f.traj = f.dir + "/s1.traj";
  std::ofstream(f.traj) << script_trajectory(d.value(), {choices_with_errors(route, 0, 2), correct_choices(route, 1)}, 100.0);
  f.who = {"--maze", test::maze_file(), "--participant", "S1", "--seed", "9", "--cues", "on",
           "--device", "trajectory:" + f.traj,
           "--force"};  // the same participant several times in one folder, on purpose
  return f;
}

// Starts a paced session into `out` and sends `signo` once its log has `lines` lines and its
// device stream one flush (a second of session time); returns the wait status.
int signal_session(const Fixture& f, const std::string& out, int signo, std::size_t lines) {
  std::vector<std::string> args = f.who;
  args.insert(args.end(), {"--out", out, "--pace", "4"});  // ~10 s of wall time: signalled mid-way
  const pid_t pid = test::spawn(maze_args(args), out + ".stdout", out + ".stderr");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while ((test::read_lines(out + "/session.jsonl").size() < lines || !std::filesystem::exists(out + "/device.log.partial")) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(kill(pid, signo), 0);
  return wait_status(pid);
}

// `maze --resume DIR` goes on from the terminated session (its log `before` lines long) to the
// uninterrupted session's end.
void expect_resumes_to(const std::string& dir, std::size_t before, const ParticipantSummary& full) {
  ASSERT_EQ(wait_status(test::spawn(maze_args({"--resume", dir, "-q"}))), 0);
  const auto resumed = test::read_lines(dir + "/session.jsonl");
  ASSERT_GT(resumed.size(), before);
  EXPECT_EQ(nlohmann::json::parse(resumed[before])["type"], "resumed");
  auto again = summarize_log(dir + "/session.jsonl");
  ASSERT_TRUE(again) << again.error().message;
  EXPECT_EQ(again->end_reason_or_crashed(), "criterion");
  EXPECT_EQ(again->resumed, 1);
  EXPECT_EQ(again->passes, full.passes);
  EXPECT_EQ(again->errors, full.errors);
  EXPECT_EQ(again->pass_correct, full.pass_correct);
  EXPECT_NEAR(again->total_time_s, full.total_time_s, 1e-9);
}

TEST(MazeSignalTest, SigtermEndsTheSessionAsTerminatedAndResumeGoesOn) {
  const Fixture f = make_fixture("signal");
  std::vector<std::string> uninterrupted = f.who;
  uninterrupted.insert(uninterrupted.end(), {"--out", f.dir + "/full", "-q"});
  ASSERT_EQ(wait_status(test::spawn(maze_args(uninterrupted))), 0);
  auto full = summarize_log(f.dir + "/full/session.jsonl");
  ASSERT_TRUE(full) << full.error().message;
  ASSERT_EQ(full->passes, 2);

  const std::string cut = f.dir + "/cut";
  const int status = signal_session(f, cut, SIGTERM, 8);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by the signal instead of ending the session";
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
  const auto lines = test::read_lines(cut + "/session.jsonl");
  ASSERT_GE(lines.size(), 9u);
  const auto last = nlohmann::json::parse(lines.back());
  EXPECT_EQ(last["type"], "session_end");
  EXPECT_EQ(last["reason"], "terminated");
  EXPECT_LT(last["passes"].get<int>(), 2) << "signalled before the end";
  EXPECT_EQ(read_text(cut + ".stderr"), "maze: terminated by SIGTERM; log flushed to " + cut +
                                            "/session.jsonl; resume with: pseudoshadow maze --resume " + cut + "\n");
  // The device stream closed as at any end: renamed into place, whole samples.
  EXPECT_FALSE(std::filesystem::exists(cut + "/device.log.partial"));
  auto samples = load_sample_log(cut + "/device.log");
  ASSERT_TRUE(samples) << samples.error().message;
  EXPECT_GE(samples->size(), 1000u);
  auto terminated = summarize_log(cut + "/session.jsonl");
  ASSERT_TRUE(terminated) << terminated.error().message;
  EXPECT_TRUE(terminated->ended);
  EXPECT_EQ(terminated->end_reason_or_crashed(), "terminated");
  EXPECT_TRUE(terminated->aborted());

  expect_resumes_to(cut, lines.size(), full.value());
}

// SIGINT (Ctrl+C) and SIGHUP (the terminal closed) end it the same way, each with its own status.
TEST(MazeSignalTest, SigintAndSighupEndTheSessionToo) {
  const Fixture f = make_fixture("signal_int_hup");
  for (const int signo : {SIGINT, SIGHUP}) {
    const std::string out = f.dir + "/s" + std::to_string(signo);
    const int status = signal_session(f, out, signo, 4);
    ASSERT_TRUE(WIFEXITED(status)) << "signal " << signo;
    EXPECT_EQ(WEXITSTATUS(status), 128 + signo);
    const auto lines = test::read_lines(out + "/session.jsonl");
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(nlohmann::json::parse(lines.back())["reason"], "terminated") << "signal " << signo;
    EXPECT_NE(read_text(out + ".stderr").find(signo == SIGINT ? "terminated by SIGINT" : "terminated by SIGHUP"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace ps::maze
