#include "scene/lut.h"

#include "scene/path_policy.h"

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/file_io.h"
#if defined(__EMSCRIPTEN__)
#include <locale.h>
#include <stdlib.h>
#endif

namespace ps {

namespace {

// A first line that starts like a table's header is quoted whole (up to 48 characters); any
// other is quoted in 16 at most: the file may be of another kind, and not ours to echo.
std::string header_excerpt(std::string_view line) {
  return excerpt(line, line.starts_with("lut ") ? 48 : 16);
}

constexpr std::string_view kExample = " (e.g. `lut distance_mm intensity` then rows like `0.5 0.55`)";

std::string_view trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// Splits on spaces, tabs and commas.
std::vector<std::string_view> fields(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == ',')) ++i;
    std::size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != ',') ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

bool to_double(std::string_view s, double& out) {
#if defined(__EMSCRIPTEN__)
  // Emscripten 3.1.6's libc++ has no floating-point from_chars (docs/web.md): strtod in the "C"
  // locale, both correctly rounded. The same text form only: no sign "+", hex or inf/nan, as
  // from_chars's general format.
  if (s.empty() || s.size() > 64 || s[0] == '+' || s.find_first_of("xXpPiInN") != std::string_view::npos) return false;
  char buf[65];
  s.copy(buf, s.size());
  buf[s.size()] = '\0';
  static const locale_t c_locale = newlocale(LC_ALL_MASK, "C", nullptr);
  char* end = nullptr;
  out = strtod_l(buf, &end, c_locale);
  return end == buf + s.size() && std::isfinite(out);
#else
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
#endif
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

std::string_view lut_axis_name(LutAxis axis) {
  return axis == LutAxis::kDistanceMm ? "distance_mm" : "speed_mm_s";
}

std::string_view lut_value_name(LutAxis axis) {
  return axis == LutAxis::kDistanceMm ? "intensity" : "gain";
}

namespace {

// The first line: which table this is.
Status read_header(const std::vector<std::string_view>& f, std::string_view line, const std::string& where, Lut& lut) {
  if (f.size() == 3 && f[0] == "lut" && f[1] == "distance_mm" && f[2] == "intensity") {
    lut.axis = LutAxis::kDistanceMm;
  } else if (f.size() == 3 && f[0] == "lut" && f[1] == "speed_mm_s" && f[2] == "gain") {
    lut.axis = LutAxis::kSpeedMmS;
  } else {
    return make_error(where + "expected the header `lut distance_mm intensity` or `lut speed_mm_s gain`, got '" +
                      header_excerpt(line) + "'");
  }
  return ok_status();
}

// A row `x y`: x >= 0 and increasing, y in [0, 1], at most kMaxLutRows rows.
Status read_row(const std::vector<std::string_view>& f, std::string_view line, const std::string& where, Lut& lut) {
  LutPoint p;
  if (f.size() != 2 || !to_double(f[0], p.x) || !to_double(f[1], p.y))
    return make_error(where + "expected a row of two finite numbers `x y`, got '" + excerpt(line) + "'" +
                      std::string(kExample));
  if (p.x < 0.0) return make_error(where + std::string(lut_axis_name(lut.axis)) + " " + fmt(p.x) + " must be >= 0");
  if (p.y < 0.0 || p.y > 1.0)
    return make_error(where + std::string(lut_value_name(lut.axis)) + " " + fmt(p.y) + " must be in [0, 1]");
  if (!lut.points.empty() && !(p.x > lut.points.back().x))
    return make_error(where + std::string(lut_axis_name(lut.axis)) + " " + fmt(p.x) +
                      " must be greater than the previous row's " + fmt(lut.points.back().x) +
                      " (rows in increasing x)");
  if (static_cast<int>(lut.points.size()) == kMaxLutRows)
    return make_error(where + "more than " + std::to_string(kMaxLutRows) + " rows");
  lut.points.push_back(p);
  return ok_status();
}

}  // namespace

Result<Lut> parse_lut(std::string_view text, const std::string& source_name) {
  Lut lut;
  bool header = false;
  int line_no = 0, last_line = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t nl = std::min(text.find('\n', pos), text.size());
    std::string_view line = text.substr(pos, nl - pos);
    pos = nl + 1;
    ++line_no;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    line = trim(line);
    if (line.empty()) continue;
    last_line = line_no;
    const std::string where = source_name + ":" + std::to_string(line_no) + ": ";
    const std::vector<std::string_view> f = fields(line);
    Status st = header ? read_row(f, line, where, lut) : read_header(f, line, where, lut);
    if (!st) return st.error();
    header = true;
  }
  if (!header) return make_error(source_name + ":1: empty lookup table" + std::string(kExample));
  if (lut.points.size() < 2)
    return make_error(source_name + ":" + std::to_string(last_line) + ": a lookup table needs at least 2 rows, got " +
                      std::to_string(lut.points.size()));
  return lut;
}

