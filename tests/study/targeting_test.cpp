// The targeting task (src/study/targeting.h, study_run.h, study_summary.h; docs/study.md,
// "Targeting"): the ring's geometry against closed forms, the design's file:line errors, a
// simulated run's sequences (every movement leaves the target the last one selected, every
// (D, W) once a block and condition), a run broken off and resumed writing the unbroken run's
// trials, and simulated participants with a known Fitts law recovered by the summary.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/experiment.h"
#include "study/study_events.h"
#include "study/study_log.h"
#include "study/study_run.h"
#include "study/study_summary.h"
#include "study/targeting.h"

#include "study/study_test_files.h"

namespace ps::study {
namespace {

using test_files::fresh_dir;
using test_files::read_text;

// Six (D, W) cells whose IDs all differ (D / W = 3, 6, 7.5, 12, 15, 30).
const std::string kDesign = R"([experiment]
name = "targeting_test"
task = "targeting"
practice_trials = 9
first_seed = 701
[scene]
path = ")" + std::string(PS_SOURCE_DIR) + R"(/scenes/default.toml"
[targeting]
distances_mm = [30.0, 60.0, 120.0]
widths_mm = [4.0, 10.0]
targets = 9
[[conditions]]
name = "as_is"
set = []
[[conditions]]
name = "no_texture"
set = ["materials.wood.a_min=0.0", "materials.wood.a_max=0.0"]
)";

Experiment design_in(const std::string& dir, const std::string& text = kDesign) {
  const std::string path = dir + "/targeting_test.toml";
  std::ofstream(path) << text;
  Result<Experiment> e = load_experiment(path);
  EXPECT_TRUE(e) << e.error().message;
  return e.value();
}

std::vector<nlohmann::json> trial_lines(const std::string& log) {
  std::vector<nlohmann::json> out;
  std::istringstream in(read_text(log));
  for (std::string l; std::getline(in, l);) {
    nlohmann::json j = nlohmann::json::parse(l);
    j.erase("sha256");
    if (j["type"] == "trial") out.push_back(j);
  }
  return out;
}

RunSpec spec_for(const std::string& dir, const std::string& participant, double a, double b) {
  RunSpec s;
  s.participant = participant;
  s.out_dir = dir;
  s.observer.pointer.a_s = a;
  s.observer.pointer.b_s_per_bit = b;
  return s;
}

TEST(TargetingTest, TheRingLiesOnItsPlaneAndEveryMovementIsTheSameChord) {
  TargetingSpec spec;
  spec.centre = {5.0, -3.0, 2.0};
  spec.normal = {0.0, 1.0, 1.0};  // a plane at 45 degrees
  spec.targets = 9;
  const Ring ring = make_ring(spec, 80.0);
  const double s = 1.0 / std::sqrt(2.0);
  // D sin(pi (n - 1) / (2 n)) with n = 9: 80 sin(80 degrees).
  const double chord = 80.0 * std::sin(80.0 * std::numbers::pi / 180.0);
  EXPECT_NEAR(movement_distance(80.0, 9), chord, 1e-12);
  std::vector<int> visits(9, 0);
  for (int step = 0; step < 9; ++step) {
    const int to = target_at_step(9, step), from = target_at_step(9, step + 8);
    ++visits[static_cast<std::size_t>(to)];
    const Point3 c = target_centre(ring, to);
    const double dx = c.x - 5.0, dy = c.y + 3.0, dz = c.z - 2.0;
    EXPECT_NEAR(std::sqrt(dx * dx + dy * dy + dz * dz), 40.0, 1e-9) << "on the circle";
    EXPECT_NEAR(s * dy + s * dz, 0.0, 1e-9) << "in the plane";
    EXPECT_NEAR(distance(target_centre(ring, from), c), chord, 1e-9) << "step " << step;
  }
  for (const int v : visits) EXPECT_EQ(v, 1) << "every target once a sequence";
  EXPECT_NEAR(target_centre(ring, 0).x, 45.0, 1e-9) << "target 0 on the ring's +x side";
}

// A touch selects once: at contact's first tick, not again while the probe rests on the
// surface or flickers in and out of contact there, nor after a rise past 0.25 mm shorter than
// 60 ms (the hand filter's ringing, seen in the window); again after a lift held that long.
TEST(TargetingTest, ATouchSelectsOnceAndAgainOnlyAfterALift) {
  TouchSelector sel(0.25, 0.06);
  double t = 0.0;
  const auto tick = [&](bool contact, double gap) { return sel.tick(t += 0.001, contact, gap); };
  EXPECT_FALSE(tick(true, -0.1)) << "down when the ring appeared: unarmed";
  for (int k = 0; k < 100; ++k) EXPECT_FALSE(tick(false, 0.2)) << "not lifted past 0.25 mm";
  EXPECT_FALSE(tick(true, 0.0));
  for (int k = 0; k < 59; ++k) tick(false, 1.0);
  EXPECT_FALSE(sel.armed()) << "lifted for 59 ms";
  tick(false, 1.0);
  tick(false, 1.0);
  EXPECT_TRUE(sel.armed()) << "lifted for 61 ms";
  EXPECT_TRUE(tick(true, 0.0)) << "contact's first tick selects";
  int more = 0;
  for (int k = 0; k < 300; ++k) more += tick(k % 3 != 0, k % 3 != 0 ? -0.05 : 0.1);  // flicker at the surface
  for (int r = 0; r < 5; ++r) {  // ringing: 0.29 mm for 7 ms, back into contact
    for (int k = 0; k < 7; ++k) more += tick(false, 0.29);
    more += tick(true, 0.0);
  }
  EXPECT_EQ(more, 0) << "resting, flickering and ringing at the surface select nothing more";
  for (int k = 0; k < 80; ++k) EXPECT_FALSE(tick(false, 0.5));
  EXPECT_TRUE(tick(true, -0.2)) << "lifted 0.5 mm for 80 ms and down again: the next selection";
}

// The probe drawn opaque hides the targets behind it: seen from above, a point under the sphere
// and one whose line of sight passes through it are hidden; one beside it, and one in front of
// it (between the eye and the sphere), and one far behind whose sight line passes above it, are not.
TEST(TargetingTest, TheProbeHidesOnlyWhatIsBehindIt) {
  const Point3 eye{0.0, -100.0, 100.0}, centre{0.0, 0.0, 8.0};
  EXPECT_TRUE(hidden_by_sphere(eye, {0.0, 0.0, 0.0}, centre, 8.0)) << "the contact point, under it";
  EXPECT_TRUE(hidden_by_sphere(eye, {0.0, 12.0, 0.0}, centre, 8.0)) << "behind it along the line of sight";
  EXPECT_FALSE(hidden_by_sphere(eye, {12.0, 0.0, 0.0}, centre, 8.0)) << "beside it";
  EXPECT_FALSE(hidden_by_sphere(eye, {0.0, -12.0, 0.0}, centre, 8.0)) << "in front of it";
  EXPECT_FALSE(hidden_by_sphere(eye, {0.0, 40.0, 0.0}, centre, 8.0)) << "far behind it: its sight line passes 16.7 mm from the centre";
}

TEST(TargetingTest, TheDesignsMistakesNameTheirLine) {
  const std::string dir = fresh_dir("targeting", "errors");
  const auto error_of = [&](const std::string& from, const std::string& to) {
    std::string text = kDesign;
    text.replace(text.find(from), from.size(), to);
    const std::string path = dir + "/bad.toml";
    std::ofstream(path) << text;
    const Result<Experiment> e = load_experiment(path);
    return e ? std::string("loaded") : e.error().message;
  };
  EXPECT_NE(error_of("practice_trials = 9", "trials = 40").find("bad.toml:4: a targeting task derives its trials"),
            std::string::npos);
  EXPECT_NE(error_of("targets = 9", "targets = 8").find("bad.toml:11: 'targets' must be odd"), std::string::npos);
  EXPECT_NE(error_of("widths_mm = [4.0, 10.0]", "widths_mm = [4.0, 12.0]").find("overlaps its neighbours"), std::string::npos);
  EXPECT_NE(error_of("first_seed = 701", "response_keys = [\"1\"]").find("answered by touching, not by keys"), std::string::npos);
  EXPECT_EQ(design_in(dir).trials, 54) << "1 sequence x 3 distances x 2 widths x 9 targets";
}

TEST(TargetingTest, EachMovementLeavesTheTargetTheLastOneSelected) {
  const std::string dir = fresh_dir("targeting", "sequences");
  const Experiment e = design_in(dir);
  const Result<RunReport> r = run_participant(e, spec_for(dir, "P01", 0.2, 0.15));
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->total, 9 + 2 * 54);
  const std::vector<nlohmann::json> trials = trial_lines(r->log_path);
  ASSERT_EQ(trials.size(), 117u);
  std::map<std::string, int> cells;  // condition D W -> movements
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const nlohmann::json& t = trials[i];
    const double d = t.at("ring_diameter"), w = t.at("width");
    EXPECT_NEAR(t.at("distance").get<double>(), movement_distance(d, 9), 1e-12);
    if (!t.at("practice").get<bool>()) ++cells[t.at("condition").get<std::string>() + " " + std::to_string(d) + " " + std::to_string(w)];
    const bool first = i == 0 || t.at("sequence") != trials[i - 1].at("sequence") || t.at("practice") != trials[i - 1].at("practice") ||
                       t.at("condition") != trials[i - 1].at("condition");
    if (first) {
      EXPECT_EQ(t.at("target"), 0) << "a sequence starts at target 0, trial " << i + 1;
      EXPECT_EQ(t.at("began"), t.at("start")) << "from its first target's centre";
    } else {
      EXPECT_EQ(t.at("from"), trials[i - 1].at("target")) << "trial " << i + 1;
      EXPECT_EQ(t.at("began"), trials[i - 1].at("end")) << "where the last selection was, trial " << i + 1;
    }
    // The hit flag against the end point's distance from the target's centre.
    const nlohmann::json& c = t.at("target_centre");
    const nlohmann::json& p = t.at("end");
    const double miss = std::hypot(p[0].get<double>() - c[0].get<double>(), p[1].get<double>() - c[1].get<double>(),
                                   p[2].get<double>() - c[2].get<double>());
    EXPECT_EQ(t.at("hit").get<bool>(), miss <= 0.5 * w);
  }
  EXPECT_EQ(cells.size(), 12u) << "2 conditions x 6 (D, W)";
  for (const auto& [cell, n] : cells) EXPECT_EQ(n, 9) << cell;
}

