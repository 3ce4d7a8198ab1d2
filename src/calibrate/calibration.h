// `pseudoshadow calibrate` without the window (docs/calibrate.md): interleaved 1-up-2-down
// staircases, one per reference point along a curve, the simulated observer that answers them
// in tests and headless runs, and the lookup table that makes equal steps look equally different.
//
// A trial shows the reference x and a comparison x + delta side by side (which side is random).
// Distance: "which pseudo-shadow is closer?" (correct: the reference, the smaller distance).
// Speed: "which texture is moving faster?" (correct: the comparison, the larger speed).
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "calibrate/staircase.h"
#include "core/result.h"
#include "scene/lut.h"

namespace ps::calibrate {

enum class CurveKind { kDistance, kSpeed };

// What the curve shows at a stimulus: intensity at a distance (mm), gain at a speed (mm/s).
using CurveFn = std::function<double(double)>;

struct Spec {
  CurveKind kind = CurveKind::kDistance;
  std::vector<double> references;  // reference points, increasing, > 0
  StaircaseParams staircase;
  std::uint64_t seed = 1;          // which staircase runs next and on which side the comparison is
};

struct Trial {
  int index = 0;                   // 0-based, in the order shown
  int point = 0;                   // which reference
  double reference = 0.0, comparison = 0.0;
  bool comparison_left = false;
  bool answered_left = false;
  bool correct = false;
  bool reversal = false;
};

class Calibration {
 public:
  explicit Calibration(Spec spec);

  bool done() const;
  // The trial to show (the same until answer() is called). Asserts !done().
  const Trial& current() const { return current_; }
  // The observer chose the left (true) or right stimulus as the closer / faster one.
  void answer(bool left);

  const Spec& spec() const { return spec_; }
  const std::vector<Trial>& trials() const { return log_; }
  std::vector<double> jnds() const;          // each reference's threshold (stimulus units)
  std::vector<int> reversals() const;
  std::vector<bool> finished() const;        // each reference's staircase has ended
  // About how many trials the whole calibration takes: the trials so far plus, per open
  // staircase, its missing reversals at its own trials per reversal so far (4 before it has two:
  // a 1-up-2-down staircase at its target reverses every 3-4 trials).
  int expected_trials() const;

 private:
  void draw_trial();

  Spec spec_;
  std::vector<Staircase> stairs_;
  std::mt19937_64 rng_;
  Trial current_;
  std::vector<Trial> log_;
};

// A scripted observer with a known psychometric function. It sees what the curve shows, c(x),
// with a JND in that quantity that grows like Weber's law, J(q) = jnd_min + weber * q, and
// answers correctly with probability Phi(z |c(a) - c(b)| / J(q_mid)), z = Phi^-1(1/sqrt 2), so
// that |c(a) - c(b)| = J is exactly its 70.7 %-correct difference, the staircase's target.
struct ObserverParams {
  double jnd_min = 0.01;
  double weber = 0.1;
  std::uint64_t seed = 1;
};

class SimulatedObserver {
 public:
  SimulatedObserver(CurveFn shown, ObserverParams params);
  double p_correct(double a, double b) const;
  // The observer's choice for `t` under the question of `kind` (true: left), right with
  // probability p_correct.
  bool answer_left(const Trial& t, CurveKind kind);

 private:
  CurveFn shown_;
  ObserverParams params_;
  std::mt19937_64 rng_;
};

// The observer's true JND at x: the delta with p_correct(x, x + delta) = 1/sqrt 2 (bisection up
// to max_delta; max_delta when it never gets there).
double true_jnd(const SimulatedObserver& o, double x, double max_delta);

// Runs `c` to the end with `o` answering, or until `stop` (asked before each trial) says so
// (the CLI's SIGTERM/SIGINT/SIGHUP: app/cli/stop_signal.h).
void run_simulated(Calibration& c, SimulatedObserver& o, const std::function<bool()>& stop = {});

// The table that makes equal steps of x look equally different (Fechner): S(x) = integral of
// 1 / JND over [0, x] (the JNDs linear between the references, constant beyond them), and the
// new curve shows at x what `shown` showed at h(x) = S^-1(S(range_max) x / range_max): its ends
// at 0 and range_max are the old curve's (the thesis curve's range is kept). Beyond range_max
// up to tail_max the table follows `shown`. `rows` rows on [0, range_max], 16 more on the tail.
Lut equalising_lut(CurveKind kind, const CurveFn& shown, const std::vector<double>& references,
                   const std::vector<double>& jnds, double range_max, double tail_max, int rows = 33);

// The trial log as CSV: a header, then one line per trial.
std::string format_trial_log(const Calibration& c);

// One trial of a log back (`calibrate --resume`): which side was answered, for the trial `c`
// shows next. Replaying a log's answers in order with the same spec (and seed) brings `c` to
// where the log stopped; a row that is not the trial `c` shows is an error naming source:line.
struct LoggedAnswer {
  int point = 0;
  double reference = 0.0, comparison = 0.0;
  bool comparison_left = false, answered_left = false;
};
Result<std::vector<LoggedAnswer>> parse_trial_log(std::string_view text, const std::string& source);
Status replay_answer(Calibration& c, const LoggedAnswer& a, const std::string& where);

std::string_view curve_name(CurveKind kind);  // "distance" / "speed"

}  // namespace ps::calibrate
