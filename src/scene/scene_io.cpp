// parse_scene / load_scene: TOML text -> overrides -> section converters -> Scene.
#include "scene/scene_io.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/file_io.h"
#include "core/install_layout.h"
#include "scene/mesh.h"
#include "scene/scene_convert.h"
#include "scene/toml_text.h"

namespace ps {
namespace {

using scene_detail::ParseContext;

std::string line_of(const ParseContext& ctx, const toml::node& node) {
  const auto line = std::max<long>(1, static_cast<long>(node.source().begin.line));
  return ctx.source_name + ":" + std::to_string(line);
}

// A section that is present must be a table; an absent one keeps the defaults.
Result<const toml::table*> section(const ParseContext& ctx, const toml::table& root,
                                   std::string_view name) {
  const toml::node* node = root.get(name);
  if (!node) return static_cast<const toml::table*>(nullptr);
  if (!node->is_table()) {
    return make_error(line_of(ctx, *node) + ": '" + std::string(name) + "' must be a table");
  }
  return node->as_table();
}

// Names the surfaces use: materials from includes that no surface uses are validated but not
// kept, so including a library of ten materials costs nothing at render time.
std::vector<std::string> used_material_names(const toml::table& root) {
  std::vector<std::string> names;
  if (const toml::array* surfaces = root["surfaces"].as_array()) {
    for (const toml::node& s : *surfaces) {
      if (const toml::table* t = s.as_table()) {
        if (auto name = (*t)["material"].value<std::string>()) names.push_back(*name);
      }
    }
  }
  return names;
}

struct MaterialEntry {
  std::string name;
  const toml::table* table;
  const scene_detail::IncludedMaterial* included;  // null: defined in the scene itself
  unsigned order;
};

// Materials in file order (toml++ keeps keys sorted), then those from includes in inclusion
// order, then ones added only by --set.
Status read_materials(const ParseContext& ctx, const toml::table& root, Scene& scene) {
  Result<const toml::table*> table = section(ctx, root, "materials");
  if (!table) return table.error();
  if ((!*table || (*table)->empty()) && ctx.included.empty()) {
    return make_error(ctx.source_name + ":1: the scene defines no materials; add at least one "
                      "[materials.NAME] table");
  }
  constexpr unsigned kIncludedBase = 1u << 30;  // after every line of the scene itself
  std::vector<MaterialEntry> entries;
  static const toml::table kNone;
  const toml::table& own = *table ? **table : kNone;  // both lvalues: no copy (it would lose lines)
  for (const auto& [name, node] : own) {
    if (!node.is_table()) {
      return make_error(line_of(ctx, node) + ": 'materials." + std::string(name.str()) +
                        "' must be a table ([materials." + std::string(name.str()) + "])");
    }
    const auto line = node.as_table()->source().begin.line;
    entries.push_back({std::string(name.str()), node.as_table(), nullptr, line == 0 ? ~0u : line});
  }
  for (const auto& [name, included] : ctx.included) {
    entries.push_back({name, included.table, &included,
                       kIncludedBase + static_cast<unsigned>(included.order)});
  }
  std::stable_sort(entries.begin(), entries.end(),
                   [](const auto& a, const auto& b) { return a.order < b.order; });
  const std::vector<std::string> used = used_material_names(root);
  for (const MaterialEntry& e : entries) {
    Material material;
    if (e.included) {
      ParseContext origin{e.included->source_name, e.included->base_dir, ctx.overridden, {}, {}, ctx.paths};
      if (Status s = scene_detail::read_material(origin, *e.table, e.name, material); !s) return s;
      if (std::find(used.begin(), used.end(), e.name) == used.end()) continue;
    } else if (Status s = scene_detail::read_material(ctx, *e.table, e.name, material); !s) {
      return s;
    }
    scene.materials.push_back(std::move(material));
  }
  return ok_status();
}

Status read_surfaces(const ParseContext& ctx, const toml::table& root, Scene& scene) {
  const toml::node* node = root.get("surfaces");
  if (!node || (node->is_array() && node->as_array()->empty())) {
    return make_error(ctx.source_name + ":1: the scene defines no surfaces; add at least one "
                      "[[surfaces]] table");
  }
  const toml::array* array = node->as_array();
  if (!array || !array->is_array_of_tables()) {
    return make_error(line_of(ctx, *node) + ": 'surfaces' must be an array of tables "
                      "([[surfaces]])");
  }
  std::vector<std::string> names;
  for (const Material& m : scene.materials) names.push_back(m.name);
  for (std::size_t i = 0; i < array->size(); ++i) {
    Surface surface;
    Status s = scene_detail::read_surface(ctx, *(*array)[i].as_table(), static_cast<int>(i),
                                          names, surface);
    if (!s) return s;
    scene.surfaces.push_back(std::move(surface));
  }
  return ok_status();
}

// [[fields]] / [[bodies]]: optional arrays of tables.
template <class T, class ReadOne>
Status read_array(const ParseContext& ctx, const toml::table& root, const char* key, std::vector<T>& out,
                  ReadOne read_one) {
  const toml::node* node = root.get(key);
  if (!node) return ok_status();
  const toml::array* array = node->as_array();
  if (!array || !array->is_array_of_tables())
    return make_error(line_of(ctx, *node) + ": '" + key + "' must be an array of tables ([[" + key + "]])");
  for (std::size_t i = 0; i < array->size(); ++i) {
    T item;
    if (Status s = read_one(*(*array)[i].as_table(), static_cast<int>(i), item); !s) return s;
    out.push_back(std::move(item));
  }
  return ok_status();
}

// Two charges at one point would make the field there the sum of two singular laws; one charge
// with their sum says the same thing.
Status check_charges(const ParseContext& ctx, const Scene& scene) {
  for (std::size_t i = 0; i < scene.fields.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      const Field &a = scene.fields[j], &b = scene.fields[i];
      if (a.type == FieldType::kCharge && b.type == FieldType::kCharge && a.position == b.position)
        return make_error(ctx.source_name + ":" + std::to_string(b.line) + ": [[fields]] #" + std::to_string(i) +
                          ": a second charge at the position of [[fields]] #" + std::to_string(j) + " (line " +
                          std::to_string(a.line) + "); merge them into one charge (their sum)");
    }
  return ok_status();
}

// The plate a button adds to the surfaces: a box 1 mm thick whose front face stands 0.25 mm
// proud of the face the button sits in (drawn over it, never z-fighting), seen but not felt
// (the button's feel is HapticScene's hole and the button spring, docs/haptics.md "Buttons").
Surface button_plate(const Button& b, int index) {
  constexpr double kThicknessMm = 1.0, kProudMm = 0.25;
  Surface s;
  s.type = SurfaceType::kBox;
  s.material_index = b.picture_material >= 0 ? b.picture_material : b.material_index;
  s.rotation_deg = b.rotation_deg;
  s.center = b.center + euler_xyz_deg(b.rotation_deg) * glm::dvec3(0.0, 0.0, kProudMm - 0.5 * kThicknessMm);
  s.box_size_mm = {b.size_mm.x, b.size_mm.y, kThicknessMm};
  s.visible = b.visible;
  s.touchable = false;
  s.button = index;
  s.line = b.line;
  return s;
}

// A white copy of material `index`, named NAME@suffix, appended to the materials: a surface that
// gets an albedo texture of its own (a button's picture, a field map) draws it in true colours
// and keeps the material's other keys and feel. Returns the copy's index.
int add_white_copy(Scene& scene, int index, const std::string& suffix) {
  Material m = scene.materials[static_cast<std::size_t>(index)];
  m.name += "@" + suffix;
  m.albedo = glm::dvec3(1.0);
  scene.materials.push_back(std::move(m));
  return static_cast<int>(scene.materials.size()) - 1;
}

Status read_buttons(const ParseContext& ctx, const toml::table& root, const std::vector<std::string>& names,
                    Scene& scene) {
  if (Status s = read_array(ctx, root, "buttons", scene.buttons, [&](const toml::table& t, int i, Button& b) {
        b.material_index = scene.surfaces[0].material_index;  // no material: the first surface's look
        return scene_detail::read_button(ctx, t, i, names, scene.probe.radius_mm, b);
      });
      !s)
    return s;
  if (scene.buttons.size() > static_cast<std::size_t>(kMaxSceneButtons))
    return make_error(ctx.source_name + ":" + std::to_string(scene.buttons[kMaxSceneButtons].line) +
                      ": [[buttons]] #" + std::to_string(kMaxSceneButtons) + ": a scene has at most " +
                      std::to_string(kMaxSceneButtons) + " buttons");
  for (std::size_t i = 0; i < scene.buttons.size(); ++i) {
    Button& b = scene.buttons[i];
    if (b.action_kind == ButtonActionKind::kFlag) {
      const auto it = std::find(scene.flags.begin(), scene.flags.end(), b.action_target);
      b.flag = static_cast<int>(it - scene.flags.begin());
      if (it == scene.flags.end()) {
        if (scene.flags.size() == static_cast<std::size_t>(kMaxSceneFlags))
          return make_error(ctx.source_name + ":" + std::to_string(b.line) + ": [[buttons]] #" + std::to_string(i) +
                            ": a scene has at most " + std::to_string(kMaxSceneFlags) + " flags");
        scene.flags.push_back(b.action_target);
      }
    }
    if (b.picture) b.picture_material = add_white_copy(scene, b.material_index, "button" + std::to_string(i));
    scene.surfaces.push_back(button_plate(b, static_cast<int>(i)));
  }
  return ok_status();
}

// A field-map surface gets a white copy of its material: the map is its albedo texture.
void add_field_map_materials(Scene& scene) {
  for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
    Surface& s = scene.surfaces[i];
    if (s.field_map)
      s.field_map_material = s.material_index = add_white_copy(scene, s.material_index, "field_map" + std::to_string(i));
  }
}

Status read_world(const ParseContext& ctx, const toml::table& root, Scene& scene) {
  if (Status s = read_array(ctx, root, "fields", scene.fields,
                            [&](const toml::table& t, int i, Field& f) { return scene_detail::read_field(ctx, t, i, f); });
      !s)
    return s;
  if (Status s = check_charges(ctx, scene); !s) return s;
  // A field map with nothing to map (Sandia's Field with an empty charge list) is a mistake
  // the picture would hide: a uniformly dark floor.
  const bool any_charge = std::any_of(scene.fields.begin(), scene.fields.end(),
                                      [](const Field& f) { return f.type == FieldType::kCharge; });
  for (std::size_t i = 0; i < scene.surfaces.size() && !any_charge; ++i)
    if (scene.surfaces[i].field_map)
      return make_error(ctx.source_name + ":" + std::to_string(scene.surfaces[i].line) + ": [[surfaces]] #" +
                        std::to_string(i) + ": 'field_map' shows the field of the scene's charges, and it has "
                        "none; add a [[fields]] with type = \"charge\", or remove field_map");
  std::vector<std::string> names;
  for (const Material& m : scene.materials) names.push_back(m.name);
  if (Status s = read_array(ctx, root, "bodies", scene.bodies, [&](const toml::table& t, int i, Body& b) {
        b.material_index = scene.surfaces[0].material_index;  // no material: the first surface's look
        return scene_detail::read_body(ctx, t, i, names, b);
      });
      !s)
    return s;
  if (scene.bodies.size() > static_cast<std::size_t>(kMaxSceneBodies))
    return make_error(ctx.source_name + ":" + std::to_string(scene.bodies[kMaxSceneBodies].line) + ": [[bodies]] #" +
                      std::to_string(kMaxSceneBodies) + ": a scene has at most " + std::to_string(kMaxSceneBodies) +
                      " bodies");
  if (Status s = read_buttons(ctx, root, names, scene); !s) return s;
  add_field_map_materials(scene);
  return ok_status();
}

Status read_sections(const ParseContext& ctx, const toml::table& root, Scene& scene) {
  scene_detail::TableReader top(ctx, &root, scene_detail::Section::kRoot, "", "the scene");
  top.check_unknown_keys();
  if (!top.ok()) return top.status();
  Result<const toml::table*> camera = section(ctx, root, "camera");
  Result<const toml::table*> light = section(ctx, root, "light");
  Result<const toml::table*> probe = section(ctx, root, "probe");
  Result<const toml::table*> render = section(ctx, root, "render");
  Result<const toml::table*> navigation = section(ctx, root, "navigation");
  for (const auto* r : {&camera, &light, &probe, &render, &navigation}) {
    if (!*r) return r->error();
  }
  if (Status s = scene_detail::read_camera(ctx, *camera, scene.camera); !s) return s;
  if (Status s = scene_detail::read_light(ctx, *light, scene.light); !s) return s;
  if (Status s = scene_detail::read_probe(ctx, *probe, scene.probe); !s) return s;
  if (Status s = scene_detail::read_render(ctx, *render, scene.render); !s) return s;
  if (Status s = scene_detail::read_navigation(ctx, *navigation, scene.navigation); !s) return s;
  if (Status s = read_materials(ctx, root, scene); !s) return s;
  if (Status s = read_surfaces(ctx, root, scene); !s) return s;
  return read_world(ctx, root, scene);
}

}  // namespace

