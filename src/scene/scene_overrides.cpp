// --set KEY=VALUE: edits the parsed TOML document before conversion, so an override goes
// through exactly the same validation as the file (its errors say "--set KEY" instead of
// "file:line").
#include <algorithm>
#include <charconv>
#include <filesystem>
#include <string_view>

#include "scene/scene_convert.h"
#include "scene/scene_io.h"
#include "scene/toml_text.h"

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
  if (Result<toml::table> doc = parse_toml("v = " + value, "--set"); doc && doc->size() == 1 && doc->contains("v"))
    return std::move(doc.value());
  toml::table doc;
  doc.insert("v", value);
  return doc;
}

Section section_of(std::string_view name) {
  if (name == "camera") return Section::kCamera;
  if (name == "light") return Section::kLight;
  if (name == "navigation") return Section::kNavigation;
  if (name == "probe") return Section::kProbe;
  if (name == "render") return Section::kRender;
  if (name == "materials") return Section::kMaterial;
  if (name == "surfaces") return Section::kSurface;
  if (name == "fields") return Section::kField;
  if (name == "bodies") return Section::kBody;
  if (name == "buttons") return Section::kButton;
  return Section::kRoot;
}

Error unknown_key(const std::string& label, std::string_view key,
                  std::span<const std::string_view> known) {
  const auto matches = close_matches(key, known);
  if (matches.empty()) return make_error(label + ": unknown key; known keys: " + join(known));
  return make_error(label + ": unknown key; close matches: " + join(matches));
}

// Inside [materials.NAME] the path's shape says which table the leaf belongs to:
// materials.NAME.KEY, materials.NAME.haptic.KEY, materials.NAME.haptic.texture.N.KEY.
Result<Section> material_leaf_section(const std::vector<std::string>& parts,
                                      const std::string& label) {
  if (parts.size() == 3) return Section::kMaterial;
  if (parts.size() == 4 && parts[2] == "haptic") return Section::kHaptic;
  if (parts.size() == 6 && parts[2] == "haptic" && parts[3] == "texture") {
    return Section::kHapticWave;
  }
  return make_error(label + ": expected materials.NAME.KEY=VALUE (or materials.NAME.haptic.KEY, "
                    "materials.NAME.haptic.texture.N.KEY)");
}

// Element `index_text` of an array of tables that must already exist.
// `what` names one element ("surface"), `holder` the array's owner ("the scene").
Result<toml::table*> element(toml::array* array, const std::string& index_text,
                             const std::string& label, const std::string& what,
                             const std::string& holder) {
  std::size_t index = 0;
  const auto& s = index_text;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), index);
  const std::size_t count = array ? array->size() : 0;
  if (ec != std::errc() || end != s.data() + s.size() || index >= count) {
    return make_error(label + ": no " + what + " '" + s + "' (" + holder + " has " +
                      std::to_string(count) + " " + (what == "body" ? std::string("bodies") : what + "s") +
                      ", numbered from 0)");
  }
  toml::table* t = (*array)[index].as_table();
  if (!t) return make_error(label + ": " + what + " " + s + " is not a table");
  return t;
}

toml::table* child_table(toml::table& parent, const std::string& key) {
  auto [it, inserted] = parent.insert(key, toml::table{});
  return it->second.as_table();
}

// The [materials.NAME] table to edit: the scene's own, else an included one (edited in place,
// so --set changes one key of a library material), else a new one.
Result<toml::table*> material_table(toml::table& root, const std::vector<std::string>& parts,
                                    const std::string& label, ParseContext& ctx) {
  toml::table* materials = child_table(root, "materials");
  if (!materials) return make_error(label + ": the scene's 'materials' is not a table");
  toml::table* t = nullptr;
  if (auto it = ctx.included.find(parts[1]); !materials->contains(parts[1]) &&
                                             it != ctx.included.end()) {
    t = it->second.table;
  } else {
    t = child_table(*materials, parts[1]);
  }
  if (t && parts.size() >= 4) t = child_table(*t, "haptic");
  if (!t) return make_error(label + ": " + parts[0] + "." + parts[1] + " is not a table");
  if (parts.size() == 6) {
    return element((*t)["texture"].as_array(), parts[4], label, "texture wave",
                   parts[0] + "." + parts[1] + ".haptic");
  }
  return t;
}

