// The fourd_* keys of a [[surfaces]] entry with type = "fourd" (docs/fourd.md).
#include <array>
#include <string>

#include "fourd/fourd_mesh.h"
#include "scene/scene_convert.h"

namespace ps::scene_detail {
namespace {

using std::string_view_literals::operator""sv;

// Same order as fourd::SurfaceKind, fourd::Projection4, fourd::LocalModelKind.
constexpr std::array kFourdSurfaces = {"flat_torus"sv, "spun_trefoil"sv, "roman"sv, "twist_spun_trefoil"sv};
constexpr std::array kFourdProjections = {"perspective"sv, "orthographic"sv};
constexpr std::array kFourdLocalModels = {"continuity"sv, "adjacency"sv, "nearest"sv};
// Same order as fourd::kRotationPlanes.
constexpr std::array kRotationKeys = {"fourd_rotation_xy_deg"sv, "fourd_rotation_xz_deg"sv, "fourd_rotation_xw_deg"sv,
                                      "fourd_rotation_yz_deg"sv, "fourd_rotation_yw_deg"sv, "fourd_rotation_zw_deg"sv};
constexpr int kMaxGrid = 1024;  // 1024^2 cells x 2 triangles stays under kMaxMeshTriangles

template <class Enum, std::size_t N>
void read_choice(TableReader& r, std::string_view key, Enum& out, const std::array<std::string_view, N>& choices) {
  int index = static_cast<int>(out);
  r.choice(key, index, choices);
  out = static_cast<Enum>(index);
}

}  // namespace

void read_fourd_keys(TableReader& r, Surface& out) {
  fourd::Spec& f = out.fourd;
  read_choice(r, "fourd", f.kind, kFourdSurfaces);
  read_choice(r, "fourd_projection", f.projection, kFourdProjections);
  r.number("fourd_eye_distance", f.eye_distance, Range::positive(1e6));
  for (std::size_t i = 0; i < kRotationKeys.size(); ++i)
    r.number(kRotationKeys[i], f.rotation_deg[i], Range::closed(-3600.0, 3600.0));
  r.int2("fourd_grid", f.nu, f.nv, 3, kMaxGrid);
  r.integer("fourd_twists", f.twists, -16, 16);
  read_choice(r, "fourd_local_model", f.local_model, kFourdLocalModels);
  r.number("fourd_suggest_kp_n_per_mm", f.suggest_kp_n_per_mm, Range::closed(0.0, 10.0));
  r.number("fourd_suggest_kv_n_s_per_mm", f.suggest_kv_n_s_per_mm, Range::closed(0.0, 1.0));
  r.number("fourd_suggest_lookahead_s", f.suggest_lookahead_s, Range::closed(0.0, 1.0));
  r.number("fourd_cutaway_mm", f.cutaway_mm, Range::closed(0.0, 1e4));
  r.number("fourd_crossing_diagram_mm", f.crossing_diagram_mm, Range::closed(0.0, 1e4));
  r.boolean("fourd_wireframe", f.wireframe);
  r.boolean("fourd_roll", f.roll.on);
  r.number("fourd_roll_turn_s", f.roll.turn_s, Range::closed(0.0, 10.0));
  r.number("fourd_roll_centre_s", f.roll.centre_s, Range::closed(0.0, 100.0));
  r.number("fourd_roll_tether_n_per_mm4", f.roll.tether_alpha_n_per_mm4, Range::closed(0.0, 1.0));
  r.number("fourd_roll_tether_max_n", f.roll.tether_max_n, Range::closed(0.0, 20.0));
  if (!r.ok()) return;
  if (out.type != SurfaceType::kFourd) {
    for (std::string_view k : known_keys(Section::kSurface))
      if (k.starts_with("fourd") && r.has(k)) return r.fail(k, "applies only to type = \"fourd\"");
    return;
  }
  r.require(r.has("fourd"), "fourd",
            "is required for type = \"fourd\": one of \"flat_torus\", \"spun_trefoil\", \"roman\", "
            "\"twist_spun_trefoil\" (e.g. fourd = \"roman\")");
  r.require(f.kind == fourd::SurfaceKind::kTwistSpunTrefoil || !r.has("fourd_twists"), "fourd_twists",
            "applies only to fourd = \"twist_spun_trefoil\"");
  // A perspective eye inside the rotated surface is found only by sampling it (a few ms): here,
  // so the error names this file and line instead of surfacing later from the renderer.
  if (r.ok() && f.projection == fourd::Projection4::kPerspective) {
    const Status eye = fourd::check_eye(f);
    if (!eye) r.fail("fourd_eye_distance", eye.error().message);
  }
}

}  // namespace ps::scene_detail
