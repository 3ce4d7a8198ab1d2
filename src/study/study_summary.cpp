#include "study/study_summary.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "study/simulate.h"
#include "study/study_log.h"

namespace ps::study {

using json = nlohmann::json;

Result<std::vector<std::string>> find_trial_logs(const std::vector<std::string>& args) {
  std::vector<std::string> logs;
  for (const std::string& arg : args) {
    const std::filesystem::path p(arg);
    std::error_code ec;
    if (std::filesystem::is_regular_file(p, ec)) {
      logs.push_back(arg);
    } else if (std::filesystem::is_regular_file(p / "trials.jsonl", ec)) {
      logs.push_back((p / "trials.jsonl").string());
    } else if (std::filesystem::is_directory(p, ec)) {
      std::vector<std::string> found;
      for (const auto& entry : std::filesystem::directory_iterator(p, ec))
        if (std::filesystem::is_regular_file(entry.path() / "trials.jsonl")) found.push_back((entry.path() / "trials.jsonl").string());
      if (found.empty()) return make_error(arg + ": no trials.jsonl in it or in its subfolders (give the --out of `study run`)");
      std::sort(found.begin(), found.end());
      logs.insert(logs.end(), found.begin(), found.end());
    } else {
      return make_error(arg + ": no such file or folder (give trial logs, participants' folders or a study folder)");
    }
  }
  return logs;
}

namespace {

Shape shape_named(const std::string& s) {
  return s == "logistic" ? Shape::kLogistic : s == "normal" ? Shape::kCumulativeNormal : Shape::kWeibull;
}

// The session_start line: who, which task, which conditions (and materials).
void read_start(ParticipantResult& p, const json& s) {
  p.participant = s.at("participant");
  p.experiment = s.at("experiment");
  p.task = s.at("task");
  for (const auto& name : s.at("conditions")) {
    ConditionResult c;
    c.condition = name;
    p.conditions.push_back(c);
  }
  if (const json o = s.value("observer", json::object()); o.value("kind", "") == "simulated" && p.task == "threshold") {
    p.truth = PsychometricParams{o.at("threshold"), o.at("slope"), o.at("guess"), o.at("lapse")};
    p.truth_shape = shape_named(o.at("shape"));
  }
  if (const json o = s.value("observer", json::object()); o.value("kind", "") == "simulated" && p.task == "targeting") {
    const json& q = o.at("pointer");
    PointerParams t;
    t.a_s = q.at("a_s");
    t.b_s_per_bit = q.at("b_s_per_bit");
    t.mt_sd_s = q.at("mt_sd_s");
    t.lognormal_mt = q.at("lognormal_mt");
    t.spread = q.at("spread");
    t.lateral = q.at("lateral");
    p.pointer_truth = t;
  }
  if (p.task == "targeting") return;
  if (p.task == "threshold") {
    const json& t = s.at("threshold");
    p.shape = shape_named(t.at("shape"));
    p.criterion = t.at("criterion");
    p.reference = t.at("reference");
    p.level_min = t.at("level_min");
    p.level_max = t.at("level_max");
  } else {
    for (const auto& m : s.at("materials")) p.materials.push_back(m);
    const std::size_t K = p.materials.size();
    for (ConditionResult& c : p.conditions) c.confusion.assign(K, std::vector<int>(K, 0));
  }
}

Point3 point_of(const json& a) { return {a.at(0), a.at(1), a.at(2)}; }

// A targeting trial line as fitts.h reads it: the nominal distance and width, the axis from the
// target it left to the one it selected, where the movement began and ended, its time and hit.
PointingTrial pointing_trial(const json& l) {
  PointingTrial t;
  t.distance = l.at("distance");
  t.width = l.at("width");
  t.start = point_of(l.at("start"));
  t.target = point_of(l.at("target_centre"));
  t.end = point_of(l.at("end"));
  t.began = point_of(l.at("began"));
  t.movement_time_s = l.at("movement_time_s");
  t.hit = l.at("hit");
  return t;
}

std::size_t condition_index(const ParticipantResult& p, const std::string& name) {
  for (std::size_t i = 0; i < p.conditions.size(); ++i)
    if (p.conditions[i].condition == name) return i;
  throw std::runtime_error("condition '" + name + "' is not among the session_start line's conditions");
}

// One threshold condition's fit: maximum likelihood with the lapse free, then the bootstrap.
void fit_condition(ConditionResult& c, const ParticipantResult& p, const std::vector<TrialResult>& trials,
                   const SummaryOptions& o) {
  c.data = group_by_level(trials);
  if (c.data.size() < 2) return;  // one level: nothing to fit (the tables say so)
  FitOptions f;
  f.shape = p.shape;
  f.guess = 0.5;
  c.fit = fit_psychometric(c.data, f);
  BootstrapOptions b;
  b.resamples = o.resamples;
  b.criterion = p.criterion;
  b.seed = o.seed;
  c.boot = bootstrap(c.data, f, c.fit, b);
  c.posterior = posterior_intervals(c.data, f, psi_prior(p.shape, p.level_min, p.level_max, p.criterion));
  if (p.reference != 0.0) {
    c.weber = weber_fraction(c.boot.threshold, p.reference);
    c.weber_ci = {c.boot.threshold_ci.low / p.reference, c.boot.threshold_ci.high / p.reference};
    c.weber_cred = {c.posterior.threshold_ci.low / p.reference, c.posterior.threshold_ci.high / p.reference};
  }
}

}  // namespace

Result<ParticipantResult> summarize_participant(const std::string& log_path, const SummaryOptions& o) {
  Result<TrialLog> log = read_trial_log(log_path);
  if (!log) return log.error();
  return summarize_participant(log.value(), log_path, o);
}

Result<ParticipantResult> summarize_participant(const TrialLog& log, const std::string& log_path, const SummaryOptions& o) {
  ParticipantResult p;
  p.log = log_path;
  p.torn = log.torn;
  std::vector<std::vector<TrialResult>> trials;
  for (const LogLine& l : log.lines) {
    try {
      const std::string type = l.json.at("type");
      if (l.number == 1) read_start(p, l.json);
      trials.resize(p.conditions.size());
      p.complete |= type == "session_end";
      if (type != "trial" || l.json.at("practice").get<bool>()) continue;
      const std::size_t c = condition_index(p, l.json.at("condition"));
      ++p.conditions[c].trials;
      if (p.task == "threshold") trials[c].push_back({l.json.at("level"), l.json.at("correct")});
      else if (p.task == "targeting") p.conditions[c].pointing.push_back(pointing_trial(l.json));
      else ++p.conditions[c].confusion.at(l.json.at("shown_index")).at(l.json.at("answered_index"));
    } catch (const std::exception& e) {
      return make_error(log_path + ":" + std::to_string(l.number) + ": not a study log line (" + e.what() +
                        "); docs/study.md lists the schema");
    }
  }
  for (std::size_t c = 0; c < p.conditions.size(); ++c) {
    if (p.task == "threshold") fit_condition(p.conditions[c], p, trials[c], o);
    else if (p.task == "targeting") p.conditions[c].fitts = fitts_participant(p.conditions[c].pointing);
    else if (p.conditions[c].trials > 0) p.conditions[c].ident = identification_stats(ConfusionMatrix(p.conditions[c].confusion));
  }
  return p;
}

}  // namespace ps::study