// Finds (or, for sections and materials, creates) the table that holds the key.
Result<toml::table*> target_table(toml::table& root, const std::vector<std::string>& parts,
                                  const std::string& label, ParseContext& ctx) {
  const Section section = section_of(parts[0]);
  if (section == Section::kMaterial) return material_table(root, parts, label, ctx);
  if (section == Section::kSurface) {
    if (parts.size() != 3) return make_error(label + ": expected surfaces.N.KEY=VALUE");
    return element(root["surfaces"].as_array(), parts[1], label, "surface", "the scene");
  }
  if (section == Section::kField || section == Section::kBody || section == Section::kButton) {
    const std::string what = section == Section::kField ? "field" : section == Section::kBody ? "body" : "button";
    if (parts.size() != 3) return make_error(label + ": expected " + parts[0] + ".N.KEY=VALUE");
    return element(root[parts[0]].as_array(), parts[1], label, what, "the scene");
  }
  if (parts.size() != 2) return make_error(label + ": expected " + parts[0] + ".KEY=VALUE");
  toml::table* t = child_table(root, parts[0]);
  if (!t) return make_error(label + ": the scene's '" + parts[0] + "' is not a table");
  return t;
}

// Leaves whose string value names a file (TableReader::file and the button's "scene:FILE").
bool names_file(std::string_view leaf) {
  return leaf.ends_with("_lut") || leaf == "mesh_file" || leaf == "albedo_texture" || leaf == "heightmap" ||
         leaf == "action";
}

}  // namespace

}  // namespace ps::scene_detail

namespace ps {

std::string anchor_override_path(const std::string& text, const std::string& base_dir) {
  namespace fs = std::filesystem;
  const auto eq = text.find('=');
  if (eq == std::string::npos) return text;
  const std::string key = scene_detail::trim(std::string_view(text).substr(0, eq));
  const std::string leaf = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
  if (!scene_detail::names_file(leaf)) return text;
  const toml::table value = scene_detail::parse_value(scene_detail::trim(std::string_view(text).substr(eq + 1)));
  const std::optional<std::string> name = value["v"].value<std::string>();
  if (!name || name->empty()) return text;
  // A button's action: only "scene:FILE" names a file ("flag:NAME" does not).
  const std::string prefix = leaf == "action" ? "scene:" : "";
  if (name->rfind(prefix, 0) != 0 || name->size() == prefix.size()) return text;
  const fs::path file(name->substr(prefix.size()));
  if (!file.is_relative()) return text;
  const std::string anchored = prefix + (fs::path(base_dir) / file).lexically_normal().string();
  std::string out = key + "=\"";
  for (char c : anchored) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace ps

namespace ps::scene_detail {

Status apply_override(toml::table& root, const std::string& given, ParseContext& ctx) {
  // Written on the command line (or anchored already by read_overrides): the working directory.
  std::error_code cwd_ec;
  const std::filesystem::path cwd = std::filesystem::current_path(cwd_ec);
  const std::string text = cwd_ec ? given : anchor_override_path(given, cwd.string());
  const auto eq = text.find('=');
  if (eq == std::string::npos) {
    return make_error("--set " + text + ": expected KEY=VALUE (e.g. probe.radius_mm=10)");
  }
  const std::string key = trim(std::string_view(text).substr(0, eq));
  const std::string label = "--set " + key;
  const std::vector<std::string> parts = split_dots(key);
  Section section = section_of(parts[0]);
  if (parts[0] == "include") {
    return make_error(label + ": includes cannot be set from the command line; edit the "
                      "scene file's 'include' instead");
  }
  if (section == Section::kRoot) return unknown_key(label, parts[0], known_keys(Section::kRoot));
  if (section == Section::kMaterial) {  // also a bare "materials": it names no table
    Result<Section> leaf_section = material_leaf_section(parts, label);
    if (!leaf_section) return leaf_section.error();
    section = *leaf_section;
  }
  const auto known = known_keys(section);
  const std::string& leaf = parts.back();
  if (parts.size() >= 2 && std::find(known.begin(), known.end(), leaf) == known.end()) {
    return unknown_key(label, leaf, known);
  }
  Result<toml::table*> table = target_table(root, parts, label, ctx);
  if (!table) return table.error();
  toml::table value = parse_value(trim(std::string_view(text).substr(eq + 1)));
  value["v"].node()->visit([&](auto& node) { (*table)->insert_or_assign(leaf, std::move(node)); });
  ctx.overridden[key] = label;
  return ok_status();
}

}  // namespace ps::scene_detail
