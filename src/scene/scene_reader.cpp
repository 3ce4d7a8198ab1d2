#include "scene/scene_reader.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace ps::scene_detail {

bool Range::contains(double v) const {
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Range::describe() const {
  if (std::isinf(hi)) return (lo_open ? "> " : ">= ") + format_number(lo);
  if (std::isinf(lo)) return (hi_open ? "< " : "<= ") + format_number(hi);
  return std::string("in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " +
         format_number(hi) + (hi_open ? ")" : "]");
}

std::string format_number(double value) {
  std::ostringstream out;
  out << value;  // %g-like: "0.5", "1e+06", "nan", "inf"
  return out.str();
}

TableReader::TableReader(const ParseContext& ctx, const toml::table* table, Section section,
                         std::string path, std::string label)
    : ctx_(ctx), table_(table), section_(section), path_(std::move(path)),
      label_(std::move(label)) {}

TableReader::~TableReader() {
  // Only meaningful when conversion ran to the end (an early error stops reading). The root
  // table's keys are whole sections, handled by read_sections() rather than read one by one.
  if (!ok_ || section_ == Section::kRoot) return;
  for (std::string_view key : known_keys(section_)) {
    assert(visited_.count(key) &&
           "TableReader: converter did not read a key listed in scene_keys.cpp");
    (void)key;
  }
}

bool TableReader::from_user(std::string_view key) const {
  return ctx_.overridden.contains(path_ + "." + std::string(key));
}

std::string TableReader::where(std::string_view key) const {
  const std::string full = path_ + "." + std::string(key);
  if (auto it = ctx_.overridden.find(full); it != ctx_.overridden.end()) return it->second;
  long line = 0;
  if (const toml::node* node = table_ ? table_->get(key) : nullptr) {
    line = static_cast<long>(node->source().begin.line);
  }
  if (line == 0 && table_) line = static_cast<long>(table_->source().begin.line);
  return ctx_.source_name + ":" + std::to_string(std::max(line, 1L));
}

void TableReader::fail(std::string_view key, const std::string& what) {
  if (!ok_) return;
  ok_ = false;
  error_ = where(key) + ": '" + std::string(key) + "' " + what;
}

void TableReader::require(bool ok, std::string_view key, const std::string& what) {
  if (!ok) fail(key, what);
}

bool TableReader::has(std::string_view key) const { return table_ && table_->contains(key); }

Status TableReader::status() const {
  if (ok_) return ok_status();
  return make_error(error_);
}

const toml::node* TableReader::visit(std::string_view key) {
  assert(std::find(known_keys(section_).begin(), known_keys(section_).end(), key) !=
             known_keys(section_).end() &&
         "TableReader::visit: key missing from scene_keys.cpp");
  visited_.emplace(key);
  if (!ok_ || !table_) return nullptr;
  return table_->get(key);
}

bool TableReader::check_number(std::string_view key, double value, Range range) {
  if (!std::isfinite(value)) {
    fail(key, "must be finite (got " + format_number(value) + ")");
    return false;
  }
  if (!range.contains(value)) {
    fail(key, "must be " + range.describe() + " (got " + format_number(value) + ")");
    return false;
  }
  return true;
}

void TableReader::number(std::string_view key, double& out, Range range) {
  const toml::node* node = visit(key);
  if (!node) return;
  if (!node->is_number()) return fail(key, "must be a number");
  const double value = node->value<double>().value_or(0.0);
  if (check_number(key, value, range)) out = value;
}

void TableReader::angle_deg(std::string_view key, double& out_rad, Range range_deg) {
  // Only convert a value that is present, so defaults stay exact.
  const bool present = has(key);
  double degrees = 0.0;
  number(key, degrees, range_deg);
  if (present && ok_) out_rad = degrees * M_PI / 180.0;
}

void TableReader::integer(std::string_view key, int& out, long long lo, long long hi) {
  const toml::node* node = visit(key);
  if (!node) return;
  if (!node->is_integer()) return fail(key, "must be an integer");
  const long long value = node->value<int64_t>().value_or(0);
  if (value < lo || value > hi) {
    return fail(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                         "] (got " + std::to_string(value) + ")");
  }
  out = static_cast<int>(value);
}

void TableReader::seed(std::string_view key, std::uint32_t& out) {
  int unused = 0;
  const toml::node* node = table_ ? table_->get(key) : nullptr;
  integer(key, unused, 0, 0xFFFFFFFFLL);  // validates type and range
  if (ok_ && node) out = static_cast<std::uint32_t>(node->value<int64_t>().value_or(0));
}

void TableReader::boolean(std::string_view key, bool& out) {
  const toml::node* node = visit(key);
  if (!node) return;
  if (!node->is_boolean()) return fail(key, "must be true or false");
  out = node->value<bool>().value_or(out);
}

void TableReader::string(std::string_view key, std::string& out) {
  const toml::node* node = visit(key);
  if (!node) return;
  if (!node->is_string()) return fail(key, "must be a string");
  out = node->value<std::string>().value_or(out);
}

bool TableReader::read_numbers(std::string_view key, const toml::node* node,
                               std::span<double> out, Range range) {
  const std::string shape = "must be an array of " + std::to_string(out.size()) + " numbers";
  const toml::array* array = node->as_array();
  if (!array) return fail(key, shape), false;
  if (array->size() != out.size()) {
    return fail(key, shape + " (got " + std::to_string(array->size()) + " elements)"), false;
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!(*array)[i].is_number()) return fail(key, shape), false;
    out[i] = (*array)[i].value<double>().value_or(0.0);
    if (!check_number(key, out[i], range)) return false;
  }
  return true;
}

void TableReader::vec3(std::string_view key, glm::dvec3& out, Range range) {
  const toml::node* node = visit(key);
  double v[3];
  if (node && read_numbers(key, node, v, range)) out = {v[0], v[1], v[2]};
}

void TableReader::vec2(std::string_view key, glm::dvec2& out, Range range) {
  const toml::node* node = visit(key);
  double v[2];
  if (node && read_numbers(key, node, v, range)) out = {v[0], v[1]};
}

void TableReader::int2(std::string_view key, int& x, int& y, long long lo, long long hi) {
  const toml::node* node = visit(key);
  double v[2];
  if (!node || !read_numbers(key, node, v, Range::any())) return;
  for (double c : v) {
    if (c != std::floor(c)) return fail(key, "must be an array of 2 integers");
    if (c < lo || c > hi) {
      return fail(key, "must have both values in [" + std::to_string(lo) + ", " +
                           std::to_string(hi) + "] (got " + format_number(c) + ")");
    }
  }
  x = static_cast<int>(v[0]);
  y = static_cast<int>(v[1]);
}

void TableReader::choice(std::string_view key, int& out,
                         std::span<const std::string_view> choices) {
  std::string value;
  const bool present = visit(key) != nullptr;
  string(key, value);
  if (!present || !ok_) return;
  const auto it = std::find(choices.begin(), choices.end(), value);
  if (it == choices.end()) {
    return fail(key, "must be one of " + join(choices, ", ") + " (got '" + value + "')");
  }
  out = static_cast<int>(it - choices.begin());
}

void TableReader::file(std::string_view key, std::string& out) {
  std::string name;
  string(key, name);
  if (!ok_ || name.empty()) return;
  namespace fs = std::filesystem;
  fs::path path(name);
  if (path.is_relative()) path = fs::path(ctx_.base_dir) / path;
  path = path.lexically_normal();
  // Confined before its existence is checked: a scene must not learn which files exist elsewhere.
  if (!from_user(key)) {
    if (Status s = ctx_.paths.admit(path, "names"); !s) return fail(key, s.error().message);
  }
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    return fail(key, "file not found: " + path.string());
  }
  out = path.string();
}

