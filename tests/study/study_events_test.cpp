// A session's BIDS-style events.tsv and its JSON sidecar (src/study/study_events.h): simulated
// sessions of both tasks run through `study run`'s code, their events written as `study summarize`
// writes them, then read back here on their own (split on tabs, the sidecar parsed) and held
// against the trial log line by line; a member the log lacks is n/a; a changed log, a session not
// ended and a torn one write none.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "study/experiment.h"
#include "study/study_events.h"
#include "study/study_log.h"
#include "study/study_run.h"

#include "study/study_test_files.h"

namespace ps::study {
namespace {

using test_files::kStudies;
using test_files::read_text;
using test_files::fresh_dir;

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::string::size_type from = 0;
  for (std::string::size_type at; (at = text.find(sep, from)) != std::string::npos; from = at + 1)
    out.push_back(text.substr(from, at - from));
  out.push_back(text.substr(from));
  return out;
}

// The log's trial lines, parsed here (not through read_trial_log).
std::vector<nlohmann::json> trial_lines(const std::string& log) {
  std::vector<nlohmann::json> out;
  std::istringstream in(read_text(log));
  for (std::string l; std::getline(in, l);)
    if (const nlohmann::json j = nlohmann::json::parse(l); j.at("type") == "trial") out.push_back(j);
  return out;
}

// What a log member should read as in a cell: 1/0 for true/false, numbers as JSON writes them.
std::string as_cell(const nlohmann::json& v) {
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

// Runs `participant` of the experiment whole into DIR/runs and writes its events; returns the log.
std::string run_session(const std::string& experiment, const std::string& dir, const std::string& participant,
                        int stop_after = 0) {
  const Experiment e = load_experiment(kStudies + experiment + ".toml").value();
  RunSpec s;
  s.participant = participant;
  s.out_dir = dir + "/runs";
  s.stop_after = stop_after;
  const Result<RunReport> r = run_participant(e, s);
  EXPECT_TRUE(r) << (r ? "" : r.error().message);
  return dir + "/runs/" + participant + "/trials.jsonl";
}

std::vector<std::string> events_files(const std::string& folder) {
  std::vector<std::string> out;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().filename().string().find("_events.") != std::string::npos) out.push_back(entry.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// The events of `log` read back and checked against the log: the header, one row per trial,
// onsets, no empty cell, n/a for what the log lacks, every cell equal to its trial's member, and
// the sidecar describing exactly the table's columns. Returns the table's columns.
std::vector<std::string> check_events(const std::string& log, const std::string& stem, const std::vector<std::string>& own) {
  const Result<EventsFiles> f = write_session_events(log);
  EXPECT_TRUE(f) << (f ? "" : f.error().message);
  if (!f) return {};
  const std::string folder = std::filesystem::path(log).parent_path().string();
  EXPECT_EQ(f->tsv, folder + "/" + stem + ".tsv");
  EXPECT_EQ(f->json, folder + "/" + stem + ".json");
  const std::string tsv = read_text(f->tsv);
  EXPECT_FALSE(tsv.empty());
  EXPECT_EQ(tsv.back(), '\n');
  EXPECT_EQ(tsv.find('\r'), std::string::npos);
  std::vector<std::string> lines = split(tsv, '\n');
  lines.pop_back();  // after the last newline
  EXPECT_EQ(lines.at(0).rfind("onset\tduration\ttrial_type\t", 0), 0u) << lines.at(0);
  const std::vector<std::string> header = split(lines.at(0), '\t');
  for (const std::string& c : own) EXPECT_NE(std::find(header.begin(), header.end(), c), header.end()) << c;
  EXPECT_EQ(std::set<std::string>(header.begin(), header.end()).size(), header.size()) << "a column named twice";

  // One row per trial line of the log, counted here from its text.
  const std::vector<nlohmann::json> trials = trial_lines(log);
  const std::string text = read_text(log);
  std::size_t counted = 0;
  for (std::string::size_type at = 0; (at = text.find("{\"type\":\"trial\",", at)) != std::string::npos; ++at) ++counted;
  EXPECT_EQ(trials.size(), counted);
  EXPECT_EQ(lines.size(), 1 + counted);

  double last_onset = 0.0;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    const std::vector<std::string> row = split(lines[r], '\t');
    EXPECT_EQ(row.size(), header.size()) << "row " << r;
    if (row.size() != header.size()) continue;
    for (const std::string& c : row) EXPECT_FALSE(c.empty()) << "row " << r;
    const double onset = std::stod(row[0]);
    EXPECT_GE(onset, 0.0);
    EXPECT_GE(onset, last_onset) << "row " << r;
    last_onset = onset;
    EXPECT_EQ(row[1], "n/a");  // the simulated run logs no durations
    const nlohmann::json& trial = trials[r - 1];
    EXPECT_EQ(row[2], trial.at("condition").get<std::string>());
    EXPECT_DOUBLE_EQ(onset, (trial.at("trial").get<double>() - 1) * kSimulatedTrialSeconds);
    for (std::size_t c = 3; c < header.size(); ++c)
      EXPECT_EQ(row[c], trial.contains(header[c]) ? as_cell(trial.at(header[c])) : "n/a") << "row " << r << ", " << header[c];
  }

  // The sidecar: an object whose members are exactly the columns, each described.
  const nlohmann::json side = nlohmann::json::parse(read_text(f->json));
  EXPECT_TRUE(side.is_object());
  std::set<std::string> described;
  for (const auto& [name, d] : side.items()) {
    described.insert(name);
    EXPECT_TRUE(d.contains("LongName") && d.at("LongName").is_string()) << name;
    EXPECT_TRUE(d.contains("Description") && !d.at("Description").get<std::string>().empty()) << name;
  }
  EXPECT_EQ(described, std::set<std::string>(header.begin(), header.end()));
  EXPECT_EQ(side.at("onset").at("Units"), "s");
  EXPECT_EQ(side.at("duration").at("Units"), "s");
  EXPECT_EQ(side.at("correct").at("Levels").at("1"), "correct");
  EXPECT_EQ(side.at("correct").at("Levels").at("0"), "wrong");
  // Every value of a categorical column is one of its Levels.
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (!side.at(header[c]).contains("Levels")) continue;
    const nlohmann::json& levels = side.at(header[c]).at("Levels");
    for (std::size_t r = 1; r < lines.size(); ++r)
      EXPECT_TRUE(levels.contains(split(lines[r], '\t')[c])) << header[c] << " row " << r;
  }
  return header;
}

TEST(StudyEventsTest, BidsLabelsKeepLettersAndDigitsOnly) {
  EXPECT_EQ(bids_label("lambda_threshold"), "lambdaThreshold");
  EXPECT_EQ(bids_label("P01"), "P01");
  EXPECT_EQ(bids_label("two words-and_more"), "twoWordsAndMore");
  EXPECT_EQ(bids_label("_x"), "x");
  EXPECT_EQ(bids_label("__"), "");
}

TEST(StudyEventsTest, AThresholdSessionsEventsMatchItsLog) {
  const std::string dir = fresh_dir("events", "threshold");
  const std::string log = run_session("lambda_threshold", dir, "P02");
  const std::vector<std::string> header = check_events(
      log, "sub-P02_task-lambdaThreshold_events",
      {"trial", "practice", "block", "level", "reference", "comparison", "interval", "response", "key", "correct"});
  EXPECT_EQ(header.size(), 13u);
  // Practice trials are in the table (the log's first 4), at block 0.
  const std::vector<std::string> lines = split(read_text(std::filesystem::path(log).parent_path() / "sub-P02_task-lambdaThreshold_events.tsv"), '\n');
  EXPECT_EQ(split(lines.at(1), '\t').at(4), "1");  // practice
  EXPECT_EQ(split(lines.at(5), '\t').at(4), "0");
  // Written again from the same log, the files are the same bytes.
  const std::string tsv = read_text(std::filesystem::path(log).parent_path() / "sub-P02_task-lambdaThreshold_events.tsv");
  ASSERT_TRUE(write_session_events(log));
  EXPECT_EQ(read_text(std::filesystem::path(log).parent_path() / "sub-P02_task-lambdaThreshold_events.tsv"), tsv);
}

TEST(StudyEventsTest, AnIdentificationSessionsEventsMatchItsLog) {
  const std::string dir = fresh_dir("events", "identification");
  const std::string log = run_session("identification", dir, "P01");
  check_events(log, "sub-P01_task-identification_events",
               {"trial", "practice", "block", "shown", "shown_index", "answered", "answered_index", "key", "correct"});
}

TEST(StudyEventsTest, AResumedSessionsEventsEqualAnUnbrokenOnes) {
  const std::string dir = fresh_dir("events", "resumed");
  run_session("theta_threshold", dir + "/a", "P01");
  run_session("theta_threshold", dir + "/b", "P01", 30);
  const std::string log = run_session("theta_threshold", dir + "/b", "P01");
  const std::string stem = "sub-P01_task-thetaThreshold_events";
  check_events(dir + "/a/runs/P01/trials.jsonl", stem, {"level", "correct"});
  check_events(log, stem, {"level", "correct"});
  EXPECT_EQ(read_text(dir + "/a/runs/P01/" + stem + ".tsv"), read_text(dir + "/b/runs/P01/" + stem + ".tsv"));
}

TEST(StudyEventsTest, WhatTheLogLacksIsNaAndATabInANameIsNoColumn) {
  // A real session's lines, then one trial line without its "key", with an empty condition and
  // a tab in its material's name: n/a, n/a and a space, the row as wide as the header.
  const std::string dir = fresh_dir("events", "lacking");
  const std::string log = run_session("identification", dir, "P01");
  TrialLog t = read_trial_log(log).value();
  std::vector<LogLine> kept;
  for (const LogLine& l : t.lines)
    if (l.json.at("type") != "trial" || l.json.at("trial") == 1) kept.push_back(l);
  t.lines = kept;
  ASSERT_EQ(t.lines.at(1).json.at("type"), "trial");
  t.lines[1].json.erase("key");
  t.lines[1].json["condition"] = "";
  t.lines[1].json["answered"] = "a\tb";
  const Result<SessionEvents> ev = session_events(t, log);
  ASSERT_TRUE(ev) << ev.error().message;
  std::vector<std::string> lines = split(ev->tsv, '\n');
  ASSERT_EQ(lines.size(), 3u);  // the header, one trial, "" after the last newline
  const std::vector<std::string> header = split(lines[0], '\t'), row = split(lines[1], '\t');
  ASSERT_EQ(row.size(), header.size());
  const auto at = [&](const std::string& c) { return row.at(static_cast<std::size_t>(std::find(header.begin(), header.end(), c) - header.begin())); };
  EXPECT_EQ(at("key"), "n/a");
  EXPECT_EQ(at("trial_type"), "n/a");
  EXPECT_EQ(at("answered"), "a b");
  EXPECT_EQ(at("shown"), t.lines[1].json.at("shown").get<std::string>());
  EXPECT_EQ(ev->stem, "sub-P01_task-identification_events");
}

TEST(StudyEventsTest, AChangedLogWritesNoEventsFile) {
  const std::string dir = fresh_dir("events", "tampered");
  const std::string log = run_session("theta_threshold", dir, "P01");
  std::string text = read_text(log);
  const std::string from = "\"trial\":9,\"practice\":false,\"block\":1";  // after 4 practice trials
  const std::string::size_type at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  const std::string::size_type correct = text.find("\"correct\":", at);
  ASSERT_NE(correct, std::string::npos);
  text.replace(correct, text.compare(correct, 14, "\"correct\":true") == 0 ? 14 : 15,
               text.compare(correct, 14, "\"correct\":true") == 0 ? "\"correct\":false" : "\"correct\":true");
  std::ofstream(log, std::ios::binary) << text;
  const Result<EventsFiles> f = write_session_events(log);
  ASSERT_FALSE(f);
  EXPECT_NE(f.error().message.find("trials.jsonl:10: checksum does not match"), std::string::npos) << f.error().message;
  EXPECT_TRUE(events_files(dir + "/runs/P01").empty());
}

TEST(StudyEventsTest, ASessionNotEndedOrCutOffWritesNoEventsFile) {
  const std::string dir = fresh_dir("events", "unfinished");
  const std::string log = run_session("theta_threshold", dir, "P01", 20);
  Result<EventsFiles> f = write_session_events(log);
  ASSERT_FALSE(f);
  EXPECT_NE(f.error().message.find("the session has not ended"), std::string::npos) << f.error().message;
  // Finished, then its session_end line cut in half: no events either.
  run_session("theta_threshold", dir, "P01");
  std::string text = read_text(log);
  text.resize(text.size() - 20);
  std::ofstream(log, std::ios::binary) << text;
  f = write_session_events(log);
  ASSERT_FALSE(f);
  EXPECT_NE(f.error().message.find("the last line is cut off"), std::string::npos) << f.error().message;
  EXPECT_TRUE(events_files(dir + "/runs/P01").empty());
}

}  // namespace
}  // namespace ps::study