TEST(TargetingTest, AResumedRunWritesTheUnbrokenRunsTrials) {
  const std::string dir = fresh_dir("targeting", "resume");
  const Experiment e = design_in(dir);
  ASSERT_TRUE(run_participant(e, spec_for(dir + "/whole", "P02", 0.2, 0.15)));
  RunSpec s = spec_for(dir + "/broken", "P02", 0.2, 0.15);
  s.stop_after = 31;  // mid-sequence: the next movement begins at trial 31's end
  ASSERT_TRUE(run_participant(e, s));
  s.stop_after = 0;
  const Result<RunReport> r = run_participant(e, s);
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_TRUE(r->complete);
  EXPECT_EQ(trial_lines(r->log_path), trial_lines(dir + "/whole/P02/trials.jsonl"));
}

// Twenty simulated participants with a = 0.3 s and b = 0.2 s/bit: each one's regression interval
// for b holds the truth in most of them (95 % intervals: 17 or more of 20 has probability 0.98),
// and the group's mean b and throughput lie where the law puts them.
TEST(TargetingTest, TheSummaryRecoversTheSimulatedLaw) {
  const std::string dir = fresh_dir("targeting", "recover");
  const Experiment e = design_in(dir);
  std::vector<ParticipantResult> people;
  int covered = 0, fits = 0;
  for (int i = 1; i <= 20; ++i) {
    char id[8];
    std::snprintf(id, sizeof id, "P%02d", i);
    const Result<RunReport> r = run_participant(e, spec_for(dir, id, 0.3, 0.2));
    ASSERT_TRUE(r) << r.error().message;
    const Result<ParticipantResult> p = summarize_participant(r->log_path, {});
    ASSERT_TRUE(p) << p.error().message;
    ASSERT_TRUE(p->pointer_truth);
    EXPECT_DOUBLE_EQ(p->pointer_truth->b_s_per_bit, 0.2);
    for (const ConditionResult& c : p->conditions) {
      ASSERT_EQ(c.fitts.cells.size(), 6u);
      ASSERT_TRUE(c.fitts.on_id.computable);
      ++fits;
      covered += c.fitts.on_id.slope_ci.low <= 0.2 && 0.2 <= c.fitts.on_id.slope_ci.high;
    }
    people.push_back(p.value());
  }
  EXPECT_GE(covered, fits * 17 / 20) << covered << " of " << fits;
  // The law's own throughput with We = W on average: the mean over the cells of ID / (a + b ID).
  double expected = 0.0, mean_b = 0.0, mean_tp = 0.0;
  for (const double d : {30.0, 60.0, 120.0})
    for (const double w : {4.0, 10.0}) {
      const double id = std::log2(movement_distance(d, 9) / w + 1.0);
      expected += id / (0.3 + 0.2 * id) / 6.0;
    }
  for (const ParticipantResult& p : people) {
    mean_b += p.conditions[0].fitts.on_id.slope / 20.0;
    mean_tp += p.conditions[0].fitts.throughput_bps / 20.0;
  }
  std::printf("b's interval holds 0.2 in %d of %d fits; mean b %.4f s/bit; mean throughput %.3f bit/s against the law's %.3f\n",
              covered, fits, mean_b, mean_tp, expected);
  EXPECT_NEAR(mean_b, 0.2, 0.01);  // 20 slopes of SD about 0.015 each: the mean's SD is 0.004
  // IDe differs from ID by the sampling of SDx (9 end points a cell): a few per cent either way.
  EXPECT_NEAR(mean_tp / expected, 1.0, 0.06) << mean_tp << " against " << expected;
}

