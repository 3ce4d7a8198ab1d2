#include "scene/scene_keys.h"

#include <algorithm>
#include <array>
#include <utility>
#include <cassert>
#include <numeric>
#include <utility>

namespace ps::scene_detail {
namespace {

using std::string_view_literals::operator""sv;

constexpr std::array kRootKeys = {"include"sv, "camera"sv,    "light"sv,   "probe"sv,
                                  "render"sv,  "materials"sv, "surfaces"sv, "fields"sv,
                                  "bodies"sv,  "buttons"sv,   "navigation"sv};
constexpr std::array kNavigationKeys = {"box_center"sv, "box_size_mm"sv, "speed_mm_s_per_mm"sv,
                                        "max_speed_mm_s"sv, "wall_n_per_mm"sv};
constexpr std::array kCameraKeys = {"projection"sv, "position"sv,        "target"sv, "up"sv,
                                    "fov_y_deg"sv,  "ortho_height_mm"sv, "near_mm"sv, "far_mm"sv};
constexpr std::array kLightKeys = {"direction"sv, "color"sv, "ambient"sv};
constexpr std::array kProbeKeys = {"shape"sv,     "radius_mm"sv,  "length_mm"sv,
                                   "axis"sv,      "mesh_file"sv,  "mesh_scale"sv,
                                   "position"sv,  "velocity"sv};
constexpr std::array kRenderKeys = {"size"sv,         "frames"sv,          "depth_map_size"sv,
                                    "background"sv,   "displacement"sv,    "weight_exponent"sv,
                                    "seed"sv,         "shadow_distance"sv,
                                    "pseudo_shadow"sv, "draw_probe"sv,       "cast_shadow"sv};
constexpr std::array kMaterialKeys = {
    "albedo"sv,          "albedo_texture"sv,        "albedo_texture_scale_mm"sv, "albedo_texture_offset_mm"sv,
    "textured"sv,        "a_min"sv,                 "a_max"sv,
    "lambda_min"sv,      "lambda_max"sv,            "theta_min"sv,
    "theta_max"sv,       "n_min"sv,                 "n_max"sv,
    "kernel_periods"sv,  "truncation"sv,            "max_impulses_per_cell"sv,
    "gabor_strategy"sv,  "stratified_impulses"sv, "bake_samples_per_lambda"sv, "gabor_filter"sv,
    "onset_distance_mm"sv, "influence_distance_mm"sv, "intensity_floor"sv,
    "intensity_scale"sv, "intensity_offset_mm"sv,   "resistance"sv,
    "peak_hz"sv,         "bandwidth_hz"sv,          "haptic"sv,
    "intensity_lut"sv,   "speed_gain_lut"sv,        "vibration_gain"sv};
// [materials.NAME.haptic]: how the material feels (scene/haptic_material.h).
constexpr std::array kHapticKeys = {
    "stiffness_n_per_mm"sv,   "stiffness_exponent"sv,     "damping_n_s_per_mm"sv,
    "static_friction"sv,      "dynamic_friction"sv,       "friction_history_ticks"sv,
    "stick_speed_mm_s"sv,     "penetrable"sv,             "viscosity_n_s_per_mm"sv,
    "magnetic_force_n"sv,     "magnetic_range_mm"sv,      "stickiness_n"sv,
    "restitution"sv,          "texture"sv};
constexpr std::array kHapticWaveKeys = {"shape"sv, "amplitude_n"sv, "period_mm"sv,
                                        "direction"sv};
constexpr std::array kSurfaceKeys = {"type"sv,      "material"sv,        "center"sv,
                                     "rotation_deg"sv, "size_mm"sv,      "radius_mm"sv,
                                     "minor_radius_mm"sv, "heightmap"sv, "height_mm"sv,
                                     "mesh_file"sv, "scale"sv,           "resolution"sv,
                                     "visible"sv,   "touchable"sv,       "visual_stretch"sv,
                                     "field_map"sv, "deformable"sv,      "deform_base_n_per_mm"sv,
                                     "deform_neighbour_n_per_mm"sv, "deform_damping_n_s_per_mm"sv,
                                     "deform_mass_g"sv, "deform_max_mm"sv, "deform_max_edge_mm"sv,
                                     // type = "fourd" (scene_fourd.cpp, docs/fourd.md)
                                     "fourd"sv, "fourd_projection"sv, "fourd_eye_distance"sv,
                                     "fourd_rotation_xy_deg"sv, "fourd_rotation_xz_deg"sv,
                                     "fourd_rotation_xw_deg"sv, "fourd_rotation_yz_deg"sv,
                                     "fourd_rotation_yw_deg"sv, "fourd_rotation_zw_deg"sv,
                                     "fourd_grid"sv, "fourd_twists"sv, "fourd_local_model"sv,
                                     "fourd_suggest_kp_n_per_mm"sv, "fourd_suggest_kv_n_s_per_mm"sv,
                                     "fourd_suggest_lookahead_s"sv, "fourd_cutaway_mm"sv, "fourd_crossing_diagram_mm"sv,
                                     "fourd_wireframe"sv,
                                     "fourd_roll"sv, "fourd_roll_turn_s"sv, "fourd_roll_centre_s"sv,
                                     "fourd_roll_tether_n_per_mm4"sv, "fourd_roll_tether_max_n"sv};

constexpr std::array kFieldKeys = {"type"sv,          "acceleration_mm_s2"sv, "force_n"sv,
                                   "fluctuation_n"sv, "frequency_hz"sv,       "viscosity_n_s_per_mm"sv,
                                   "center"sv,        "size_mm"sv,            "rotation_deg"sv,
                                   "position"sv,      "charge_n_mm2"sv,       "softening_mm"sv};
constexpr std::array kBodyKeys = {"mass_g"sv,      "spring_n_per_mm"sv, "rest_length_mm"sv,
                                  "damping_n_s_per_mm"sv, "radius_mm"sv, "material"sv,
                                  "position"sv,    "floor"sv,           "floor_z_mm"sv,
                                  "restitution"sv, "time_scale"sv,      "substeps"sv,
                                  "air_damping_per_s"sv, "max_length_mm"sv};
constexpr std::array kButtonKeys = {"center"sv,   "size_mm"sv,  "rotation_deg"sv, "stiffness_n_per_mm"sv,
                                    "travel_mm"sv, "action"sv,  "material"sv,     "visible"sv,
                                    "picture"sv,   "label"sv};

}  // namespace

std::span<const std::string_view> known_keys(Section section) {
  switch (section) {
    case Section::kRoot: return kRootKeys;
    case Section::kCamera: return kCameraKeys;
    case Section::kLight: return kLightKeys;
    case Section::kNavigation: return kNavigationKeys;
    case Section::kProbe: return kProbeKeys;
    case Section::kRender: return kRenderKeys;
    case Section::kMaterial: return kMaterialKeys;
    case Section::kHaptic: return kHapticKeys;
    case Section::kHapticWave: return kHapticWaveKeys;
    case Section::kSurface: return kSurfaceKeys;
    case Section::kField: return kFieldKeys;
    case Section::kBody: return kBodyKeys;
    case Section::kButton: return kButtonKeys;
  }
  assert(false && "known_keys: unhandled Section");
  return {};
}

std::string_view key_unit(std::string_view leaf) {
  // Longest suffixes first: "stiffness_n_per_mm" ends in "_mm" too.
  if (leaf.ends_with("_n_s_per_mm")) return "N s/mm";
  if (leaf.ends_with("_n_per_mm")) return "N/mm";
  if (leaf.ends_with("_mm_s")) return "mm/s";
  if (leaf.ends_with("_n")) return "N";
  if (leaf.ends_with("_mm")) return "mm";
  if (leaf.ends_with("_deg")) return "deg";
  if (leaf.ends_with("_hz")) return "Hz";
  static constexpr std::pair<std::string_view, std::string_view> kNamed[] = {
      {"position", "mm"},   {"target", "mm"},     {"center", "mm"},    {"velocity", "mm/s"},
      {"lambda_min", "mm"}, {"lambda_max", "mm"}, {"theta_min", "deg"}, {"theta_max", "deg"},
      {"size", "px"},       {"depth_map_size", "px"}};
  for (const auto& [name, unit] : kNamed)
    if (leaf == name) return unit;
  return {};
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::vector<std::string_view> close_matches(std::string_view key,
                                            std::span<const std::string_view> candidates) {
  // A third of the key's length (at least 2) catches typos without suggesting unrelated keys;
  // a key missing only its unit suffix ("radius" for "radius_mm") counts as one edit.
  const std::size_t limit = std::max<std::size_t>(2, key.size() / 3);
  std::vector<std::pair<std::size_t, std::string_view>> scored;
  for (std::string_view c : candidates) {
    const bool prefix = key.size() >= 3 && (c.starts_with(key) || key.starts_with(c));
    const std::size_t d = prefix ? 1 : edit_distance(key, c);
    if (d <= limit) scored.emplace_back(d, c);
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  // Only the best-scoring candidates: "lamda_min" suggests lambda_min, not also lambda_max.
  std::vector<std::string_view> out;
  for (std::size_t i = 0; i < scored.size() && i < 3 && scored[i].first == scored[0].first; ++i) {
    out.push_back(scored[i].second);
  }
  return out;
}

std::string join(std::span<const std::string_view> items, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += separator;
    out += items[i];
  }
  return out;
}

}  // namespace ps::scene_detail
