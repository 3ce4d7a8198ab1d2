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
#include <optional>

#include "app/window/tune_panel.h"
#include "support/gl_test.h"
#include "tune/tune_session.h"

namespace ps {
namespace {

class TunePanelGLTest : public test::GlTest {};

// One ImGui context for the test, its font atlas built (no texture is ever uploaded), and the
// panel over `session`, docked in a strip tall enough to show every section without scrolling.
class PanelDriver {
 public:
  explicit PanelDriver(TuneSession& session) : session_(session) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(dock_.width(), dock_.height());
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int tw = 0, th = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &tw, &th);
  }
  ~PanelDriver() { ImGui::DestroyContext(); }
  PanelDriver(const PanelDriver&) = delete;
  PanelDriver& operator=(const PanelDriver&) = delete;
  // One frame: the mouse at `pos`, its left button `down`.
  void frame(ImVec2 pos, bool down) {
    ImGuiIO& io = ImGui::GetIO();
    io.DeltaTime = 1.0f / 60.0f;
    io.MousePos = pos;  // Debian 12's ImGui (1.86) predates the event queue
    io.MouseDown[0] = down;
    ImGui::NewFrame();
    panel_.draw(session_, dock_);
    ImGui::Render();
  }
  void idle() { frame(ImVec2(-100.f, -100.f), false); }
  // Where the knob editing `key` was drawn in the last frame; none if it was not drawn.
  std::optional<UiRect> rect(const std::string& key) const {
    const auto it = panel_.knob_rects().find(key);
    return it == panel_.knob_rects().end() ? std::nullopt : std::optional<UiRect>(it->second);
  }
  // Presses and releases the mouse on the checkbox editing `key` (its square box is at the
  // left of its row); false if it is not on the panel.
  bool click_checkbox(const std::string& key) {
    idle();
    const std::optional<UiRect> c = rect(key);
    if (!c) return false;
    const ImVec2 box(c->x0 + 0.5f * c->height(), 0.5f * (c->y0 + c->y1));
    frame(box, false);
    frame(box, true);
    frame(box, false);
    return true;
  }

 private:
  TuneSession& session_;
  TunePanel panel_;
  UiRect dock_ = UiRect::at(0.f, 0.f, 420.f, 6000.f);
};

// Values of two images (same size) that differ by more than eps.
int changed_values(const Image& a, const Image& b, float eps) {
  int n = 0;
  for (std::size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) n += std::abs(a.pixels[i] - b.pixels[i]) > eps;
  return n;
}

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

  PanelDriver ui(s);
  ui.idle();
  ui.idle();
  const std::string key = "surfaces.0.fourd_rotation_xw_deg";
  ASSERT_TRUE(ui.rect(key)) << "the world section shows the 4D turns";
  const UiRect r = *ui.rect(key);
  const float y = 0.5f * (r.y0 + r.y1);
  ui.frame(ImVec2(r.x0 + 0.5f * r.width(), y), false);
  ui.frame(ImVec2(r.x0 + 0.5f * r.width(), y), true);
  for (int i = 1; i <= 4; ++i) ui.frame(ImVec2(r.x0 + (0.5f + 0.0625f * i) * r.width(), y), true);
  ui.frame(ImVec2(r.x0 + 0.75f * r.width(), y), false);  // released: applied
  ASSERT_TRUE(s.edits().count(key)) << s.last_error();
  const double angle = std::atof(s.edits().at(key).c_str());
  std::printf("xw slider dragged to %s\n", s.edits().at(key).c_str());
  EXPECT_NEAR(angle, 90.0, 10.0);
  EXPECT_NEAR(s.renderer().scene().surfaces[0].fourd.rotation_deg[2], angle, 1e-3);
  ASSERT_TRUE(s.renderer().render_frame());
  auto after = s.renderer().read_aov(Aov::kNormal);
  ASSERT_TRUE(after);
  EXPECT_GT(changed_values(after.value(), before.value(), 1e-3f), 300) << "the surface is reprojected";

  const std::string roll = "surfaces.0.fourd_roll";
  ASSERT_TRUE(ui.click_checkbox(roll));
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
  PanelDriver ui(s);
  const std::string key = "materials." + s.renderer().scene().materials[0].name + ".gabor_filter";
  ASSERT_TRUE(ui.click_checkbox(key));
  ASSERT_TRUE(s.edits().count(key)) << s.last_error();
  EXPECT_EQ(s.edits().at(key), "\"none\"");
  EXPECT_EQ(s.renderer().scene().materials[0].gabor.filter, GaborParams::Filter::kNone);
  ASSERT_TRUE(s.renderer().render_frame());
  auto after = s.renderer().read_aov(Aov::kTexture);
  ASSERT_TRUE(after);
  EXPECT_GT(changed_values(after.value(), before.value(), 1e-4f), 10) << "the shadow's texture is no longer filtered";
}

PS_INSTANTIATE_HEADLESS_BACKENDS(TunePanelGLTest);

}  // namespace
}  // namespace ps
