#include "study/study_run.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <random>

#include <nlohmann/json.hpp>

#include "maze/maze_log.h"
#include "study/study_log.h"
#include "study/study_trials.h"

namespace ps::study {

std::uint64_t trial_seed(std::uint64_t seed, std::uint64_t trial, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (trial + 1) + 0xBF58476D1CE4E5B9ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

namespace {

ojson names(const std::vector<Variant>& v, const std::vector<int>& order = {}) {
  ojson a = ojson::array();
  if (order.empty())
    for (const Variant& x : v) a.push_back(x.name);
  for (const int i : order) a.push_back(v[static_cast<std::size_t>(i)].name);
  return a;
}

// Who answers this run's trials: the responder's own description, or the simulated participant.
ojson observer_of(const RunState& s) {
  if (s.spec.responder) return ojson::parse(s.spec.responder->describe().dump());
  const ObserverSpec& o = s.spec.observer;
  ojson j = {{"kind", "simulated"}, {"seed", s.observer_seed}, {"shape", shape_name(o.shape)},
             {"threshold", o.truth.threshold}, {"slope", o.truth.slope}, {"guess", o.truth.guess},
             {"lapse", o.truth.lapse}, {"p_correct", o.p_correct}};
  if (s.e.task == Task::kTargeting)  // its Fitts law and scatter (pointing_sim.h)
    j["pointer"] = {{"a_s", o.pointer.a_s}, {"b_s_per_bit", o.pointer.b_s_per_bit}, {"mt_sd_s", o.pointer.mt_sd_s},
                    {"lognormal_mt", o.pointer.lognormal_mt}, {"spread", o.pointer.spread}, {"lateral", o.pointer.lateral}};
  return j;
}

ojson session_start(const RunState& s) {
  const Experiment& e = s.e;
  ojson j = {{"type", "session_start"}, {"schema", kStudyLogSchema}, {"experiment", e.name},
             {"experiment_file", e.path}, {"experiment_sha256", file_sha256(e.path)}, {"task", task_name(e.task)}, {"scene", e.scene},
             {"participant", s.plan.participant}, {"seed", s.plan.seed}, {"conditions", names(e.conditions)},
             {"condition_order", names(e.conditions, s.plan.order)}, {"trials", e.trials}, {"blocks", e.blocks},
             {"practice_trials", e.practice}, {"total_trials", total_trials(e)}, {"response_keys", e.response_keys}};
  if (e.task == Task::kThreshold)
    j["threshold"] = {{"method", method_name(e.threshold.method)}, {"keys", e.threshold.keys},
                      {"reference", e.threshold.reference}, {"level_min", e.threshold.level_min},
                      {"level_max", e.threshold.level_max}, {"shape", shape_name(e.threshold.shape)},
                      {"criterion", e.threshold.criterion}, {"guess", 0.5}};
  else if (e.task == Task::kTargeting)
    j["targeting"] = {{"distances_mm", e.targeting.distances_mm}, {"widths_mm", e.targeting.widths_mm},
                      {"targets", e.targeting.targets}, {"sequences", e.targeting.sequences},
                      {"centre", e.targeting.centre}, {"normal", e.targeting.normal}};
  else
    j["materials"] = names(e.materials);
  j["observer"] = observer_of(s);
  return j;
}

// Who answered the log's last part: session_start's "observer", or the last `resumed` line's
// when a part was answered by someone else (a person's trials, then a simulated tail).
nlohmann::json last_observer(const TrialLog& log) {
  nlohmann::json o = log.lines.front().json.value("observer", nlohmann::json::object());
  for (const LogLine& l : log.lines)
    if (l.json.value("type", "") == "resumed" && l.json.contains("observer")) o = l.json.at("observer");
  return o;
}

// A log goes on only with what began it: the same experiment, file unchanged, and participant;
// a simulated participant after a simulated part only with the same options, otherwise the
// trials after the break would not be the unbroken run's. A person may take over from a
// simulated participant and the other way round (the `resumed` line says who answers on).
Status check_same_session(const RunState& s, const TrialLog& log) {
  const nlohmann::json& start = log.lines.front().json;
  const std::string where = log.lines.front().json.value("participant", "") + "/trials.jsonl: ";
  if (start.value("experiment", "") != s.e.name || start.value("participant", "") != s.plan.participant)
    return make_error(s.spec.out_dir + ": the log there is of experiment '" + start.value("experiment", "") +
                      "', participant '" + start.value("participant", "") + "': give another --out");
  if (start.value("experiment_sha256", "") != file_sha256(s.e.path))
    return make_error(s.spec.out_dir + "/" + where + s.e.path + " changed since this participant started: resume with the file the run began with");
  const nlohmann::json now = nlohmann::json::parse(observer_of(s).dump()), before = last_observer(log);
  if (now.value("kind", "") == "simulated" && before.value("kind", "") == "simulated" && now != before)
    return make_error(s.spec.out_dir + "/" + where + "the simulated participant's options differ from the run's first part "
                      "(its session_start line's \"observer\"): give the same ones");
  return ok_status();
}

// An existing log: its trials replayed into the tracks; the count of whole trials, whether it
// ended, and the last checksum (the chain goes on from it).
Result<int> replay(RunState& s, const TrialLog& log, bool& complete, std::string& last) {
  if (Status st = check_same_session(s, log); !st) return st.error();
  int done = 0;
  for (const LogLine& l : log.lines) {
    const std::string type = l.json.value("type", "");
    complete |= type == "session_end";
    if (type != "trial") continue;
    if (l.json.value("trial", 0) != done + 1)
      return make_error(s.spec.out_dir + ": trial " + std::to_string(done + 1) + " expected at line " + std::to_string(l.number));
    ++done;
    const Slot slot = slot_of(s.e, s.plan, done - 1);
    if (s.e.task == Task::kThreshold && !slot.practice)
      s.tracks[static_cast<std::size_t>(slot.condition)].update(l.json.at("level"), l.json.at("correct"));
    if (s.e.task == Task::kTargeting) {  // where the next movement begins
      const nlohmann::json& p = l.json.at("end");
      s.last_end = Point3{p.at(0), p.at(1), p.at(2)};
    }
  }
  last = log.lines.back().checksum;
  return done;
}

// An existing log read and checked, its trials replayed (replay); r's counts and torn warning set,
// `observer` who answered its last part.
Status read_existing(RunState& s, RunReport& r, std::string& last, nlohmann::json& observer) {
  Result<TrialLog> log = read_trial_log(r.log_path);
  if (!log) return log.error();
  r.torn = log.value().torn;
  observer = last_observer(log.value());
  Result<int> done = replay(s, log.value(), r.complete, last);
  if (!done) return done.error();
  r.done_before = done.value();
  return ok_status();
}

Status append(maze::SessionLog& log, const ojson& j, std::string& last) {
  const std::string line = seal_line(j.dump(), last);
  last = line.substr(line.size() - 66, 64);
  return log.append_line(line);
}

}  // namespace

Result<RunReport> run_participant(const Experiment& e, const RunSpec& spec) {
  Result<int> index = participant_index(spec.participant);
  if (!index) return index.error();
  RunState s{e, spec, plan_entry(e, index.value()), {}, 0, std::nullopt};
  s.plan.participant = spec.participant;
  s.observer_seed = spec.observer.seed != 0 ? spec.observer.seed : s.plan.seed;
  if (e.task == Task::kThreshold) s.tracks.assign(e.conditions.size(), Track(e.threshold));
  RunReport r;
  const std::filesystem::path dir = std::filesystem::path(spec.out_dir) / spec.participant;
  r.log_path = (dir / "trials.jsonl").string();
  r.total = total_trials(e);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return make_error(dir.string() + ": cannot create the participant's directory: " + ec.message());
  const DirLock lock(dir.string());
  if (!lock.held())
    return make_error(dir.string() + ": another `study run` is writing this participant's log (two would interleave their trials)");
  std::string last;
  const bool exists = std::filesystem::exists(r.log_path);
  if (!exists && spec.resume_only)
    return make_error(r.log_path + ": no trial log to resume (start the participant with `study run`)");
  nlohmann::json observer_before;
  if (exists)
    if (Status st = read_existing(s, r, last, observer_before); !st) return st.error();
  if (r.complete) return r;
  Result<maze::SessionLog> log = exists ? maze::SessionLog::open_existing(r.log_path) : maze::SessionLog::open(r.log_path);
  if (!log) return log.error();
  ojson resumed = {{"type", "resumed"}, {"at_trial", r.done_before + 1}};
  const ojson who = observer_of(s);
  if (exists && nlohmann::json::parse(who.dump()) != observer_before) resumed["observer"] = who;
  Status st = exists ? append(log.value(), resumed, last) : append(log.value(), session_start(s), last);
  for (int k = r.done_before; st && k < r.total && (spec.stop_after <= 0 || r.written < spec.stop_after); ++k) {
    Result<std::optional<ojson>> line = trial_of(s, k);
    if (!line) return line.error();  // every trial before it is on disk already
    if (!line.value()) {
      r.stopped = true;
      break;
    }
    st = append(log.value(), *line.value(), last);
    ++r.written;
  }
  if (st && r.done_before + r.written == r.total) {
    st = append(log.value(), {{"type", "session_end"}, {"trials", r.total}}, last);
    r.complete = true;
  }
  if (!st) return st.error();
  return r;
}

}  // namespace ps::study
