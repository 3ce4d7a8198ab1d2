// A box of text over a window's frame (the maze's instructions, label and score, calibrate's
// question): at `pos`, in one Dear ImGui window per call, its lines wrapped to the window's
// width so that nothing is cut off at the right edge at 512 x 512 or larger (a line too long
// for the room left of `pos` breaks between words). Between ImGui::NewFrame and ImGui::Render.
#pragma once

#include <string>

#include <imgui.h>

#include "app/window/ui_layout.h"

namespace ps {

// The margin kept between the box and the window's right edge, px.
inline constexpr float kTextBoxMarginPx = 10.f;

// Draws `text` at `pos` (window pixels) at `font_scale`; returns the box's rectangle as ImGui
// laid it out (an auto-sized box takes its size from the frame before: a new text settles on
// the second frame).
UiRect draw_text_box(const char* id, ImVec2 pos, const std::string& text, float font_scale);

}  // namespace ps
