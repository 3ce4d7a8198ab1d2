// The scene model: what a scene file (docs/scene-format.md) describes, after parsing and
// validation. Units everywhere: lengths in millimetres (mm), speeds in mm/s, frequencies in
// Hz, angles in radians here (degrees in the file), colours linear RGB in [0,1].
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "fourd/spec.h"
#include "scene/haptic_material.h"
#include "scene/lut.h"

namespace ps {

enum class Projection { kPerspective, kOrthographic };

struct Camera {
  Projection projection = Projection::kPerspective;
  glm::dvec3 position{0.0, -120.0, 160.0};  // mm
  glm::dvec3 target{0.0, 0.0, 0.0};         // mm
  glm::dvec3 up{0.0, 0.0, 1.0};
  double fov_y_deg = 40.0;        // perspective: vertical field of view
  double ortho_height_mm = 100.0; // orthographic: height of the view volume
  double near_mm = 1.0;
  double far_mm = 5000.0;
};

// One directional light; `direction` is the direction the light travels.
struct Light {
  glm::dvec3 direction{-0.3, 0.4, -1.0};
  glm::dvec3 color{1.0, 1.0, 1.0};
  double ambient = 0.25;
};

// The 8 Gabor parameters of thesis §4.3.1 plus the kernel shape knobs.
struct GaborParams {
  double a_min = 1.0, a_max = 1.0;                 // amplitude (element height), unitless
  double lambda_min_mm = 0.5, lambda_max_mm = 0.5; // wavelength (element width)
  double theta_min_rad = 0.0, theta_max_rad = 0.0; // orientation range on the reference plane
  double n_min = 20.0, n_max = 30.0;               // impulses per kernel footprint (element spacing)
  double kernel_periods = 1.0;   // Gaussian envelope width W = kernel_periods * lambda
  double truncation = 0.05;      // kernel cut where exp(-r^2/W^2) < truncation
  int max_impulses_per_cell = 64;  // hard cap so huge n cannot hang the shader
  // Evaluation strategy (docs/benchmarks.md). kNaive: the thesis's random count per cell
  // (n / pi on average). kStratified: exactly `stratified_impulses` per cell, one per stratum
  // of a jittered grid; n is then ignored (another texture, same spectrum, fewer kernels).
  // kBaked: the naive texture made periodic (period: a whole number of cells, cell indices
  // wrapped into [-N/2, N/2), so inside the central period it IS the naive texture), baked
  // once per material into a tile of values and derivatives and read back by bicubic Hermite
  // interpolation (src/reference/gabor.h: make_gabor_bake_plan).
  // kAuto: per material, the first baked tile (bilinear at 24 then 32 samples per lambda_min,
  // then Hermite at 16 then 32) whose measured error against the naive texture is <= 1 % of
  // sigma and whose period covers the shadow window, else naive.
  // kBakedLinear: the same periodic texture, values only, read by one bilinear texture fetch
  // (cheaper than Hermite's four RGBA32F fetches, but it needs ~1.5-2x the samples per
  // lambda_min for the same error: 24-32; at the default 16 it errs ~1.1 % of sigma).
  enum class Strategy { kNaive, kStratified, kBaked, kAuto, kBakedLinear };
  Strategy strategy = Strategy::kAuto;  // the fastest that meets the 1 % bar (docs/benchmarks.md)
  int stratified_impulses = 4;
  int bake_samples_per_lambda = 16;  // kBaked: tile samples per lambda_min (texel = lambda_min / this)
  // Anti-aliasing (Lagae et al. 2009 §5; docs/architecture.md, "Texture filtering"). kAnalytic:
  // every kernel convolved with the pixel's footprint, a Gaussian in (u, v) of covariance
  // filter_pixel_variance * J J^T (J: the screen-space derivatives of (u, v), mm per pixel);
  // baked tiles get mip levels baked from that filtered definition. kNone: the point-sampled
  // texture (aliases where lambda is a few pixels or less). Default kAnalytic: measured in
  // `bench --texture-filter` (docs/benchmarks.md, "Texture filtering").
  enum class Filter { kNone, kAnalytic };
  Filter filter = Filter::kAnalytic;
  // Variance of the Gaussian standing for one pixel's box, in pixels^2: 1/12 is the box's own
  // variance, so the two agree to second order in frequency.
  double filter_pixel_variance = 1.0 / 12.0;
  bool operator==(const GaborParams&) const = default;
};

struct Material {
  std::string name;
  glm::dvec3 albedo{0.8, 0.8, 0.8};
  std::string albedo_texture;  // absolute path after loading, empty = none
  double albedo_texture_scale_mm = 50.0;  // world size of one texture repeat
  glm::dvec2 albedo_texture_offset_mm{0.0};  // world (x, y) where a repeat starts
  bool textured = true;        // false: no Gabor texture (compiled out of the shader)
  GaborParams gabor;
  double onset_distance_mm = 5.0;      // texture shows where probe-surface distance < onset
  double influence_distance_mm = 50.0; // no pseudo-shadow at all beyond this distance
  // Pseudo-shadow intensity: 1 if d <= 0, else floor + scale / (d + offset)  (thesis §4.3.2).
  double intensity_floor = 0.1;
  double intensity_scale = 0.9;
  double intensity_offset_mm = 1.25;
  double resistance = 1.0;  // hardness: fraction of the penetration pushed back per frame
  // Speed modulation (thesis §4.3.1): amplitude *= exp(-(df/bandwidth)^2), df against peak.
  double peak_hz = 250.0;
  double bandwidth_hz = 100.0;
  // Lookup tables replacing the two formulas above (scene/lut.h; empty: the formula, bit for
  // bit): distance mm -> intensity for 0 < d < influence, speed mm/s -> amplitude gain.
  Lut intensity_lut{LutAxis::kDistanceMm, {}, {}};
  Lut speed_gain_lut{LutAxis::kSpeedMmS, {}, {}};
  HapticMaterial haptic;  // how it feels (scene/haptic_material.h)
  // Gain of its vibrotactile texture (src/vibration/, docs/vibration.md): 0 silences the
  // surface (its texture and its contact transients); untextured materials have no texture term.
  double vibration_gain = 1.0;
  bool operator==(const Material&) const = default;
};

enum class SurfaceType { kPlane, kSphere, kTorus, kHeightField, kMesh, kBox, kFourd };

// The bendable polygons of A Virtual Universe §6 (world/deformable.h): the drawn vertices on
// springs to their rest positions and to their neighbours, dented by the probe; the felt
// shape stays at rest.
struct DeformParams {
  bool enabled = false;               // `deformable`
  double base_n_per_mm = 0.05;        // spring from each vertex to its base point
  double neighbour_n_per_mm = 0.2;    // spring between neighbouring vertices' displacements
  double damping_n_s_per_mm = 0.005;  // per vertex, on its velocity
  double mass_g = 1.0;                // per vertex
  double max_mm = 6.0;                // no vertex moves farther from its base point
  // The drawn mesh is split (each triangle into four, edge midpoints shared) until no edge is
  // longer than this, so a dent is round on a coarse mesh (Sandia's "divided into six").
  double max_edge_mm = 1.5;
};

struct Surface {
  SurfaceType type = SurfaceType::kPlane;
  std::string material;      // material name as written
  int material_index = 0;    // index into Scene::materials (resolved by the parser)
  glm::dvec3 center{0.0};    // mm
  glm::dvec3 rotation_deg{0.0};  // XYZ Euler rotation applied to the local shape
  // plane / height field: local XY extent; normal is local +Z
  glm::dvec2 size_mm{200.0, 200.0};
  // sphere radius; torus major radius
  double radius_mm = 50.0;
  // torus tube radius
  double minor_radius_mm = 15.0;
  // height field: grey image (absolute path after loading) scaled to [0, height_mm]
  std::string heightmap;
  double height_mm = 5.0;
  // mesh: file loaded through assimp (absolute path after loading), uniform scale
  std::string mesh_file;
  double scale = 1.0;
  // box: full edge lengths along local X, Y, Z
  glm::dvec3 box_size_mm{20.0, 20.0, 20.0};
  int resolution = 64;       // tessellation of procedural shapes (segments)
  bool visible = true;       // false: felt but not drawn (a hidden object)
  bool touchable = true;     // false: drawn but not felt
  // Drawn stretched by these factors along its local axes, about `center`, while it is felt
  // unstretched (A Virtual Universe §3, "Illusion"); the drawn probe is stretched alike near it
  // (visual_position). [1, 1, 1]: as felt.
  glm::dvec3 visual_stretch{1.0};
  // Field map (A Virtual Universe §5): the surface shows |F| of the scene's charges as a colour map
  // (render/field_map.h).
  // It gets its own material, `field_map_material` (a white copy of `material`).
  bool field_map = false;
  int field_map_material = -1;
  DeformParams deform;       // deformable + deform_* keys
  // fourd: a surface embedded in R^4, rotated in 4D and projected to 3D (docs/fourd.md); `scale`
  // is mm per 4D unit of its 3D image, `center` and `rotation_deg` place that image as usual.
  fourd::Spec fourd;
  int button = -1;           // >= 0: the plate the scene's [[buttons]] #button adds (not in the file)
  int line = 0;              // line in the scene file, for error messages
};

enum class ProbeShape { kSphere, kCapsule, kMesh };

struct Probe {
  ProbeShape shape = ProbeShape::kSphere;
  double radius_mm = 8.0;        // sphere and capsule radius
  double length_mm = 30.0;       // capsule: distance between the two cap centres
  glm::dvec3 axis{0.0, 0.0, 1.0};  // capsule: direction from tip cap centre to the other
  std::string mesh_file;         // mesh probe (absolute path after loading)
  double mesh_scale = 1.0;
  glm::dvec3 position{0.0, 0.0, 10.0};  // mm; sphere centre / capsule tip-cap centre / mesh origin
  glm::dvec3 velocity{0.0, 0.0, 0.0};   // mm/s
};

enum class DisplacementMethod { kWeightedAverage, kExactMax };

// How a surface point's distance d to the probe is measured (docs/rendering.md, "Distance on
// curved receivers"): along the one reference normal for the whole footprint (the thesis, §5.1),
// or along the surface's own normal (a ray through the probe depth map's height field).
enum class ShadowDistance { kReferencePlane, kSurfaceNormal };

struct RenderSettings {
  int width = 512, height = 512;
  int frames = 1;
  int depth_map_size = 256;         // probe depth map resolution (square)
  glm::dvec3 background{0.18, 0.19, 0.22};
  DisplacementMethod displacement = DisplacementMethod::kWeightedAverage;
  double weight_exponent = 20.0;    // c in weight = (1 - d)^c (thesis §4.5.4)
  ShadowDistance shadow_distance = ShadowDistance::kSurfaceNormal;
  std::uint32_t seed = 1;           // Gabor impulse seed
  // The visual feedback conditions of a targeting experiment (docs/scene-format.md, [render]):
  // the probe's pseudo-shadow in the colour image (false: colour only; AOVs, reductions and the
  // haptic side unchanged), the probe drawn opaque (as `--show-probe`; either draws it), an
  // ordinary hard shadow of the probe's bounding sphere along [light] (colour only).
  bool pseudo_shadow = true;
  bool draw_probe = false;
  bool cast_shadow = false;
};

// [[fields]]: forces of the haptic world that are not surfaces (docs/haptics.md, "Fields").
enum class FieldType { kGravity, kUniform, kViscous, kCharge };

struct Field {
  FieldType type = FieldType::kUniform;
  // gravity: the acceleration of every body (mm/s^2)
  glm::dvec3 acceleration_mm_s2{0.0, 0.0, -9810.0};
  // uniform: F = force_n + fluctuation_n sin(2 pi frequency_hz t) on the probe
  // (Sepulveda-Cervantes et al., room 5)
  glm::dvec3 force_n{0.0};
  glm::dvec3 fluctuation_n{0.0};
  double frequency_hz = 1.0;
  // viscous: F = -viscosity_n_s_per_mm v on the probe inside the region
  // (Sepulveda-Cervantes et al., room 2)
  double viscosity_n_s_per_mm = 0.0;
  // uniform and viscous: a box region (centre, full edges, XYZ Euler rotation); uniform fields
  // without size_mm act everywhere, viscous ones need it
  bool bounded = false;
  glm::dvec3 center{0.0};
  glm::dvec3 size_mm{0.0};
  glm::dvec3 rotation_deg{0.0};
  // charge: a point charge at `position`; F = charge (p - c) / (|p - c|^2 + s^2)^(3/2), s =
  // softening_mm (A Virtual Universe §5: Coulomb's law, softened so it stays finite at the charge)
  glm::dvec3 position{0.0};
  double charge_n_mm2 = 0.0;  // > 0 pushes the probe away, < 0 pulls it in
  double softening_mm = 2.0;
  int line = 0;
};

inline constexpr int kMaxSceneBodies = 4;  // the haptic state carries this many positions

// [[bodies]]: a mass hanging from the proxy on a spring (A Virtual Universe §4;
// docs/haptics.md, "Bodies").
struct Body {
  double mass_g = 50.0;
  double spring_n_per_mm = 0.1;        // spring between the proxy and the body
  double rest_length_mm = 30.0;
  double damping_n_s_per_mm = 0.0;     // along the spring
  // Air drag, as a rate: the body's own velocity decays by 1/e in 1 / air_damping_per_s
  // simulated seconds (F = -air_damping_per_s m v). Damps the swing across the spring, which
  // the damping along it cannot: without it a ball keeps circling after the hand stops.
  double air_damping_per_s = 0.0;
  // > 0: the spring cannot stretch past this length (a band that tightens into a string), so
  // the body stays within it of the proxy however the hand flings it. 0: unbounded.
  double max_length_mm = 0.0;
  double radius_mm = 6.0;
  std::string material;                // its look; empty: the first surface's material
  int material_index = 0;
  glm::dvec3 position{0.0, 0.0, -30.0};  // start, mm (absolute)
  bool floor = true;                   // bounces on the plane z = floor_z_mm
  double floor_z_mm = 0.0;
  double restitution = 0.6;            // bounce speed / impact speed
  double time_scale = 1.0;             // simulated seconds per real second (< 1: heavier, slower)
  int substeps = 4;                    // integration steps per haptic tick
  int line = 0;
};

inline constexpr int kMaxSceneButtons = 16;
inline constexpr std::size_t kMaxButtonLabelChars = 32;  // one short line on the button
inline constexpr int kMaxSceneFlags = 32;  // HapticState::flags is a 32-bit mask

// [[buttons]]: a flush button in a surface (A Virtual Universe §2; docs/haptics.md, "Buttons"): a
// rectangle of the face it sits in that gives way to the probe with its own spring, and past
// `travel_mm` stops pushing and fires its action.
enum class ButtonActionKind { kScene, kFlag };

struct Button {
  glm::dvec3 center{0.0};          // centre of its face, on the surface it sits in, mm
  glm::dvec2 size_mm{30.0, 30.0};  // face extent along local X and Y
  glm::dvec3 rotation_deg{0.0};    // XYZ Euler, as a plane's: local +Z is the outward normal
  double stiffness_n_per_mm = 0.2; // its spring (softer than the wall around it)
  double travel_mm = 3.0;          // press depth at which it fires and its force stops
  std::string action;              // as written: "scene:FILE" or "flag:NAME"
  // The text drawn on it in the window (`run`): the file's `label`, else the target scene's
  // file name without its extension ("field" for scene:field.toml) or the flag's name.
  std::string label;
  ButtonActionKind action_kind = ButtonActionKind::kFlag;
  std::string action_target;       // scene: the file's absolute path; flag: its name
  int flag = -1;                   // flag: index into Scene::flags
  std::string material;            // the plate's look and feel; empty: the first surface's
  int material_index = 0;
  bool visible = true;             // draw its plate
  // Its plate shows a picture of the scene its scene action leads to (rendered headless by the
  // renderer, cached until that scene file changes: render/button_pictures.h). The plate gets
  // its own material, `picture_material` (a copy of `material`, white, the picture as albedo
  // texture mapped along world X/Y onto the plate: a panel facing +Z).
  bool picture = false;
  int picture_material = -1;
  int line = 0;
};

// [navigation] (A Virtual Universe §5, Field's craft): the probe moves in a box of the device's
// workspace; pushing a wall of it moves the view (and the box with it) in that direction at a
// speed that follows the push, and the wall pushes back. HapticLoop applies it
// (docs/universe.md, "Field").
struct Navigation {
  bool enabled = false;                  // the table is present
  glm::dvec3 box_center{0.0};            // workspace (device) mm
  glm::dvec3 box_size_mm{120.0, 90.0, 60.0};
  double speed_mm_s_per_mm = 20.0;       // view speed per mm the hand is past a wall
  double max_speed_mm_s = 300.0;
  double wall_n_per_mm = 0.5;            // the wall's spring on the hand
  int line = 0;
};

struct Scene {
  std::string path;  // file the scene came from ("<embedded default>" for the built-in one)
  Camera camera;
  Light light;
  Probe probe;
  RenderSettings render;
  std::vector<Material> materials;
  std::vector<Surface> surfaces;
  std::vector<Field> fields;
  std::vector<Body> bodies;
  std::vector<Button> buttons;
  std::vector<std::string> flags;  // names toggled by the buttons' flag actions, first use first
  Navigation navigation;
};

}  // namespace ps
