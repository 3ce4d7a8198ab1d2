// Text boxes over the window (app/window/text_box.h): the maze's instructions and calibrate's
// question fit a 512 x 512 window and larger; no GL (Dear ImGui lays out without a backend).
#include <gtest/gtest.h>

#include <imgui.h>

#include <string>
#include <tuple>

#include "app/window/text_box.h"
#include "maze/maze.h"

namespace ps {
namespace {

class ImGuiFrames {
 public:
  explicit ImGuiFrames(float w, float h) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(w, h);
    io.DeltaTime = 1.f / 60.f;
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int tw = 0, th = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &tw, &th);  // builds the font atlas NewFrame needs
  }
  ~ImGuiFrames() { ImGui::DestroyContext(); }
  // Three frames (an auto-sized box takes its size from the frame before); the last one's box.
  UiRect box(ImVec2 pos, const std::string& text, float scale) {
    UiRect r;
    for (int i = 0; i < 3; ++i) {
      ImGui::NewFrame();
      r = draw_text_box("##t", pos, text, scale);
      ImGui::Render();
    }
    return r;
  }
};

// The maze's instructions at the maze window's place and scale (maze_overlay.cpp) and calibrate's
// question with its progress line: inside the window with the margin, at 512 x 512 and 1280 x
// 800. Without wrapping the instructions' longest line at scale 1.3 is ~700 px wide: the first
// check fails then.
TEST(TextBoxTest, InstructionsAndQuestionsFitA512Window) {
  const std::string question =
      "Which patch looks darker?  Left / Right arrow.  Esc stops (every answer is kept).\n"
      "trial 37 of about 230; staircases done: 1 of 4";
  for (const ImVec2 size : {ImVec2(512, 512), ImVec2(1280, 800)}) {
    ImGuiFrames frames(size.x, size.y);
    for (const auto& [pos, text, scale] : {std::tuple{ImVec2(30, 60), std::string(maze::kDefaultInstructions), 1.3f},
                                           std::tuple{ImVec2(10, 10), question, 1.0f}}) {
      const UiRect r = frames.box(pos, text, scale);
      SCOPED_TRACE(testing::Message() << "window " << size.x << "x" << size.y << ", box at " << pos.x);
      EXPECT_LE(r.x1, size.x - kTextBoxMarginPx + 0.5f);
      EXPECT_LE(r.y1, size.y);
      EXPECT_GT(r.width(), 0.4f * (size.x - pos.x)) << "a box that wraps uses the room it has";
    }
  }
}

}  // namespace
}  // namespace ps
