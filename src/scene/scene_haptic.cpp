// [materials.NAME.haptic] and its [[materials.NAME.haptic.texture]] waves: how a material feels
// (scene/haptic_material.h; docs/scene-format.md has the table of keys, docs/haptics.md the laws).
#include <array>

#include "scene/scene_convert.h"

namespace ps::scene_detail {
namespace {

using std::string_view_literals::operator""sv;

// Upper bounds are sanity limits, far above what an impedance device renders stably (a
// desktop device manages a few N/mm and ~10 N), so a unit mix-up (N/m for N/mm) is caught.
constexpr double kMaxStiffnessNPerMm = 100.0;
constexpr double kMaxDampingNSPerMm = 1.0;  // 1000 N s/m
constexpr double kMaxForceN = 100.0;
constexpr double kMaxFriction = 5.0;        // mu; rubber on dry rubber is ~1-2
constexpr double kMaxLengthMm = 1e5;

constexpr std::array kWaveShapes = {"sine"sv, "square"sv};

Status read_wave(const ParseContext& ctx, const toml::table& table, const std::string& path,
                 int index, HapticWave& out) {
  const std::string at = path + "." + std::to_string(index);
  TableReader r(ctx, &table, Section::kHapticWave, at,
                "[[" + path + "]] #" + std::to_string(index));
  r.check_unknown_keys();
  int shape = static_cast<int>(out.shape);
  r.choice("shape", shape, kWaveShapes);
  out.shape = static_cast<HapticWave::Shape>(shape);
  r.number("amplitude_n", out.amplitude_n, Range::closed(0.0, kMaxForceN));
  r.number("period_mm", out.period_mm, Range::positive(kMaxLengthMm));
  r.vec2("direction", out.direction, Range::any());
  r.require(glm::length(out.direction) > 1e-9, "direction", "must be non-zero");
  if (r.ok()) out.direction = glm::normalize(out.direction);
  return r.status();
}

void read_texture(const ParseContext& ctx, TableReader& r, HapticMaterial& out) {
  const toml::array* waves = r.table_array("texture");
  if (!waves) return;
  const std::string path = r.path() + ".texture";
  if (waves->size() > static_cast<std::size_t>(kMaxHapticWaves)) {
    return r.fail("texture", "has " + std::to_string(waves->size()) +
                                 " waves, more than the limit of " +
                                 std::to_string(kMaxHapticWaves));
  }
  out.texture.clear();
  for (std::size_t i = 0; i < waves->size() && r.ok(); ++i) {
    HapticWave wave;
    r.adopt(read_wave(ctx, *(*waves)[i].as_table(), path, static_cast<int>(i), wave));
    out.texture.push_back(wave);
  }
}

}  // namespace

Status read_haptic(const ParseContext& ctx, const toml::table* table, const std::string& path,
                   HapticMaterial& out) {
  TableReader r(ctx, table, Section::kHaptic, path, "[" + path + "]");
  r.check_unknown_keys();
  r.number("stiffness_n_per_mm", out.stiffness_n_per_mm, Range::closed(0.0, kMaxStiffnessNPerMm));
  r.number("stiffness_exponent", out.stiffness_exponent, Range::closed(0.0, 3.0));
  r.number("damping_n_s_per_mm", out.damping_n_s_per_mm, Range::closed(0.0, kMaxDampingNSPerMm));
  r.number("static_friction", out.static_friction, Range::closed(0.0, kMaxFriction));
  r.number("dynamic_friction", out.dynamic_friction, Range::closed(0.0, kMaxFriction));
  r.integer("friction_history_ticks", out.friction_history_ticks, 1, kMaxFrictionHistoryTicks);
  r.number("stick_speed_mm_s", out.stick_speed_mm_s, Range::positive(1000.0));
  r.boolean("penetrable", out.penetrable);
  r.number("viscosity_n_s_per_mm", out.viscosity_n_s_per_mm,
           Range::closed(0.0, kMaxDampingNSPerMm));
  r.number("magnetic_force_n", out.magnetic_force_n, Range::closed(0.0, kMaxForceN));
  r.number("magnetic_range_mm", out.magnetic_range_mm, Range::closed(0.0, 1000.0));
  r.number("stickiness_n", out.stickiness_n, Range::closed(0.0, kMaxForceN));
  r.number("restitution", out.restitution, Range::closed(0.0, 1.0));
  read_texture(ctx, r, out);
  r.require(out.dynamic_friction <= out.static_friction, "dynamic_friction",
            "(" + format_number(out.dynamic_friction) + ") must be <= 'static_friction' (" +
                format_number(out.static_friction) + ")");
  r.require(out.viscosity_n_s_per_mm == 0.0 || out.penetrable, "viscosity_n_s_per_mm",
            "acts only inside a penetrable material; add 'penetrable = true' (water, thick fluid)");
  r.require(out.magnetic_force_n == 0.0 || out.magnetic_range_mm > 0.0, "magnetic_range_mm",
            "must be > 0 when 'magnetic_force_n' is set (the attraction acts within this range)");
  return r.status();
}

}  // namespace ps::scene_detail
