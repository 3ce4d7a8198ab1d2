// `study summarize`'s files (study_summary.h) for both tasks, and experiment files mangled at
// random: every one either loads or is refused with a "file:line: " message, never a crash.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
#include <sstream>

#include "study/experiment.h"
#include "study/study_run.h"
#include "study/study_summary.h"

#include "study/study_test_files.h"

namespace ps::study {
namespace {

using test_files::kStudies;
using test_files::read_text;

int count_lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

// Three participants of `name` run and summarized into DIR/summary; returns DIR.
std::string run_three(const std::string& name, std::vector<std::string>& notes) {
  const std::string dir = std::string(PS_BINARY_DIR) + "/tests/study/summaries/" + name;
  std::filesystem::remove_all(dir);
  const Experiment e = load_experiment(kStudies + name + ".toml").value();
  std::vector<ParticipantResult> people;
  for (const char* p : {"P01", "P02", "P03"}) {
    RunSpec s;
    s.participant = p;
    s.out_dir = dir + "/runs";
    EXPECT_TRUE(run_participant(e, s));
  }
  const auto logs = find_trial_logs({dir + "/runs"});
  EXPECT_TRUE(logs);
  EXPECT_EQ(logs->size(), 3u);
  for (const std::string& log : logs.value()) people.push_back(summarize_participant(log, {100, 1}).value());
  EXPECT_TRUE(write_study_summary(dir + "/summary", people, notes));
  return dir + "/summary/";
}

TEST(StudySummaryTest, ThresholdTablesSummaryAndPlot) {
  std::vector<std::string> notes;
  const std::string out = run_three("lambda_threshold", notes);
  const std::string participants = read_text(out + "participants.csv");
  EXPECT_EQ(count_lines(participants), 1 + 3 * 2);  // header, 3 participants x 2 conditions
  EXPECT_EQ(participants.rfind("participant,condition,trials,complete,threshold,threshold_low,threshold_high,slope,", 0), 0u);
  EXPECT_NE(participants.find(",criterion,threshold_cred_low,threshold_cred_high,slope_cred_low,slope_cred_high,"
                              "weber_cred_low,weber_cred_high\n"),
            std::string::npos);
  EXPECT_NE(participants.find("\nP03,stroke_17,60,yes,"), std::string::npos);
  const std::string groups = read_text(out + "groups.csv");
  EXPECT_EQ(count_lines(groups), 1 + 2 * 3);  // 2 conditions x threshold, slope, weber
  EXPECT_NE(groups.find("\nstroke_33,threshold,3,"), std::string::npos);
  EXPECT_NE(read_text(out + "summary.md").find("# lambda_threshold: summary"), std::string::npos);
  const bool gnuplot = std::system("command -v gnuplot > /dev/null 2>&1") == 0;
  EXPECT_EQ(std::filesystem::exists(out + "psychometric.png"), gnuplot);
  if (gnuplot) {  // the simulated participants' own function beside the fits (their session_start's observer)
    EXPECT_NE(read_text(out + "psychometric.gp").find("0.5 + (1 - 0.5 - 0.02) * (x > 0 ? 1 - exp(-(x / 0.1) ** 3) : 0) lc black"),
              std::string::npos);
  } else {
    EXPECT_NE(notes.at(0).find("psychometric.png skipped: gnuplot not found"), std::string::npos);
  }
  EXPECT_NE(read_text(out + "summary.md").find("\n3 participants, task"), std::string::npos);
  // One participant: the count in the singular, and why the intervals over participants are empty.
  const auto logs = find_trial_logs({out + "../runs"});
  ASSERT_TRUE(logs);
  const std::vector<ParticipantResult> one{summarize_participant(logs->at(0), {100, 1}).value()};
  std::vector<std::string> one_notes;
  ASSERT_TRUE(write_study_summary(out + "../one", one, one_notes));
  const std::string md = read_text(out + "../one/summary.md");
  EXPECT_NE(md.find("\n1 participant, task"), std::string::npos);
  EXPECT_NE(md.find("a t interval needs two"), std::string::npos);
}

TEST(StudySummaryTest, IdentificationTablesAndConfusionPlot) {
  std::vector<std::string> notes;
  const std::string out = run_three("identification", notes);
  const std::string participants = read_text(out + "participants.csv");
  EXPECT_EQ(count_lines(participants), 1 + 3);
  EXPECT_NE(participants.find("percent_correct,information_bits,miller_madow_bits,corrected_bits,distinguishable"),
            std::string::npos);
  EXPECT_NE(participants.find("\nP01,main,96,yes,"), std::string::npos);
  EXPECT_NE(read_text(out + "groups.csv").find("\nmain,corrected_bits,3,"), std::string::npos);
  const bool gnuplot = std::system("command -v gnuplot > /dev/null 2>&1") == 0;
  EXPECT_EQ(std::filesystem::exists(out + "confusion.png"), gnuplot);
}

// Bytes flipped, lines cut and duplicated in the shipped files: each result is a loaded
// experiment or a one-line error naming the file and a line.
TEST(ExperimentFuzzTest, MangledFilesLoadOrNameALine) {
  std::mt19937_64 rng(47);
  const std::regex located("^fuzz\\.toml:[0-9]+: [^\n]+$");
  int refused = 0, loaded = 0;
  for (const char* name : {"lambda_threshold", "theta_threshold", "distance_threshold", "identification", "targeting"}) {
    const std::string text = read_text(kStudies + name + ".toml");
    for (int i = 0; i < 500; ++i) {
      std::string t = text;
      for (int k = 0; k < 1 + static_cast<int>(rng() % 4); ++k) {
        const std::size_t at = rng() % t.size();
        switch (rng() % 4) {
          case 0: t[at] = static_cast<char>(rng() % 128); break;       // a byte changed
          case 1: t.erase(at, rng() % 20); break;                     // some bytes gone
          case 2: t.insert(at, t.substr(rng() % t.size(), 30)); break; // a piece repeated
          default: t.resize(at); break;                                // cut short
        }
        if (t.empty()) t = "x";
      }
      const Result<Experiment> e = parse_experiment(t, "fuzz.toml");
      if (e) {
        ++loaded;
        continue;
      }
      ++refused;
      EXPECT_TRUE(std::regex_match(e.error().message, located)) << e.error().message;
    }
  }
  EXPECT_GT(refused, 1000);  // the mangling does reach the checks
  EXPECT_GT(loaded, 10);     // and some mangled files are still experiments (comments, spaces)
}

}  // namespace
}  // namespace ps::study
