// Targeting statistics (docs/study.md, "Targeting statistics (Fitts, ISO 9241-9)"): pointing
// trials reduced to effective distance, effective width, effective index of difficulty and
// throughput per condition, as Soukoreff & MacKenzie (2004) define them for ISO 9241-9; the Fitts
// regression MT = a + b ID per participant with t intervals; throughput across participants.
//
// Lengths are in whatever unit the trials give (mm, px, m): only their ratios enter an index of
// difficulty, so the unit cancels. Times are seconds, indices of difficulty bits, throughput
// bits per second.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "core/student_t.h"
#include "study/fit.h"  // Interval

namespace ps::study {

// A point in 2D (z = 0) or 3D, in the trials' length unit.
struct Point3 {
  double x = 0.0, y = 0.0, z = 0.0;
};

struct PointingTrial {
  double distance = 0.0;  // nominal D: the design's amplitude, from start to target centre
  double width = 0.0;     // nominal W, measured along the task axis
  // The task axis runs from `start` (the centre of the start position or of the "from" target)
  // to `target` (the target's centre); end points are projected onto it, so a sideways miss
  // changes neither the amplitude nor the spread.
  Point3 start;
  Point3 target;
  Point3 end;  // where the selection was made
  // Where the movement actually began, when not at `start`: in a serial (reciprocal) task, the
  // previous selection. The movement's amplitude is then (end - began) along the axis, which is
  // MacKenzie's "add the previous trial's dx" for collinear back-and-forth movements.
  std::optional<Point3> began;
  double movement_time_s = 0.0;
  bool hit = false;
};

// The end point's signed offset from the target centre along the axis (> 0: overshoot) and the
// movement's amplitude along it; NaN both when start and target coincide (no axis).
struct AxisProjection {
  double dx = 0.0;
  double amplitude = 0.0;
};
AxisProjection project_on_axis(const PointingTrial& t);

// Why a cell's effective measures are missing. What the arithmetic reached before it stopped stays
// filled in (trials, misses, mean MT, De; SDx once there are two trials; We once SDx > 0; IDe once
// De > 0); the rest is NaN, never inf, and TP is NaN unless the status is kOk, so a missing value
// is never mistaken for a measured one and never reaches a mean.
enum class CellStatus {
  kOk,
  kTooFewTrials,   // fewer than 2 trials: no standard deviation
  kNoSpread,       // SDx = 0 (every end point at the same place along the axis): We = 0, IDe infinite
  kNoAxis,         // a trial whose start and target coincide, or a coordinate that is not finite
  kNoAmplitude,    // De <= 0: the movements did not go towards the target on average
  kNoTime,         // mean MT <= 0 or not finite
};
std::string_view to_string(CellStatus s);

// Soukoreff & MacKenzie's (2004) We = sqrt(2 pi e) SDx, rounded as ISO 9241-9 and the paper give
// it: the width of a uniform distribution with the entropy of a normal of SD SDx. (sqrt(2 pi e) is
// 4.13273; the rounding moves We by 0.007 %.)
inline constexpr double kEffectiveWidthFactor = 4.133;

// One condition (D, W) of one participant.
struct FittsCell {
  double distance = 0.0, width = 0.0;  // nominal D and W
  double id_bits = 0.0;                // ID = log2(D / W + 1), Shannon form
  int trials = 0;
  int misses = 0;
  double error_percent = 0.0;      // 100 misses / trials
  double mean_mt_s = 0.0;          // mean movement time
  double effective_distance = 0.0; // De: mean amplitude along the axis (NaN without an axis)
  double mean_dx = 0.0;            // mean end-point offset along the axis (> 0: overshoot)
  double sd_x = 0.0;               // SDx: sample SD (n - 1) of the end points along the axis
  double effective_width = 0.0;    // We = 4.133 SDx
  double effective_id_bits = 0.0;  // IDe = log2(De / We + 1)
  double throughput_bps = 0.0;     // TP = IDe / mean MT
  CellStatus status = CellStatus::kTooFewTrials;
  bool computable() const { return status == CellStatus::kOk; }
};

// The cell of one condition's trials (all of the same D and W: the caller groups them).
FittsCell fitts_cell(std::span<const PointingTrial> trials);
// The trials grouped by (D, W), compared exactly, in order of D then W.
std::vector<FittsCell> fitts_cells(std::span<const PointingTrial> trials);

// Ordinary least squares y = intercept + slope x with two-sided t intervals (n - 2 degrees of
// freedom). Not computable with fewer than 3 points (no degree of freedom left for the residual
// variance) or with every x equal; the numbers are then NaN.
struct LinearFit {
  int points = 0;
  double intercept = 0.0, slope = 0.0;
  Interval intercept_ci, slope_ci;
  double intercept_se = 0.0, slope_se = 0.0;
  double r_squared = 0.0;
  double residual_sd = 0.0;  // sqrt(SSE / (n - 2))
  bool computable = false;
};
LinearFit fit_line(std::span<const double> x, std::span<const double> y, double confidence = 0.95);

// One participant in one condition of the experiment (a device, a rendering): their cells,
// throughput as the mean of the computable cells' throughputs ("mean of means", Soukoreff &
// MacKenzie 2004, recommendation 5), and the regressions of the cells' mean MT on the nominal ID
// (every cell with trials and a positive time) and on IDe (computable cells only). Intercepts in
// seconds, slopes in seconds per bit.
struct FittsParticipant {
  std::vector<FittsCell> cells;
  int cells_used = 0;  // computable cells behind throughput_bps and the IDe regression
  double throughput_bps = 0.0;  // NaN when no cell is computable
  LinearFit on_id;
  LinearFit on_effective_id;
};
FittsParticipant fitts_participant(std::span<const PointingTrial> trials, double confidence = 0.95);

// A mean over participants with its two-sided t interval (n - 1 degrees of freedom): NaN
// interval and computable = false below two values; NaN values are left out and counted.
struct MeanInterval {
  int n = 0;
  int left_out = 0;  // NaN values (participants whose throughput was not computable)
  double mean = 0.0, sd = 0.0;
  Interval ci;
  bool computable = false;
};
MeanInterval mean_interval(std::span<const double> values, double confidence = 0.95);
// Throughput across participants: mean_interval of their throughput_bps.
MeanInterval throughput_across(std::span<const FittsParticipant> participants, double confidence = 0.95);

// Student's t (its CDF and quantile): core/student_t.h, shared with the maze's summaries.

}  // namespace ps::study
