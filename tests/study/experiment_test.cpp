// Experiment files (src/study/experiment.h): the shipped ones load and their stimuli are scenes
// the program reads; a bad file is refused naming file:line and what is allowed. The plan's
// balanced Latin squares (maze::williams_square, shared with the maze) are counted out.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "maze/maze_plan.h"
#include "study/experiment.h"
#include "study/experiment_scene.h"
#include "study/study_plan.h"

namespace ps::study {
namespace {

const std::string kStudies = std::string(PS_SOURCE_DIR) + "/scenes/studies/";

// A minimal valid threshold experiment; tests append or replace lines.
std::string valid_text(const std::string& threshold_extra = "") {
  return "[experiment]\ntask = \"threshold\"\n[scene]\npath = \"" + std::string(PS_SOURCE_DIR) +
         "/scenes/default.toml\"\n[threshold]\nkeys = [\"materials.wood.lambda_min\", \"materials.wood.lambda_max\"]\n"
         "reference = 1.3\nlevel_min = 0.01\nlevel_max = 1.0\n" + threshold_extra;
}

std::string error_of(const std::string& text) {
  const Result<Experiment> e = parse_experiment(text, "bad.toml");
  return e ? std::string("no error") : e.error().message;
}

TEST(ExperimentFileTest, ShippedExperimentsLoadAndTheirStimuliAreScenes) {
  for (const char* name : {"lambda_threshold", "theta_threshold", "distance_threshold", "identification", "targeting"}) {
    const Result<Experiment> e = load_experiment(kStudies + name + ".toml");
    ASSERT_TRUE(e) << e.error().message;
    EXPECT_EQ(e->name, name);
    const Status s = check_experiment_scene(e.value());
    EXPECT_TRUE(s) << s.error().message;
  }
  const Experiment lambda = load_experiment(kStudies + "lambda_threshold.toml").value();
  EXPECT_EQ(lambda.task, Task::kThreshold);
  EXPECT_EQ(lambda.threshold.method, Method::kPsi);
  EXPECT_EQ(lambda.threshold.keys.size(), 2u);
  EXPECT_DOUBLE_EQ(lambda.threshold.reference, 1.3);
  EXPECT_EQ(lambda.conditions.size(), 2u);
  EXPECT_EQ(lambda.practice, 4);
  EXPECT_EQ(load_experiment(kStudies + "theta_threshold.toml")->threshold.method, Method::kStaircase);
  EXPECT_EQ(load_experiment(kStudies + "identification.toml")->materials.size(), 4u);
  const Experiment targeting = load_experiment(kStudies + "targeting.toml").value();
  EXPECT_EQ(targeting.task, Task::kTargeting);
  EXPECT_EQ(targeting.conditions.size(), 5u);
  EXPECT_EQ(targeting.trials, 3 * 2 * 9);  // derived: sequences x distances x widths x targets
}

TEST(ExperimentFileTest, TheVariedValueIsWrittenAsASetOverride) {
  Experiment e = load_experiment(kStudies + "distance_threshold.toml").value();
  const std::vector<std::string> o = threshold_overrides(e, e.conditions[0], 2.5);
  ASSERT_EQ(o.size(), 2u);
  EXPECT_EQ(o[0], "probe.velocity=[0.0, 0.0, 0.0]");
  EXPECT_EQ(o[1], "probe.position=[0.0, 0.0, 10.5]");  // offset 8 + 2.5
}

TEST(ExperimentFileTest, UnknownKeysNameTheLineAndTheKnownKeys) {
  EXPECT_EQ(error_of(valid_text("methdo = \"psi\"\n")),
            "bad.toml:10: unknown key 'methdo' in [threshold]; known keys: method, keys, value, reference, offset, "
            "level_min, level_max, shape, criterion, lapse");
  EXPECT_NE(error_of("[experimnt]\nname = \"x\"\n").find("bad.toml:1: unknown key 'experimnt' in [the file's top level]"),
            std::string::npos);
  EXPECT_NE(error_of(valid_text() + "[[conditions]]\nname = \"a\"\nsett = [\"a=1\"]\n").find("bad.toml:12: unknown key 'sett'"),
            std::string::npos);
}

TEST(ExperimentFileTest, BadValuesSayWhatIsAllowed) {
  EXPECT_EQ(error_of(valid_text("method = \"quest\"\n")), "bad.toml:10: 'method' must be one of \"psi\", \"staircase\"");
  EXPECT_EQ(error_of(valid_text("criterion = 1.5\n")), "bad.toml:10: 'criterion' must be a number in [0.51, 0.99]");
  EXPECT_EQ(error_of(valid_text("value = \"[0, 0, 1]\"\n")),
            "bad.toml:10: 'value' must hold {} where the number goes, e.g. \"[0.0, 0.0, {}]\"");
  EXPECT_EQ(error_of("[experiment]\ntrials = 2.5\n"), "bad.toml:2: 'trials' must be a whole number");
  EXPECT_EQ(error_of("[experiment]\nfirst_seed = 1.5\n"), "bad.toml:2: 'first_seed' must be a whole number");
  EXPECT_EQ(error_of("[experiment]\nblocks = 0\n"), "bad.toml:2: 'blocks' must be a number in [1, 100]");
  EXPECT_EQ(error_of(valid_text() + "[[conditions]]\nname = \"a\"\nset = [\"probe.velocity\"]\n"),
            "bad.toml:12: 'set' holds --set-style overrides KEY=VALUE, e.g. \"materials.wood.a_max=0.5\" (got "
            "\"probe.velocity\")");
  EXPECT_NE(error_of(valid_text() + "[[conditions]]\nname = \"a\"\n[[conditions]]\nname = \"a\"\n")
                .find("bad.toml:12: two [[conditions]] are named 'a'"),
            std::string::npos)
      << error_of(valid_text() + "[[conditions]]\nname = \"a\"\n[[conditions]]\nname = \"a\"\n");
  EXPECT_NE(error_of("[experiment]\nname = \n").find("bad.toml:2:"), std::string::npos);  // TOML syntax
}

TEST(ExperimentFileTest, WholeFileRulesAreChecked) {
  std::string reversed = valid_text();
  reversed.replace(reversed.find("level_max = 1.0"), 15, "level_max = 0.001");
  EXPECT_EQ(error_of(reversed), "bad.toml:1: [threshold] level_min must be below level_max");
  EXPECT_NE(error_of("[experiment]\ntask = \"threshold\"\n").find("[scene] path is missing"), std::string::npos);
  EXPECT_NE(error_of("[experiment]\ntask = \"identification\"\n[scene]\npath = \"x.toml\"\n")
                .find("at least 2 [[identification.materials]]"),
            std::string::npos);
  EXPECT_EQ(error_of("[experiment]\ntask = \"identification\"\ntrials = 10\n[scene]\npath = \"x.toml\"\n"
                     "[[identification.materials]]\nname = \"a\"\n[[identification.materials]]\nname = \"b\"\n"
                     "[[identification.materials]]\nname = \"c\"\n"),
            "bad.toml:1: [experiment] trials (10) must be a multiple of the 3 materials, so that each is shown equally often");
  EXPECT_NE(error_of("[experiment]\nresponse_keys = [\"1\", \"2\", \"3\"]\n" + valid_text().substr(13))
                .find("a 2AFC threshold takes 2 keys"),
            std::string::npos);
}

TEST(ExperimentFileTest, AKeyTheSceneDoesNotKnowIsRefusedWithTheExperimentsLine) {
  const std::string text = valid_text() + "[[conditions]]\nname = \"typo\"\nset = [\"materials.wood.lamda_min=1\"]\n";
  const Result<Experiment> e = parse_experiment(text, "typo.toml");
  ASSERT_TRUE(e) << e.error().message;
  const Status s = check_experiment_scene(e.value());
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("typo.toml:10: the scene with condition 'typo' at the reference does not load"),
            std::string::npos)
      << s.error().message;
  EXPECT_NE(s.error().message.find("lamda_min"), std::string::npos) << s.error().message;
}

// Every condition at every position equally often, and every ordered pair of neighbours equally
// often, over the square's rows (Williams 1949), for 2 to 7 conditions.
TEST(StudyPlanTest, WilliamsSquaresAreBalancedForAnyNumberOfConditions) {
  for (int n = 2; n <= 7; ++n) {
    const auto rows = maze::williams_square(n);
    ASSERT_EQ(rows.size(), static_cast<std::size_t>(n % 2 ? 2 * n : n)) << n;
    std::map<std::pair<int, int>, int> at, follows;
    for (const auto& r : rows)
      for (int j = 0; j < n; ++j) {
        ++at[{r[static_cast<std::size_t>(j)], j}];
        if (j > 0) ++follows[{r[static_cast<std::size_t>(j - 1)], r[static_cast<std::size_t>(j)]}];
      }
    EXPECT_EQ(at.size(), static_cast<std::size_t>(n * n)) << n;
    for (const auto& [k, count] : at) EXPECT_EQ(count, static_cast<int>(rows.size()) / n) << n;
    EXPECT_EQ(follows.size(), static_cast<std::size_t>(n * (n - 1))) << n;
    for (const auto& [k, count] : follows) EXPECT_EQ(count, n % 2 ? 2 : 1) << n;
  }
}

TEST(StudyPlanTest, RowsCarryIdsSeedsAndBalancedOrders) {
  Experiment e = load_experiment(kStudies + "lambda_threshold.toml").value();
  const auto plan = make_study_plan(e, 4);
  ASSERT_EQ(plan.size(), 4u);
  EXPECT_EQ(plan[0].participant, "P01");
  EXPECT_EQ(plan[3].participant, "P04");
  EXPECT_EQ(plan[0].seed, 101u);
  EXPECT_EQ(plan[3].seed, 104u);
  EXPECT_EQ(plan[0].order, (std::vector<int>{0, 1}));
  EXPECT_EQ(plan[1].order, (std::vector<int>{1, 0}));
  EXPECT_EQ(plan[2].order, (std::vector<int>{0, 1}));
  const std::string csv = study_plan_csv(e, plan);
  EXPECT_EQ(csv.substr(0, csv.find("P03")),
            "participant,seed,order,position_1,position_2\nP01,101,stroke_33 stroke_17,stroke_33,stroke_17\n"
            "P02,102,stroke_17 stroke_33,stroke_17,stroke_33\n");
  EXPECT_EQ(participant_index("P07").value(), 6);
  EXPECT_FALSE(participant_index("07"));
  EXPECT_FALSE(participant_index("P0"));
  EXPECT_FALSE(participant_index("Px1"));
}

}  // namespace
}  // namespace ps::study
