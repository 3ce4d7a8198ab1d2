#include "app/window/text_box.h"

#include <algorithm>

namespace ps {

UiRect draw_text_box(const char* id, ImVec2 pos, const std::string& text, float font_scale) {
  const ImGuiStyle& style = ImGui::GetStyle();
  // The wrap position is window-local: the box's right edge is the wrap plus the padding.
  const float room = ImGui::GetIO().DisplaySize.x - pos.x - kTextBoxMarginPx - style.WindowPadding.x;
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin(id, nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs);
  ImGui::SetWindowFontScale(font_scale);
  ImGui::PushTextWrapPos(std::max(room, 8.f * ImGui::GetFontSize()));  // a sliver of a window: a word a line
  ImGui::TextUnformatted(text.c_str());
  ImGui::PopTextWrapPos();
  const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  ImGui::End();
  return UiRect::at(at.x, at.y, size.x, size.y);
}

}  // namespace ps
