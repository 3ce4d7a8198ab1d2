// Section converters: one flat list of keys per table, in the order of docs/scene-format.md.
#include "scene/scene_convert.h"

#include <algorithm>
#include <array>

namespace ps::scene_detail {
namespace {

using std::string_view_literals::operator""sv;

// Limits (documented in docs/scene-format.md). Lengths: 100 m is far beyond any desk-top
// scene, yet small enough that float positions keep sub-micrometre precision near the origin.
constexpr double kMaxLengthMm = 1e5;
constexpr int kMaxRenderDimension = 8192;
constexpr long long kMaxRenderPixels = 16'777'216;  // 4096 x 4096: keeps targets < 256 MB
constexpr int kMaxFrames = 100'000;
constexpr double kMaxImpulseDensity = 1e4;  // n beyond this would only burn shader time
constexpr int kMaxResolution = 1024;        // 1024^2 * 2 triangles stays under kMaxMeshTriangles

constexpr std::array kProjections = {"perspective"sv, "orthographic"sv};
constexpr std::array kProbeShapes = {"sphere"sv, "capsule"sv, "mesh"sv};
constexpr std::array kDisplacements = {"weighted_average"sv, "exact_max"sv};
constexpr std::array kShadowDistances = {"reference_plane"sv, "surface_normal"sv};
constexpr std::array kGaborStrategies = {"naive"sv, "stratified"sv, "baked"sv, "auto"sv, "baked_linear"sv};
// Same order as GaborParams::Filter.
constexpr std::array kGaborFilters = {"none"sv, "analytic"sv};
// Same order as SurfaceType.
constexpr std::array kSurfaceTypes = {"plane"sv, "sphere"sv, "torus"sv, "heightfield"sv,
                                      "mesh"sv,  "box"sv,    "fourd"sv};

const Range kLength = Range::positive(kMaxLengthMm);
const Range kCoordinate = Range::closed(-kMaxLengthMm, kMaxLengthMm);
const Range kUnit = Range::closed(0.0, 1.0);

bool is_power_of_two(int v) { return v > 0 && (v & (v - 1)) == 0; }

template <class Enum>
void read_enum(TableReader& r, std::string_view key, Enum& out,
               std::span<const std::string_view> choices) {
  int index = static_cast<int>(out);
  r.choice(key, index, choices);
  out = static_cast<Enum>(index);
}

void check_min_max(TableReader& r, std::string_view min_key, double lo, double hi,
                   std::string_view max_key) {
  r.require(lo <= hi, min_key,
            "(" + format_number(lo) + ") must be <= '" + std::string(max_key) + "' (" +
                format_number(hi) + ")");
}

}  // namespace

Status read_camera(const ParseContext& ctx, const toml::table* table, Camera& out) {
  TableReader r(ctx, table, Section::kCamera, "camera", "[camera]");
  r.check_unknown_keys();
  read_enum(r, "projection", out.projection, kProjections);
  r.vec3("position", out.position, kCoordinate);
  r.vec3("target", out.target, kCoordinate);
  r.vec3("up", out.up, Range::any());
  r.number("fov_y_deg", out.fov_y_deg, Range{0.0, 180.0, true, true});
  r.number("ortho_height_mm", out.ortho_height_mm, kLength);
  r.number("near_mm", out.near_mm, kLength);
  r.number("far_mm", out.far_mm, Range::positive(1e7));
  const glm::dvec3 view = out.target - out.position;
  r.require(glm::length(view) > 1e-9, "target", "must differ from 'position'");
  r.require(out.far_mm > out.near_mm, "far_mm", "must be > 'near_mm'");
  const double up_len = glm::length(out.up);
  r.require(up_len > 1e-9 && glm::length(glm::cross(view, out.up)) > 1e-6 * up_len *
                                 glm::length(view),
            "up", "must be non-zero and not parallel to the view direction (target - position)");
  return r.status();
}

Status read_light(const ParseContext& ctx, const toml::table* table, Light& out) {
  TableReader r(ctx, table, Section::kLight, "light", "[light]");
  r.check_unknown_keys();
  r.vec3("direction", out.direction, Range::any());
  r.vec3("color", out.color, Range::closed(0.0, 1000.0));
  r.number("ambient", out.ambient, kUnit);
  r.require(glm::length(out.direction) > 1e-9, "direction", "must be non-zero");
  return r.status();
}

Status read_navigation(const ParseContext& ctx, const toml::table* table, Navigation& out) {
  if (table == nullptr) return ok_status();
  TableReader r(ctx, table, Section::kNavigation, "navigation", "[navigation]");
  out.enabled = true;
  out.line = static_cast<int>(table->source().begin.line);
  r.check_unknown_keys();
  r.vec3("box_center", out.box_center, kCoordinate);
  r.vec3("box_size_mm", out.box_size_mm, kLength);
  r.number("speed_mm_s_per_mm", out.speed_mm_s_per_mm, Range::closed(0.0, 1e4));
  r.number("max_speed_mm_s", out.max_speed_mm_s, Range::positive(1e5));
  r.number("wall_n_per_mm", out.wall_n_per_mm, Range::closed(0.0, 100.0));
  return r.status();
}

Status read_probe(const ParseContext& ctx, const toml::table* table, Probe& out) {
  TableReader r(ctx, table, Section::kProbe, "probe", "[probe]");
  r.check_unknown_keys();
  read_enum(r, "shape", out.shape, kProbeShapes);
  r.number("radius_mm", out.radius_mm, kLength);
  r.number("length_mm", out.length_mm, Range::closed(0.0, kMaxLengthMm));
  r.vec3("axis", out.axis, Range::any());
  r.file("mesh_file", out.mesh_file);
  r.number("mesh_scale", out.mesh_scale, Range::positive(1e6));
  r.vec3("position", out.position, kCoordinate);
  r.vec3("velocity", out.velocity, Range::closed(-1e6, 1e6));
  r.require(glm::length(out.axis) > 1e-9, "axis", "must be non-zero");
  if (r.ok()) out.axis = glm::normalize(out.axis);
  r.require(out.shape != ProbeShape::kMesh || !out.mesh_file.empty(), "mesh_file",
            "is required when shape = \"mesh\"");
  return r.status();
}

Status read_render(const ParseContext& ctx, const toml::table* table, RenderSettings& out) {
  TableReader r(ctx, table, Section::kRender, "render", "[render]");
  r.check_unknown_keys();
  r.int2("size", out.width, out.height, 1, kMaxRenderDimension);
  r.require(static_cast<long long>(out.width) * out.height <= kMaxRenderPixels, "size",
            "has " + std::to_string(static_cast<long long>(out.width) * out.height) +
                " pixels, more than the limit of " + std::to_string(kMaxRenderPixels));
  r.integer("frames", out.frames, 1, kMaxFrames);
  r.integer("depth_map_size", out.depth_map_size, 16, 4096);
  r.require(is_power_of_two(out.depth_map_size), "depth_map_size",
            "must be a power of two in [16, 4096] (got " + std::to_string(out.depth_map_size) +
                ")");
  r.vec3("background", out.background, kUnit);
  read_enum(r, "displacement", out.displacement, kDisplacements);
  read_enum(r, "shadow_distance", out.shadow_distance, kShadowDistances);
  r.number("weight_exponent", out.weight_exponent, Range::positive(1000.0));
  r.seed("seed", out.seed);
  r.boolean("pseudo_shadow", out.pseudo_shadow);
  r.boolean("draw_probe", out.draw_probe);
  r.boolean("cast_shadow", out.cast_shadow);
  return r.status();
}

namespace {

void read_gabor(TableReader& r, GaborParams& g) {
  r.number("a_min", g.a_min, kUnit);
  r.number("a_max", g.a_max, kUnit);
  r.number("lambda_min", g.lambda_min_mm, Range::positive(1000.0));
  r.number("lambda_max", g.lambda_max_mm, Range::positive(1000.0));
  // Orientations are pi-periodic; +-360 degrees is generous and catches radians-vs-degrees
  // mix-ups only when they are large, so the docs stress that the file takes degrees.
  r.angle_deg("theta_min", g.theta_min_rad, Range::closed(-360.0, 360.0));
  r.angle_deg("theta_max", g.theta_max_rad, Range::closed(-360.0, 360.0));
  r.number("n_min", g.n_min, Range::closed(0.0, kMaxImpulseDensity));
  r.number("n_max", g.n_max, Range::closed(0.0, kMaxImpulseDensity));
  r.number("kernel_periods", g.kernel_periods, Range::positive(100.0));
  r.number("truncation", g.truncation, Range{0.0, 1.0, true, true});
  r.integer("max_impulses_per_cell", g.max_impulses_per_cell, 1, 1024);
  read_enum(r, "gabor_strategy", g.strategy, kGaborStrategies);
  read_enum(r, "gabor_filter", g.filter, kGaborFilters);
  r.integer("stratified_impulses", g.stratified_impulses, 1, 1024);
  r.integer("bake_samples_per_lambda", g.bake_samples_per_lambda, 4, 64);
  // theta_min > theta_max is allowed on purpose (see docs): no check for theta.
  check_min_max(r, "a_min", g.a_min, g.a_max, "a_max");
  check_min_max(r, "lambda_min", g.lambda_min_mm, g.lambda_max_mm, "lambda_max");
  check_min_max(r, "n_min", g.n_min, g.n_max, "n_max");
}

// A lookup table file (scene/lut.h); its own errors name the table's file:line.
void read_lut_key(TableReader& r, std::string_view key, Lut& out) {
  std::string path;
  r.file(key, path);
  if (!r.ok() || path.empty()) return;
  auto lut = read_lut(path, out.axis);
  if (!lut) return r.adopt(lut.error());
  out = std::move(lut.value());
}

}  // namespace

Status read_material(const ParseContext& ctx, const toml::table& table, const std::string& name,
                     Material& out) {
  TableReader r(ctx, &table, Section::kMaterial, "materials." + name,
                "[materials." + name + "]");
  out.name = name;
  r.check_unknown_keys();
  r.vec3("albedo", out.albedo, kUnit);
  r.file("albedo_texture", out.albedo_texture);
  r.number("albedo_texture_scale_mm", out.albedo_texture_scale_mm, kLength);
  r.vec2("albedo_texture_offset_mm", out.albedo_texture_offset_mm, Range::closed(-kMaxLengthMm, kMaxLengthMm));
  r.boolean("textured", out.textured);
  read_gabor(r, out.gabor);
  r.number("onset_distance_mm", out.onset_distance_mm, Range::closed(0.0, kMaxLengthMm));
  r.number("influence_distance_mm", out.influence_distance_mm, kLength);
  r.number("intensity_floor", out.intensity_floor, kUnit);
  r.number("intensity_scale", out.intensity_scale, Range::closed(0.0, 1000.0));
  r.number("intensity_offset_mm", out.intensity_offset_mm, kLength);
  r.number("resistance", out.resistance, kUnit);
  r.number("peak_hz", out.peak_hz, Range::positive(1e6));
  r.number("bandwidth_hz", out.bandwidth_hz, Range::positive(1e6));
  r.number("vibration_gain", out.vibration_gain, Range::closed(0.0, 10.0));
  read_lut_key(r, "intensity_lut", out.intensity_lut);
  read_lut_key(r, "speed_gain_lut", out.speed_gain_lut);
  const toml::table* haptic = r.sub_table("haptic");
  r.adopt(read_haptic(ctx, haptic, "materials." + name + ".haptic", out.haptic));
  return r.status();
}

namespace {

// The shape's extent, its files (height map, mesh) and its tessellation.
void read_shape_keys(TableReader& r, Surface& out) {
  // One key for the extent of a shape: [x, y] for planes and height fields, [x, y, z] for a box.
  if (out.type == SurfaceType::kBox) {
    r.vec3("size_mm", out.box_size_mm, kLength);
  } else {
    r.vec2("size_mm", out.size_mm, kLength);
  }
  r.number("radius_mm", out.radius_mm, kLength);
  r.number("minor_radius_mm", out.minor_radius_mm, kLength);
  r.file("heightmap", out.heightmap);
  r.number("height_mm", out.height_mm, Range::closed(-kMaxLengthMm, kMaxLengthMm));
  r.file("mesh_file", out.mesh_file);
  r.number("scale", out.scale, Range::positive(1e6));
  r.integer("resolution", out.resolution, 3, kMaxResolution);
}

// deformable and deform_*: the dent's springs, mass and limits, on a tessellated surface only.
void read_deform_keys(TableReader& r, Surface& out) {
  r.boolean("deformable", out.deform.enabled);
  r.number("deform_base_n_per_mm", out.deform.base_n_per_mm, Range::positive(1e3));
  r.number("deform_neighbour_n_per_mm", out.deform.neighbour_n_per_mm, Range::positive(1e3));
  r.number("deform_damping_n_s_per_mm", out.deform.damping_n_s_per_mm, Range::closed(0.0, 1e3));
  r.number("deform_mass_g", out.deform.mass_g, Range::positive(1e6));
  r.number("deform_max_mm", out.deform.max_mm, Range::positive(kMaxLengthMm));
  r.number("deform_max_edge_mm", out.deform.max_edge_mm, Range::closed(0.05, kMaxLengthMm));
  r.require(!out.deform.enabled || out.type == SurfaceType::kMesh || out.type == SurfaceType::kSphere ||
                out.type == SurfaceType::kTorus || out.type == SurfaceType::kHeightField,
            "deformable", "needs a tessellated surface (mesh, sphere, torus or heightfield): a plane's or a "
                          "box's few vertices cannot dent");
  r.require(!out.deform.enabled || out.visual_stretch == glm::dvec3(1.0), "deformable",
            "cannot be combined with visual_stretch (the dent follows the drawn probe on the felt shape)");
}

}  // namespace

Status read_surface(const ParseContext& ctx, const toml::table& table, int index,
                    const std::vector<std::string>& material_names, Surface& out) {
  const std::string path = "surfaces." + std::to_string(index);
  TableReader r(ctx, &table, Section::kSurface, path, "[[surfaces]] #" + std::to_string(index));
  out.line = static_cast<int>(table.source().begin.line);
  r.check_unknown_keys();
  read_enum(r, "type", out.type, kSurfaceTypes);
  r.string("material", out.material);
  r.vec3("center", out.center, kCoordinate);
  r.vec3("rotation_deg", out.rotation_deg, Range::closed(-3600.0, 3600.0));
  read_shape_keys(r, out);
  r.boolean("visible", out.visible);
  r.boolean("touchable", out.touchable);
  r.vec3("visual_stretch", out.visual_stretch, Range::closed(0.1, 10.0));
  r.boolean("field_map", out.field_map);
  read_fourd_keys(r, out);
  r.require(!out.field_map || out.type == SurfaceType::kPlane || out.type == SurfaceType::kBox, "field_map",
            "needs a plane or a box (the map lies on its top, along world X and Y)");
  read_deform_keys(r, out);
  r.require(out.type != SurfaceType::kTorus || out.minor_radius_mm < out.radius_mm,
            "minor_radius_mm", "must be < 'radius_mm' for a torus (a ring torus)");
  r.require(out.type != SurfaceType::kHeightField || !out.heightmap.empty(), "heightmap",
            "is required when type = \"heightfield\"");
  r.require(out.type != SurfaceType::kMesh || !out.mesh_file.empty(), "mesh_file",
            "is required when type = \"mesh\"");
  const auto it = std::find(material_names.begin(), material_names.end(), out.material);
  if (r.ok() && it == material_names.end()) {
    std::vector<std::string_view> names(material_names.begin(), material_names.end());
    r.fail("material", out.material.empty()
                           ? "is required; defined materials: " + join(names)
                           : "names unknown material '" + out.material +
                                 "'; defined materials: " + join(names));
  }
  out.material_index = static_cast<int>(it - material_names.begin());
  return r.status();
}

}  // namespace ps::scene_detail
