// A person answering `study run` (src/study/study_run.h, Responder; the window is one,
// app/study/study_window.h): the log holds exactly the answers given, for the stimulus each was
// given; a stop keeps every answer and no session_end; a simulated tail takes over on resume and
// writes the unbroken simulated run's trials where they do not depend on the person's answers; an
// answer that names no choice is an error, not a line.
#include <gtest/gtest.h>

#include <optional>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/experiment.h"
#include "study/study_run.h"
#include "study/study_summary.h"

#include "study/study_test_files.h"

namespace ps::study {
namespace {

using test_files::fresh_dir;
using test_files::kStudies;
using test_files::read_text;

std::vector<nlohmann::json> lines_of(const std::string& path) {
  std::vector<nlohmann::json> out;
  std::istringstream in(read_text(path));
  for (std::string l; std::getline(in, l);) out.push_back(nlohmann::json::parse(l));
  return out;
}

std::vector<nlohmann::json> of_type(const std::vector<nlohmann::json>& lines, const std::string& type) {
  std::vector<nlohmann::json> out;
  for (const nlohmann::json& j : lines)
    if (j.value("type", "") == type) out.push_back(j);
  return out;
}

// Answers from a list, then stops (none); keeps every stimulus it was asked about.
struct ScriptedPerson final : Responder {
  std::vector<int> answers;
  std::vector<TrialStimulus> asked;
  Result<std::optional<int>> answer(const TrialStimulus& t) override {
    if (asked.size() == answers.size()) return std::optional<int>();
    asked.push_back(t);
    return std::optional<int>(answers[asked.size() - 1]);
  }
  Result<std::optional<Pointed>> point(const TrialStimulus&) override { return make_error("not a targeting run"); }
  nlohmann::json describe() const override { return {{"kind", "person"}, {"answered_in", "test"}}; }
};

RunSpec spec_for(const std::string& dir, Responder* who) {
  RunSpec s;
  s.participant = "P02";
  s.out_dir = dir;
  s.responder = who;
  return s;
}

TEST(StudyResponderTest, TheLogHoldsExactlyTheAnswersGivenForTheStimuliShown) {
  const Experiment e = load_experiment(kStudies + "lambda_threshold.toml").value();
  ScriptedPerson person;
  person.answers = {1, 2, 2, 1, 2, 1, 1};  // 4 practice trials, then 3 that count
  const Result<RunReport> r = run_participant(e, spec_for(fresh_dir("responder", "exact"), &person));
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_TRUE(r->stopped);
  EXPECT_FALSE(r->complete);
  EXPECT_EQ(r->written, 7);
  const std::vector<nlohmann::json> lines = lines_of(r->log_path);
  EXPECT_EQ(lines.front().at("observer").at("kind"), "person");
  EXPECT_TRUE(of_type(lines, "session_end").empty()) << "a stopped run has not ended";
  const std::vector<nlohmann::json> trials = of_type(lines, "trial");
  ASSERT_EQ(trials.size(), 7u);
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const TrialStimulus& t = person.asked[i];
    EXPECT_EQ(trials[i].at("trial"), t.trial);
    EXPECT_EQ(trials[i].at("response"), person.answers[i]);
    EXPECT_EQ(trials[i].at("key"), e.response_keys[static_cast<std::size_t>(person.answers[i] - 1)]);
    EXPECT_EQ(trials[i].at("interval"), t.interval);  // the comparison where the person was shown it
    EXPECT_DOUBLE_EQ(trials[i].at("level").get<double>(), t.level);
    EXPECT_DOUBLE_EQ(trials[i].at("comparison").get<double>(), e.threshold.reference + t.level);
    EXPECT_EQ(trials[i].at("correct"), person.answers[i] == t.interval);
    EXPECT_EQ(trials[i].at("practice"), i < 4);
    // Practice is shown at the largest difference; the trials that count at Psi's choices.
    if (i < 4) {
      EXPECT_DOUBLE_EQ(t.level, e.threshold.level_max);
    }
  }
}

// The person stops (Esc), then a simulated participant answers the rest (`study resume
// --simulate`): the `resumed` line says who answers on, the log ends, its chain holds, and in
// identification, whose draws hang on the seed and the trial's number alone, the tail is the
// unbroken simulated run's own.
TEST(StudyResponderTest, ASimulatedTailTakesOverFromAPerson) {
  const Experiment e = load_experiment(kStudies + "identification.toml").value();
  const std::string dir = fresh_dir("responder", "tail"), whole = fresh_dir("responder", "whole");
  ScriptedPerson person;
  person.answers = {0, 1, 2, 3, 3, 2, 1, 0, 0, 0};
  ASSERT_TRUE(run_participant(e, spec_for(dir, &person)));
  const Result<RunReport> tail = run_participant(e, spec_for(dir, nullptr));
  ASSERT_TRUE(tail) << tail.error().message;
  EXPECT_TRUE(tail->complete);
  EXPECT_EQ(tail->done_before, 10);
  const Result<RunReport> simulated = run_participant(e, spec_for(whole, nullptr));
  ASSERT_TRUE(simulated) << simulated.error().message;

  const std::vector<nlohmann::json> lines = lines_of(tail->log_path);
  const std::vector<nlohmann::json> resumed = of_type(lines, "resumed");
  ASSERT_EQ(resumed.size(), 1u);
  EXPECT_EQ(resumed[0].at("observer").at("kind"), "simulated");
  std::vector<nlohmann::json> mixed = of_type(lines, "trial"), unbroken = of_type(lines_of(simulated->log_path), "trial");
  ASSERT_EQ(mixed.size(), unbroken.size());
  for (std::size_t i = 0; i < mixed.size(); ++i) {
    mixed[i].erase("sha256");
    unbroken[i].erase("sha256");
    EXPECT_EQ(mixed[i].at("shown"), unbroken[i].at("shown")) << "trial " << i + 1 << ": the same material shown";
    if (i < 10) EXPECT_EQ(mixed[i].at("answered_index"), person.answers[i]);
    else EXPECT_EQ(mixed[i], unbroken[i]) << "trial " << i + 1;
  }
  EXPECT_TRUE(summarize_participant(tail->log_path, {50, 1}));  // the chain holds across the change

  // And back: a person may go on after a simulated part, which a second simulated participant
  // with other options may not (ResumeRefusesAnotherSimulatedParticipant).
  const std::string back = fresh_dir("responder", "back");
  RunSpec first = spec_for(back, nullptr);
  first.stop_after = 5;
  ASSERT_TRUE(run_participant(e, first));
  ScriptedPerson next;
  next.answers = {1, 1};
  const Result<RunReport> r = run_participant(e, spec_for(back, &next));
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->done_before + r->written, 7);
  EXPECT_EQ(of_type(lines_of(r->log_path), "resumed").at(0).at("observer").at("kind"), "person");
}

TEST(StudyResponderTest, AnAnswerThatNamesNoChoiceIsAnErrorNotALine) {
  const Experiment e = load_experiment(kStudies + "lambda_threshold.toml").value();
  ScriptedPerson person;
  person.answers = {2, 3};
  const Result<RunReport> r = run_participant(e, spec_for(fresh_dir("responder", "bad"), &person));
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("the answer 3 to trial 2 names no choice"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace ps::study
