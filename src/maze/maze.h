// The haptic cue maze of Sepulveda-Cervantes et al. §V-VII (docs/maze.md): a maze description (room
// size, corridor length, cue parameters; scenes/maze/*.toml), the participant's route drawn from a
// seed, and the generator that turns both into the ordinary scene model (scene/scene.h), one
// scene per pass through the rooms, so the renderer, the haptic loop, replay and goldens work
// on it unchanged. No GL.
//
// Layout (mm; +Y is "ahead", the way the participant enters every room; z = 0 is the floor):
//
//        |   exit corridor (length L)   |             next room's entrance
//   +----+----------+   +---------------+----+
//   |         hall (depth = corridor width)  |        hall north wall
//   |   +--------------+   +--------------+  |        room north wall, straight door
//   | W |                                 | E |
//   | c      room interior 2a x 2a          c |       west / east walls, left / right doors
//   | h |                                 | h |
//   |   +--------------+   +--------------+  |        room south wall, entrance
//                      |   |                          entrance corridor
//
// The left and right doors open into channels that run ahead beside the room into the hall;
// the straight door opens into the hall itself; the hall's door leads on to the next room. So
// every exit leads on (a wrong exit is a failed trial, not a dead end), and which exit the
// probe took is read off where it left the interior (maze_track.h).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "scene/scene.h"

