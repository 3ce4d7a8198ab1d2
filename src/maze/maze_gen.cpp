// The participant's route and the scene of one pass through the maze (maze.h). The scene is
// written as scene-file TOML and read by the ordinary parser, so it obeys every rule of
// docs/scene-format.md and `maze --write-scene` gives a file `run`, `replay` and `render` take.
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "maze/maze.h"
#include "scene/scene_io.h"

namespace ps::maze {

namespace {

struct SplitMix64 {  // Steele, Lea & Flood 2014: the same numbers on every platform
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, n) by rejection (no modulo bias).
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t limit = ~0ull - (~0ull % n);
    for (;;)
      if (const std::uint64_t v = next(); v < limit) return v % n;
  }
};

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v == 0.0 ? 0.0 : v);  // no "-0"
  return buf;
}
std::string vec(glm::dvec3 v) { return "[" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + "]"; }
std::string vec(glm::dvec2 v) { return "[" + num(v.x) + ", " + num(v.y) + "]"; }

// Collects the surfaces of one pass as TOML, with their kind and slot alongside.
struct Builder {
  explicit Builder(const MazeDesc& desc) : d(desc), g(room_geometry(desc)) {}
  const MazeDesc& d;
  RoomGeometry g;
  std::ostringstream toml, fields_;  // surfaces, then [[fields]]
  std::vector<SurfaceKind> kinds;
  std::vector<int> slots;

  void box(double x0, double x1, double y0, double y1, const std::string& material, int slot) {
    if (x1 - x0 <= 1e-9 || y1 - y0 <= 1e-9) return;  // a door as wide as its wall: no piece
    toml << "\n[[surfaces]]\ntype = \"box\"\nmaterial = \"" << material << "\"\ncenter = "
         << vec(glm::dvec3(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * g.height)) << "\nsize_mm = "
         << vec(glm::dvec3(x1 - x0, y1 - y0, g.height)) << "\n";
    kinds.push_back(SurfaceKind::kWall);
    slots.push_back(slot);
  }
  // A floor (z = 0, facing up, drawn) and its ceiling (z = height, facing down, felt only: the
  // camera looks down through it, and a drawn ceiling would hide the room).
  void floor_and_ceiling(double x0, double x1, double y0, double y1, const std::string& material, int slot) {
    for (int ceiling = 0; ceiling < 2; ++ceiling) {
      toml << "\n[[surfaces]]\ntype = \"plane\"\nmaterial = \"" << material << "\"\ncenter = "
           << vec(glm::dvec3(0.5 * (x0 + x1), 0.5 * (y0 + y1), ceiling ? g.height : 0.0)) << "\nsize_mm = "
           << vec(glm::dvec2(x1 - x0, y1 - y0)) << "\nresolution = 4\n"
           << (ceiling ? "rotation_deg = [180.0, 0.0, 0.0]\nvisible = false\n" : "");
      kinds.push_back(ceiling ? SurfaceKind::kCeiling : SurfaceKind::kFloor);
      slots.push_back(slot);
    }
  }
  // The corridor from slot's hall to the next room (slot -1: the start corridor).
  void exit_corridor(int slot) {
    const double y0 = g.center_y(slot) + g.a + 2.0 * g.t + g.h, y1 = g.center_y(slot + 1) - g.a - g.t;
    const double half = 0.5 * g.c;
    box(-half - g.t, -half, y0, y1, "wall", slot);
    box(half, half + g.t, y0, y1, "wall", slot);
    floor_and_ceiling(-half - g.t, half + g.t, y0, y1, "wall", slot);
  }
  void cap(double y0, double y1, int slot) { box(-0.5 * g.c - g.t, 0.5 * g.c + g.t, y0, y1, "wall", slot); }
  void room(int slot, Cue cue, bool cues);
  void cue_content(int slot, Cue cue);
};

