// The parameter panel's material knobs (app/window/tune_panel.h) and the rules that keep its edits
// valid: each slider's range lies inside the scene format's limits (scene-format.md, checked by
// tests/app/ui_layout_test.cpp against the loader), and a slider of a min/max pair moves its
// partner along instead of offering a value the loader refuses (lambda_min 16.98 with
// lambda_max 1.6). Pure data and functions: no ImGui.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace ps {

// One editable number of a material: scene key (last component), unit, slider range, scale.
struct PanelParam {
  const char* key;
  const char* unit;
  float lo, hi;
  bool log;
  double (*get)(const Material&);
};
std::span<const PanelParam> panel_material_params();

// The material pairs whose loader check is `min <= max` (scene_convert.cpp, read_gabor): a_*,
// lambda_*, n_*. theta_min > theta_max is allowed by the format on purpose (scene-format.md,
// "Reversed θ ranges"), so theta is not linked.
struct LinkedPair {
  const char* min_key;
  const char* max_key;
};
std::span<const LinkedPair> panel_linked_pairs();

struct PanelEdit {
  std::string key;  // full scene key, "materials.wood.lambda_max"
  double value;
};
// The edits that set `param` of material `m` to `value` and keep its pair ordered: the partner
// first (moved to `value` when it would end up on the wrong side), then the knob itself, so each
// edit leaves a scene the loader accepts.
std::vector<PanelEdit> linked_edits(const Material& m, const std::string& param, double value);

// A scene error as the panel says it: the loader names an override "--set KEY: ...", but in the
// window the value came from the panel ("panel: KEY: ...").
std::string panel_message(const std::string& error);

}  // namespace ps