Result<Scene> parse_scene(std::string_view text, const std::string& source_name,
                          const std::string& base_dir,
                          const std::vector<std::string>& overrides,
                          const std::vector<std::string>& allow_paths) {
  ParseContext ctx{source_name, base_dir, {}, {}, {}, PathPolicy::for_scene(base_dir, allow_paths)};
  Result<toml::table> parsed = parse_toml(text, source_name);
  if (!parsed) return parsed.error();
  toml::table& root = parsed.value();
  // Includes first, so --set reaches included materials too.
  if (Status s = scene_detail::resolve_includes(root, ctx); !s) return s.error();
  for (const std::string& o : overrides) {
    if (Status s = scene_detail::apply_override(root, o, ctx); !s) return s.error();
  }
  Scene scene;
  scene.path = source_name;
  if (Status s = read_sections(ctx, root, scene); !s) return s.error();
  return scene;
}

Result<Scene> load_scene(const std::string& path, const std::vector<std::string>& overrides,
                         const std::vector<std::string>& allow_paths) {
  // An ifstream opens a directory and reads nothing, which would be reported as an empty scene.
  if (std::error_code dir_ec; std::filesystem::is_directory(path, dir_ec))
    return make_error(path + ": is a directory, not a scene file (give a .toml file, e.g. scenes/default.toml)");
  std::error_code size_ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, size_ec);
  if (!size_ec && bytes > kMaxSceneFileBytes)
    return make_error(path + ": scene file is " + std::to_string(bytes) + " bytes, more than the limit of " +
                      std::to_string(kMaxSceneFileBytes));
  const std::optional<std::string> text = read_whole_file(path);
  if (!text) {
    std::error_code ec;
    const bool exists = std::filesystem::exists(path, ec);
    return make_error(path + ": cannot open scene file: " +
                      (exists ? "permission denied or not a file" : "no such file"));
  }
  const std::string base_dir =
      std::filesystem::absolute(std::filesystem::path(path)).parent_path().string();
  return parse_scene(*text, path, base_dir, overrides, allow_paths);
}

Result<Scene> load_scene_or_default(const std::string& path, const std::vector<std::string>& overrides,
                                    const std::vector<std::string>& allow_paths) {
  if (path.empty())
    return parse_scene(default_scene_text(), kDefaultSceneName, default_scene_base_dir(), overrides, allow_paths);
  return load_scene(path, overrides, allow_paths);
}

// Found from the binary's own location, never compiled in (core/install_layout.h).
std::string default_scene_base_dir() { return (install::data_dir() / "scenes").string(); }

}  // namespace ps
