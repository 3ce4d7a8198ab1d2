#include "study/study_trials.h"

#include <string>

#include "study/fit.h"
#include "study/targeting.h"

namespace ps::study {

namespace {

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

}  // namespace

Result<std::optional<ojson>> trial_of(RunState& s, int k) {
  const Slot slot = slot_of(s.e, s.plan, k);
  Responder* const who = s.spec.responder;
  if (s.e.task == Task::kTargeting) {
    const TrialStimulus m = targeting_stimulus(s, slot, k);
    if (!who) return std::optional<ojson>(targeting_line(s, m, simulated_movement(s, m, k)));
    Result<std::optional<Pointed>> made = who->point(m);
    if (!made) return made.error();
    if (!made.value()) return std::optional<ojson>();
    return std::optional<ojson>(targeting_line(s, m, *made.value()));
  }
  const TrialStimulus t = stimulus_of(s, slot, k);
  if (!who) return std::optional<ojson>(trial_line(s, t, simulated_answer(s, t, k)));
  Result<std::optional<int>> a = who->answer(t);
  if (!a) return a.error();
  if (!a.value()) return std::optional<ojson>();
  const int answer = *a.value();
  const bool pair = s.e.task == Task::kThreshold;
  const int first = pair ? 1 : 0, n = pair ? 2 : static_cast<int>(s.e.materials.size());
  if (answer < first || answer >= first + n)
    return make_error("study: the answer " + std::to_string(answer) + " to trial " + std::to_string(t.trial) + " names no choice");
  return std::optional<ojson>(trial_line(s, t, answer));
}

}  // namespace ps::study
