#include "study/study_run.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <random>

#include <nlohmann/json.hpp>

#include "calibrate/staircase.h"
#include "maze/maze_log.h"
#include "study/fit.h"
#include "study/psi.h"
#include "study/simulate.h"
#include "study/study_log.h"
#include "study/study_plan.h"
#include "study/targeting.h"

namespace ps::study {

using ojson = nlohmann::ordered_json;  // members in the order written

std::uint64_t trial_seed(std::uint64_t seed, std::uint64_t trial, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (trial + 1) + 0xBF58476D1CE4E5B9ull * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

namespace {

enum Stream : std::uint64_t { kInterval = 1, kObserver = 2, kMaterials = 3, kCells = 4 };

// Where trial k (from 0) stands: practice first, then each block runs the participant's
// conditions in order, `trials` each.
struct Slot {
  bool practice = false;
  int block = 0;      // from 1 (0: practice)
  int condition = 0;  // index into Experiment::conditions
  int in_segment = 0; // the trial's place in its block and condition
};

Slot slot_of(const Experiment& e, const PlanEntry& plan, int k) {
  if (k < e.practice) return {true, 0, plan.order[0], k};
  const int m = k - e.practice, per_block = e.trials * static_cast<int>(plan.order.size());
  return {false, m / per_block + 1, plan.order[static_cast<std::size_t>((m % per_block) / e.trials)], m % e.trials};
}

int total_trials(const Experiment& e) { return e.practice + e.blocks * static_cast<int>(e.conditions.size()) * e.trials; }

// One condition's adaptive procedure: Psi or calibrate's staircase, over [level_min, level_max].
class Track {
 public:
  explicit Track(const ThresholdSpec& t) {
    if (t.method == Method::kPsi) {
      SimulationSpec s;  // only what simulation_grid reads: the shape, the guess, the levels, the lapse
      s.shape = t.shape;
      s.level_min = t.level_min;
      s.level_max = t.level_max;
      s.psi_lapse = t.lapse;
      psi_.emplace(simulation_grid(s, false));
    } else {
      calibrate::StaircaseParams p;
      p.start_delta = t.level_max / 2.0;  // an easy start, inside the range: the coarse steps find the threshold
      p.min_delta = t.level_min;
      p.max_delta = t.level_max;
      p.max_trials = 1 << 30;  // the experiment's trial count ends it
      stairs_.emplace(p);
    }
  }
  double next() { return psi_ ? psi_->next_level() : stairs_->delta(); }
  void update(double level, bool correct) {
    if (psi_) psi_->update(level, correct);
    else stairs_->record(correct);
  }

 private:
  std::optional<PsiMethod> psi_;
  std::optional<calibrate::Staircase> stairs_;
};

struct RunState {
  const Experiment& e;
  const RunSpec& spec;
  PlanEntry plan;
  std::vector<Track> tracks;  // one per condition
  std::uint64_t observer_seed = 0;
  std::optional<Point3> last_end;  // targeting: the last selection, where the next movement begins
};

// The trial's stimulus: threshold, the level (the track's next; practice at level_max) and which
// interval holds the comparison; identification, the material shown (material_of).
int material_of(const RunState& s, const Slot& slot);

TrialStimulus stimulus_of(RunState& s, const Slot& slot, int k) {
  TrialStimulus t;
  t.trial = k + 1;
  t.total = total_trials(s.e);
  t.practice = slot.practice;
  t.block = slot.block;
  t.condition = slot.condition;
  if (s.e.task == Task::kThreshold) {
    const ThresholdSpec& th = s.e.threshold;
    t.level = slot.practice ? th.level_max : s.tracks[static_cast<std::size_t>(slot.condition)].next();
    t.reference = th.reference;
    t.comparison = th.reference + t.level;
    std::mt19937_64 rng(trial_seed(s.plan.seed, static_cast<std::uint64_t>(k), kInterval));
    t.interval = uniform01(rng) < 0.5 ? 1 : 2;  // which interval shows the comparison
  } else {
    t.shown = material_of(s, slot);
  }
  return t;
}

// The simulated participant's answer to trial k: its own draws, from its seed and k alone.
int simulated_answer(const RunState& s, const TrialStimulus& t, int k) {
  if (s.e.task == Task::kThreshold) {
    SimulatedObserver o(s.spec.observer.shape, s.spec.observer.truth,
                        trial_seed(s.observer_seed, static_cast<std::uint64_t>(k), kObserver));
    return o.respond(t.level) ? t.interval : 3 - t.interval;
  }
  const int K = static_cast<int>(s.e.materials.size());
  std::mt19937_64 rng(trial_seed(s.observer_seed, static_cast<std::uint64_t>(k), kObserver));
  int answered = t.shown;
  if (uniform01(rng) >= s.spec.observer.p_correct) {
    answered = static_cast<int>(uniform01(rng) * (K - 1));  // one of the others, each alike
    if (answered >= t.shown) ++answered;
  }
  return answered;
}

// The trial's log line, with the answer; a threshold trial's answer also moves its track.
ojson trial_line(RunState& s, const TrialStimulus& t, int answer) {
  const std::string& condition = s.e.conditions[static_cast<std::size_t>(t.condition)].name;
  if (s.e.task == Task::kThreshold) {
    const bool correct = answer == t.interval;
    if (!t.practice) s.tracks[static_cast<std::size_t>(t.condition)].update(t.level, correct);
    return {{"type", "trial"}, {"trial", t.trial}, {"practice", t.practice}, {"block", t.block},
            {"condition", condition}, {"level", t.level}, {"reference", t.reference}, {"comparison", t.comparison},
            {"interval", t.interval}, {"response", answer},
            {"key", s.e.response_keys[static_cast<std::size_t>(answer - 1)]}, {"correct", correct}};
  }
  return {{"type", "trial"}, {"trial", t.trial}, {"practice", t.practice}, {"block", t.block}, {"condition", condition},
          {"shown", s.e.materials[static_cast<std::size_t>(t.shown)].name}, {"shown_index", t.shown},
          {"answered", s.e.materials[static_cast<std::size_t>(answer)].name}, {"answered_index", answer},
          {"key", s.e.response_keys[static_cast<std::size_t>(answer)]}, {"correct", t.shown == answer}};
}

// A fair shuffle of 0..n-1: Fisher-Yates from the engine's bits (fit.h's uniform01).
std::vector<int> shuffled(int n, std::mt19937_64& rng) {
  std::vector<int> order(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) order[static_cast<std::size_t>(i)] = i;
  for (int i = n - 1; i > 0; --i)
    std::swap(order[static_cast<std::size_t>(i)], order[static_cast<std::size_t>(uniform01(rng) * (i + 1))]);
  return order;
}

// The material of a trial: each block and condition shows the materials in turn, shuffled in
// rounds of K from the participant's seed, so every material is shown equally often.
int material_of(const RunState& s, const Slot& slot) {
  const int K = static_cast<int>(s.e.materials.size());
  const auto u = [](int v) { return static_cast<std::uint64_t>(v); };
  const std::uint64_t segment = trial_seed(trial_seed(s.plan.seed, u(slot.block), kMaterials), u(slot.condition), kMaterials);
  std::mt19937_64 rng(trial_seed(segment, u(slot.in_segment / K), kMaterials));
  return shuffled(K, rng)[static_cast<std::size_t>(slot.in_segment % K)];
}

ojson point_json(const Point3& p) { return ojson::array({p.x, p.y, p.z}); }

// A targeting trial: one movement of a sequence. Each block and condition runs every (D, W)
// `sequences` times, in an order shuffled from the participant's seed; a sequence is `targets`
// movements across its ring (targeting.h). Practice runs the first condition's order of block 1.
TrialStimulus targeting_stimulus(const RunState& s, const Slot& slot, int k) {
  const TargetingSpec& t = s.e.targeting;
  const int n = t.targets, nw = static_cast<int>(t.widths_mm.size());
  const int cells = t.sequences * static_cast<int>(t.distances_mm.size()) * nw;
  const auto u = [](int v) { return static_cast<std::uint64_t>(v); };
  const int block = slot.practice ? 1 : slot.block;
  TrialStimulus m;
  m.trial = k + 1;
  m.total = total_trials(s.e);
  m.practice = slot.practice;
  m.block = slot.block;
  m.condition = slot.practice ? s.plan.order[0] : slot.condition;
  std::mt19937_64 rng(trial_seed(trial_seed(s.plan.seed, u(block), kCells), u(m.condition), kCells));
  const std::vector<int> order = shuffled(cells, rng);
  const int sequence = (slot.in_segment / n) % cells;
  m.sequence = sequence + 1;
  m.step = slot.in_segment % n;
  const int cell = order[static_cast<std::size_t>(sequence)] % (cells / t.sequences);
  m.ring_diameter = t.distances_mm[static_cast<std::size_t>(cell / nw)];
  m.width = t.widths_mm[static_cast<std::size_t>(cell % nw)];
  const Ring ring = make_ring(t, m.ring_diameter);
  m.from = target_at_step(n, m.step + n - 1);
  m.to = target_at_step(n, m.step);
  m.start = target_centre(ring, m.from);
  m.target = target_centre(ring, m.to);
  m.distance = movement_distance(m.ring_diameter, n);
  return m;
}

// The simulated participant's movement: it moves from where its last selection was (the
// previous target's centre at a sequence's start); its time from the law at the nominal
// distance and width (the truth the summary recovers); its end point scattered about the target
// along the axis from where it began and across it (the pointer's frame: target at the distance
// along +x).
Pointed simulated_movement(const RunState& s, const TrialStimulus& m, int k) {
  const Ring ring = make_ring(s.e.targeting, m.ring_diameter);
  const Point3 began = m.step == 0 ? m.start : s.last_end.value_or(m.start);
  SimulatedPointer pointer(s.spec.observer.pointer, trial_seed(s.observer_seed, static_cast<std::uint64_t>(k), kObserver));
  const PointingTrial p = pointer.point(m.distance, m.width);
  const Point3 end = on_axis(ring, began, m.target, distance(began, m.target) + (p.end.x - m.distance), p.end.y);
  return {began, end, p.movement_time_s};
}

// A targeting trial's log line; the movement's end is where the next one begins.
ojson targeting_line(RunState& s, const TrialStimulus& m, const Pointed& p) {
  s.last_end = p.end;
  return {{"type", "trial"}, {"trial", m.trial}, {"practice", m.practice}, {"block", m.block},
          {"condition", s.e.conditions[static_cast<std::size_t>(m.condition)].name}, {"sequence", m.sequence},
          {"ring_diameter", m.ring_diameter}, {"distance", m.distance}, {"width", m.width}, {"from", m.from},
          {"target", m.to}, {"start", point_json(m.start)}, {"target_centre", point_json(m.target)},
          {"began", point_json(p.began)}, {"end", point_json(p.end)}, {"movement_time_s", p.movement_time_s},
          {"hit", distance(p.end, m.target) <= 0.5 * m.width}};
}

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
    if (e.task == Task::kTargeting) {
      const TrialStimulus m = targeting_stimulus(s, slot_of(e, s.plan, k), k);
      Pointed p;
      if (!spec.responder) {
        p = simulated_movement(s, m, k);
      } else {
        Result<std::optional<Pointed>> made = spec.responder->point(m);
        if (!made) return made.error();  // every trial before it is on disk already
        if (!made.value()) {
          r.stopped = true;
          break;
        }
        p = *made.value();
      }
      st = append(log.value(), targeting_line(s, m, p), last);
      ++r.written;
      continue;
    }
    const TrialStimulus t = stimulus_of(s, slot_of(e, s.plan, k), k);
    int answer = 0;
    if (!spec.responder) {
      answer = simulated_answer(s, t, k);
    } else {
      Result<std::optional<int>> a = spec.responder->answer(t);
      if (!a) return a.error();  // every trial before it is on disk already
      if (!a.value()) {
        r.stopped = true;
        break;
      }
      answer = *a.value();
      const int n = e.task == Task::kThreshold ? 2 : static_cast<int>(e.materials.size());
      const int first = e.task == Task::kThreshold ? 1 : 0;
      if (answer < first || answer >= first + n)
        return make_error("study: the answer " + std::to_string(answer) + " to trial " + std::to_string(t.trial) + " names no choice");
    }
    st = append(log.value(), trial_line(s, t, answer), last);
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
