#include "app/window/tune_panel.h"

#include <cfloat>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/window/panel_links.h"
#include "reference/modulation.h"
#include "tune/edit_key.h"
#include "tune/overrides_file.h"

namespace ps {

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.7g", v);
  return buf;
}

std::string vec_text(const float* v) {
  return "[" + number(v[0]) + "," + number(v[1]) + "," + number(v[2]) + "]";
}

// A curve over x in [x_lo, x_hi] whose tooltip names the axis value under the mouse in its
// unit ("d = 2.50 mm: 0.431") instead of ImGui's sample index (SetTooltip replaces the tooltip
// PlotLines just made). The sample under the mouse is found as PlotLines finds it.
void curve(const char* id, const float* y, int n, const char* caption, double x_lo, double x_hi,
           const char* x_name, const char* x_unit, const char* y_name) {
  ImGui::TextWrapped("%s", caption);  // above, not inside the plot: a narrow panel would cut it
  ImGui::SetNextItemWidth(-FLT_MIN);
  ImGui::PlotLines(id, y, n, 0, nullptr, 0.f, 1.f, ImVec2(0, 70));
  if (!ImGui::IsItemHovered()) return;
  const float pad = ImGui::GetStyle().FramePadding.x;
  const float x0 = ImGui::GetItemRectMin().x + pad, x1 = ImGui::GetItemRectMax().x - pad;
  const float t = std::clamp((ImGui::GetIO().MousePos.x - x0) / std::max(x1 - x0, 1.f), 0.f, 0.9999f);
  const int i = static_cast<int>(t * n);
  const double x = x_lo + (x_hi - x_lo) * i / (n - 1);
  ImGui::SetTooltip("%s = %.4g %s\n%s %.3f", x_name, x, x_unit, y_name, y[i]);
}

}  // namespace

void TunePanel::record_rect(const std::string& key) {
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  knob_rects_[key] = {a.x, a.y, b.x, b.y};
}

// The label on its own line (wrapped, never cut), the slider below it across the panel.
bool TunePanel::slider(const std::string& label, const std::string& key, float* v, int n, float lo, float hi,
                       bool log) {
  if (active_.key == key) std::copy(active_.value, active_.value + n, v);
  ImGui::TextWrapped("%s", label.c_str());
  ImGui::SetNextItemWidth(-FLT_MIN);
  const std::string id = "##" + key;
  const ImGuiSliderFlags flags = log ? ImGuiSliderFlags_Logarithmic : 0;
  if (n == 1) ImGui::SliderFloat(id.c_str(), v, lo, hi, "%.4g", flags);
  else ImGui::DragFloat3(id.c_str(), v, (hi - lo) / 400.f, lo, hi, "%.3g");
  record_rect(key);
  if (ImGui::IsItemActive()) {
    active_.key = key;
    std::copy(v, v + n, active_.value);
  }
  if (ImGui::IsItemDeactivated() && active_.key == key) active_.key.clear();
  return ImGui::IsItemDeactivatedAfterEdit();
}

bool TunePanel::wants_input() const {
  return visible_ && (ImGui::GetIO().WantCaptureMouse || ImGui::GetIO().WantCaptureKeyboard);
}

bool TunePanel::wants_keys() const { return visible_ && ImGui::GetIO().WantTextInput; }

void TunePanel::apply(TuneSession&, const std::string& key, const std::string& value) {
  pending_.push_back({key, value, false, Lut{}});
}

void TunePanel::apply_pending(TuneSession& session) {
  for (const PendingEdit& e : pending_) {
    if (e.curve) {
      const Status s = session.set_curve(e.key, e.lut);
      status_ = s ? (e.lut.empty() ? "dropped the edit of " + e.key
                                   : "set " + e.key + " (" + std::to_string(e.lut.points.size()) + " rows)")
                  : panel_message(s.error().message);
    } else {
      const Status s = session.set(e.key, e.value);
      status_ = s ? "set " + e.key + " = " + e.value : panel_message(s.error().message);
    }
  }
  pending_.clear();
}

