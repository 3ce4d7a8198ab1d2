// [[fields]], [[bodies]] and [[buttons]]: the haptic world beyond surfaces
// (docs/scene-format.md has the keys, docs/haptics.md the laws).
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "scene/scene_convert.h"

namespace ps::scene_detail {
namespace {

using std::string_view_literals::operator""sv;

// Same order as FieldType.
constexpr std::array kFieldTypes = {"gravity"sv, "uniform"sv, "viscous"sv, "charge"sv};
constexpr double kMaxLengthMm = 1e5;
constexpr double kMaxForceN = 100.0;  // as the haptic materials: a unit mix-up is caught
const Range kCoordinate = Range::closed(-kMaxLengthMm, kMaxLengthMm);

// Keys that only one kind of field reads: given to another kind they are an error, not ignored.
void only_for(TableReader& r, FieldType type, std::initializer_list<std::string_view> keys,
              std::initializer_list<FieldType> owners, std::string_view owner_names) {
  for (FieldType o : owners)
    if (o == type) return;
  for (std::string_view k : keys)
    if (r.has(k)) return r.fail(k, "applies only to type = " + std::string(owner_names));
}

// A body's or button's `material`: empty keeps the index the caller set (the first surface's).
void resolve_material(TableReader& r, const std::vector<std::string>& material_names, const std::string& name,
                      int& index) {
  if (name.empty()) return;
  const auto it = std::find(material_names.begin(), material_names.end(), name);
  if (it == material_names.end()) {
    if (r.ok()) {
      std::vector<std::string_view> names(material_names.begin(), material_names.end());
      r.fail("material", "names unknown material '" + name + "'; defined materials: " + join(names));
    }
    return;
  }
  index = static_cast<int>(it - material_names.begin());
}

}  // namespace

Status read_field(const ParseContext& ctx, const toml::table& table, int index, Field& out) {
  const std::string path = "fields." + std::to_string(index);
  TableReader r(ctx, &table, Section::kField, path, "[[fields]] #" + std::to_string(index));
  out.line = static_cast<int>(table.source().begin.line);
  r.check_unknown_keys();
  r.require(r.has("type"), "type", "is required: one of \"gravity\", \"uniform\", \"viscous\", \"charge\"");
  int type = static_cast<int>(out.type);
  r.choice("type", type, kFieldTypes);
  out.type = static_cast<FieldType>(type);
  r.vec3("acceleration_mm_s2", out.acceleration_mm_s2, Range::closed(-1e7, 1e7));
  r.vec3("force_n", out.force_n, Range::closed(-kMaxForceN, kMaxForceN));
  r.vec3("fluctuation_n", out.fluctuation_n, Range::closed(-kMaxForceN, kMaxForceN));
  r.number("frequency_hz", out.frequency_hz, Range::closed(0.0, 500.0));
  r.number("viscosity_n_s_per_mm", out.viscosity_n_s_per_mm, Range::closed(0.0, 1.0));
  r.vec3("center", out.center, kCoordinate);
  r.vec3("size_mm", out.size_mm, Range::positive(kMaxLengthMm));
  r.vec3("rotation_deg", out.rotation_deg, Range::closed(-3600.0, 3600.0));
  r.vec3("position", out.position, kCoordinate);
  r.number("charge_n_mm2", out.charge_n_mm2, Range::closed(-1e6, 1e6));
  r.number("softening_mm", out.softening_mm, Range::positive(kMaxLengthMm));
  out.bounded = r.has("size_mm");
  if (!r.ok()) return r.status();
  only_for(r, out.type, {"acceleration_mm_s2"}, {FieldType::kGravity}, "\"gravity\"");
  only_for(r, out.type, {"force_n", "fluctuation_n", "frequency_hz"}, {FieldType::kUniform}, "\"uniform\"");
  only_for(r, out.type, {"viscosity_n_s_per_mm"}, {FieldType::kViscous}, "\"viscous\"");
  only_for(r, out.type, {"center", "size_mm", "rotation_deg"}, {FieldType::kUniform, FieldType::kViscous},
           "\"uniform\" or \"viscous\" (their region)");
  only_for(r, out.type, {"position", "charge_n_mm2", "softening_mm"}, {FieldType::kCharge}, "\"charge\"");
  r.require(out.type != FieldType::kViscous || out.bounded, "size_mm",
            "is required for a viscous field: the box region where it acts (centre 'center')");
  r.require(out.type != FieldType::kViscous || r.has("viscosity_n_s_per_mm"), "viscosity_n_s_per_mm",
            "is required for a viscous field (b in F = -b v, N s/mm)");
  r.require(out.type != FieldType::kCharge || out.charge_n_mm2 != 0.0, "charge_n_mm2",
            "is required and non-zero for a charge (> 0 pushes the probe away, < 0 pulls it in)");
  return r.status();
}

Status read_body(const ParseContext& ctx, const toml::table& table, int index,
                 const std::vector<std::string>& material_names, Body& out) {
  const std::string path = "bodies." + std::to_string(index);
  TableReader r(ctx, &table, Section::kBody, path, "[[bodies]] #" + std::to_string(index));
  out.line = static_cast<int>(table.source().begin.line);
  r.check_unknown_keys();
  r.number("mass_g", out.mass_g, Range::positive(1e5));
  r.number("spring_n_per_mm", out.spring_n_per_mm, Range::positive(100.0));
  r.number("rest_length_mm", out.rest_length_mm, Range::closed(0.0, kMaxLengthMm));
  r.number("damping_n_s_per_mm", out.damping_n_s_per_mm, Range::closed(0.0, 1.0));
  r.number("air_damping_per_s", out.air_damping_per_s, Range::closed(0.0, 1000.0));
  r.number("max_length_mm", out.max_length_mm, Range::closed(0.0, kMaxLengthMm));
  r.require(out.max_length_mm == 0.0 || out.max_length_mm >= out.rest_length_mm, "max_length_mm",
            "(" + std::to_string(out.max_length_mm) + ") must be 0 (unbounded) or >= 'rest_length_mm' (" +
                std::to_string(out.rest_length_mm) + ")");
  r.number("radius_mm", out.radius_mm, Range::positive(kMaxLengthMm));
  r.string("material", out.material);
  r.vec3("position", out.position, kCoordinate);
  r.boolean("floor", out.floor);
  r.number("floor_z_mm", out.floor_z_mm, kCoordinate);
  r.number("restitution", out.restitution, Range::closed(0.0, 1.0));
  r.number("time_scale", out.time_scale, Range::closed(0.01, 10.0));
  r.integer("substeps", out.substeps, 1, 64);
  resolve_material(r, material_names, out.material, out.material_index);
  return r.status();
}

namespace {

// action = "scene:FILE" (the file resolved and admitted) or "flag:NAME", and the label it gives
// an unlabelled button; false when it is neither form.
bool read_action(const ParseContext& ctx, TableReader& r, Button& out) {
  const std::size_t colon = out.action.find(':');
  const std::string kind = out.action.substr(0, colon);
  const std::string target = colon == std::string::npos ? std::string() : out.action.substr(colon + 1);
  if ((kind != "scene" && kind != "flag") || target.empty()) {
    r.fail("action", "'" + out.action + "' is not \"scene:FILE\" or \"flag:NAME\"");
    return false;
  }
  out.action_kind = kind == "scene" ? ButtonActionKind::kScene : ButtonActionKind::kFlag;
  if (out.action_kind == ButtonActionKind::kScene) {
    namespace fs = std::filesystem;
    fs::path file(target);
    if (file.is_relative()) file = fs::path(ctx.base_dir) / file;
    file = file.lexically_normal();
    std::error_code ec;
    if (Status s = ctx.paths.admit(file, "names"); !s && !r.from_user("action")) r.fail("action", s.error().message);
    if (!fs::is_regular_file(file, ec)) r.fail("action", "scene file not found: " + file.string());
    out.action_target = file.string();
    if (out.label.empty()) out.label = fs::path(target).stem().string();
  } else {
    out.action_target = target;
    if (out.label.empty()) out.label = target;
    if (out.picture) r.fail("picture", "needs a \"scene:FILE\" action: the picture is of the scene the button leads to");
  }
  return true;
}

}  // namespace

Status read_button(const ParseContext& ctx, const toml::table& table, int index,
                   const std::vector<std::string>& material_names, double probe_radius_mm, Button& out) {
  const std::string path = "buttons." + std::to_string(index);
  TableReader r(ctx, &table, Section::kButton, path, "[[buttons]] #" + std::to_string(index));
  out.line = static_cast<int>(table.source().begin.line);
  r.check_unknown_keys();
  r.vec3("center", out.center, kCoordinate);
  r.vec2("size_mm", out.size_mm, Range::positive(kMaxLengthMm));
  r.vec3("rotation_deg", out.rotation_deg, Range::closed(-3600.0, 3600.0));
  r.number("stiffness_n_per_mm", out.stiffness_n_per_mm, Range::positive(100.0));
  r.number("travel_mm", out.travel_mm, Range::positive(1000.0));
  r.string("action", out.action);
  r.string("material", out.material);
  r.boolean("visible", out.visible);
  r.boolean("picture", out.picture);
  r.string("label", out.label);
  // A label is read on the button in the window: one short line.
  r.require(out.label.size() <= kMaxButtonLabelChars && out.label.find('\n') == std::string::npos, "label",
            "must be one line of at most " + std::to_string(kMaxButtonLabelChars) + " characters (got " +
                std::to_string(out.label.size()) + ")");
  if (!r.ok()) return r.status();
  r.require(r.has("action"), "action",
            "is required: what the button does when pushed past its travel, \"scene:FILE\" (switch to that "
            "scene) or \"flag:NAME\" (toggle a named flag)");
  if (!r.ok()) return r.status();
  if (!read_action(ctx, r, out)) return r.status();
  // The probe (a sphere of radius R) must fit in the button to push it in: a narrower one
  // would hold it on its rim.
  const double narrowest = std::min(out.size_mm.x, out.size_mm.y);
  if (r.ok() && narrowest < 2.0 * probe_radius_mm)
    r.fail("size_mm", "is narrower than the probe (" + (std::ostringstream() << 2.0 * probe_radius_mm).str() +
                          " mm across): the probe could not push it in; make it at least that wide");
  resolve_material(r, material_names, out.material, out.material_index);
  return r.status();
}

}  // namespace ps::scene_detail