Result<Lut> read_lut(const std::string& path, LutAxis expected) {
  // 256 rows of two numbers and comments fit in far less; a bigger file is not a table.
  constexpr std::uintmax_t kMaxBytes = 1 << 20;
  std::error_code ec;
  if (const std::uintmax_t bytes = std::filesystem::file_size(path, ec); !ec && bytes > kMaxBytes)
    return make_error(path + ": lookup table file is " + std::to_string(bytes) + " bytes, more than the limit of " +
                      std::to_string(kMaxBytes));
  const std::optional<std::string> read = read_whole_file(path);
  if (!read) return make_error(path + ": cannot open lookup table: " + std::strerror(errno));
  const std::string& text = *read;
  auto lut = parse_lut(text, path);
  if (!lut) return lut;
  if (lut->axis != expected) {
    // The header is the first line that is not blank or a comment.
    int line = 1;
    for (std::size_t pos = 0; pos < text.size(); ++line) {
      const std::size_t nl = std::min(text.find('\n', pos), text.size());
      std::string_view l = std::string_view(text).substr(pos, nl - pos);
      if (const auto hash = l.find('#'); hash != std::string_view::npos) l = l.substr(0, hash);
      if (!trim(l).empty()) break;
      pos = nl + 1;
    }
    return make_error(path + ":" + std::to_string(line) + ": this key needs a `lut " +
                      std::string(lut_axis_name(expected)) + " " + std::string(lut_value_name(expected)) +
                      "` table, the file is a `lut " + std::string(lut_axis_name(lut->axis)) + " " +
                      std::string(lut_value_name(lut->axis)) + "` table");
  }
  lut->file = path;
  return lut;
}

std::string format_lut(const Lut& lut, const std::vector<std::string>& comments) {
  std::string out;
  for (const std::string& c : comments) out += "# " + c + "\n";
  out += "lut " + std::string(lut_axis_name(lut.axis)) + " " + std::string(lut_value_name(lut.axis)) + "\n";
  for (const LutPoint& p : lut.points) out += fmt(p.x) + " " + fmt(p.y) + "\n";
  return out;
}

Status write_lut(const std::string& path, const Lut& lut, const std::vector<std::string>& comments) {
  return write_file_atomic(path, format_lut(lut, comments));
}

double lut_eval(const Lut& lut, double x) {
  assert(!lut.points.empty() && "lut_eval: empty table (check Lut::empty() and use the formula)");
  const std::vector<LutPoint>& p = lut.points;
  if (!(x > p.front().x)) return p.front().y;  // also NaN: the first row
  if (x >= p.back().x) return p.back().y;
  // First row with x_i > x (exists: x < back().x); its predecessor has x_{i-1} <= x.
  const auto hi = std::upper_bound(p.begin(), p.end(), x, [](double v, const LutPoint& q) { return v < q.x; });
  const LutPoint& b = *hi;
  const LutPoint& a = *(hi - 1);
  const double t = (x - a.x) / (b.x - a.x);
  return a.y + t * (b.y - a.y);
}

}  // namespace ps
