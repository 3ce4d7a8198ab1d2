#include "tune/overrides_file.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

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

Result<std::vector<std::string>> read_overrides(const std::string& path) {
  std::ifstream f(path);
  if (!f) return make_error(path + ": cannot open override file: " + std::strerror(errno));
  std::vector<std::string> out;
  std::string line;
  for (int n = 1; std::getline(f, line); ++n) {
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto eq = t.find('=');
    if (eq == std::string::npos || eq == 0 || trim(t.substr(eq + 1)).empty())
      return make_error(path + ":" + std::to_string(n) + ": expected KEY = VALUE (e.g. materials.wood.lambda_min = 0.4)");
    out.push_back(trim(t.substr(0, eq)) + "=" + trim(t.substr(eq + 1)));
  }
  return out;
}

}  // namespace ps
