#include "study/fitts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "core/student_t.h"

namespace ps::study {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double dot(const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Point3 minus(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
bool finite(const Point3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

double sample_mean(std::span<const double> v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

// Sample standard deviation (n - 1), two-pass so that a large common offset (end points far
// from the origin) costs no digits.
double sample_sd(std::span<const double> v, double mean) {
  double ss = 0.0;
  for (double x : v) ss += (x - mean) * (x - mean);
  return std::sqrt(ss / static_cast<double>(v.size() - 1));
}

double shannon_id(double distance, double width) { return std::log2(distance / width + 1.0); }

}  // namespace

AxisProjection project_on_axis(const PointingTrial& t) {
  const Point3 axis = minus(t.target, t.start);
  const double length = std::sqrt(dot(axis, axis));
  if (!(length > 0.0) || !std::isfinite(length) || !finite(t.end) || (t.began && !finite(*t.began)))
    return {kNaN, kNaN};
  const Point3 u{axis.x / length, axis.y / length, axis.z / length};
  AxisProjection p;
  p.dx = dot(minus(t.end, t.target), u);
  p.amplitude = dot(minus(t.end, t.began ? *t.began : t.start), u);
  return p;
}

std::string_view to_string(CellStatus s) {
  switch (s) {
    case CellStatus::kOk: return "ok";
    case CellStatus::kTooFewTrials: return "not computable: fewer than 2 trials";
    case CellStatus::kNoSpread: return "not computable: SDx = 0 (every end point at one place on the axis)";
    case CellStatus::kNoAxis: return "not computable: a trial without a task axis (start = target, or not finite)";
    case CellStatus::kNoAmplitude: return "not computable: effective distance <= 0";
    case CellStatus::kNoTime: return "not computable: mean movement time <= 0";
  }
  return "?";
}

FittsCell fitts_cell(std::span<const PointingTrial> trials) {
  FittsCell c;
  c.effective_distance = c.mean_dx = c.sd_x = kNaN;
  c.effective_width = c.effective_id_bits = c.throughput_bps = c.mean_mt_s = kNaN;
  c.trials = static_cast<int>(trials.size());
  if (trials.empty()) {
    c.id_bits = kNaN;
    return c;  // kTooFewTrials
  }
  c.distance = trials.front().distance;
  c.width = trials.front().width;
  c.id_bits = shannon_id(c.distance, c.width);
  std::vector<double> dx, amplitude, mt;
  bool axes = true;
  for (const PointingTrial& t : trials) {
    if (!t.hit) ++c.misses;
    mt.push_back(t.movement_time_s);
    const AxisProjection p = project_on_axis(t);
    if (!std::isfinite(p.dx) || !std::isfinite(p.amplitude)) axes = false;
    dx.push_back(p.dx);
    amplitude.push_back(p.amplitude);
  }
  c.error_percent = 100.0 * c.misses / c.trials;
  c.mean_mt_s = sample_mean(mt);
  if (axes) {
    c.effective_distance = sample_mean(amplitude);
    c.mean_dx = sample_mean(dx);
  }
  // The order of the checks is the order of the arithmetic: a standard deviation needs two
  // trials, every projection needs an axis, We needs a spread, IDe a positive De, TP a time.
  if (c.trials < 2) {
    c.status = CellStatus::kTooFewTrials;
    return c;
  }
  if (!axes) {
    c.status = CellStatus::kNoAxis;
    return c;
  }
  c.sd_x = sample_sd(dx, c.mean_dx);
  if (!(c.sd_x > 0.0)) {
    c.status = CellStatus::kNoSpread;
    return c;
  }
  c.effective_width = kEffectiveWidthFactor * c.sd_x;
  if (!(c.effective_distance > 0.0)) {
    c.status = CellStatus::kNoAmplitude;
    return c;
  }
  c.effective_id_bits = shannon_id(c.effective_distance, c.effective_width);
  if (!(c.mean_mt_s > 0.0) || !std::isfinite(c.mean_mt_s)) {
    c.status = CellStatus::kNoTime;
    return c;
  }
  c.throughput_bps = c.effective_id_bits / c.mean_mt_s;
  c.status = CellStatus::kOk;
  return c;
}

std::vector<FittsCell> fitts_cells(std::span<const PointingTrial> trials) {
  std::map<std::pair<double, double>, std::vector<PointingTrial>> groups;  // ordered by D, then W
  for (const PointingTrial& t : trials) groups[{t.distance, t.width}].push_back(t);
  std::vector<FittsCell> cells;
  for (const auto& [key, group] : groups) cells.push_back(fitts_cell(group));
  return cells;
}

LinearFit fit_line(std::span<const double> x, std::span<const double> y, double confidence) {
  LinearFit f;
  f.points = static_cast<int>(std::min(x.size(), y.size()));
  f.intercept = f.slope = f.intercept_se = f.slope_se = f.r_squared = f.residual_sd = kNaN;
  f.intercept_ci = f.slope_ci = {kNaN, kNaN};
  if (f.points < 3) return f;
  const auto n = static_cast<double>(f.points);
  const double mx = sample_mean(x.first(f.points)), my = sample_mean(y.first(f.points));
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (int i = 0; i < f.points; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (!(sxx > 0.0)) return f;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  double sse = 0.0;
  for (int i = 0; i < f.points; ++i) {
    const double r = y[i] - (f.intercept + f.slope * x[i]);
    sse += r * r;
  }
  // r^2 = 1 - SSE / SST; with every y equal (SST = 0) the line explains all there is.
  f.r_squared = syy > 0.0 ? 1.0 - sse / syy : 1.0;
  f.residual_sd = std::sqrt(sse / (n - 2.0));
  f.slope_se = f.residual_sd / std::sqrt(sxx);
  f.intercept_se = f.residual_sd * std::sqrt(1.0 / n + mx * mx / sxx);
  const double t = student_t_quantile(0.5 + 0.5 * confidence, n - 2.0);
  f.slope_ci = {f.slope - t * f.slope_se, f.slope + t * f.slope_se};
  f.intercept_ci = {f.intercept - t * f.intercept_se, f.intercept + t * f.intercept_se};
  f.computable = true;
  return f;
}

FittsParticipant fitts_participant(std::span<const PointingTrial> trials, double confidence) {
  FittsParticipant p;
  p.cells = fitts_cells(trials);
  std::vector<double> id, mt_all, ide, mt_ok;
  double tp_sum = 0.0;
  for (const FittsCell& c : p.cells) {
    // The nominal regression needs only a time per cell, so a cell of one trial or of no spread
    // still counts there; the effective one needs IDe.
    if (c.trials > 0 && c.mean_mt_s > 0.0 && std::isfinite(c.mean_mt_s) && std::isfinite(c.id_bits))
      id.push_back(c.id_bits), mt_all.push_back(c.mean_mt_s);
    if (!c.computable()) continue;
    ++p.cells_used;
    tp_sum += c.throughput_bps;
    ide.push_back(c.effective_id_bits);
    mt_ok.push_back(c.mean_mt_s);
  }
  p.throughput_bps = p.cells_used > 0 ? tp_sum / p.cells_used : kNaN;
  p.on_id = fit_line(id, mt_all, confidence);
  p.on_effective_id = fit_line(ide, mt_ok, confidence);
  return p;
}

MeanInterval mean_interval(std::span<const double> values, double confidence) {
  MeanInterval m;
  std::vector<double> v;
  for (double x : values)
    if (std::isfinite(x)) v.push_back(x);
    else ++m.left_out;
  m.n = static_cast<int>(v.size());
  m.mean = v.empty() ? kNaN : sample_mean(v);
  m.sd = kNaN;
  m.ci = {kNaN, kNaN};
  if (m.n < 2) return m;
  m.sd = sample_sd(v, m.mean);
  const double half = student_t_quantile(0.5 + 0.5 * confidence, m.n - 1.0) * m.sd / std::sqrt(static_cast<double>(m.n));
  m.ci = {m.mean - half, m.mean + half};
  m.computable = true;
  return m;
}

MeanInterval throughput_across(std::span<const FittsParticipant> participants, double confidence) {
  std::vector<double> tp;
  for (const FittsParticipant& p : participants) tp.push_back(p.throughput_bps);
  return mean_interval(tp, confidence);
}

}  // namespace ps::study
