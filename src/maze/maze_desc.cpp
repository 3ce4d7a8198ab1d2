// Reading a maze description (docs/maze.md, "The description"): a small TOML file whose every
// key is optional; unknown keys, wrong types and values out of range are "file:line: ..." errors.
#include <cmath>
#include <fstream>
#include <sstream>

#include <toml++/toml.h>

#include "maze/maze.h"
#include "core/file_io.h"
#include "scene/toml_text.h"

namespace ps::maze {

namespace {

struct Key {
  const char* name;
  double lo, hi;  // valid range, both ends included
  double* number = nullptr;
  glm::dvec2* vec2 = nullptr;
  glm::dvec3* vec3 = nullptr;
  int* integer = nullptr;
};

struct Reader {
  std::string source;
  std::string error;

  std::string at(const toml::node& n) const {
    return source + ":" + std::to_string(std::max<long>(1, static_cast<long>(n.source().begin.line))) + ": ";
  }
  bool fail(const toml::node& n, const std::string& what) {
    if (error.empty()) error = at(n) + what;
    return false;
  }
  bool number(const toml::node& n, const Key& k, double& out) {
    const auto v = n.value<double>();
    if (!v) return fail(n, std::string("'") + k.name + "' must be a number");
    if (!std::isfinite(*v) || *v < k.lo || *v > k.hi) {
      std::ostringstream o;
      o << "'" << k.name << "' must be in [" << k.lo << ", " << k.hi << "] (got " << *v << ")";
      return fail(n, o.str());
    }
    out = *v;
    return true;
  }
  template <int N>
  bool vec(const toml::node& n, const Key& k, double* out) {
    const toml::array* arr = n.as_array();
    if (arr == nullptr || arr->size() != N)
      return fail(n, std::string("'") + k.name + "' must be an array of " + std::to_string(N) + " numbers, e.g. " +
                         (N == 2 ? "[0.0, 10.0]" : "[1.0, 0.0, 0.0]"));
    for (int i = 0; i < N; ++i)
      if (!number(*arr->get(static_cast<std::size_t>(i)), k, out[i])) return false;
    return true;
  }
  bool table(const toml::table& t, const std::string& name, const std::vector<Key>& keys) {
    for (const auto& [key, node] : t) {
      const Key* k = nullptr;
      for (const Key& c : keys)
        if (key.str() == c.name) k = &c;
      if (k == nullptr) {
        std::string known;
        for (const Key& c : keys) known += (known.empty() ? "" : ", ") + std::string(c.name);
        return fail(node, "unknown key '" + std::string(key.str()) + "' in [" + name + "]; known keys: " + known);
      }
      bool ok = true;
      if (k->number != nullptr) ok = number(node, *k, *k->number);
      if (k->vec2 != nullptr) ok = vec<2>(node, *k, &k->vec2->x);
      if (k->vec3 != nullptr) ok = vec<3>(node, *k, &k->vec3->x);
      if (k->integer != nullptr) {
        double v = 0.0;
        ok = number(node, *k, v);
        if (ok && v != std::floor(v)) ok = fail(node, std::string("'") + k->name + "' must be a whole number");
        if (ok) *k->integer = static_cast<int>(v);
      }
      if (!ok) return false;
    }
    return true;
  }
};

// The geometric rules the generator relies on; each message says what to change.
std::string check_geometry(const MazeDesc& d) {
  std::ostringstream o;
  if (d.wall_dynamic_friction > d.wall_static_friction)
    o << "[walls] 'dynamic_friction' (" << d.wall_dynamic_friction << ") must be <= 'static_friction' ("
      << d.wall_static_friction << ")";
  else if (d.corridor_width_mm < 2.0 * d.probe_radius_mm + 4.0)
    o << "'corridor_width_mm' (" << d.corridor_width_mm << ") must be at least the probe's diameter + 4 mm ("
      << 2.0 * d.probe_radius_mm + 4.0 << ") so the probe fits through every door";
  else if (d.room_size_mm < d.corridor_width_mm + 4.0 * d.probe_radius_mm)
    o << "'room_size_mm' (" << d.room_size_mm << ") must be at least 'corridor_width_mm' + 4 probe radii ("
      << d.corridor_width_mm + 4.0 * d.probe_radius_mm << ")";
  else if (d.room_height_mm < 2.0 * d.probe_radius_mm + 4.0)
    o << "'room_height_mm' (" << d.room_height_mm << ") must be at least the probe's diameter + 4 mm";
  else if (d.corridor_length_mm < d.corridor_width_mm)
    o << "'corridor_length_mm' (" << d.corridor_length_mm << ") must be at least 'corridor_width_mm' ("
      << d.corridor_width_mm << "): the probe starts in a corridor and must fit in it";
  else if (d.hidden_height_mm + d.hidden_radius_mm > d.room_height_mm)
    o << "[cues.hidden_sphere] 'height_mm' + 'radius_mm' (" << d.hidden_height_mm + d.hidden_radius_mm
      << ") must be at most 'room_height_mm' (" << d.room_height_mm << "): the sphere stays under the ceiling";
  else if (std::abs(d.hidden_offset_mm.x) + d.hidden_radius_mm > 0.5 * d.room_size_mm ||
           std::abs(d.hidden_offset_mm.y) + d.hidden_radius_mm > 0.5 * d.room_size_mm)
    o << "[cues.hidden_sphere] must lie inside the room: |offset| + radius <= room_size_mm / 2";
  return o.str();
}

using Tables = std::vector<std::pair<std::string, std::vector<Key>>>;

// Every table of the description: its keys, their valid ranges and where each lands in `d`. Kept
// whole (over 40 lines): it is one table of data, read top to bottom.
Tables maze_tables(MazeDesc& d) {
  return {
      {"maze",
       {{"room_size_mm", 20, 2000, &d.room_size_mm},
        {"room_height_mm", 10, 1000, &d.room_height_mm},
        {"corridor_width_mm", 10, 1000, &d.corridor_width_mm},
        {"corridor_length_mm", 0, 2000, &d.corridor_length_mm},
        {"wall_thickness_mm", 1, 100, &d.wall_thickness_mm},
        {"probe_radius_mm", 1, 50, &d.probe_radius_mm},
        {"max_passes", 1, 100, nullptr, nullptr, nullptr, &d.max_passes}}},
      {"walls",
       {{"stiffness_n_per_mm", 0.01, 100, &d.wall_stiffness_n_per_mm},
        {"static_friction", 0, 5, &d.wall_static_friction},
        {"dynamic_friction", 0, 5, &d.wall_dynamic_friction},
        {"albedo", 0, 1, nullptr, nullptr, &d.wall_albedo}}},
      {"camera",
       {{"height_mm", 10, 5000, &d.camera_height_mm},
        {"behind_mm", 0, 5000, &d.camera_behind_mm},
        {"fov_y_deg", 5, 150, &d.camera_fov_y_deg},
        {"image_size", 16, 4096, nullptr, nullptr, nullptr, &d.image_size}}},
      {"cues.texture",
       {{"lambda_mm", 0.05, 100, &d.texture_lambda_mm},
        {"peak_hz", 0.1, 1e4, &d.texture_peak_hz},
        {"amplitude_n", 0, 100, &d.texture_amplitude_n},
        {"period_mm", 0.05, 1000, &d.texture_period_mm}}},
      {"cues.viscosity", {{"viscosity_n_s_per_mm", 0, 1, &d.viscosity_n_s_per_mm}}},
      {"cues.elastic",
       {{"stiffness_n_per_mm", 0.01, 100, &d.elastic_stiffness_n_per_mm},
        {"restitution", 0, 1, &d.elastic_restitution}}},
      {"cues.hidden_sphere",
       {{"radius_mm", 1, 1000, &d.hidden_radius_mm},
        {"offset_mm", -1000, 1000, nullptr, &d.hidden_offset_mm},
        {"height_mm", 0, 1000, &d.hidden_height_mm}}},
      {"cues.external_force",
       {{"force_n", -100, 100, nullptr, nullptr, &d.external_force_n},
        {"fluctuation_n", -100, 100, nullptr, nullptr, &d.external_fluctuation_n},
        {"frequency_hz", 0, 500, &d.external_frequency_hz}}},
  };
}

// [instructions]: one string key, the live window's first screen.
Status read_instructions(const Reader& r, const toml::table& t, MazeDesc& d) {
  for (const auto& [k, n] : t) {
    const auto v = n.value<std::string>();
    if (k.str() != "text") return make_error(r.at(n) + "unknown key '" + std::string(k.str()) + "' in [instructions]; known keys: text");
    if (!v || v->empty()) return make_error(r.at(n) + "'text' must be a non-empty string, e.g. text = \"Press Space to start.\"");
    d.instructions = *v;
  }
  return ok_status();
}

// [cues.*]: each cue is a sub-table of [cues], read against its "cues.<name>" entry in `tables`.
Status read_cues(Reader& r, const toml::table& t, const Tables& tables) {
  for (const auto& [cue_key, cue_node] : t) {
    const std::string full = "cues." + std::string(cue_key.str());
    const toml::table* ct = cue_node.as_table();
    bool known = false;
    for (const auto& [tname, keys] : tables)
      if (tname == full && ct != nullptr) known = r.table(*ct, full, keys);
    if (!r.error.empty()) return make_error(r.error);
    if (!known)
      return make_error(r.at(cue_node) + "unknown table [" + full +
                        "]; the cue tables are texture, viscosity, elastic, hidden_sphere, external_force");
  }
  return ok_status();
}

// One top-level table: [instructions], [cues] or a plain table of numbers.
Status read_table(Reader& r, const std::string& name, const toml::node& node, const Tables& tables, MazeDesc& d) {
  const toml::table* t = node.as_table();
  if (t == nullptr) return make_error(r.at(node) + "'" + name + "' must be a table, e.g. [" + name + "]");
  if (name == "instructions") return read_instructions(r, *t, d);
  if (name == "cues") return read_cues(r, *t, tables);
  bool known = false;
  for (const auto& [tname, keys] : tables)
    if (tname == name) known = r.table(*t, name, keys);
  if (!r.error.empty()) return make_error(r.error);
  if (!known) return make_error(r.at(node) + "unknown table [" + name + "]; known: maze, walls, camera, instructions, cues.*");
  return ok_status();
}

}  // namespace

Result<MazeDesc> parse_maze_desc(const std::string& text, const std::string& source_name) {
  Result<toml::table> parsed = parse_toml(text, source_name);
  if (!parsed) return parsed.error();
  MazeDesc d;
  d.path = source_name;
  Reader r{source_name, {}};
  const Tables tables = maze_tables(d);
  for (const auto& [key, node] : parsed.value())
    if (Status st = read_table(r, std::string(key.str()), node, tables, d); !st) return st.error();
  if (const std::string bad = check_geometry(d); !bad.empty()) return make_error(source_name + ":1: " + bad);
  return d;
}

Result<MazeDesc> load_maze_desc(const std::string& path) {
  const std::optional<std::string> text = read_whole_file(path);
  if (!text) return make_error(path + ": cannot open maze description (give an existing file, e.g. scenes/maze/maze.toml)");
  return parse_maze_desc(*text, path);
}

}  // namespace ps::maze