// A wall with a centred door of the corridor's width, as two boxes.
void Builder::room(int slot, Cue cue, bool cues) {
  const double y = g.center_y(slot), a = g.a, t = g.t, c = g.c, h = g.h, half = 0.5 * g.c, W = g.outer_x();
  const std::string m = !cues                         ? "wall"
                        : cue == Cue::kTexture        ? "texture"
                        : cue == Cue::kElastic        ? "elastic"
                                                      : "wall";
  box(-W, -half, y - a - t, y - a, m, slot);  // south wall, the entrance between its halves
  box(half, W, y - a - t, y - a, m, slot);
  for (const double side : {-1.0, 1.0}) {  // west (left door) and east (right door) walls
    const double x0 = side < 0 ? -a - t : a, x1 = side < 0 ? -a : a + t;
    box(x0, x1, y - a, y - half, m, slot);
    box(x0, x1, y + half, y + a + t, m, slot);
    const double o0 = side < 0 ? -W : a + t + c, o1 = side < 0 ? -a - t - c : W;  // channel's outer wall
    box(o0, o1, y - a - t, y + a + 2.0 * t + h, "wall", slot);
  }
  box(-a - t, -half, y + a, y + a + t, m, slot);  // north wall, the straight door between
  box(half, a + t, y + a, y + a + t, m, slot);
  box(-W, -half, y + a + t + h, y + a + 2.0 * t + h, "wall", slot);  // hall's far wall and its door
  box(half, W, y + a + t + h, y + a + 2.0 * t + h, "wall", slot);
  floor_and_ceiling(-a - t, a + t, y - a - t, y + a + t, m, slot);  // the room's own floor and ceiling
  floor_and_ceiling(-W, -a - t, y - a - t, y + a + t, "wall", slot);  // under the channels
  floor_and_ceiling(a + t, W, y - a - t, y + a + t, "wall", slot);
  floor_and_ceiling(-W, W, y + a + t, y + a + 2.0 * t + h, "wall", slot);  // the hall
  exit_corridor(slot);
  if (cues) cue_content(slot, cue);
}

// The cues that are not materials: the hidden sphere and the two fields over the room interior.
void Builder::cue_content(int slot, Cue cue) {
  const glm::dvec3 centre(0.0, g.center_y(slot), 0.5 * g.height);
  const glm::dvec3 size(2.0 * g.a, 2.0 * g.a, g.height);
  if (cue == Cue::kHiddenSphere) {
    toml << "\n[[surfaces]]\ntype = \"sphere\"\nmaterial = \"wall\"\nvisible = false\nradius_mm = "
         << num(d.hidden_radius_mm) << "\ncenter = "
         << vec(glm::dvec3(d.hidden_offset_mm.x, d.hidden_offset_mm.y + g.center_y(slot), d.hidden_height_mm)) << "\n";
    kinds.push_back(SurfaceKind::kHidden);
    slots.push_back(slot);
  } else if (cue == Cue::kViscosity) {
    fields_ << "\n[[fields]]\ntype = \"viscous\"\nviscosity_n_s_per_mm = " << num(d.viscosity_n_s_per_mm)
            << "\ncenter = " << vec(centre) << "\nsize_mm = " << vec(size) << "\n";
  } else if (cue == Cue::kExternalForce) {
    fields_ << "\n[[fields]]\ntype = \"uniform\"\nforce_n = " << vec(d.external_force_n) << "\nfluctuation_n = "
            << vec(d.external_fluctuation_n) << "\nfrequency_hz = " << num(d.external_frequency_hz)
            << "\ncenter = " << vec(centre) << "\nsize_mm = " << vec(size) << "\n";
  }
}

std::string friction(const MazeDesc& d) {  // after a stiffness line, before the next key
  return "\nstatic_friction = " + num(d.wall_static_friction) + "\ndynamic_friction = " + num(d.wall_dynamic_friction) + "\n";
}

