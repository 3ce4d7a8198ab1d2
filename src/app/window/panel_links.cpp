#include "app/window/panel_links.h"

#include <cmath>
#include <cstring>

namespace ps {

namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

// Ranges: inside the file's limits (scene_convert.cpp) and narrowed to what a slider can
// usefully sweep; ctrl+click types any value, which the loader still checks.
const PanelParam kMaterialParams[] = {
    {"a_min", "", 0.f, 1.f, false, [](const Material& m) { return m.gabor.a_min; }},
    {"a_max", "", 0.f, 1.f, false, [](const Material& m) { return m.gabor.a_max; }},
    {"lambda_min", "mm", 0.05f, 20.f, true, [](const Material& m) { return m.gabor.lambda_min_mm; }},
    {"lambda_max", "mm", 0.05f, 20.f, true, [](const Material& m) { return m.gabor.lambda_max_mm; }},
    {"theta_min", "deg", -180.f, 180.f, false, [](const Material& m) { return m.gabor.theta_min_rad * kRadToDeg; }},
    {"theta_max", "deg", -180.f, 180.f, false, [](const Material& m) { return m.gabor.theta_max_rad * kRadToDeg; }},
    {"n_min", "per kernel", 0.f, 100.f, false, [](const Material& m) { return m.gabor.n_min; }},
    {"n_max", "per kernel", 0.f, 100.f, false, [](const Material& m) { return m.gabor.n_max; }},
    {"onset_distance_mm", "mm", 0.f, 50.f, false, [](const Material& m) { return m.onset_distance_mm; }},
    {"intensity_floor", "", 0.f, 1.f, false, [](const Material& m) { return m.intensity_floor; }},
    {"intensity_scale", "", 0.f, 10.f, false, [](const Material& m) { return m.intensity_scale; }},
    {"intensity_offset_mm", "mm", 0.01f, 20.f, true, [](const Material& m) { return m.intensity_offset_mm; }},
    {"peak_hz", "Hz", 1.f, 1000.f, true, [](const Material& m) { return m.peak_hz; }},
    {"bandwidth_hz", "Hz", 1.f, 1000.f, true, [](const Material& m) { return m.bandwidth_hz; }},
    {"resistance", "", 0.f, 1.f, false, [](const Material& m) { return m.resistance; }},
};

const LinkedPair kPairs[] = {{"a_min", "a_max"}, {"lambda_min", "lambda_max"}, {"n_min", "n_max"}};

const PanelParam* find_param(const std::string& key) {
  for (const PanelParam& p : kMaterialParams)
    if (key == p.key) return &p;
  return nullptr;
}

}  // namespace

std::span<const PanelParam> panel_material_params() { return kMaterialParams; }
std::span<const LinkedPair> panel_linked_pairs() { return kPairs; }

std::vector<PanelEdit> linked_edits(const Material& m, const std::string& param, double value) {
  const std::string prefix = "materials." + m.name + ".";
  std::vector<PanelEdit> out;
  for (const LinkedPair& pair : kPairs) {
    const bool is_min = param == pair.min_key, is_max = param == pair.max_key;
    if (!is_min && !is_max) continue;
    const PanelParam* partner = find_param(is_min ? pair.max_key : pair.min_key);
    const double other = partner->get(m);
    if ((is_min && value > other) || (is_max && value < other)) out.push_back({prefix + partner->key, value});
  }
  out.push_back({prefix + param, value});
  return out;
}

std::string panel_message(const std::string& error) {
  constexpr const char* kSet = "--set ";
  if (error.rfind(kSet, 0) == 0) return "panel: " + error.substr(std::strlen(kSet));
  return error;
}

}  // namespace ps
