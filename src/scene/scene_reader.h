// TableReader: reads and validates the keys of one scene table into the Scene model.
// Errors are sticky (the first one wins) so converters read as flat lists of keys; every
// message starts with the location: "file:line:" or, for a value given on the command line,
// "--set KEY:".
#pragma once

#include <limits>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <toml++/toml.h>

#include "core/result.h"
#include "scene/path_policy.h"
#include "scene/scene_keys.h"

namespace ps::scene_detail {

// A [materials.NAME] table that came from an included file (scene_include.cpp).
struct IncludedMaterial {
  toml::table* table = nullptr;  // owned by ParseContext::included_docs
  std::string source_name;       // the file that defines it, as messages name it
  std::string base_dir;          // its relative paths resolve against this
  std::string identity;          // "canonical path:line": the same definition reached twice
  int order = 0;                 // depth-first inclusion order
};

struct ParseContext {
  std::string source_name;  // file name used in messages
  std::string base_dir;     // relative paths resolve against this
  std::map<std::string, std::string, std::less<>> overridden;  // dotted key path -> "--set KEY"
  // Materials from `include`d files that the scene does not define itself, by name; --set
  // edits these tables in place, so an override reaches an included material too.
  std::vector<std::unique_ptr<toml::table>> included_docs;
  std::map<std::string, IncludedMaterial, std::less<>> included;
  PathPolicy paths;  // which files the scene may reference (scene/path_policy.h)
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
  // A nested table ([materials.NAME.haptic]) or array of tables ([[...texture]]): null when
  // absent or after an error; the wrong kind of value fails with the expected TOML form.
  const toml::table* sub_table(std::string_view key);
  const toml::array* table_array(std::string_view key);
  // Adopts another reader's error (a nested table's) so the first error still wins.
  void adopt(const Status& nested);

  void check_unknown_keys();
  // Cross-key rule: when `ok` is false, fails at `key` with "'key' <what>".
  void require(bool ok, std::string_view key, const std::string& what);
  void fail(std::string_view key, const std::string& what);

  bool has(std::string_view key) const;
  bool ok() const { return ok_; }
  Status status() const;
  std::string where(std::string_view key) const;  // "file:line" or "--set KEY"
  bool from_user(std::string_view key) const;     // set by --set / --overrides, not the file
  const std::string& path() const { return path_; }
  const std::string& label() const { return label_; }

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
