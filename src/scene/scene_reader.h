// TableReader: reads and validates the keys of one scene table into the Scene model.
// Errors are sticky (the first one wins) so converters read as flat lists of keys; every
// message starts with the location: "file:line:" or, for a value given on the command line,
// "--set KEY:".
#pragma once

#include <limits>
#include <map>
#include <set>
#include <span>
#include <string>
#include <string_view>

#include <glm/glm.hpp>
#include <toml++/toml.h>

#include "core/result.h"
#include "scene/scene_keys.h"

namespace ps::scene_detail {

struct ParseContext {
  std::string source_name;  // file name used in messages
  std::string base_dir;     // relative paths resolve against this
  std::map<std::string, std::string, std::less<>> overridden;  // dotted key path -> "--set KEY"
};

// Allowed interval for a number; open ends exclude the bound.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
  static Range any() { return {}; }
  static Range positive(double hi = std::numeric_limits<double>::infinity()) {
    return {0.0, hi, true, false};
  }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  bool contains(double v) const;
  std::string describe() const;  // "> 0", "in [0, 1]"
};

std::string format_number(double value);

class TableReader {
 public:
  // `path` is the dotted path of the table ("camera", "materials.wood", "surfaces.0"),
  // `label` how messages name it ("[camera]", "[materials.wood]", "[[surfaces]] #0").
  TableReader(const ParseContext& ctx, const toml::table* table, Section section,
              std::string path, std::string label);
  // Asserts (debug) that the converter asked for every known key of the section.
  ~TableReader();

  void number(std::string_view key, double& out, Range range);
  void angle_deg(std::string_view key, double& out_rad, Range range_deg);
  void integer(std::string_view key, int& out, long long lo, long long hi);
  void seed(std::string_view key, std::uint32_t& out);
  void boolean(std::string_view key, bool& out);
  void string(std::string_view key, std::string& out);
  void vec3(std::string_view key, glm::dvec3& out, Range range);
  void vec2(std::string_view key, glm::dvec2& out, Range range);
  void int2(std::string_view key, int& x, int& y, long long lo, long long hi);
  // Reads a string that must be one of `choices`; `out` gets its index.
  void choice(std::string_view key, int& out, std::span<const std::string_view> choices);
  // Reads a file name, resolves it against the base dir and checks that the file exists.
  void file(std::string_view key, std::string& out);

  void check_unknown_keys();
  // Cross-key rule: when `ok` is false, fails at `key` with "'key' <what>".
  void require(bool ok, std::string_view key, const std::string& what);
  void fail(std::string_view key, const std::string& what);

  bool has(std::string_view key) const;
  bool ok() const { return ok_; }
  Status status() const;
  std::string where(std::string_view key) const;  // "file:line" or "--set KEY"

 private:
  const toml::node* visit(std::string_view key);
  bool read_numbers(std::string_view key, const toml::node* node, std::span<double> out,
                    Range range);
  bool check_number(std::string_view key, double value, Range range);

  const ParseContext& ctx_;
  const toml::table* table_;
  Section section_;
  std::string path_;
  std::string label_;
  std::set<std::string, std::less<>> visited_;
  bool ok_ = true;
  std::string error_;
};

}  // namespace ps::scene_detail
