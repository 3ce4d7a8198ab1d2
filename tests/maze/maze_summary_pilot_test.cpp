// `maze summarize` on what pilots leave (docs/maze.md, "Pilots, aborted sessions, duplicates"):
// one aborted session has no group mean (NaN: an empty cell in the CSV files, "—" in
// summary.md, never 0.00) and no plot to draw (each skipped with its reason, no file written);
// the same session given twice is refused naming both logs; a participant's folder and a study
// folder are read as the logs they hold.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "maze/maze_summary.h"
#include "maze_test_util.h"

namespace ps::maze {
namespace {

std::string data(const std::string& name) { return std::string(PS_SOURCE_DIR) + "/tests/maze/data/" + name; }

ParticipantSummary read(const std::string& path) {
  auto p = summarize_log(path);
  EXPECT_TRUE(p) << p.error().message;
  return p.value();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// P4 quit in pass 1 after one room: aborted, so N = 0 in its group, and no pass ended.
TEST(MazeSummaryPilotTest, OneAbortedSessionHasNoMeanAndNoPlot) {
  const std::vector<ParticipantSummary> people = {read(data("p4_cues_on_quit.jsonl"))};
  const auto groups = summarize_groups(people);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].participants, 0);
  EXPECT_EQ(groups[0].excluded, 1);
  EXPECT_TRUE(std::isnan(groups[0].mean_total_time_s));
  EXPECT_TRUE(std::isnan(groups[0].mean_trials_to_criterion));
  EXPECT_TRUE(std::isnan(groups[0].mean_errors[0]));
  const auto notes = group_notes(groups);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "cues_on session 1: N = 0, no mean (1 aborted session left out; --include-aborted counts them)");

  const auto plans = plan_plots(people, groups);
  ASSERT_EQ(plans.size(), 2u);
  EXPECT_EQ(plans[0].note(), "errors_by_room.png skipped: no session in the group means (1 aborted left out; "
                             "--include-aborted counts them)");
  EXPECT_EQ(plans[1].note(), "time_per_trial.png skipped: no completed trials (a trial: one pass through all six rooms)");
  const std::string dir = test::temp_dir("pilot_aborted");
  ASSERT_TRUE(write_tables(dir, people, groups, summarize_retests(people), notes));
  auto plots = write_plots(dir, people, groups);
  ASSERT_TRUE(plots) << plots.error().message;
  for (const char* f : {"errors_by_room.png", "time_per_trial.png", "errors_by_room.png.partial", "time_per_trial.png.partial"})
    EXPECT_FALSE(std::filesystem::exists(dir + "/" + f)) << f << ": nothing to draw, nothing written";

