// `maze --resume DIR` after SIGKILL at random moments: the resumed session's summary equals the
// uninterrupted session's apart from the resumed marker, and its log is the killed log's lines,
// one `resumed` line, then the rest of the session. Runs the real `pseudoshadow maze` in child
// processes (no GL).
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "maze/maze_resume.h"
#include "maze/maze_script.h"
#include "maze/maze_summary.h"
#include "maze_test_util.h"

namespace ps::maze {
namespace {

// With kill_after_s >= 0 the child is killed that long after `log` has its first bytes (the
// session's start), not after the spawn: a slow start (an ASan build on loaded cores took more
// than 0.6 s) would otherwise be killed before the session exists, and leave nothing to resume.
int run_child(const std::vector<std::string>& args, double kill_after_s = -1.0, bool* killed = nullptr,
              const std::string& log = "") {
  const pid_t pid = test::spawn(args);
  if (kill_after_s >= 0.0) {
    std::error_code ec;
    for (int ms = 0; !log.empty() && ms < 120000; ms += 5) {
      if (std::filesystem::file_size(log, ec) > 0 && !ec) break;
      if (waitpid(pid, nullptr, WNOHANG) == pid) return -1;  // it ended before its session began
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
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
  // Paced at 16x, the ~40 s session takes ~2.5 s of wall time from its log's first line; kills
  // fall anywhere in it.
  std::mt19937 rng(20261126);
  std::uniform_real_distribution<double> when(0.3, 2.3);
  int resumed = 0;
  for (int k = 0; k < 4; ++k) {
    const double after = when(rng);
    const std::string cut = dir + "/cut" + std::to_string(k);
    bool killed = false;
    run_child(with({"--out", cut, "--pace", "16"}), after, &killed, cut + "/session.jsonl");
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

// A log whose last line was cut off in its write (a power cut, a full disk; here cut by hand in
// the middle of a `branch` line): `summarize` and `--resume` leave that line out with a warning
// instead of failing on it; the resume moves the fragment to session.jsonl.torn and goes on from
// the line before, and the finished log summarizes as the uninterrupted session. A line that is
// not JSON anywhere else is still an error naming file:line.
TEST(MazeResumeTest, ATornLastLineIsLeftOutWithAWarningAndTheSessionGoesOn) {
  const std::string dir = test::temp_dir("resume_torn");
  auto d = load_maze_desc(test::maze_file());
  ASSERT_TRUE(d) << d.error().message;
  const Route route = draw_route(9);
  std::ofstream(dir + "/p.traj") << script_trajectory(d.value(), {choices_with_errors(route, 0, 2), correct_choices(route, 1)}, 100.0);
  ASSERT_EQ(run_child(maze_args({"--maze", test::maze_file(), "--participant", "T", "--seed", "9", "--cues", "on",
                                 "--device", "trajectory:" + dir + "/p.traj", "--out", dir + "/full"})),
            0);
  auto full = summarize_log(dir + "/full/session.jsonl");
  ASSERT_TRUE(full) << full.error().message;
  const auto lines = test::read_lines(dir + "/full/session.jsonl");
  std::size_t k = 0;  // the fifth branch line: cut in its middle
  for (int branches = 0; k < lines.size() && branches < 5; ++k)
    if (nlohmann::json::parse(lines[k])["type"] == "branch") ++branches;
  ASSERT_LT(k, lines.size());
  const std::string cut_at = lines[k - 1].substr(0, lines[k - 1].size() / 2);
  std::filesystem::create_directories(dir + "/cut");
  {
    std::ofstream cut(dir + "/cut/session.jsonl", std::ios::binary);
    for (std::size_t i = 0; i + 1 < k; ++i) cut << lines[i] << "\n";
    cut << cut_at;  // no newline: the write stopped here
  }
  std::filesystem::copy_file(dir + "/full/device.log", dir + "/cut/device.log");
  auto torn = summarize_log(dir + "/cut/session.jsonl");
  ASSERT_TRUE(torn) << torn.error().message;
  EXPECT_NE(torn->torn.find("session.jsonl:" + std::to_string(k) + ": the last line is cut off"), std::string::npos) << torn->torn;
  ASSERT_EQ(run_child(maze_args({"--resume", dir + "/cut"})), 0);
  EXPECT_EQ(test::read_lines(dir + "/cut/session.jsonl.torn"), std::vector<std::string>{cut_at});
  const auto resumed = test::read_lines(dir + "/cut/session.jsonl");
  ASSERT_GT(resumed.size(), k);
  EXPECT_EQ(nlohmann::json::parse(resumed[k - 1])["type"], "resumed") << "the session goes on from the line before the cut";
  auto again = summarize_log(dir + "/cut/session.jsonl");
  ASSERT_TRUE(again) << again.error().message;
  EXPECT_TRUE(again->torn.empty());
  expect_same_session(again.value(), full.value());
  // Not JSON and not last: an error naming the line.
  {
    std::ofstream bad(dir + "/bad.jsonl", std::ios::binary);
    bad << lines[0] << "\n" << cut_at << "\n" << lines[1] << "\n";
  }
  auto bad = summarize_log(dir + "/bad.jsonl");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("bad.jsonl:2: not a maze log line"), std::string::npos) << bad.error().message;
}

// A session whose perfect pass was logged but whose session_end line was not (the process
// stopped in between): it ended by the criterion all the same, so --resume refuses it and writes
// nothing, as for a log with that line.
TEST(MazeResumeTest, APerfectPassWithoutItsSessionEndLineHasNothingToResume) {
  const std::string dir = test::temp_dir("resume_no_end");
  auto d = load_maze_desc(test::maze_file());
  ASSERT_TRUE(d) << d.error().message;
  std::ofstream(dir + "/ok.traj") << script_trajectory(d.value(), {correct_choices(draw_route(4), 0)}, 200.0);
  ASSERT_EQ(run_child(maze_args({"--maze", test::maze_file(), "--participant", "E", "--seed", "4", "--cues", "off",
                                 "--device", "trajectory:" + dir + "/ok.traj", "--out", dir + "/s"})),
            0);
  auto lines = test::read_lines(dir + "/s/session.jsonl");
  ASSERT_EQ(nlohmann::json::parse(lines.back())["type"], "session_end");
  lines.pop_back();
  {
    std::ofstream out(dir + "/s/session.jsonl", std::ios::trunc);
    for (const std::string& l : lines) out << l << "\n";
  }
  auto r = read_resume_point(dir + "/s/session.jsonl");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("the session ended (criterion: pass 1 had every room right"), std::string::npos)
      << r.error().message;
  EXPECT_EQ(run_child(maze_args({"--resume", dir + "/s"})), 1);
  EXPECT_EQ(test::read_lines(dir + "/s/session.jsonl"), lines) << "a refused resume writes nothing";
}

// Where a resumed window session puts the live hand (resume_place): where the participant's own
// path goes next. The session is cut after each room left (its log up to that `branch` line, as a
// kill leaves it); the expected place is read from the scripted path itself, not from the maze's
// geometry: the path passes within 0.5 mm of it between the room left and the next room entered
// (it walks through the hall's door, (0, hall, R + 1), on its way). A place one hall further
// lies 224 mm (a room's pitch) past any point of that stretch, one hall back 140 mm behind it.
// 0.5 mm: the path's points are written with 4 decimals; the stretch is the path's straight
// segments between its way points.
struct PathPoint {
  double t, x, y, z;
};

std::vector<PathPoint> read_path(const std::string& text) {
  std::vector<PathPoint> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    PathPoint p{};
    std::istringstream(line) >> p.t >> p.x >> p.y >> p.z;
    out.push_back(p);
  }
  return out;
}

// The nearest the path comes to `q` between t0 and t1 (its segments, clipped to that time).
double nearest_on_path(const std::vector<PathPoint>& path, const glm::dvec3& q, double t0, double t1) {
  double best = 1e300;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const PathPoint& a = path[i - 1];
    const PathPoint& b = path[i];
    if (b.t < t0 || a.t > t1 || !(b.t > a.t)) continue;
    for (int k = 0; k <= 1000; ++k) {
      const double t = std::clamp(a.t + (b.t - a.t) * k / 1000.0, t0, t1);
      const double u = (t - a.t) / (b.t - a.t);
      const glm::dvec3 p(a.x + u * (b.x - a.x), a.y + u * (b.y - a.y), a.z + u * (b.z - a.z));
      best = std::min(best, glm::length(p - q));
    }
  }
  return best;
}

TEST(MazeResumeTest, TheLiveHandResumesWhereTheParticipantsPathGoesNext) {
  const std::string dir = test::temp_dir("resume_place");
  auto d = load_maze_desc(test::maze_file());
  ASSERT_TRUE(d) << d.error().message;
  const Route route = draw_route(9);
  const std::string text = script_trajectory(d.value(), {choices_with_errors(route, 0, 2), correct_choices(route, 1)}, 100.0);
  std::ofstream(dir + "/p.traj") << text;
  ASSERT_EQ(run_child(maze_args({"--maze", test::maze_file(), "--participant", "P", "--seed", "9", "--cues", "on",
                                 "--device", "trajectory:" + dir + "/p.traj", "--out", dir + "/full"})),
            0);
  const std::vector<PathPoint> path = read_path(text);
  const auto lines = test::read_lines(dir + "/full/session.jsonl");
  // The rooms entered, in order: where each stretch ends.
  std::vector<double> entered;
  for (const std::string& l : lines)
    if (const auto j = nlohmann::json::parse(l); j["type"] == "branch") entered.push_back(j["enter_s"].get<double>());
  ASSERT_EQ(entered.size(), 12u);
  int checked = 0;
  for (std::size_t k = 0, rooms = 0; k < lines.size(); ++k) {
    if (nlohmann::json::parse(lines[k])["type"] != "branch" || ++rooms == entered.size()) continue;
    std::filesystem::create_directories(dir + "/cut");
    std::ofstream cut(dir + "/cut/session.jsonl", std::ios::trunc);
    for (std::size_t i = 0; i <= k; ++i) cut << lines[i] << "\n";
    cut.close();
    auto r = read_resume_point(dir + "/cut/session.jsonl");
    ASSERT_TRUE(r) << r.error().message;
    const glm::dvec3 place = resume_place(d.value(), r.value());
    SCOPED_TRACE(testing::Message() << "cut after room " << rooms << " (left at " << r->time_s << " s)");
    EXPECT_LT(nearest_on_path(path, place, r->time_s, entered[rooms]), 0.5);
    ++checked;
  }
  EXPECT_EQ(checked, 11);
}

}  // namespace
}  // namespace ps::maze
