// `pseudoshadow bench`: the data shaping behind its plots, kept apart from gnuplot so it can be
// tested without it. bench.png is a grid of small panels, one per knob group (each with its own
// axes and error metric); bench_ratios.png is a bar chart of the Gabor strategies' speed-ups
// over the naive sum. Labels are placed here, not by gnuplot, so that none covers another
// label or a point (gnuplot puts every label at the same offset from its point).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "app/bench/bench_sweep.h"
#include "core/result.h"

namespace ps::bench {

// Reads bench.csv as written by csv_text() (bench_report.h), so that `bench --plot-only` can
// draw the plots again without running the sweep. `path` names the file in errors
// ("bench.csv:7: ..."). Columns are found by name; "n/a" reads as NaN.
Result<std::vector<BenchRow>> parse_csv(std::string_view text, const std::string& path);

// A knob value as a point label: the group's name is stripped where the value repeats it and
// the long strategy names are shortened ("baked_linear_24" -> "lin 24", "weighted_c10" ->
// "c=10"); the panel's title says what the short names stand for.
std::string short_label(std::string_view group, std::string_view value);

// One axis of a panel. Logarithmic when the largest value is kLogAxisRatio times the smallest or
// more (a linear axis would crush the small ones into one corner: the Gabor strategies' times,
// 8 to 63 ms, put five settings within 1 ms), linear otherwise; padded so no point sits on the frame.
inline constexpr double kLogAxisRatio = 5.0;
struct Axis {
  double lo = 0.0, hi = 1.0;
  bool log = false;
  double unit(double v) const;  // v mapped to [0, 1] across the axis
};
Axis fit_axis(const std::vector<double>& values);

struct PlotPoint {
  double time_ms = 0.0, error = 0.0;  // error floored at kErrorFloor (a log axis cannot show 0)
  std::string label;                  // short_label()
  bool pareto = false;                // on the group's Pareto front (bench.csv's `pareto`)
};
inline constexpr double kErrorFloor = 1e-7;

struct Panel {
  std::string group, metric;
  std::vector<PlotPoint> points;  // sorted by time, so the Pareto points join left to right
  Axis x, y;                      // time (ms), error (the metric's unit)
};
// One panel per group, in the order the groups first appear in `rows`.
std::vector<Panel> group_panels(const std::vector<BenchRow>& rows);

// What the label placement needs to know about the panel as drawn, in pixels.
struct LabelGeometry {
  double plot_w_px = 340.0, plot_h_px = 340.0;  // the panel's plotting area (about bench.png's)
  double char_w_px = 7.0, char_h_px = 14.0;     // an upper bound on the label font's advance and line height
  double marker_px = 9.0;                       // side of the square a point's marker covers
};

struct PlacedLabel {
  std::string text;
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;  // its box in graph coordinates [0, 1]
  bool leader = false;                            // set away from its point: draw a line to it
  double px = 0.0, py = 0.0;                      // the point, graph coordinates
};
// For each point of `p` (same order), the first of eight positions around it (right, left,
// above, below, then the diagonals) whose box stays inside the panel and meets no marker and
// no label already placed; if none is free, the same eight a step further out (up to three
// steps, with a leader line); where every position collides, the one with the least overlap.
std::vector<PlacedLabel> place_labels(const Panel& p, const LabelGeometry& geo);

// Each Gabor strategy against the naive sum, from one run's rows: the whole frame, the surface
// pass, and the Gabor evaluation alone (the surface pass's time above the untextured `none`
// row). `gabor` is NaN where the strategy's surface pass is not above `none` (noise level).
// Empty when the rows hold no `naive` or no `none` strategy.
struct SpeedUp {
  std::string strategy;
  double frame_ms = 0.0, frame = 0.0, surface = 0.0, gabor = 0.0;  // speed-ups are naive / strategy
  double error = 0.0;                                              // RMS vs naive, sigma
  bool meets_bar = false;                                          // error <= kTextureBar
};
inline constexpr double kTextureBar = 0.01;  // 1 % sigma RMS: the bar for replacing the naive sum
std::vector<SpeedUp> strategy_speedups(const std::vector<BenchRow>& rows);

}  // namespace ps::bench
