#include "app/bench/bench_plot.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace ps::bench {

namespace {

std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> out;
  size_t start = 0;
  for (;;) {
    const size_t comma = line.find(',', start);
    out.emplace_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

// A whole field as a number; "n/a" (what csv_text writes for a value that was not measured) is NaN.
bool parse_number(const std::string& s, double& out) {
  if (s == "n/a") {
    out = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

constexpr std::array<const char*, 14> kColumns = {
    "group", "value", "frame_ms", "surface_ms", "error_metric", "error", "pareto", "texture_rms_sigma",
    "texture_vs_ideal", "texture_vs_target", "displacement_rel", "distance_max_mm", "normal_deg", "footprint_pixels"};

// Fills one row from its fields (in kColumns order); returns the name of the first bad column.
const char* fill_row(const std::vector<std::string>& f, BenchRow& r) {
  r.group = f[0];
  r.value = f[1];
  r.metric = f[4];
  if (r.group.empty()) return "group";
  if (r.value.empty()) return "value";
  double* const numbers[] = {&r.m.frame_ms, &r.m.surface_ms, nullptr, &r.error, nullptr, &r.m.texture_rms_sigma,
                             &r.m.texture_vs_ideal, &r.m.texture_vs_target, &r.m.displacement_rel,
                             &r.m.distance_max_mm, &r.m.normal_deg};
  for (size_t i = 0; i < std::size(numbers); ++i)
    if (numbers[i] && !parse_number(f[i + 2], *numbers[i])) return kColumns[i + 2];
  if (!(r.m.frame_ms > 0.0)) return "frame_ms";  // a time axis is logarithmic or starts at 0: > 0 ms
  if (f[6] != "0" && f[6] != "1") return "pareto";
  r.pareto = f[6] == "1";
  double px = 0.0;
  if (!parse_number(f[13], px) || !(px >= 0.0) || px != std::floor(px)) return "footprint_pixels";
  r.m.footprint_pixels = static_cast<int>(px);
  return nullptr;
}

}  // namespace

Result<std::vector<BenchRow>> parse_csv(std::string_view text, const std::string& path) {
  std::vector<BenchRow> rows;
  int line_no = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    std::string_view line = text.substr(pos, nl - pos);
    pos = nl + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::vector<std::string> f = split_fields(line);
    if (line_no == 1) {
      if (f.size() != kColumns.size() || !std::equal(f.begin(), f.end(), kColumns.begin()))
        return make_error(path + ":1: not a bench.csv header; expected '" + std::string(kColumns[0]) + "," +
                          kColumns[1] + ",frame_ms,...' as written by `pseudoshadow bench`");
      continue;
    }
    if (line.empty()) continue;
    const std::string where = path + ":" + std::to_string(line_no) + ": ";
    if (f.size() != kColumns.size())
      return make_error(where + std::to_string(f.size()) + " fields, expected " + std::to_string(kColumns.size()));
    BenchRow r;
    if (const char* bad = fill_row(f, r))
      return make_error(where + "bad " + bad + " value (e.g. frame_ms 34.76, error 0.0079 or n/a, pareto 0 or 1)");
    rows.push_back(std::move(r));
  }
  if (line_no == 0) return make_error(path + ": empty file, expected a bench.csv header");
  if (rows.empty()) return make_error(path + ": no result rows after the header");
  return rows;
}

std::string short_label(std::string_view group, std::string_view value) {
  std::string v(value);
  const std::string prefix = std::string(group) + "_";
  if (v.size() > prefix.size() && v.compare(0, prefix.size(), prefix) == 0) v.erase(0, prefix.size());
  // Longest first, so "baked_linear_" is not read as "baked_".
  static const std::pair<const char*, const char*> kShort[] = {
      {"baked_linear_", "lin "}, {"baked_", "bake "}, {"stratified_", "strat "}, {"weighted_c", "c="}};
  for (const auto& [from, to] : kShort) {
    const std::string_view f(from);
    if (v.size() > f.size() && v.compare(0, f.size(), f) == 0) return to + v.substr(f.size());
  }
  std::replace(v.begin(), v.end(), '_', ' ');
  return v;
}

double Axis::unit(double v) const {
  if (log) return (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo));
  return (v - lo) / (hi - lo);
}

Axis fit_axis(const std::vector<double>& values) {
  assert(!values.empty() && "fit_axis: no values (a panel always has at least one point)");
  const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
  Axis a;
  a.log = *mn > 0.0 && *mx / *mn >= kLogAxisRatio;
  // 15 % of the span on each side: room for a marker and its label at the extremes.
  constexpr double kPad = 0.15;
  if (a.log) {
    const double l0 = std::log10(*mn), l1 = std::log10(*mx), pad = kPad * (l1 - l0);
    a.lo = std::pow(10.0, l0 - pad);
    a.hi = std::pow(10.0, l1 + pad);
    return a;
  }
  // Equal values (one point, or a metric that does not move) still need a non-empty range.
  const double span = *mx > *mn ? *mx - *mn : std::max(std::abs(*mx) * 0.1, 1e-9);
  a.lo = *mn - kPad * span;
  a.hi = *mx + kPad * span;
  if (*mn >= 0.0 && a.lo < 0.0) a.lo = 0.0;  // times and errors are never negative
  return a;
}

std::vector<Panel> group_panels(const std::vector<BenchRow>& rows) {
  std::vector<Panel> panels;
  for (const BenchRow& r : rows) {
    auto it = std::find_if(panels.begin(), panels.end(), [&](const Panel& p) { return p.group == r.group; });
    if (it == panels.end()) {
      panels.push_back(Panel{r.group, r.metric, {}, {}, {}});
      it = panels.end() - 1;
    }
    const double err = std::isfinite(r.error) ? std::max(r.error, kErrorFloor) : kErrorFloor;
    it->points.push_back(PlotPoint{r.m.frame_ms, err, short_label(r.group, r.value), r.pareto});
  }
  for (Panel& p : panels) {
    std::stable_sort(p.points.begin(), p.points.end(),
                     [](const PlotPoint& a, const PlotPoint& b) { return a.time_ms < b.time_ms; });
    std::vector<double> xs, ys;
    for (const PlotPoint& q : p.points) {
      xs.push_back(q.time_ms);
      ys.push_back(q.error);
    }
    p.x = fit_axis(xs);
    p.y = fit_axis(ys);
  }
  return panels;
}

namespace {

struct Box {
  double x0, y0, x1, y1;
};

double overlap(const Box& a, const Box& b) {
  const double w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return w > 0.0 && h > 0.0 ? w * h : 0.0;
}

// The part of `b` outside the unit square.
double outside(const Box& b) {
  const Box unit{0.0, 0.0, 1.0, 1.0};
  return (b.x1 - b.x0) * (b.y1 - b.y0) - overlap(b, unit);
}

}  // namespace

namespace {

// The eight boxes of one ring around the point (x, y): right, left, above, below, then the
// diagonals. `gx`, `gy` is the gap between the point and the box; the first ring touches the
// marker's edge, the outer ones are further out and get a leader line.
std::array<Box, 8> ring(double x, double y, double w, double h, double gx, double gy) {
  return {{{x + gx, y - h / 2, x + gx + w, y + h / 2}, {x - gx - w, y - h / 2, x - gx, y + h / 2},
           {x - w / 2, y + gy, x + w / 2, y + gy + h}, {x - w / 2, y - gy - h, x + w / 2, y - gy},
           {x + gx, y + gy, x + gx + w, y + gy + h}, {x + gx, y - gy - h, x + gx + w, y - gy},
           {x - gx - w, y + gy, x - gx, y + gy + h}, {x - gx - w, y - gy - h, x - gx, y - gy}}};
}

double cost(const Box& c, const std::vector<Box>& obstacles) {
  double sum = 4.0 * outside(c);  // leaving the panel costs more than covering something: a clipped label cannot be read
  for (const Box& o : obstacles) sum += overlap(c, o);
  return sum;
}

}  // namespace

std::vector<PlacedLabel> place_labels(const Panel& p, const LabelGeometry& geo) {
  std::vector<Box> obstacles;
  const double mw = 0.5 * geo.marker_px / geo.plot_w_px, mh = 0.5 * geo.marker_px / geo.plot_h_px;
  for (const PlotPoint& q : p.points) {
    const double x = p.x.unit(q.time_ms), y = p.y.unit(q.error);
    obstacles.push_back({x - mw, y - mh, x + mw, y + mh});
  }
  // Ring 1: a third of a character beyond the marker's edge; each further ring 1.2 lines out.
  const double step_x = 1.2 * geo.char_h_px / geo.plot_w_px, step_y = 1.2 * geo.char_h_px / geo.plot_h_px;
  constexpr int kRings = 4;
  std::vector<PlacedLabel> out;
  for (const PlotPoint& q : p.points) {
    const double x = p.x.unit(q.time_ms), y = p.y.unit(q.error);
    const double w = (q.label.size() + 0.5) * geo.char_w_px / geo.plot_w_px, h = geo.char_h_px / geo.plot_h_px;
    Box best{};
    int best_ring = 0;
    double best_cost = std::numeric_limits<double>::infinity();
    for (int r = 0; r < kRings && best_cost > 0.0; ++r) {
      const double gx = mw + geo.char_w_px / 3.0 / geo.plot_w_px + r * step_x;
      const double gy = mh + geo.char_h_px / 6.0 / geo.plot_h_px + r * step_y;
      for (const Box& c : ring(x, y, w, h, gx, gy)) {
        // Among colliding boxes an outer one must be clearly better: a label beside its point
        // reads faster than one on a leader. A free box ends the search (rings go outwards).
        const double k = cost(c, obstacles) * (1.0 + 0.5 * r);
        if (k < best_cost) {
          best_cost = k;
          best = c;
          best_ring = r;
        }
        if (k == 0.0) break;
      }
    }
    obstacles.push_back(best);
    PlacedLabel l{q.label, best.x0, best.y0, best.x1, best.y1, best_ring > 0, x, y};
    out.push_back(l);
  }
  return out;
}

std::vector<SpeedUp> strategy_speedups(const std::vector<BenchRow>& rows) {
  const BenchRow *naive = nullptr, *none = nullptr;
  for (const BenchRow& r : rows)
    if (r.group == "gabor_strategy") {
      if (r.value == "naive") naive = &r;
      if (r.value == "none") none = &r;
    }
  std::vector<SpeedUp> out;
  if (!naive || !none) return out;
  const double gabor_naive = naive->m.surface_ms - none->m.surface_ms;
  for (const BenchRow& r : rows) {
    if (r.group != "gabor_strategy" || &r == none) continue;
    const double gabor_r = r.m.surface_ms - none->m.surface_ms;
    out.push_back(SpeedUp{r.value, r.m.frame_ms, naive->m.frame_ms / r.m.frame_ms,
                          naive->m.surface_ms / r.m.surface_ms,
                          gabor_r > 0.0 ? gabor_naive / gabor_r : std::numeric_limits<double>::quiet_NaN(), r.error,
                          r.error <= kTextureBar});
  }
  return out;
}

}  // namespace ps::bench