std::string header(const MazeDesc& d, const glm::dvec3& probe, bool texture, bool elastic) {
  std::ostringstream o;
  const Camera cam = follow_camera(d, probe);
  o << "# generated by `pseudoshadow maze` from " << std::filesystem::path(d.path).filename().string()
    << " (docs/maze.md)\n\n[camera]\nposition = " << vec(cam.position) << "\ntarget = " << vec(cam.target)
    << "\nup = " << vec(cam.up) << "\nfov_y_deg = " << num(cam.fov_y_deg) << "\nnear_mm = 1.0\nfar_mm = "
    << num(cam.far_mm) << "\n\n[probe]\nshape = \"sphere\"\nradius_mm = " << num(d.probe_radius_mm)
    << "\nposition = " << vec(probe) << "\n\n[render]\nsize = [" << d.image_size << ", " << d.image_size
    << "]\n\n[materials.wall]\nalbedo = " << vec(d.wall_albedo) << "\ntextured = false\n"
    << "[materials.wall.haptic]\nstiffness_n_per_mm = " << num(d.wall_stiffness_n_per_mm) << friction(d);
  if (texture) {
    // Same look as every room (Sepulveda-Cervantes et al. §V: landmarks inhibited); the Gabor
    // texture shows only in the pseudo-shadow near the probe, at its peak for a probe moving at
    // lambda * peak_hz.
    o << "\n[materials.texture]\nalbedo = " << vec(d.wall_albedo) << "\ntextured = true\na_min = 1.0\na_max = 1.0\n"
      << "lambda_min = " << num(d.texture_lambda_mm) << "\nlambda_max = " << num(d.texture_lambda_mm)
      << "\ntheta_min = 0.0\ntheta_max = 180.0\npeak_hz = " << num(d.texture_peak_hz)
      << "\nbandwidth_hz = " << num(0.4 * d.texture_peak_hz) << "\n[materials.texture.haptic]\nstiffness_n_per_mm = "
      << num(d.wall_stiffness_n_per_mm) << friction(d) << "[[materials.texture.haptic.texture]]\nshape = \"square\"\namplitude_n = "
      << num(d.texture_amplitude_n) << "\nperiod_mm = " << num(d.texture_period_mm)
      << "\ndirection = [1.0, 1.0]\n";  // diagonal: felt whichever way the probe slides
  }
  if (elastic)
    o << "\n[materials.elastic]\nalbedo = " << vec(d.wall_albedo) << "\ntextured = false\n"
      << "[materials.elastic.haptic]\nstiffness_n_per_mm = " << num(d.elastic_stiffness_n_per_mm) << friction(d)
      << "restitution = " << num(d.elastic_restitution) << "\n";
  return o.str();
}

}  // namespace

const char* cue_name(Cue cue) {
  switch (cue) {
    case Cue::kNone: return "none";
    case Cue::kTexture: return "texture";
    case Cue::kViscosity: return "viscosity";
    case Cue::kElastic: return "elastic";
    case Cue::kHiddenSphere: return "hidden_sphere";
    case Cue::kExternalForce: return "external_force";
  }
  return "?";
}

const char* cue_label(Cue cue) {
  switch (cue) {
    case Cue::kNone: return "learning room";
    case Cue::kTexture: return "room A";
    case Cue::kViscosity: return "room B";
    case Cue::kElastic: return "room C";
    case Cue::kHiddenSphere: return "room D";
    case Cue::kExternalForce: return "room E";
  }
  return "?";
}

bool parse_cue(const std::string& name, Cue& out) {
  for (int i = 0; i <= static_cast<int>(Cue::kExternalForce); ++i)
    if (name == cue_name(static_cast<Cue>(i))) {
      out = static_cast<Cue>(i);
      return true;
    }
  return false;
}

const char* exit_name(Exit e) { return e == Exit::kLeft ? "left" : e == Exit::kStraight ? "straight" : "right"; }

bool parse_exit(const std::string& name, Exit& out) {
  for (const Exit e : {Exit::kLeft, Exit::kStraight, Exit::kRight})
    if (name == exit_name(e)) {
      out = e;
      return true;
    }
  return false;
}

const char* surface_kind_name(SurfaceKind k) {
  return k == SurfaceKind::kFloor ? "floor" : k == SurfaceKind::kWall ? "wall" : k == SurfaceKind::kCeiling ? "ceiling" : "hidden";
}

std::array<Cue, kRoomsPerPass> Route::order(int pass) const {
  if (!planned.empty()) {
    const auto& r = planned[static_cast<std::size_t>(pass) % planned.size()];
    return {Cue::kNone, r[0], r[1], r[2], r[3], r[4]};
  }
  SplitMix64 rng{seed ^ (0xd1b54a32d192ed03ull * static_cast<std::uint64_t>(pass + 1))};
  std::array<Cue, 5> rooms = kCueRooms;
  for (std::size_t i = rooms.size() - 1; i > 0; --i) std::swap(rooms[i], rooms[rng.below(i + 1)]);  // Fisher-Yates
  return {Cue::kNone, rooms[0], rooms[1], rooms[2], rooms[3], rooms[4]};
}

