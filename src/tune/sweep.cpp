#include "tune/sweep.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "scene/scene_io.h"
#include "scene/scene_keys.h"

namespace ps {

namespace {

std::string trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  return std::string(s.substr(b, s.find_last_not_of(" \t") - b + 1));
}

// Splits at commas outside [...] so array values such as [0,0,5] stay whole.
std::vector<std::string> split_list(std::string_view text) {
  std::vector<std::string> out;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    const char c = i < text.size() ? text[i] : ',';
    if (c == '[') ++depth;
    if (c == ']') --depth;
    if (c == ',' && depth <= 0) {
      out.push_back(trim(text.substr(start, i - start)));
      start = i + 1;
    }
  }
  return out;
}

Result<double> parse_number(const std::string& label, const std::string& what, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size())
    return make_error(label + ": " + what + " '" + text + "' is not a number");
  if (!std::isfinite(v)) return make_error(label + ": " + what + " must be finite (got " + text + ")");
  return v;
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

Result<std::vector<std::string>> parse_range(const std::string& label, const std::string& value) {
  const auto c1 = value.find(':'), c2 = value.find(':', c1 + 1);
  if (c2 == std::string::npos || value.find(':', c2 + 1) != std::string::npos)
    return make_error(label + ": expected FROM:TO:STEPS, e.g. 0.2:1.0:5");
  auto from = parse_number(label, "FROM", trim(value.substr(0, c1)));
  if (!from) return from.error();
  auto to = parse_number(label, "TO", trim(value.substr(c1 + 1, c2 - c1 - 1)));
  if (!to) return to.error();
  const std::string steps_text = trim(value.substr(c2 + 1));
  char* end = nullptr;
  const long steps = std::strtol(steps_text.c_str(), &end, 10);
  if (steps_text.empty() || end != steps_text.c_str() + steps_text.size() || steps < 2 ||
      steps > static_cast<long>(kMaxSweepCells))
    return make_error(label + ": STEPS must be a whole number in [2, " + std::to_string(kMaxSweepCells) +
                      "] (got '" + steps_text + "')");
  std::vector<std::string> values;
  for (long i = 0; i < steps; ++i)
    values.push_back(number_text(*from + (*to - *from) * static_cast<double>(i) / static_cast<double>(steps - 1)));
  return values;
}

}  // namespace

Result<SweepAxis> parse_sweep(std::string_view spec) {
  const std::string label = "--sweep " + std::string(spec);
  const auto eq = spec.find('=');
  if (eq == std::string_view::npos || trim(spec.substr(0, eq)).empty())
    return make_error(label + ": expected KEY=V1,V2,... or KEY=FROM:TO:STEPS");
  SweepAxis axis{trim(spec.substr(0, eq)), {}};
  const std::string value = trim(spec.substr(eq + 1));
  const bool range = value.find(':') != std::string::npos && value.find(',') == std::string::npos &&
                     value.find('[') == std::string::npos && value.find('"') == std::string::npos;
  if (range) {
    auto values = parse_range(label, value);
    if (!values) return values.error();
    axis.values = std::move(values.value());
    return axis;
  }
  axis.values = split_list(value);
  for (const auto& v : axis.values) {
    if (v.empty()) return make_error(label + ": empty value in the list");
    if (v == "nan" || v == "+nan" || v == "-nan") return make_error(label + ": values must be finite (got " + v + ")");
  }
  return axis;
}

Result<SweepAxis> parse_scene_sweep(std::string_view list) {
  SweepAxis axis{std::string(kSceneAxisKey), split_list(list)};
  for (const auto& v : axis.values)
    if (v.empty()) return make_error("--sweep-scenes: empty file name in the list");
  return axis;
}

Result<std::size_t> sweep_cell_count(const std::vector<SweepAxis>& axes) {
  std::size_t n = 1;
  for (const auto& a : axes) {
    n *= a.values.size();
    if (n > kMaxSweepCells) break;
  }
  if (n > kMaxSweepCells) {
    std::string sizes;
    for (const auto& a : axes) sizes += (sizes.empty() ? "" : " x ") + std::to_string(a.values.size());
    return make_error("the sweep has more than " + std::to_string(kMaxSweepCells) + " cells (" + sizes +
                      "); split it into several sheets");
  }
  return n;
}

std::vector<std::size_t> sweep_cell(const std::vector<SweepAxis>& axes, std::size_t index) {
  std::vector<std::size_t> cell(axes.size());
  for (std::size_t i = axes.size(); i-- > 0;) {
    cell[i] = index % axes[i].values.size();
    index /= axes[i].values.size();
  }
  return cell;
}

std::string sweep_label(const std::vector<SweepAxis>& axes, const std::vector<std::size_t>& cell) {
  std::string label;
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const std::string& v = axes[i].values[cell[i]];
    if (!label.empty()) label += ' ';
    if (axes[i].key == kSceneAxisKey) {
      label += std::filesystem::path(v).stem().string();
    } else {
      // The key as given, and the value's unit: "probe.velocity=[500,0,0] mm/s".
      const auto dot = axes[i].key.rfind('.');
      const std::string_view unit =
          scene_detail::key_unit(std::string_view(axes[i].key).substr(dot == std::string::npos ? 0 : dot + 1));
      label += axes[i].key + "=" + v + (unit.empty() ? "" : " " + std::string(unit));
    }
  }
  return label;
}

}  // namespace ps