const toml::table* TableReader::sub_table(std::string_view key) {
  const toml::node* node = visit(key);
  if (!node) return nullptr;
  if (!node->is_table()) {
    fail(key, "must be a table ([" + path_ + "." + std::string(key) + "])");
    return nullptr;
  }
  return node->as_table();
}

const toml::array* TableReader::table_array(std::string_view key) {
  const toml::node* node = visit(key);
  if (!node) return nullptr;
  const toml::array* array = node->as_array();
  if (!array || !array->is_array_of_tables()) {
    fail(key, "must be an array of tables ([[" + path_ + "." + std::string(key) + "]])");
    return nullptr;
  }
  return array;
}

void TableReader::adopt(const Status& nested) {
  if (!ok_ || nested) return;
  ok_ = false;
  error_ = nested.error().message;
}

void TableReader::check_unknown_keys() {
  if (!table_ || !ok_) return;
  for (const auto& [key, node] : *table_) {
    const auto known = known_keys(section_);
    if (std::find(known.begin(), known.end(), key.str()) != known.end()) continue;
    std::string message = where(key.str()) + ": unknown key '" + std::string(key.str()) +
                          "' in " + label_;
    const auto matches = close_matches(key.str(), known);
    if (!matches.empty()) message += "; did you mean '" + std::string(matches[0]) + "'?";
    ok_ = false;
    error_ = message;
    return;
  }
}

}  // namespace ps::scene_detail