Route draw_route(std::uint64_t seed) {
  Route r;
  r.seed = seed;
  SplitMix64 rng{seed};
  for (Exit& e : r.correct) e = static_cast<Exit>(rng.below(3));
  return r;
}

RoomGeometry room_geometry(const MazeDesc& d) {
  RoomGeometry g;
  g.a = 0.5 * d.room_size_mm;
  g.t = d.wall_thickness_mm;
  g.c = d.corridor_width_mm;
  g.h = d.corridor_width_mm;
  g.length = d.corridor_length_mm;
  g.height = d.room_height_mm;
  return g;
}

glm::dvec3 RoomGeometry::start(double probe_radius_mm) const {
  return {0.0, center_y(0) - a - t - 0.5 * length, probe_radius_mm + 1.0};
}

Camera follow_camera(const MazeDesc& d, const glm::dvec3& probe) {
  Camera c;
  c.position = glm::dvec3(probe.x, probe.y - d.camera_behind_mm, d.camera_height_mm);
  c.target = glm::dvec3(probe.x, probe.y, 0.0);
  c.up = glm::dvec3(0.0, 1.0, 0.0);  // ahead is up on screen; never parallel to a downward view
  c.fov_y_deg = d.camera_fov_y_deg;
  c.far_mm = 4.0 * d.camera_height_mm + 1000.0;
  return c;
}

std::string room_label_text(Cue cue, bool cues) { return cues ? std::string() : std::string(cue_label(cue)); }

Result<MazeScene> generate_scene(const MazeDesc& desc, const Route& route, bool cues, int pass) {
  Builder b(desc);
  const std::array<Cue, kRoomsPerPass> order = route.order(pass);
  const int first = pass * kRoomsPerPass;
  bool texture = false, elastic = false;
  if (pass == 0) {
    b.exit_corridor(-1);  // the start corridor, closed behind the probe
    const double y0 = b.g.center_y(-1) + b.g.a + 2.0 * b.g.t + b.g.h;
    b.cap(y0 - b.g.t, y0, -1);
  } else {  // the previous pass's last room, where the probe is when this scene takes over
    const Cue tail = route.order(pass - 1)[kRoomsPerPass - 1];
    texture |= cues && tail == Cue::kTexture;
    elastic |= cues && tail == Cue::kElastic;
    b.room(first - 1, tail, cues);
    // Its entrance led back into the previous pass's rooms, which this scene does not hold: closed.
    const double south = b.g.center_y(first - 1) - b.g.a;
    b.cap(south - b.g.t, south, first - 1);
  }
  for (int i = 0; i < kRoomsPerPass; ++i) {
    texture |= cues && order[static_cast<std::size_t>(i)] == Cue::kTexture;
    elastic |= cues && order[static_cast<std::size_t>(i)] == Cue::kElastic;
    b.room(first + i, order[static_cast<std::size_t>(i)], cues);
  }
  const double end = b.g.center_y(first + kRoomsPerPass) - b.g.a - b.g.t;
  b.cap(end, end + b.g.t, first + kRoomsPerPass - 1);  // closed after the last room
  const glm::dvec3 probe = pass == 0 ? b.g.start(desc.probe_radius_mm)
                                     : glm::dvec3(0.0, b.g.hall_y(first - 1), desc.probe_radius_mm + 1.0);
  MazeScene out;
  out.text = header(desc, probe, texture, elastic) + b.toml.str() + b.fields_.str();
  char name[96];
  std::snprintf(name, sizeof name, "<maze seed %llu pass %d cues %s>", static_cast<unsigned long long>(route.seed),
                pass + 1, cues ? "on" : "off");
  auto scene = parse_scene(out.text, name, std::filesystem::path(desc.path).parent_path().string());
  if (!scene) return make_error("generated maze scene: " + scene.error().message + " (a bug: please report it)");
  out.scene = std::move(scene.value());
  out.kinds = std::move(b.kinds);
  out.slots = std::move(b.slots);
  return out;
}

}  // namespace ps::maze
