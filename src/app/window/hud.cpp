#include "app/window/hud.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "app/window/run_keys.h"
#include "fourd/fourd_mesh.h"

namespace ps {

namespace {

// Scene names longer than this are cut ("table5_1_constr..."): the box stays narrow.
constexpr size_t kMaxSceneChars = 16;

std::string line(const char* name, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
std::string line(const char* name, const char* fmt, ...) {
  char value[96];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(value, sizeof value, fmt, args);
  va_end(args);
  char out[128];
  std::snprintf(out, sizeof out, "%-12s%s", name, value);  // the font is monospaced: columns align
  return out;
}

// The keys in two columns and the legend under them; narrow: one column, the legend wrapped to
// its width (where the wide box would cover a button, app/window/ui_layout.h).
std::string help_text(bool narrow = false) {
  std::string text = run_keys_text("", narrow ? 1 : 2);
  text += "\n";
  if (!narrow) {
    for (const char* l : shadow_legend()) text += std::string(l) + "\n";
  } else {
    std::size_t width = 0;
    for (std::size_t a = 0, b; (b = text.find('\n', a)) != std::string::npos; a = b + 1) width = std::max(width, b - a);
    std::string legend;
    for (const char* l : shadow_legend()) legend += std::string(legend.empty() ? "" : " ") + l;
    std::string row;
    for (std::size_t a = 0; a < legend.size();) {
      std::size_t b = legend.find(' ', a);
      if (b == std::string::npos) b = legend.size();
      const std::string word = legend.substr(a, b - a);
      if (!row.empty() && row.size() + 1 + word.size() > width) {
        text += row + "\n";
        row.clear();
      }
      row += (row.empty() ? "" : " ") + word;
      a = b + 1;
    }
    if (!row.empty()) text += row + "\n";
  }
  text.pop_back();
  return text;
}

// A box of text at `rect` that takes no input, so a click on it reaches the probe and camera.
UiRect text_box(const char* id, const UiRect& rect, const std::string& text, float bg_alpha) {
  constexpr ImGuiWindowFlags kOverlay = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                                        ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                        ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
  ImGui::SetNextWindowPos(ImVec2(rect.x0, rect.y0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(rect.width(), rect.height()), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(bg_alpha);
  ImGui::Begin(id, nullptr, kOverlay);
  ImGui::TextUnformatted(text.c_str());
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  ImGui::End();
  return UiRect::at(pos.x, pos.y, size.x, size.y);
}

// The box a text needs: the text's extent plus the window padding on each side.
ImVec2 box_size(const std::string& text) {
  const ImVec2 t = ImGui::CalcTextSize(text.c_str());
  const ImVec2 pad = ImGui::GetStyle().WindowPadding;
  return ImVec2(std::ceil(t.x + 2.f * pad.x), std::ceil(t.y + 2.f * pad.y));
}

// Each button's label on its lower edge, over a dark band so it reads on any picture. Drawn
// behind every ImGui window (the background list): the layout keeps the boxes off the buttons.
void draw_button_labels(const std::vector<ButtonOverlay>& buttons) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  for (const ButtonOverlay& b : buttons) {
    if (b.label.empty()) continue;
    const ImVec2 t = ImGui::CalcTextSize(b.label.c_str());
    const float pad = 3.f;
    const float x = std::round(0.5f * (b.rect.x0 + b.rect.x1 - t.x)), y = std::round(b.rect.y1 - t.y - 2.f * pad);
    dl->AddRectFilled(ImVec2(x - pad, y - pad), ImVec2(x + t.x + pad, y + t.y + pad), IM_COL32(0, 0, 0, 170), 3.f);
    dl->AddText(ImVec2(x, y), IM_COL32(255, 255, 255, 255), b.label.c_str());
  }
}

// The 4D-depth colour legend: a line of the readouts whose gap between "far" and "near" is filled
// with the surfaces' colour map (fourd::depth_colour, gamma-encoded as the image is).
constexpr const char* kDepthLegendName = "4D depth";
constexpr const char* kDepthLegendGap = "            ";

ImU32 depth_colour_u32(double t) {
  const glm::dvec3 c = glm::pow(fourd::depth_colour(t), glm::dvec3(1.0 / 2.2));
  return IM_COL32(static_cast<int>(255.0 * c.r + 0.5), static_cast<int>(255.0 * c.g + 0.5),
                  static_cast<int>(255.0 * c.b + 0.5), 255);
}

void draw_depth_legend(const UiRect& box, const std::string& hud_text) {
  const std::size_t at = hud_text.find(kDepthLegendName);
  if (at == std::string::npos) return;
  const int row = static_cast<int>(std::count(hud_text.begin(), hud_text.begin() + static_cast<long>(at), '\n'));
  const ImVec2 pad = ImGui::GetStyle().WindowPadding;
  const std::string before = hud_text.substr(at, hud_text.find("far", at) + 4 - at);
  const float h = ImGui::GetTextLineHeight(), w = ImGui::CalcTextSize(kDepthLegendGap).x;
  const float x0 = box.x0 + pad.x + ImGui::CalcTextSize(before.c_str()).x, y0 = box.y0 + pad.y + row * h;
  constexpr int kStops = 4;  // the map's five stops, linear between them
  for (int i = 0; i < kStops; ++i) {
    const ImU32 a = depth_colour_u32(double(i) / kStops), b = depth_colour_u32(double(i + 1) / kStops);
    ImGui::GetForegroundDrawList()->AddRectFilledMultiColor(ImVec2(x0 + w * i / kStops, y0 + 0.15f * h),
                                                            ImVec2(x0 + w * (i + 1) / kStops, y0 + 0.85f * h), a, b, b, a);
  }
}

}  // namespace

std::vector<std::string> hud_lines(const HudReadouts& r) {
  std::string scene = r.scene;
  if (scene.size() > kMaxSceneChars) scene = scene.substr(0, kMaxSceneChars - 3) + "...";
  std::vector<std::string> out = {
      line("scene", "%s", scene.c_str()),
      line("distance", "%s", probe_distance_text(r.probe).c_str()),
      line("penetration", "%.2f mm", r.penetration_mm),
      line("contact", "%s", r.probe.state == ProbeState::kTouching ? "yes" : "no"),
      line("force", "%.2f N", r.force_n),
      line("speed", "%.0f mm/s", r.speed_mm_s),
      line("frame", "%.1f ms", r.frame_ms),
      line("haptic", "%.0f Hz", r.haptic_hz),
      line("jitter p99", "%.0f us", r.jitter_p99_us),
  };
  // Touching: how deep the hand pressed past the proxy (what the push-out hides from the eye).
  if (r.probe.state == ProbeState::kTouching) out.insert(out.begin() + 4, line("pressed", "%.1f mm", r.probe.pressed_mm));
  const std::size_t frame_line = r.probe.state == ProbeState::kTouching ? 8 : 7;
  if (r.gpu_frame_ms) out.insert(out.begin() + static_cast<std::ptrdiff_t>(frame_line), line("gpu frame", "%.1f ms", *r.gpu_frame_ms));
  // The texture is the per-pixel sum until its tile is baked: say the picture will not change.
  if (r.bake_progress < 1.0) out.push_back(line("texture", "baking %.0f %%", 100.0 * r.bake_progress));
  if (r.button >= 0)
    out.push_back(line("button", "#%d in %.1f of %.1f mm", r.button, r.button_depth_mm, r.button_travel_mm));
  if (r.flags) out.push_back(line("flags on", "%s", r.flags->empty() ? "none" : r.flags->c_str()));
  if (r.view_mm) out.push_back(line("view", "%+.0f %+.0f %+.0f mm", r.view_mm->x, r.view_mm->y, r.view_mm->z));
  if (r.rolled_deg) out.push_back(line("rolled", "%.0f deg", *r.rolled_deg));
  if (r.turn4_deg) {  // the planes the keys name (help: "1-3 / Shift  4D xy xz xw")
    const std::array<double, 6>& a = *r.turn4_deg;
    out.push_back(line("4D xy xz xw", "%.0f %.0f %.0f deg", a[0], a[1], a[2]));
    out.push_back(line("4D yz yw zw", "%.0f %.0f %.0f deg", a[3], a[4], a[5]));
    out.push_back(line(kDepthLegendName, "far %s near", kDepthLegendGap));  // the colours: draw()
  }
  if (!r.error.empty()) out.push_back(line("reload", "FAILED (F1)"));
  if (!r.notice.empty()) out.push_back(line("note", "%s", r.notice.c_str()));
  return out;
}

std::string title_summary(const HudReadouts& r) {
  const std::string head = "pseudoshadow \u2014 " + r.scene + " \u2014 ";
  if (!r.error.empty()) return head + "RELOAD FAILED (last good state kept): " + r.error;
  return head + probe_distance_text(r.probe);
}

UiLayoutInput WindowUi::layout_input(const ShadowMeasure& shadow, const std::vector<ButtonOverlay>& buttons,
                                     const std::string& hud_text, const std::string& help,
                                     const std::string& help_narrow) const {
  const ImVec2 display = ImGui::GetIO().DisplaySize, hud_size = box_size(hud_text), help_size = box_size(help);
  UiLayoutInput in;
  in.width = display.x;
  in.height = display.y;
  in.shadow = shadow.bbox;
  in.panel = panel_.visible();
  in.panel_width = panel_width_for(display.x);
  in.panel_height = panel_.collapsed() ? ImGui::GetFrameHeight() : display.y;
  in.hud_w = hud_size.x;
  in.hud_h = hud_size.y;
  in.help = help_;
  in.help_w = help_size.x;
  in.help_h = help_size.y;
  if (!buttons.empty()) {  // only where buttons may need the room
    const ImVec2 narrow_size = box_size(help_narrow);
    in.help_narrow_w = narrow_size.x;
    in.help_narrow_h = narrow_size.y;
  }
  for (const ButtonOverlay& b : buttons) in.buttons.push_back(b.rect);
  if (ImGui::IsMousePosValid()) in.pointer = std::make_pair(ImGui::GetIO().MousePos.x, ImGui::GetIO().MousePos.y);
  in.now_s = ImGui::GetTime();
  in.last = placement_;
  return in;
}

UiFrameReport WindowUi::draw(const HudReadouts& readouts, const ShadowMeasure& shadow, TuneSession& session,
                             double now_s, const std::vector<ButtonOverlay>& buttons) {
  if (help_timeout_ && now_s >= kHelpSeconds) hide_help();
  std::string hud_text;
  for (const std::string& l : hud_lines(readouts)) hud_text += l + "\n";
  hud_text.pop_back();
  const std::string help = help_text(), help_narrow = help_text(true);
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const UiLayoutInput in = layout_input(shadow, buttons, hud_text, help, help_narrow);
  const UiLayout layout = layout_ui(in);
  placement_ = layout.placement;

  UiFrameReport report;
  report.shadow = shadow.bbox;
  report.buttons = in.buttons;
  draw_button_labels(buttons);
  if (layout.panel) {
    UiRect dock = *layout.panel;
    dock.y1 = display.y;  // the expanded size; a collapsed panel draws its title bar only
    report.panel = panel_.draw(session, dock);
  }
  if (layout.hud) {
    report.hud = text_box("##readouts", *layout.hud, hud_text, 0.65f);
    draw_depth_legend(*report.hud, hud_text);
  }
  if (layout.help) report.help = text_box("##help", *layout.help, layout.help_narrow ? help_narrow : help, 0.8f);
  return report;
}

}  // namespace ps