void TunePanel::material_section(TuneSession& session) {
  const Scene& scene = session.renderer().scene();
  material_ = std::clamp(material_, 0, static_cast<int>(scene.materials.size()) - 1);
  if (scene.materials.size() > 1) {
    const char* current = scene.materials[material_].name.c_str();
    if (ImGui::BeginCombo("material", current)) {
      for (int i = 0; i < static_cast<int>(scene.materials.size()); ++i)
        if (ImGui::Selectable(scene.materials[i].name.c_str(), i == material_)) material_ = i;
      ImGui::EndCombo();
    }
  }
  const Material& m = scene.materials[material_];
  const std::string prefix = "materials." + m.name + ".";
  for (const PanelParam& p : panel_material_params()) {
    float v = static_cast<float>(p.get(m));
    const std::string label = std::string(p.key) + (p.unit[0] ? std::string(" (") + p.unit + ")" : "");
    // A min/max pair stays ordered: the partner follows the knob (linked_edits).
    if (slider(label, prefix + p.key, &v, 1, p.lo, p.hi, p.log))
      for (const PanelEdit& e : linked_edits(m, p.key, v)) apply(session, e.key, number(e.value));
  }
  // The texture's anti-aliasing (docs/architecture.md, "Texture filtering"): off shows what the
  // unfiltered sum aliases.
  bool filtered = m.gabor.filter == GaborParams::Filter::kAnalytic;
  const bool toggled = ImGui::Checkbox(("filter the texture (anti-aliasing)##" + prefix).c_str(), &filtered);
  record_rect(prefix + "gabor_filter");
  if (toggled) apply(session, prefix + "gabor_filter", filtered ? "\"analytic\"" : "\"none\"");
  float c = static_cast<float>(scene.render.weight_exponent);
  if (slider("weight exponent c", "render.weight_exponent", &c, 1, 1.f, 100.f, false))
    apply(session, "render.weight_exponent", number(c));
}

void TunePanel::probe_camera_section(TuneSession& session) {
  const Scene& scene = session.renderer().scene();
  float r = static_cast<float>(scene.probe.radius_mm);
  if (slider("probe radius (mm)", "probe.radius_mm", &r, 1, 0.5f, 50.f, true)) apply(session, "probe.radius_mm", number(r));
  float vel[3] = {float(scene.probe.velocity.x), float(scene.probe.velocity.y), float(scene.probe.velocity.z)};
  if (slider("probe velocity (mm/s)", "probe.velocity", vel, 3, -2000.f, 2000.f, false))
    apply(session, "probe.velocity", vec_text(vel));
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("probe position follows the device (mouse); velocity too while it moves");
  ImGui::PopStyleColor();
  float fov = static_cast<float>(scene.camera.fov_y_deg);
  if (slider("camera fov_y (deg)", "camera.fov_y_deg", &fov, 1, 5.f, 120.f, false))
    apply(session, "camera.fov_y_deg", number(fov));
  float eye[3] = {float(scene.camera.position.x), float(scene.camera.position.y), float(scene.camera.position.z)};
  if (slider("camera position (mm)", "camera.position", eye, 3, -1000.f, 1000.f, false))
    apply(session, "camera.position", vec_text(eye));
}

bool TunePanel::has_world_knobs(const Scene& scene) {
  for (std::size_t i = 0; i < scene.surfaces.size(); ++i)
    if (scene.surfaces[i].visual_stretch != glm::dvec3(1.0) &&
        std::find(stretched_.begin(), stretched_.end(), static_cast<int>(i)) == stretched_.end())
      stretched_.push_back(static_cast<int>(i));
  const bool fourd = std::any_of(scene.surfaces.begin(), scene.surfaces.end(),
                                 [](const Surface& s) { return s.type == SurfaceType::kFourd; });
  return !stretched_.empty() || !scene.bodies.empty() || fourd;
}

// A surface embedded in 4D (docs/fourd.md): the six 4D rotation angles (the image reprojected
// at each edit, like keys 1-6) and the force suggestions' gains (0 and 0: off).
void TunePanel::fourd_section(TuneSession& session, const Surface& s, std::size_t i) {
  static constexpr const char* kPlanes[6] = {"xy", "xz", "xw", "yz", "yw", "zw"};  // fourd::kRotationPlanes
  const std::string prefix = "surfaces." + std::to_string(i) + ".";
  for (int p = 0; p < 6; ++p) {
    float a = static_cast<float>(s.fourd.rotation_deg[static_cast<std::size_t>(p)]);
    const std::string key = prefix + "fourd_rotation_" + kPlanes[p] + "_deg";
    if (slider("4D turn " + std::string(kPlanes[p]) + " (deg)", key, &a, 1, -180.f, 180.f, false))
      apply(session, key, number(a));
  }
  float kp = static_cast<float>(s.fourd.suggest_kp_n_per_mm), kv = static_cast<float>(s.fourd.suggest_kv_n_s_per_mm);
  if (slider("suggestion K_p (N/mm, 0: off)", prefix + "fourd_suggest_kp_n_per_mm", &kp, 1, 0.f, 2.f, false))
    apply(session, prefix + "fourd_suggest_kp_n_per_mm", number(kp));
  if (slider("suggestion K_v (N s/mm)", prefix + "fourd_suggest_kv_n_s_per_mm", &kv, 1, 0.f, 0.05f, false))
    apply(session, prefix + "fourd_suggest_kv_n_s_per_mm", number(kv));
  // The rolling manifold (Hanson & Zhang §6): the view turns with the proxy's walk.
  bool roll = s.fourd.roll.on;
  const bool toggled = ImGui::Checkbox(("rolling manifold##" + prefix).c_str(), &roll);
  record_rect(prefix + "fourd_roll");
  if (toggled) apply(session, prefix + "fourd_roll", roll ? "true" : "false");
}

