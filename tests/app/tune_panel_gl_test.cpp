// The F1 panel driven as a person drives it, headless: a Dear ImGui context with no window and
// no drawing backend (ImGui builds its frames from synthetic mouse events alone), the panel
// drawn over a TuneSession on a real GL context. A drag on the 4D-turn slider of a surface
// embedded in 4D, and a click on its rolling checkbox, must reach the session as the same
// edits a --set makes, and the rebuilt renderer must draw the reprojected surface
// (docs/fourd.md, "Turning in 4D in run").
#include <gtest/gtest.h>

#include <imgui.h>

#include <cmath>
#include <cstdlib>

#include "app/tune_panel.h"
#include "support/gl_test.h"
#include "tune/tune_session.h"

namespace ps {
namespace {

class TunePanelGLTest : public test::GlTest {};

// One ImGui context for the test, its font atlas built (no texture is ever uploaded).
class HeadlessImGui {
 public:
  HeadlessImGui(float w, float h) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(w, h);
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int tw = 0, th = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &tw, &th);
  }
  ~HeadlessImGui() { ImGui::DestroyContext(); }
  // One frame: the mouse at `pos`, its left button `down`; the panel drawn in `dock`.
  void frame(TunePanel& panel, TuneSession& session, const UiRect& dock, ImVec2 pos, bool down) {
    ImGuiIO& io = ImGui::GetIO();
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = pos;  // Debian 12's ImGui (1.86) predates the event queue
    io.MouseDown[0] = down;
    ImGui::NewFrame();
    panel.draw(session, dock);
    ImGui::Render();
  }
};

// Drag the xw slider (-180 .. 180 degrees) from its centre to 3/4 of its width: ImGui maps the
// grab's travel linearly, so the value lands near 90 degrees (the grab's own width takes a few
// pixels off the travel: 10 degrees either way). The session then holds the edit, the scene
// the angle, and the frame differs from the one before (the surface reprojected). The checkbox
// click turns rolling on through the same path.
TEST_P(TunePanelGLTest, FourdTurnSliderAndRollingCheckboxEditTheSession) {
  TuneSource src;
  src.scene_path = std::string(PS_SOURCE_DIR) + "/scenes/fourd/roman.toml";
  src.overrides = {"render.size=[96,96]"};
  auto session = TuneSession::open(src);
  ASSERT_TRUE(session) << session.error().message;
  TuneSession& s = *session.value();
  ASSERT_TRUE(s.renderer().render_frame());
  auto before = s.renderer().read_aov(Aov::kNormal);
  ASSERT_TRUE(before);

  HeadlessImGui ui(420.f, 6000.f);
  TunePanel panel;
  const UiRect dock = UiRect::at(0.f, 0.f, 420.f, 6000.f);
  const ImVec2 away(-100.f, -100.f);
  ui.frame(panel, s, dock, away, false);
  ui.frame(panel, s, dock, away, false);
  const std::string key = "surfaces.0.fourd_rotation_xw_deg";
  ASSERT_TRUE(panel.knob_rects().count(key)) << "the world section shows the 4D turns";
  const UiRect r = panel.knob_rects().at(key);
  const float y = 0.5f * (r.y0 + r.y1);
  ui.frame(panel, s, dock, ImVec2(r.x0 + 0.5f * r.width(), y), false);
  ui.frame(panel, s, dock, ImVec2(r.x0 + 0.5f * r.width(), y), true);
  for (int i = 1; i <= 4; ++i) ui.frame(panel, s, dock, ImVec2(r.x0 + (0.5f + 0.0625f * i) * r.width(), y), true);
  ui.frame(panel, s, dock, ImVec2(r.x0 + 0.75f * r.width(), y), false);  // released: applied
  ASSERT_TRUE(s.edits().count(key)) << s.last_error();
  const double angle = std::atof(s.edits().at(key).c_str());
  std::printf("xw slider dragged to %s\n", s.edits().at(key).c_str());
  EXPECT_NEAR(angle, 90.0, 10.0);
  EXPECT_NEAR(s.renderer().scene().surfaces[0].fourd.rotation_deg[2], angle, 1e-3);
  ASSERT_TRUE(s.renderer().render_frame());
  auto after = s.renderer().read_aov(Aov::kNormal);
  ASSERT_TRUE(after);
  int changed = 0;
  for (std::size_t i = 0; i < after.value().pixels.size(); ++i)
    changed += std::abs(after.value().pixels[i] - before.value().pixels[i]) > 1e-3f;
  EXPECT_GT(changed, 300) << "the surface is reprojected";

  const std::string roll = "surfaces.0.fourd_roll";
  ui.frame(panel, s, dock, away, false);
  ASSERT_TRUE(panel.knob_rects().count(roll));
  const UiRect c = panel.knob_rects().at(roll);
  const ImVec2 box(c.x0 + 0.5f * c.height(), 0.5f * (c.y0 + c.y1));  // the box is square, at the left
  ui.frame(panel, s, dock, box, false);
  ui.frame(panel, s, dock, box, true);
  ui.frame(panel, s, dock, box, false);
  ASSERT_TRUE(s.edits().count(roll)) << s.last_error();
  EXPECT_EQ(s.edits().at(roll), "true");
  EXPECT_TRUE(s.renderer().scene().surfaces[0].fourd.roll.on);
}

// The material section's anti-aliasing checkbox on the default scene: a click turns the filter
// off (the edit --set makes), and the texture AOV changes in the shadow (the unfiltered sum).
TEST_P(TunePanelGLTest, TextureFilterCheckboxTurnsTheFilterOff) {
  TuneSource src;
  src.overrides = {"render.size=[96,96]"};
  auto session = TuneSession::open(src);
  ASSERT_TRUE(session) << session.error().message;
  TuneSession& s = *session.value();
  ASSERT_TRUE(s.renderer().render_frame());
  auto before = s.renderer().read_aov(Aov::kTexture);
  ASSERT_TRUE(before);
  HeadlessImGui ui(420.f, 6000.f);
  TunePanel panel;
  const UiRect dock = UiRect::at(0.f, 0.f, 420.f, 6000.f);
  const ImVec2 away(-100.f, -100.f);
  ui.frame(panel, s, dock, away, false);
  const std::string key = "materials." + s.renderer().scene().materials[0].name + ".gabor_filter";
  ASSERT_TRUE(panel.knob_rects().count(key));
  const UiRect c = panel.knob_rects().at(key);
  const ImVec2 box(c.x0 + 0.5f * c.height(), 0.5f * (c.y0 + c.y1));
  ui.frame(panel, s, dock, box, false);
  ui.frame(panel, s, dock, box, true);
  ui.frame(panel, s, dock, box, false);
  ASSERT_TRUE(s.edits().count(key)) << s.last_error();
  EXPECT_EQ(s.edits().at(key), "\"none\"");
  EXPECT_EQ(s.renderer().scene().materials[0].gabor.filter, GaborParams::Filter::kNone);
  ASSERT_TRUE(s.renderer().render_frame());
  auto after = s.renderer().read_aov(Aov::kTexture);
  ASSERT_TRUE(after);
  int changed = 0;
  for (std::size_t i = 0; i < after.value().pixels.size(); ++i)
    changed += std::abs(after.value().pixels[i] - before.value().pixels[i]) > 1e-4f;
  EXPECT_GT(changed, 10) << "the shadow's texture is no longer filtered";
}

PS_INSTANTIATE_HEADLESS_BACKENDS(TunePanelGLTest);

}  // namespace
}  // namespace ps
