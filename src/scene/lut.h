// Perceptual lookup tables (thesis §5.2): a material's distance -> intensity or speed -> gain
// curve given as rows of (x, y) instead of the thesis formula (docs/scene-format.md, "Lookup
// tables"). File format, one item per line, `#` starts a comment, blank lines are skipped:
//
//   lut distance_mm intensity        header: the x axis and its unit, then the y quantity
//   0      0.82                      rows: x y (a comma may separate them), x strictly
//   0.5    0.55                      increasing, x >= 0, y in [0, 1], 2..kMaxLutRows rows
//
// Headers: `lut distance_mm intensity` (materials.NAME.intensity_lut) and `lut speed_mm_s gain`
// (materials.NAME.speed_gain_lut). Between rows the value is linear in x; before the first and
// after the last row it is the end row's y (clamped ends). The GPU reads the same rows from a
// uniform block (glsl/lib/intensity_lut.glsl) and interpolates them the same way.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"

namespace ps {

enum class LutAxis { kDistanceMm, kSpeedMmS };

// The most rows a table may have: the GPU's binary search takes log2(256) = 8 fetches.
inline constexpr int kMaxLutRows = 256;

struct LutPoint {
  double x = 0.0, y = 0.0;
  bool operator==(const LutPoint&) const = default;
};

struct Lut {
  LutAxis axis = LutAxis::kDistanceMm;
  std::vector<LutPoint> points;  // empty: no table (the formula applies)
  std::string file;              // where it was read from (absolute after loading); "" inline
  bool empty() const { return points.empty(); }
  bool operator==(const Lut& o) const { return axis == o.axis && points == o.points; }
};

// "distance_mm" / "speed_mm_s"; the header's y names "intensity" / "gain".
std::string_view lut_axis_name(LutAxis axis);
std::string_view lut_value_name(LutAxis axis);

// Parses a table's text; `source_name` names it in errors ("<source>:<line>: <what>").
Result<Lut> parse_lut(std::string_view text, const std::string& source_name);
// Reads and parses a file; `expected` is the axis the key needs (a speed table given as
// intensity_lut is an error naming the header's line).
Result<Lut> read_lut(const std::string& path, LutAxis expected);

// The text of a table (header, a comment line per entry of `comments`, then one row per point
// with 9 significant digits: a written table reads back within 1e-9 relative).
std::string format_lut(const Lut& lut, const std::vector<std::string>& comments = {});
// format_lut written atomically (core/file_io.h).
Status write_lut(const std::string& path, const Lut& lut,
                 const std::vector<std::string>& comments = {});

// The table's value at x: linear between rows, the end rows' y outside them. Asserts non-empty.
double lut_eval(const Lut& lut, double x);

// `rows` rows sampled from f at x_i = x_max * i / (rows - 1) (for editing a formula as a curve
// and for tests).
template <class F>
Lut sample_lut(LutAxis axis, double x_max, int rows, F&& f) {
  Lut out;
  out.axis = axis;
  for (int i = 0; i < rows; ++i) {
    const double x = x_max * i / (rows - 1);
    out.points.push_back({x, f(x)});
  }
  return out;
}

}  // namespace ps