namespace ps::maze {

// The five cue rooms and the dummy learning room (Sepulveda-Cervantes et al.: §V items 1-5,
// §VI item 7).
enum class Cue { kNone, kTexture, kViscosity, kElastic, kHiddenSphere, kExternalForce };
inline constexpr int kRoomsPerPass = 6;  // the dummy room, then the five cue rooms
inline constexpr std::array<Cue, 5> kCueRooms = {Cue::kTexture, Cue::kViscosity, Cue::kElastic,
                                                 Cue::kHiddenSphere, Cue::kExternalForce};
const char* cue_name(Cue cue);   // "none", "texture", "viscosity", "elastic", "hidden_sphere", "external_force"
const char* cue_label(Cue cue);  // what the screen shows with cues off: "learning room", "room A" ... "room E"
bool parse_cue(const std::string& name, Cue& out);

enum class Exit { kLeft, kStraight, kRight };
const char* exit_name(Exit e);  // "left", "straight", "right"
bool parse_exit(const std::string& name, Exit& out);

// What a maze description holds. Defaults are scenes/maze/maze.toml's values.
// What the live window shows before the session's clock starts ([instructions] text).
inline constexpr const char* kDefaultInstructions =
    "Welcome to the maze.\n\n"
    "Move the mouse to steer the ball through a series of rooms. Every room has three exits:\n"
    "left, straight ahead and right. One of them is the right one; try to find the right way\n"
    "through every room. After each pass through the rooms you see which exits were right.\n"
    "The session ends after a pass with every room right.\n\n"
    "Page Up / Page Down raise and lower the ball. Esc ends the session.\n\n"
    "Press Space to start.";

struct MazeDesc {
  std::string path;                 // the file it came from (for scene names and errors)
  std::string instructions = kDefaultInstructions;  // the live window's first screen
  double room_size_mm = 120.0;      // interior, square (2a)
  double room_height_mm = 40.0;     // floor to ceiling
  double corridor_width_mm = 36.0;  // doors, corridors, channels and hall depth
  double corridor_length_mm = 50.0; // from a hall to the next room
  double wall_thickness_mm = 6.0;
  double probe_radius_mm = 6.0;
  int max_passes = 10;              // a session stops after this many passes without criterion
  // The walls, floor and ceiling of every room (always touchable: Sepulveda-Cervantes et al.,
  // §VI item 6).
  double wall_stiffness_n_per_mm = 0.5;
  // Low friction on every room's surfaces (the cue rooms' too, so friction is no cue): a probe
  // pushed diagonally into a wall slides along it instead of sticking (MazeSceneTest.WallsLetTheProbeSlide).
  double wall_static_friction = 0.05;
  double wall_dynamic_friction = 0.05;
  glm::dvec3 wall_albedo{0.62, 0.64, 0.68};
  // The camera follows the probe from above and behind (docs/maze.md).
  double camera_height_mm = 150.0;
  double camera_behind_mm = 60.0;
  double camera_fov_y_deg = 60.0;
  int image_size = 512;
  // (1) texture room: a Gabor texture in the pseudo-shadow and a haptic texture wave.
  double texture_lambda_mm = 2.0;
  double texture_peak_hz = 30.0;       // texture peaks at lambda * peak = 60 mm/s
  double texture_amplitude_n = 0.15;
  double texture_period_mm = 2.0;
  // (2) viscosity room: F = -b v over the whole room.
  double viscosity_n_s_per_mm = 0.004;
  // (3) elastic room: walls, floor and ceiling of another stiffness and restitution.
  double elastic_stiffness_n_per_mm = 1.5;
  double elastic_restitution = 0.8;
  // (4) hidden sphere room: felt, never drawn; centre relative to the room centre (x, y) and
  // above the floor. At the probe's own height its contact normal is level, so the probe slides
  // round it; a centre higher up presses the probe into the floor, where the god-object wedges
  // (docs/maze.md, "Known limits").
  double hidden_radius_mm = 14.0;
  glm::dvec2 hidden_offset_mm{-12.0, 10.0};
  double hidden_height_mm = 7.0;
  // (5) external force room: F = F0 + F1 sin(2 pi f t) over the whole room.
  glm::dvec3 external_force_n{0.0, 0.0, 0.0};
  glm::dvec3 external_fluctuation_n{1.0, 0.0, 0.0};
  double external_frequency_hz = 2.0;
};

// Reads and checks a description; errors are "file:line: what to fix".
Result<MazeDesc> load_maze_desc(const std::string& path);
Result<MazeDesc> parse_maze_desc(const std::string& text, const std::string& source_name);

// A participant's route: the correct exit of every room (by its cue, fixed for the participant)
// and the order of the five cue rooms in each pass (drawn again every pass, as in
// Sepulveda-Cervantes et al. §V: "the rooms are presented in random order so the correct route
// is not in the same order all the time"). The dummy room is always first.
struct Route {
  std::uint64_t seed = 0;
  std::array<Exit, 6> correct{};  // indexed by static_cast<int>(Cue)
  // A study plan's cue-room orders (maze_plan.h), pass p taking planned[p % size]; empty: each
  // pass's order is drawn from the seed.
  std::vector<std::array<Cue, 5>> planned;
  Exit correct_exit(Cue cue) const { return correct[static_cast<std::size_t>(cue)]; }
  // The six rooms of pass `pass` (from 0), dummy first.
  std::array<Cue, kRoomsPerPass> order(int pass) const;
};
// Deterministic on every platform (SplitMix64, not <random>'s distributions).
Route draw_route(std::uint64_t seed);

// Where room `slot` (global: pass * 6 + room in the pass; -1 is the start corridor's) sits.
struct RoomGeometry {
  double a = 60.0;  // half the interior side
  double t = 6.0, c = 36.0, h = 36.0, length = 50.0, height = 40.0;
  double pitch() const { return 2.0 * a + 3.0 * t + h + length; }
  double center_y(int slot) const { return slot * pitch(); }
  double outer_x() const { return a + 2.0 * t + c; }         // outer faces of the channel walls
  double channel_x() const { return a + t + 0.5 * c; }       // centre line of the side channels
  double hall_y(int slot) const { return center_y(slot) + a + t + 0.5 * h; }  // hall centre line
  // The probe's start: in the start corridor, 1 mm above the floor.
  glm::dvec3 start(double probe_radius_mm) const;
};
RoomGeometry room_geometry(const MazeDesc& desc);

// What a generated scene's surface is, for the session log's contact counts.
enum class SurfaceKind { kFloor, kWall, kCeiling, kHidden };
const char* surface_kind_name(SurfaceKind k);

struct MazeScene {
  Scene scene;
  std::vector<SurfaceKind> kinds;  // per scene surface
  std::vector<int> slots;          // per scene surface: the global slot it belongs to
  std::string text;                // the TOML the scene was parsed from (`maze --write-scene`)
};

// The scene of pass `pass`: that pass's six rooms in order, plus the previous pass's last room
// (so switching scenes at the end of a pass is seamless; for pass 0 the start corridor), closed
// after the last room. cues = false: every room is the dummy room (Sepulveda-Cervantes et al.,
// §VI item 5).
Result<MazeScene> generate_scene(const MazeDesc& desc, const Route& route, bool cues, int pass);

// The label shown on screen while the probe is in `cue`'s room (empty with cues on, as in
// Sepulveda-Cervantes et al. §VI item 2: "during trials with haptic cues enabled the labels
// are hidden").
std::string room_label_text(Cue cue, bool cues);

// The camera that follows the probe: above and behind it, looking at the floor under it.
Camera follow_camera(const MazeDesc& desc, const glm::dvec3& probe_mm);

}  // namespace ps::maze
