// `maze summarize` on small logs written by hand (tests/maze/data): every number of the tables
// equals the one worked out by hand in the comments below (to 1e-12: sums and means of a few
// decimals); a log cut short (no session_end) still counts what it holds; the retest (session 2)
// is compared with session 1; bad lines are file:line errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <fstream>

#include "maze/maze_summary.h"
#include "maze_test_util.h"

namespace ps::maze {
namespace {

std::string data(const std::string& name) { return std::string(PS_SOURCE_DIR) + "/tests/maze/data/" + name; }
constexpr std::size_t kNone = 0, kTexture = 1, kViscosity = 2, kElastic = 3, kHidden = 4, kExternal = 5;

std::vector<ParticipantSummary> three() {
  std::vector<ParticipantSummary> people;
  for (const char* f : {"p1_cues_on.jsonl", "p2_cues_off.jsonl", "p3_cues_on_cut.jsonl"}) {
    auto p = summarize_log(data(f));
    EXPECT_TRUE(p) << p.error().message;
    people.push_back(p.value());
  }
  return people;
}

TEST(MazeSummaryTest, ParticipantNumbersEqualTheHandComputedOnes) {
  const auto people = three();
  const ParticipantSummary& p1 = people[0];
  EXPECT_EQ(p1.participant, "P1");
  EXPECT_EQ(p1.condition, "cues_on");
  EXPECT_EQ(p1.seed, 3u);
  EXPECT_EQ(p1.passes, 2);
  EXPECT_EQ(p1.trials_to_criterion, 2);
  EXPECT_TRUE(p1.ended);
  EXPECT_DOUBLE_EQ(p1.total_time_s, 40.0);
  // Pass 1 wrong in texture and elastic; pass 2 all right.
  EXPECT_EQ(p1.errors, (std::array<int, 6>{0, 1, 0, 1, 0, 0}));
  EXPECT_EQ(p1.trials, (std::array<int, 6>{2, 2, 2, 2, 2, 2}));
  // Room times (pass 1 + pass 2) / 2: none (2 + 1.5) / 2, texture (3 + 2) / 2, viscosity (4 + 3)
  // / 2, elastic (2.5 + 2) / 2, hidden (3.5 + 3) / 2, external (3 + 2.5) / 2.
  const double want[6] = {1.75, 2.5, 3.5, 2.25, 3.25, 2.75};
  for (int c = 0; c < 6; ++c) EXPECT_NEAR(p1.mean_room_time_s(c), want[c], 1e-12) << c;
  EXPECT_EQ(p1.pass_time_s, (std::vector<double>{20.0, 16.0}));
  EXPECT_EQ(p1.pass_correct, (std::vector<int>{4, 6}));
  // P3 was cut short after one pass and one room of the next: no criterion, its last time.
  const ParticipantSummary& p3 = people[2];
  EXPECT_FALSE(p3.ended);
  EXPECT_EQ(p3.passes, 1);
  EXPECT_EQ(p3.trials_to_criterion, 0);
  EXPECT_DOUBLE_EQ(p3.total_time_s, 30.0);
  EXPECT_EQ(p3.errors, (std::array<int, 6>{1, 1, 0, 0, 0, 0}));
  EXPECT_NEAR(p3.mean_room_time_s(static_cast<int>(kNone)), 1.5, 1e-12);  // (2 + 1) / 2
}

// With the aborted P3 counted (--include-aborted), as before the exclusion rule.
TEST(MazeSummaryTest, GroupNumbersEqualTheHandComputedOnes) {
  const auto groups = summarize_groups(three(), true);
  ASSERT_EQ(groups.size(), 2u);
  const GroupSummary& on = groups[0];  // P1 and P3
  EXPECT_EQ(on.condition, "cues_on");
  EXPECT_EQ(on.participants, 2);
  EXPECT_EQ(on.reached_criterion, 1);
  EXPECT_DOUBLE_EQ(on.mean_trials_to_criterion, 2.0);
  EXPECT_DOUBLE_EQ(on.mean_total_time_s, 35.0);  // (40 + 30) / 2
  EXPECT_DOUBLE_EQ(on.mean_errors[kNone], 0.5);  // (0 + 1) / 2
  EXPECT_DOUBLE_EQ(on.mean_errors[kTexture], 1.0);  // (1 + 1) / 2
  EXPECT_DOUBLE_EQ(on.mean_errors[kElastic], 0.5);
  EXPECT_DOUBLE_EQ(on.mean_errors[kViscosity], 0.0);
  EXPECT_NEAR(on.mean_room_time_s[kNone], 1.625, 1e-12);  // (1.75 + 1.5) / 2
  EXPECT_NEAR(on.mean_room_time_s[kTexture], 2.25, 1e-12);  // (2.5 + 2) / 2
  EXPECT_NEAR(on.mean_room_time_s[kViscosity], 2.75, 1e-12);  // (3.5 + 2) / 2
  EXPECT_EQ(on.mean_pass_time_s, (std::vector<double>{17.0, 16.0}));  // (20 + 14) / 2; P1 alone
  const GroupSummary& off = groups[1];  // P2
  EXPECT_EQ(off.participants, 1);
  EXPECT_DOUBLE_EQ(off.mean_errors[kTexture], 1.0);
  EXPECT_DOUBLE_EQ(off.mean_errors[kExternal], 1.0);
  EXPECT_DOUBLE_EQ(off.mean_errors[kHidden], 0.0);
  EXPECT_NEAR(off.mean_room_time_s[kTexture], 1.75, 1e-12);  // (2 + 1.5) / 2
  EXPECT_DOUBLE_EQ(off.mean_total_time_s, 20.0);
}

TEST(MazeSummaryTest, TablesAndPlotsAreWritten) {
  const auto people = three();
  const auto groups = summarize_groups(people, true);
  const std::string dir = test::temp_dir("summary_tables");
  ASSERT_TRUE(write_tables(dir, people, groups, summarize_retests(people)));
  const auto groups_csv = test::read_lines(dir + "/groups.csv");
  ASSERT_EQ(groups_csv.size(), 3u);
  EXPECT_EQ(groups_csv[1].rfind("cues_on,1,2,1,2.000,35.000,0.500,1.000,0.000,0.500,0.000,0.000,1.625,2.250,2.750,", 0), 0u)
      << groups_csv[1];
  const auto trials = test::read_lines(dir + "/trials.csv");
  EXPECT_EQ(trials.size(), 1u + 2 + 2 + 1);
  auto plots = write_plots(dir, people, groups);
  ASSERT_TRUE(plots) << plots.error().message;
  for (const char* png : {"/errors_by_room.png", "/time_per_trial.png"})
    EXPECT_GT(std::filesystem::file_size(dir + png), 1000u) << png;
}

// The retest of Sepulveda-Cervantes et al. §VII: P1 (cues on) took 40 s, then 30 s in
// session 2: faster; P2 (cues off) 20 s, then 25 s: slower; P3 was cut short (no complete first
// session): not counted. The retest sessions form groups of their own (session 2), not mixed
// into session 1's means.
TEST(MazeSummaryTest, RetestComparesSessionTwoWithSessionOne) {
  auto people = three();
  for (const char* f : {"p1_cues_on_retest.jsonl", "p2_cues_off_retest.jsonl"}) {
    auto p = summarize_log(data(f));
    ASSERT_TRUE(p) << p.error().message;
    EXPECT_EQ(p->session, 2);
    people.push_back(p.value());
  }
  EXPECT_EQ(people[0].session, 1);  // logs without the field are first sessions
  const auto retests = summarize_retests(people);
  ASSERT_EQ(retests.size(), 2u);
  EXPECT_EQ(retests[0].condition, "cues_on");
  EXPECT_EQ(retests[0].retested, 1);
  EXPECT_EQ(retests[0].faster, 1);
  EXPECT_EQ(retests[1].condition, "cues_off");
  EXPECT_EQ(retests[1].retested, 1);
  EXPECT_EQ(retests[1].faster, 0);
  const auto groups = summarize_groups(people, true);
  ASSERT_EQ(groups.size(), 4u);
  EXPECT_EQ(groups[0].session, 1);
  EXPECT_DOUBLE_EQ(groups[0].mean_total_time_s, 35.0);  // session 1 of cues_on as before: (40 + 30) / 2
  EXPECT_EQ(groups[2].condition, "cues_on");
  EXPECT_EQ(groups[2].session, 2);
  EXPECT_DOUBLE_EQ(groups[2].mean_total_time_s, 30.0);
  EXPECT_DOUBLE_EQ(groups[3].mean_errors[kElastic], 1.0);  // P2's retest: one wrong exit in the elastic room
  const std::string dir = test::temp_dir("summary_retest");
  ASSERT_TRUE(write_tables(dir, people, groups, retests));
  EXPECT_EQ(test::read_lines(dir + "/retest.csv"),
            (std::vector<std::string>{"condition,retested,faster_on_retest,share_faster", "cues_on,1,1,1.000",
                                      "cues_off,1,0,0.000"}));
}

// Five cues-on sessions' worth of rules: P1 (criterion), P3 (cut short: crashed), P4 (quit), P5
// (resumed once, then criterion). By default the aborted P3 and P4 are left out of the means:
// N = 2 (P1, P5). 95 % CI half width for two values a, b: t(0.975, 1) sd / sqrt(2) with
// sd = |a - b| / sqrt(2), i.e. t |a - b| / 2 with t = tan(0.475 pi) = 12.7062: one degree of
// freedom's t is Cauchy, whose quantile is tan(pi (p - 1/2)).
const double kT1 = std::tan(0.475 * std::numbers::pi);

TEST(MazeSummaryTest, AbortedSessionsLeaveTheMeansAndEndReasonsAreReported) {
  std::vector<ParticipantSummary> people;
  for (const char* f : {"p1_cues_on.jsonl", "p3_cues_on_cut.jsonl", "p4_cues_on_quit.jsonl", "p5_cues_on_resumed.jsonl"}) {
    auto p = summarize_log(data(f));
    ASSERT_TRUE(p) << p.error().message;
    people.push_back(p.value());
  }
  EXPECT_EQ(people[3].resumed, 1);
  EXPECT_TRUE(people[3].ended);
  EXPECT_FALSE(people[3].aborted());
  EXPECT_EQ(people[3].total_time_s, 30.0);
  EXPECT_TRUE(people[1].aborted());
  EXPECT_TRUE(people[2].aborted());
  const auto groups = summarize_groups(people);
  ASSERT_EQ(groups.size(), 1u);
  const GroupSummary& g = groups[0];
  EXPECT_EQ(g.participants, 2);
  EXPECT_EQ(g.excluded, 2);
  EXPECT_EQ(g.reached_criterion, 2);
  EXPECT_DOUBLE_EQ(g.mean_trials_to_criterion, 1.5);  // (2 + 1) / 2
  EXPECT_DOUBLE_EQ(g.mean_total_time_s, 35.0);       // (40 + 30) / 2
  EXPECT_NEAR(g.ci_total_time_s, kT1 * 10.0 / 2.0, 1e-9);
  EXPECT_DOUBLE_EQ(g.mean_errors[kTexture], 0.5);  // (1 + 0) / 2
  EXPECT_NEAR(g.ci_errors[kTexture], kT1 * 1.0 / 2.0, 1e-9);
  EXPECT_EQ(g.mean_pass_time_s, (std::vector<double>{24.0, 16.0}));  // (20 + 28) / 2; P1 alone
  EXPECT_NEAR(g.ci_pass_time_s[0], kT1 * 8.0 / 2.0, 1e-9);
  EXPECT_TRUE(std::isnan(g.ci_pass_time_s[1])) << "one participant: no interval";
  EXPECT_EQ(g.pass_n, (std::vector<int>{2, 1}));
  const auto all = summarize_groups(people, true);
  EXPECT_EQ(all[0].participants, 4);
  EXPECT_EQ(all[0].excluded, 0);
  EXPECT_DOUBLE_EQ(all[0].mean_total_time_s, 28.0);  // (40 + 30 + 12 + 30) / 4
  const std::string dir = test::temp_dir("summary_aborted");
  ASSERT_TRUE(write_tables(dir, people, groups, summarize_retests(people)));
  const auto pc = test::read_lines(dir + "/participants.csv");
  ASSERT_EQ(pc.size(), 5u);
  EXPECT_NE(pc[0].find(",end_reason,resumed"), std::string::npos) << pc[0];
  const char* ends[4] = {",criterion,0", ",crashed,0", ",quit,0", ",criterion,1"};
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(pc[i + 1].substr(pc[i + 1].size() - std::string(ends[i]).size()), ends[i]) << pc[i + 1];
  const auto gc = test::read_lines(dir + "/groups.csv");
  EXPECT_EQ(gc[1].rfind("cues_on,1,2,2,1.500,35.000,", 0), 0u) << gc[1];
  EXPECT_NE(gc[1].find(",2,63.531,"), std::string::npos) << "excluded, then the CI of the total time (12.7062 x 5): " << gc[1];
  const auto rooms = test::read_lines(dir + "/rooms.csv");
  EXPECT_EQ(rooms.size(), 1u + 12 + 7 + 1 + 6);  // every branch line of the four logs
  EXPECT_EQ(rooms[0], "participant,condition,session,pass,room,cue,exit,correct,time_s,path_mm,contacts_floor,"
                      "contacts_wall,contacts_ceiling,contacts_hidden");
  EXPECT_EQ(rooms[21], "P5,cues_on,1,1,1,none,straight,yes,2.000,120.50,1,2,0,0");
}

TEST(MazeSummaryTest, BadLinesNameFileAndLine) {
  const std::string dir = test::temp_dir("summary_bad");
  std::ofstream(dir + "/bad.jsonl") << R"({"type":"session_start","participant":"X","condition":"cues_on","seed":1})"
                                    << "\n{not json\n";
  auto r = summarize_log(dir + "/bad.jsonl");
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("bad.jsonl:2: not a maze log line"), std::string::npos) << r.error().message;
  std::ofstream(dir + "/first.jsonl") << R"({"type":"branch","cue":"none","correct":true,"room_time_s":1})" << "\n";
  auto f = summarize_log(dir + "/first.jsonl");
  ASSERT_FALSE(f);
  EXPECT_NE(f.error().message.find("first.jsonl:1: "), std::string::npos) << f.error().message;
}

// A number where a whole number belongs: fuzz_maze_log's finding ("seed": 7.7e47 was converted to
// an integer by a cast that is undefined behaviour out of range), and a fraction or a negative
// count that the cast used to truncate or wrap. Each is refused at file:line, naming the key; a
// whole number written as a float (3.0, as a hand-edited log may have it) is still read.
TEST(MazeSummaryTest, NumbersThatAreNoWholeNumbersInRangeAreRefusedAtFileLine) {
  const std::string dir = test::temp_dir("summary_ints");
  const std::string start = R"({"type":"session_start","participant":"X","condition":"cues_on","seed":)";
  const std::pair<const char*, const char*> cases[] = {
      {"7.77e47}", "'seed' must be a whole number in range, got 7.77e+47"},
      {"-1}", "'seed' must be a whole number in range, got -1"},
      {"2.5}", "'seed' must be a whole number in range, got 2.5"},
      {R"(1, "session": 1e300})", "'session' must be a whole number in range"},
      {R"(1, "session": 4294967296})", "'session' must be a whole number in range"}};
  for (const auto& [tail, message] : cases) {
    std::ofstream(dir + "/n.jsonl") << start << tail << "\n";
    auto r = summarize_log(dir + "/n.jsonl");
    ASSERT_FALSE(r) << tail;
    EXPECT_NE(r.error().message.find("n.jsonl:1: "), std::string::npos) << r.error().message;
    EXPECT_NE(r.error().message.find(message), std::string::npos) << r.error().message;
  }
  std::ofstream(dir + "/ok.jsonl") << start << R"(3.0, "session": 2})" << "\n";
  auto ok = summarize_log(dir + "/ok.jsonl");
  ASSERT_TRUE(ok) << ok.error().message;
  EXPECT_EQ(ok->seed, 3u);
  EXPECT_EQ(ok->session, 2);
}

}  // namespace
}  // namespace ps::maze