void TunePanel::world_section(TuneSession& session) {
  const Scene& scene = session.renderer().scene();
  for (int i : stretched_) {
    if (i >= static_cast<int>(scene.surfaces.size())) continue;
    const glm::dvec3& st = scene.surfaces[static_cast<std::size_t>(i)].visual_stretch;
    float v[3] = {float(st.x), float(st.y), float(st.z)};
    const std::string key = "surfaces." + std::to_string(i) + ".visual_stretch";
    if (slider("surface " + std::to_string(i) + " drawn stretch", key, v, 3, 0.25f, 4.f, true))
      apply(session, key, vec_text(v));
  }
  for (std::size_t i = 0; i < scene.surfaces.size(); ++i)
    if (scene.surfaces[i].type == SurfaceType::kFourd) fourd_section(session, scene.surfaces[i], i);
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    float t = static_cast<float>(scene.bodies[b].time_scale);
    const std::string key = "bodies." + std::to_string(b) + ".time_scale";
    if (slider("body " + std::to_string(b) + " time scale (< 1: heavier)", key, &t, 1, 0.05f, 2.f, true))
      apply(session, key, number(t));
  }
}

// Under a curve's plot: its lookup table as a row of vertical sliders, one per row (the row's y;
// its x in the tooltip), applied when released (TuneSession::set_curve, saved with the overrides
// as a table file). Until edited, a button turns the curve into kEditRows rows sampled from it.
void TunePanel::curve_editor(TuneSession& session, const Material& m, bool intensity, double x_max) {
  constexpr int kMaxSliders = 24;
  const std::string key = EditKey::curve(m.name, intensity ? CurveKind::kIntensity : CurveKind::kSpeedGain).text();
  const Lut& scene_lut = intensity ? m.intensity_lut : m.speed_gain_lut;
  const auto edited = session.curve_edits().find(key);
  const Lut* cur = edited != session.curve_edits().end() ? &edited->second : scene_lut.empty() ? nullptr : &scene_lut;
  ImGui::PushID(key.c_str());
  if (!cur || static_cast<int>(cur->points.size()) > kMaxSliders) {
    resample_button(session, m, intensity, x_max, key, cur != nullptr);
    ImGui::PopID();
    return;
  }
  const int n = static_cast<int>(cur->points.size());
  const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
  const float w = std::max(6.f, (ImGui::GetContentRegionAvail().x - spacing * (n - 1)) / n);
  for (int i = 0; i < n; ++i) {
    if (i > 0) ImGui::SameLine(0.f, spacing);
    if (row_slider(session, key, *cur, i, w, intensity)) {
      ImGui::PopID();
      return;  // `cur` may point into the edits just replaced
    }
  }
  if (edited != session.curve_edits().end() && ImGui::SmallButton("back to the scene's curve")) set_curve(session, key, Lut{});
  ImGui::PopID();
}

// A curve with no table, or too many rows for sliders: a button samples kEditRows rows from it.
void TunePanel::resample_button(TuneSession& session, const Material& m, bool intensity, double x_max,
                                const std::string& key, bool has_table) {
  constexpr int kEditRows = 12;  // enough to shape the curve, few enough to fit the strip
  if (ImGui::Button(has_table ? "resample the table to edit it" : "edit as a curve")) {
    const LutAxis axis = intensity ? LutAxis::kDistanceMm : LutAxis::kSpeedMmS;
    Lut lut = sample_lut(axis, x_max, kEditRows - (intensity ? 1 : 0), [&](double x) {
      return intensity ? intensity_curve(m, x) : amplitude_gain(m, x);
    });
    // The intensity table's last row at the influence distance keeps the curve's tail.
    if (intensity && m.influence_distance_mm > x_max) lut.points.push_back({m.influence_distance_mm, intensity_curve(m, m.influence_distance_mm)});
    set_curve(session, key, lut);
  }
}