TEST(TargetingTest, ItsEventsHaveOneRowPerMovementWithItsHit) {
  const std::string dir = fresh_dir("targeting", "events");
  const Experiment e = design_in(dir);
  const Result<RunReport> r = run_participant(e, spec_for(dir, "P03", 0.2, 0.15));
  ASSERT_TRUE(r) << r.error().message;
  const Result<EventsFiles> f = write_session_events(r->log_path);
  ASSERT_TRUE(f) << f.error().message;
  std::istringstream tsv(read_text(f->tsv));
  std::string header;
  std::getline(tsv, header);
  EXPECT_NE(header.find("\tmovement_time_s\thit"), std::string::npos) << header;
  int rows = 0;
  for (std::string l; std::getline(tsv, l);) ++rows;
  EXPECT_EQ(rows, 117);
}

// A person's movements (the window's, app/study/study_window.h) are logged as made, for the
// stimuli chosen before they were made: the same targets, widths and rings as a simulated run
// of the same participant. Stopping keeps them; a simulated tail finishes the run.
TEST(TargetingTest, APersonsMovementsAreLoggedAsMadeForTheStimuliShown) {
  struct Pointer final : Responder {
    std::vector<TrialStimulus> asked;
    Result<std::optional<int>> answer(const TrialStimulus&) override { return make_error("not a targeting answer"); }
    Result<std::optional<Pointed>> point(const TrialStimulus& t) override {
      if (asked.size() == 12) return std::optional<Pointed>();  // Esc after 12 movements
      asked.push_back(t);
      // Lands 0.3 W to the side of the centre on odd trials (a hit), 0.7 W on even ones (a miss).
      const double off = (asked.size() % 2 ? 0.3 : 0.7) * t.width;
      const Point3 began{t.start.x + 1.0, t.start.y, t.start.z};
      return std::optional<Pointed>(Pointed{began, {t.target.x + off, t.target.y, t.target.z}, 0.25 * static_cast<double>(asked.size())});
    }
    nlohmann::json describe() const override { return {{"kind", "person"}, {"answered_in", "test"}}; }
  } person;
  const std::string dir = fresh_dir("targeting", "person"), sim_dir = fresh_dir("targeting", "person_sim");
  const Experiment e = design_in(dir);
  RunSpec s = spec_for(dir, "P01", 0.2, 0.15);
  s.responder = &person;
  const Result<RunReport> r = run_participant(e, s);
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_TRUE(r->stopped);
  EXPECT_EQ(r->written, 12);
  const Result<RunReport> sim = run_participant(design_in(sim_dir), spec_for(sim_dir, "P01", 0.2, 0.15));
  ASSERT_TRUE(sim) << sim.error().message;
  const std::vector<nlohmann::json> made = trial_lines(r->log_path), unbroken = trial_lines(sim->log_path);
  ASSERT_EQ(made.size(), 12u);
  for (std::size_t i = 0; i < made.size(); ++i) {
    const TrialStimulus& t = person.asked[i];
    for (const char* k : {"trial", "condition", "sequence", "ring_diameter", "distance", "width", "from", "target", "start", "target_centre"})
      EXPECT_EQ(made[i].at(k), unbroken[i].at(k)) << "trial " << i + 1 << " " << k;
    EXPECT_DOUBLE_EQ(made[i].at("movement_time_s").get<double>(), 0.25 * static_cast<double>(i + 1));
    EXPECT_DOUBLE_EQ(made[i].at("end").at(0).get<double>(), t.target.x + (i % 2 ? 0.7 : 0.3) * t.width);
    EXPECT_DOUBLE_EQ(made[i].at("began").at(0).get<double>(), t.start.x + 1.0);
    EXPECT_EQ(made[i].at("hit"), i % 2 == 0) << "a hit within W / 2 of the centre, a miss beyond";
  }
  // The simulated tail goes on from the person's last selection and finishes the run.
  const Result<RunReport> tail = run_participant(e, spec_for(dir, "P01", 0.2, 0.15));
  ASSERT_TRUE(tail) << tail.error().message;
  EXPECT_TRUE(tail->complete);
  EXPECT_EQ(tail->done_before, 12);
  const std::vector<nlohmann::json> all = trial_lines(r->log_path);
  ASSERT_EQ(all.size(), unbroken.size());
  EXPECT_EQ(all[12].at("began"), made[11].at("end")) << "trial 13 is a sequence's 4th movement: it begins where the person's last ended";
}

}  // namespace
}  // namespace ps::study
