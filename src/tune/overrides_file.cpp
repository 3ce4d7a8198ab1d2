#include "tune/overrides_file.h"

#include <cassert>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/file_io.h"
#include "scene/scene_io.h"
#include "tune/edit_key.h"

namespace ps {

namespace fs = std::filesystem;

std::string overrides_path_for(const std::string& scene_path) {
  fs::path p(scene_path);
  p.replace_extension(".overrides.toml");
  return p.string();
}

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

bool is_number(const std::string& v) {
  if (v.empty()) return false;
  char* end = nullptr;
  std::strtod(v.c_str(), &end);
  return end == v.c_str() + v.size();
}

std::string quoted(const std::string& v) {
  std::string out = "\"";
  for (char c : v) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string override_value_text(const std::string& value) {
  const std::string v = trim(value);
  if (is_number(v) || v == "true" || v == "false") return v;
  if (!v.empty() && (v.front() == '[' || v.front() == '"')) return v;
  return quoted(v);
}

std::string format_overrides(const std::map<std::string, std::string>& edits, const std::string& scene_name) {
  std::string text = "# Overrides for " + scene_name + " written by `pseudoshadow run`/`tune`.\n"
                     "# One `--set KEY=VALUE` per line; apply with --overrides THIS_FILE.\n";
  for (const auto& [key, value] : edits) text += key + " = " + override_value_text(value) + "\n";
  return text;
}

std::string curve_file_for(const std::string& overrides_path, const std::string& key) {
  // "materials.wood.intensity_lut" -> "wood.intensity"; "a.overrides.toml" -> "a"
  const EditKey k = EditKey::parse(key);
  const std::string_view field = k.field();
  const std::string rest = std::string(k.material()) + "." + std::string(field.substr(0, field.size() - 4));  // "_lut"
  fs::path p(overrides_path);
  std::string stem = p.filename().string();
  if (const auto dot = stem.find(".overrides"); dot != std::string::npos) stem = stem.substr(0, dot);
  else stem = p.stem().string();
  return (p.parent_path() / (stem + "." + rest + ".lut")).string();
}

Status save_overrides_file(const std::string& path, const std::map<std::string, std::string>& edits,
                           const std::map<std::string, Lut>& curves, const std::string& scene_name) {
  std::map<std::string, std::string> lines = edits;
  for (const auto& [key, lut] : curves) {
    assert(EditKey::parse(key).curve() != CurveKind::kNone && "save_overrides_file: not a curve key");
    const std::string file = curve_file_for(path, key);
    if (Status s = prepare_output_dir(file); !s) return s;
    if (Status s = write_lut(file, lut, {"Edited in the tuning panel: " + key + " of " + scene_name}); !s) return s;
    // The table lies next to the override file, and read_overrides resolves against that file.
    lines[key] = quoted(fs::path(file).filename().generic_string());
  }
  return write_file_atomic(path, format_overrides(lines, scene_name));
}

Result<std::vector<std::string>> read_overrides(const std::string& path) {
  std::ifstream f(path);
  if (!f) return make_error(path + ": cannot open override file: " + std::strerror(errno));
  std::error_code ec;
  const fs::path dir = fs::absolute(path, ec).parent_path();
  std::vector<std::string> out;
  std::string line;
  for (int n = 1; std::getline(f, line); ++n) {
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto eq = t.find('=');
    if (eq == std::string::npos || eq == 0 || trim(t.substr(eq + 1)).empty())
      return make_error(path + ":" + std::to_string(n) + ": expected KEY = VALUE (e.g. materials.wood.lambda_min = 0.4)");
    out.push_back(anchor_override_path(trim(t.substr(0, eq)) + "=" + trim(t.substr(eq + 1)), dir.string()));
  }
  return out;
}

}  // namespace ps