// Row i's slider (its y; its x in the tooltip); true when a release just set the curve.
bool TunePanel::row_slider(TuneSession& session, const std::string& key, const Lut& cur, int i, float w, bool intensity) {
  const std::string id = key + "#" + std::to_string(i);
  float y = static_cast<float>(cur.points[static_cast<std::size_t>(i)].y);
  if (active_.key == id) y = active_.value[0];
  ImGui::PushID(i);
  ImGui::VSliderFloat("##row", ImVec2(w, 80.f), &y, 0.f, 1.f, "");
  if (ImGui::IsItemActive()) active_ = {id, {y, 0.f, 0.f}};
  if (ImGui::IsItemHovered() || ImGui::IsItemActive())
    ImGui::SetTooltip("%s = %.4g %s\n%s %.3f", intensity ? "d" : "speed", cur.points[static_cast<std::size_t>(i)].x,
                      intensity ? "mm" : "mm/s", intensity ? "intensity" : "gain", y);
  if (ImGui::IsItemDeactivated() && active_.key == id) active_.key.clear();
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    Lut lut = cur;
    lut.points[static_cast<std::size_t>(i)].y = y;
    ImGui::PopID();
    set_curve(session, key, lut);
    return true;
  }
  ImGui::PopID();
  return false;
}

void TunePanel::set_curve(TuneSession&, const std::string& key, const Lut& lut) {
  pending_.push_back({key, std::string(), true, lut});
}

void TunePanel::plots(TuneSession& session) {
  const Scene& scene = session.renderer().scene();
  const Material& m = scene.materials[material_];
  constexpr int kSamples = 120;
  float intensity[kSamples], gain[kSamples];
  // Speed axis: up to 3x the speed whose frequency at lambda_max is the peak, so the band-pass
  // is visible whatever the material's scale (wood: 375 mm/s).
  const double d_max = std::max(10.0, m.onset_distance_mm * 1.5);
  const double v_max = std::clamp(3.0 * (m.peak_hz + m.bandwidth_hz) * m.gabor.lambda_max_mm, 10.0, 5000.0);
  for (int i = 0; i < kSamples; ++i) {
    intensity[i] = static_cast<float>(shadow_intensity(m, -1.0 + (d_max + 1.0) * i / (kSamples - 1)));
    gain[i] = static_cast<float>(amplitude_gain(m, v_max * i / (kSamples - 1)));
  }
  char caption[96];
  std::snprintf(caption, sizeof caption, "intensity vs distance, -1..%.0f mm", d_max);
  curve("##intensity", intensity, kSamples, caption, -1.0, d_max, "d", "mm", "intensity");
  curve_editor(session, m, true, d_max);
  std::snprintf(caption, sizeof caption, "amplitude gain vs speed, 0..%.0f mm/s", v_max);
  curve("##gain", gain, kSamples, caption, 0.0, v_max, "speed", "mm/s", "gain");
  // The intensity editor may have rebuilt the renderer (and its scene): look the material up again.
  curve_editor(session, session.renderer().scene().materials[material_], false, v_max);
  ImGui::Text("speed gain this frame: %.3f", session.renderer().stats().speed_gain);
}

UiRect TunePanel::draw(TuneSession& session, const UiRect& dock) {
  ImGui::SetNextWindowPos(ImVec2(dock.x0, dock.y0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(dock.width(), dock.height()), ImGuiCond_Always);
  constexpr ImGuiWindowFlags kDocked = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                       ImGuiWindowFlags_NoSavedSettings;
  // Taller content than the window scrolls inside the strip (a 512-pixel window cannot show
  // every section at once), so the curves and the save button stay reachable.
  const bool open = ImGui::Begin("parameters (F1)", nullptr, kDocked);
  knob_rects_.clear();
  collapsed_ = ImGui::IsWindowCollapsed();
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  if (open) contents(session);
  ImGui::End();
  apply_pending(session);  // after the sections, which read the scene the edits rebuild
  return UiRect::at(pos.x, pos.y, size.x, size.y);
}

void TunePanel::contents(TuneSession& session) {
  if (!session.last_error().empty()) {  // reload errors are long (file:line + driver log): wrap
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.4f, 0.3f, 1));
    ImGui::TextWrapped("not applied, last good state kept: %s", panel_message(session.last_error()).c_str());
    ImGui::PopStyleColor();
  }
  if (ImGui::CollapsingHeader("material", ImGuiTreeNodeFlags_DefaultOpen)) material_section(session);
  if (ImGui::CollapsingHeader("curves", ImGuiTreeNodeFlags_DefaultOpen)) plots(session);
  if (ImGui::CollapsingHeader("probe and camera")) probe_camera_section(session);
  if (has_world_knobs(session.renderer().scene()) && ImGui::CollapsingHeader("world", ImGuiTreeNodeFlags_DefaultOpen))
    world_section(session);
  ImGui::Text("%zu edited keys, %zu edited curves", session.edits().size(), session.curve_edits().size());
  if (ImGui::Button("Save overrides")) {
    const Status s = session.save_overrides();
    status_ = s ? "saved " + overrides_path_for(session.scene_path()) : s.error().message;
    std::printf("%s\n", status_.c_str());
  }
  ImGui::TextWrapped("%s", status_.c_str());
}

}  // namespace ps