  // groups.csv: every mean an empty cell; the counts stay numbers.
  const auto gc = test::read_lines(dir + "/groups.csv");
  ASSERT_EQ(gc.size(), 2u);
  EXPECT_EQ(gc[1].rfind("cues_on,1,0,0,,,,,,,,,,,,,,,1,,,,,,,", 0), 0u) << gc[1];
  // participants.csv: the rooms never left have no mean time (P4 left only the learning room).
  const auto pc = test::read_lines(dir + "/participants.csv");
  ASSERT_EQ(pc.size(), 2u);
  EXPECT_TRUE(contains(pc[1], ",5.000,,,,,,quit,0")) << pc[1];
  // summary.md: "—" where a mean of nobody stands, never 0.00; the notes listed.
  std::ifstream md_in(dir + "/summary.md");
  const std::string md((std::istreambuf_iterator<char>(md_in)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(contains(md, "| cues_on | 1 | 0 (1) | 0 | — | — | — | — | — | — | — | — |")) << md;
  EXPECT_FALSE(contains(md, "0.00 |")) << md;
  EXPECT_TRUE(contains(md, "## Notes\n\n- cues_on session 1: N = 0")) << md;
}

// Counted with --include-aborted, the same session has a mean (N = 1) and a bar to draw, but
// still no pass: the time plot alone is skipped.
TEST(MazeSummaryPilotTest, AnIncludedAbortedSessionDrawsItsErrorsOnly) {
  const std::vector<ParticipantSummary> people = {read(data("p4_cues_on_quit.jsonl"))};
  const auto groups = summarize_groups(people, true);
  EXPECT_EQ(groups[0].participants, 1);
  EXPECT_DOUBLE_EQ(groups[0].mean_total_time_s, 12.0);
  EXPECT_TRUE(std::isnan(groups[0].mean_room_time_s[1])) << "no one left the texture room";
  const auto plans = plan_plots(people, groups);
  EXPECT_TRUE(plans[0].skipped.empty()) << plans[0].skipped;
  EXPECT_FALSE(plans[1].skipped.empty());
  const std::string dir = test::temp_dir("pilot_included");
  auto plots = write_plots(dir, people, groups);
  ASSERT_TRUE(plots) << plots.error().message;
  EXPECT_GT(std::filesystem::file_size(dir + "/errors_by_room.png"), 1000u);
  EXPECT_FALSE(std::filesystem::exists(dir + "/time_per_trial.png"));
}

TEST(MazeSummaryPilotTest, TheSameSessionTwiceIsRefusedNamingBothLogs) {
  const std::string p1 = data("p1_cues_on.jsonl");
  const std::string dir = test::temp_dir("pilot_twice");
  std::filesystem::copy_file(p1, dir + "/copy.jsonl");
  const auto twice = check_no_duplicates({read(p1), read(dir + "/copy.jsonl")});
  ASSERT_FALSE(twice);
  EXPECT_EQ(twice.error().message, p1 + " and " + dir + "/copy.jsonl are the same session (participant P1, session 1, "
                                        "the same session_start line): give each session once");
  // A retest (session 2) of the same participant is another session.
  EXPECT_TRUE(check_no_duplicates({read(p1), read(data("p1_cues_on_retest.jsonl"))}));
  // Logs with started_at: two runs of P7's session 1 differ by it; a copy does not.
  const std::string start = R"({"type":"session_start","participant":"P7","condition":"cues_on","seed":7,"started_at":")";
  std::ofstream(dir + "/a.jsonl") << start << R"(2025-03-01T10:00:00.000Z","time_s":0})" << "\n";
  std::ofstream(dir + "/b.jsonl") << start << R"(2025-03-01T11:30:00.000Z","time_s":0})" << "\n";
  std::ofstream(dir + "/a_copy.jsonl") << start << R"(2025-03-01T10:00:00.000Z","device":"mouse","time_s":0})" << "\n";
  EXPECT_TRUE(check_no_duplicates({read(dir + "/a.jsonl"), read(dir + "/b.jsonl")}));
  const auto copied = check_no_duplicates({read(dir + "/a.jsonl"), read(dir + "/b.jsonl"), read(dir + "/a_copy.jsonl")});
  ASSERT_FALSE(copied);
  EXPECT_TRUE(contains(copied.error().message, dir + "/a.jsonl and " + dir + "/a_copy.jsonl are the same session "
                                               "(participant P7, session 1, started 2025-03-01T10:00:00.000Z)"))
      << copied.error().message;
}

// A participant's folder (what `maze --out DIR` writes) is its session.jsonl; a study folder is
// each subfolder's, in name order, practice/ never; a folder with no log is a note.
TEST(MazeSummaryPilotTest, FoldersAreReadAsTheLogsTheyHold) {
  const std::string study = test::temp_dir("pilot_folders");
  for (const char* p : {"P02", "P01", "P01/practice"}) std::filesystem::create_directories(study + "/" + p);
  std::filesystem::copy_file(data("p2_cues_off.jsonl"), study + "/P02/session.jsonl");
  std::filesystem::copy_file(data("p1_cues_on.jsonl"), study + "/P01/session.jsonl");
  std::filesystem::copy_file(data("p3_cues_on_cut.jsonl"), study + "/P01/practice/session.jsonl");
  std::filesystem::create_directories(study + "/empty");
  std::ofstream(study + "/notes.txt") << "not a folder of logs\n";
  std::vector<std::string> notes;
  auto one = find_session_logs({study + "/P01"}, notes);
  ASSERT_TRUE(one) << one.error().message;
  EXPECT_EQ(one.value(), (std::vector<std::string>{study + "/P01/session.jsonl"}));
  auto all = find_session_logs({study, data("p4_cues_on_quit.jsonl")}, notes);
  ASSERT_TRUE(all) << all.error().message;
  EXPECT_EQ(all.value(), (std::vector<std::string>{study + "/P01/session.jsonl", study + "/P02/session.jsonl",
                                                   data("p4_cues_on_quit.jsonl")}));
  EXPECT_TRUE(notes.empty());
  auto none = find_session_logs({study + "/empty"}, notes);
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->empty());
  EXPECT_EQ(notes, (std::vector<std::string>{study + "/empty: no session.jsonl in it or in its subfolders: nothing from it"}));
  auto missing = find_session_logs({study + "/P03"}, notes);
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().message,
            study + "/P03: no such file or folder (give session logs, participants' folders or a study folder)");
}

}  // namespace
}  // namespace ps::maze
