// --set KEY=VALUE: edits the parsed TOML document before conversion, so an override goes
// through exactly the same validation as the file (its errors say "--set KEY" instead of
// "file:line").
#include <algorithm>
#include <charconv>
#include <string_view>

#include "scene/scene_convert.h"

namespace ps::scene_detail {
namespace {

std::string trim(std::string_view s) {
  const auto begin = s.find_first_not_of(" \t");
  if (begin == std::string_view::npos) return {};
  const auto end = s.find_last_not_of(" \t");
  return std::string(s.substr(begin, end - begin + 1));
}

std::vector<std::string> split_dots(const std::string& key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t dot; (dot = key.find('.', start)) != std::string::npos; start = dot + 1) {
    parts.push_back(key.substr(start, dot - start));
  }
  parts.push_back(key.substr(start));
  return parts;
}

// VALUE is a TOML value ("0.4", "[0,0,5]", "\"x\"", "true"); anything TOML rejects (a bare
// word such as exact_max) is taken as a string.
toml::table parse_value(const std::string& value) {
  try {
    toml::table doc = toml::parse("v = " + value);
    if (doc.size() == 1 && doc.contains("v")) return doc;
  } catch (const toml::parse_error&) {
  }
  toml::table doc;
  doc.insert("v", value);
  return doc;
}

Section section_of(std::string_view name) {
  if (name == "camera") return Section::kCamera;
  if (name == "light") return Section::kLight;
  if (name == "probe") return Section::kProbe;
  if (name == "render") return Section::kRender;
  if (name == "materials") return Section::kMaterial;
  if (name == "surfaces") return Section::kSurface;
  return Section::kRoot;
}

Error unknown_key(const std::string& label, std::string_view key,
                  std::span<const std::string_view> known) {
  const auto matches = close_matches(key, known);
  if (matches.empty()) return make_error(label + ": unknown key; known keys: " + join(known));
  return make_error(label + ": unknown key; close matches: " + join(matches));
}

// Finds (or, for sections and materials, creates) the table that holds the key.
Result<toml::table*> target_table(toml::table& root, const std::vector<std::string>& parts,
                                  const std::string& label) {
  const Section section = section_of(parts[0]);
  const bool nested = section == Section::kMaterial || section == Section::kSurface;
  if (parts.size() != (nested ? 3u : 2u)) {
    return make_error(label + ": expected " +
                      (nested ? parts[0] + ".NAME.KEY" : parts[0] + ".KEY") + "=VALUE");
  }
  if (section == Section::kSurface) {
    toml::array* surfaces = root["surfaces"].as_array();
    std::size_t index = 0;
    const auto& s = parts[1];
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), index);
    const std::size_t count = surfaces ? surfaces->size() : 0;
    if (ec != std::errc() || end != s.data() + s.size() || index >= count) {
      return make_error(label + ": no surface '" + s + "' (the scene has " +
                        std::to_string(count) + " surfaces, numbered from 0)");
    }
    toml::table* t = (*surfaces)[index].as_table();
    if (!t) return make_error(label + ": surfaces." + s + " is not a table");
    return t;
  }
  auto [it, inserted] = root.insert(parts[0], toml::table{});
  toml::table* t = it->second.as_table();
  if (t && section == Section::kMaterial) {
    auto [m, added] = t->insert(parts[1], toml::table{});
    t = m->second.as_table();
  }
  if (!t) return make_error(label + ": the scene's '" + parts[0] + "' is not a table");
  return t;
}

}  // namespace

Status apply_override(toml::table& root, const std::string& text, ParseContext& ctx) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) {
    return make_error("--set " + text + ": expected KEY=VALUE (e.g. probe.radius_mm=10)");
  }
  const std::string key = trim(std::string_view(text).substr(0, eq));
  const std::string label = "--set " + key;
  const std::vector<std::string> parts = split_dots(key);
  const Section section = section_of(parts[0]);
  if (section == Section::kRoot) return unknown_key(label, parts[0], known_keys(Section::kRoot));
  const auto known = known_keys(section);
  const std::string& leaf = parts.back();
  if (parts.size() >= 2 && std::find(known.begin(), known.end(), leaf) == known.end()) {
    return unknown_key(label, leaf, known);
  }
  Result<toml::table*> table = target_table(root, parts, label);
  if (!table) return table.error();
  toml::table value = parse_value(trim(std::string_view(text).substr(eq + 1)));
  value["v"].node()->visit([&](auto& node) { (*table)->insert_or_assign(leaf, std::move(node)); });
  ctx.overridden[key] = label;
  return ok_status();
}

}  // namespace ps::scene_detail
