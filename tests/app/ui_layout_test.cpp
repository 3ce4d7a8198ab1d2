// The window overlays of `run` without a window: the shadow's bounding box measured on AOV
// pixels, where the panel, the readouts and the help go around it, the readout text and the
// key table (app/window/ui_layout.h, app/window/hud.h, app/window/run_keys.h).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

#include "app/window/hud.h"
#include "app/window/run_keys.h"
#include "app/window/ui_layout.h"

namespace ps {
namespace {

Image gray(int w, int h, float v) {
  Image im;
  im.width = w;
  im.height = h;
  im.channels = 1;
  im.pixels.assign(static_cast<size_t>(w) * h, v);
  return im;
}

TEST(UiLayoutTest, ShadowBoxIsTheBoundOfThePixelsAboveTheVisibleThreshold) {
  Image intensity = gray(8, 6, 0.f), distance = gray(8, 6, std::numeric_limits<float>::quiet_NaN());
  intensity.at(2, 1, 0) = 0.5f;
  intensity.at(5, 3, 0) = 0.02f;
  intensity.at(7, 5, 0) = kShadowVisibleIntensity;  // at the threshold: invisible, not counted
  distance.at(2, 1, 0) = 3.0f;
  distance.at(5, 3, 0) = 7.5f;
  distance.at(7, 5, 0) = -1.0f;  // not shadowed: its distance is not the probe's
  const ShadowMeasure m = measure_shadow(intensity, &distance, 8, 6);
  ASSERT_TRUE(m.bbox.has_value());
  EXPECT_EQ(m.pixels, 2u);
  // Pixels 2..5 in x and 1..3 in y: half-open [2, 6) x [1, 4).
  EXPECT_FLOAT_EQ(m.bbox->x0, 2.f);
  EXPECT_FLOAT_EQ(m.bbox->y0, 1.f);
  EXPECT_FLOAT_EQ(m.bbox->x1, 6.f);
  EXPECT_FLOAT_EQ(m.bbox->y1, 4.f);
  ASSERT_TRUE(m.min_distance_mm.has_value());
  EXPECT_DOUBLE_EQ(*m.min_distance_mm, 3.0);
}

TEST(UiLayoutTest, ShadowBoxScalesToTheWindowAndIsAbsentWithoutShadow) {
  Image intensity = gray(8, 6, 0.f);
  intensity.at(3, 2, 0) = 1.f;
  const ShadowMeasure m = measure_shadow(intensity, nullptr, 16, 18);  // x2 wide, x3 high
  ASSERT_TRUE(m.bbox.has_value());
  EXPECT_FLOAT_EQ(m.bbox->x0, 6.f);
  EXPECT_FLOAT_EQ(m.bbox->x1, 8.f);
  EXPECT_FLOAT_EQ(m.bbox->y0, 6.f);
  EXPECT_FLOAT_EQ(m.bbox->y1, 9.f);
  EXPECT_FALSE(m.min_distance_mm.has_value()) << "no distance AOV was given";
  const ShadowMeasure none = measure_shadow(gray(8, 6, 0.f), nullptr, 8, 6);
  EXPECT_FALSE(none.bbox.has_value());
  EXPECT_EQ(none.pixels, 0u);
}

// A shadow seen in perspective: a solid core of 3 x 3 pixels around (20, 30) and a faint tail
// reaching 20 pixels below it but only 8 above (the near half looks larger). The core's centre
// is the middle of the core (pixel centres: 20.5, 30.5), scaled to the window; the box's centre
// is 6 pixels lower. A second, fainter blob elsewhere does not move the core.
TEST(UiLayoutTest, TheShadowsCentreIsItsCoreNotItsBox) {
  Image intensity = gray(64, 64, 0.f);
  for (int y = 22; y <= 50; ++y)
    for (int x = 14; x <= 26; ++x) intensity.at(x, y, 0) = 0.2f;
  for (int y = 29; y <= 31; ++y)
    for (int x = 19; x <= 21; ++x) intensity.at(x, y, 0) = 1.f;
  intensity.at(20, 30, 0) = 0.95f;  // within 10 % of the darkest: still the core
  intensity.at(5, 45, 0) = 0.85f;   // outside it
  const ShadowMeasure m = measure_shadow(intensity, nullptr, 128, 64);  // x2 wide
  ASSERT_TRUE(m.core.has_value());
  EXPECT_FLOAT_EQ(m.core->first, 2.f * 20.5f);
  EXPECT_FLOAT_EQ(m.core->second, 30.5f);
  ASSERT_TRUE(m.bbox.has_value());
  EXPECT_GT(0.5f * (m.bbox->y0 + m.bbox->y1) - m.core->second, 5.f) << "the box's centre is lower";
  EXPECT_FALSE(measure_shadow(gray(8, 6, 0.f), nullptr, 8, 6).core.has_value());
}

TEST(UiLayoutTest, RectanglesAreHalfOpen) {
  const UiRect a = UiRect::at(0, 0, 10, 10);
  EXPECT_FALSE(intersects(a, UiRect::at(10, 0, 5, 5))) << "touching edges do not overlap";
  EXPECT_TRUE(intersects(a, UiRect::at(9, 9, 5, 5)));
  EXPECT_FLOAT_EQ(overlap_area(a, UiRect::at(9, 8, 5, 5)), 2.f);
  EXPECT_FALSE(intersects(a, UiRect{}));
}

// The default scene at 512^2 with its probe at the start: the shadow as measured on its AOV
// (tools/window_check_xvfb.sh), the box sizes the default font gives the readouts and help.
UiLayoutInput default_scene(const UiRect& shadow) {
  UiLayoutInput in;
  in.width = in.height = 512.f;
  in.shadow = shadow;
  in.panel = true;
  in.panel_width = panel_width_for(512.f);
  in.panel_height = 512.f;
  in.hud_w = 184.f;
  in.hud_h = 133.f;
  in.help = true;
  in.help_w = 339.f;
  in.help_h = 133.f;
  return in;
}

void expect_clear(const UiLayout& l, const UiRect& shadow) {
  ASSERT_TRUE(l.panel.has_value());
  ASSERT_TRUE(l.help.has_value());
  ASSERT_TRUE(l.hud.has_value()) << "the default scene has room for the readouts beside the help";
  EXPECT_FALSE(intersects(*l.panel, shadow));
  EXPECT_FALSE(intersects(*l.hud, shadow));
  EXPECT_FALSE(intersects(*l.help, shadow));
  EXPECT_FALSE(intersects(*l.hud, *l.panel));
  EXPECT_FALSE(intersects(*l.help, *l.panel));
  EXPECT_FALSE(intersects(*l.help, *l.hud));
  for (const UiRect& r : {*l.panel, *l.hud, *l.help}) {
    EXPECT_GE(r.x0, 0.f);
    EXPECT_GE(r.y0, 0.f);
    EXPECT_LE(r.x1, 512.f);
    EXPECT_LE(r.y1, 512.f);
  }
}

TEST(UiLayoutTest, CentredShadowKeepsThePanelRightAndTheBoxesAroundIt) {
  const UiRect shadow{160, 195, 352, 330};
  const UiLayout l = layout_ui(default_scene(shadow));
  EXPECT_EQ(l.placement.panel_side, PanelSide::kRight);
  EXPECT_FLOAT_EQ(l.panel->x1, 512.f);
  expect_clear(l, shadow);
}

TEST(UiLayoutTest, ShadowOnTheRightMovesThePanelLeft) {
  const UiRect shadow{303, 195, 496, 330};  // the probe 12 mm to the right
  const UiLayout l = layout_ui(default_scene(shadow));
  EXPECT_EQ(l.placement.panel_side, PanelSide::kLeft);
  EXPECT_FLOAT_EQ(l.panel->x0, 0.f);
  expect_clear(l, shadow);
}

TEST(UiLayoutTest, ShadowInTheTopLeftSendsTheReadoutsToAnotherCorner) {
  const UiRect shadow{0, 0, 150, 150};
  UiLayoutInput in = default_scene(shadow);
  in.panel = in.help = false;
  const UiLayout l = layout_ui(in);
  EXPECT_NE(l.placement.hud_corner, Corner::kTopLeft);
  ASSERT_TRUE(l.hud.has_value());
  EXPECT_FALSE(intersects(*l.hud, shadow));
  // The corner farthest from the shadow.
  EXPECT_EQ(l.placement.hud_corner, Corner::kBottomRight);
}

TEST(UiLayoutTest, LastPlacementIsKeptWhileItStaysClear) {
  const UiRect shadow{200, 200, 300, 300};  // both sides and all corners are clear
  UiLayoutInput in = default_scene(shadow);
  in.last.panel_side = PanelSide::kLeft;
  in.last.hud_corner = Corner::kBottomRight;
  const UiLayout l = layout_ui(in);
  EXPECT_EQ(l.placement.panel_side, PanelSide::kLeft) << "no jump to the preferred right side";
  EXPECT_EQ(l.placement.hud_corner, Corner::kBottomRight);
}

TEST(UiLayoutTest, ShadowWiderThanTheRoomLeavesThePanelOnTheSideItCoversLess) {
  const UiRect shadow{100, 100, 480, 400};  // 380 of 512 px wide: no strip is clear
  const UiLayout l = layout_ui(default_scene(shadow));
  // With the 4 px margin the right strip [358, 512) would cover columns 358..484 (126), the
  // left one [0, 154) columns 96..154 (58): less than half, worth the move.
  EXPECT_EQ(l.placement.panel_side, PanelSide::kLeft);
  // Covering 104 columns on the left instead of 126 on the right is not: the panel stays.
  const UiRect wide{54, 100, 480, 400};
  EXPECT_EQ(layout_ui(default_scene(wide)).placement.panel_side, PanelSide::kRight);
}

TEST(UiLayoutTest, ReadoutsWaitWhileTheHelpHasNoRoomBesideThem) {
  // A large shadow leaves only a band of 146 px at the top: 339 + 184 px of help and readouts
  // do not fit side by side in the 358 px the panel leaves, and below the shadow the help
  // would cover it.
  UiLayoutInput in = default_scene(UiRect{100, 150, 400, 470});
  const UiLayout l = layout_ui(in);
  ASSERT_TRUE(l.help.has_value());
  EXPECT_FALSE(l.hud.has_value());
  EXPECT_FALSE(intersects(*l.help, UiRect{100, 150, 400, 470}));
  in.help = false;
  EXPECT_TRUE(layout_ui(in).hud.has_value()) << "the readouts come back when the help hides";
}

TEST(UiLayoutTest, ReportIsJsonWithOneObjectPerFrame) {
  UiFrameReport f;
  f.frame = 7;
  f.shadow = UiRect{1, 2, 3, 4};
  f.hud = UiRect::at(6, 6, 10.5f, 20);
  f.buttons = {UiRect{10, 20, 30, 40}, UiRect{50, 60, 70, 80}};
  const std::string json = ui_report_json(512, 480, {f});
  EXPECT_NE(json.find("\"window\": [512, 480]"), std::string::npos) << json;
  EXPECT_NE(json.find("{\"frame\": 7, \"shadow\": [1.0, 2.0, 3.0, 4.0], \"hud\": [6.0, 6.0, 16.5, 26.0], "
                      "\"help\": null, \"panel\": null, "
                      "\"buttons\": [[10.0, 20.0, 30.0, 40.0], [50.0, 60.0, 70.0, 80.0]]}"),
            std::string::npos)
      << json;
}

TEST(HudTest, NoShadowReadsOutOfReachAndContactReadsTouching) {
  HudReadouts r;
  r.scene = "default.toml";
  EXPECT_EQ(title_summary(r), "pseudoshadow \u2014 default.toml \u2014 out of reach");
  r.probe = probe_readout({1.26, false, {}, {}});
  EXPECT_EQ(title_summary(r), "pseudoshadow \u2014 default.toml \u2014 1.3 mm");
  r.probe = probe_readout({-0.4, true, {}, {}});
  EXPECT_EQ(title_summary(r), "pseudoshadow \u2014 default.toml \u2014 touching");
  r.error = "glsl/surface.frag:3: error";
  EXPECT_NE(title_summary(r).find("RELOAD FAILED"), std::string::npos);
}

TEST(HudTest, ReadoutsNameEveryQuantityWithItsUnit) {
  HudReadouts r;
  r.scene = "table5_1_construction_paper.toml";
  r.probe = probe_readout({2.0, false, {}, {}});
  r.frame_ms = 16.7;
  r.haptic_hz = 998.0;
  r.jitter_p99_us = 45.0;
  r.speed_mm_s = 250.0;
  r.penetration_mm = 0.0;
  r.force_n = 0.5;
  const std::vector<std::string> lines = hud_lines(r);
  std::string all;
  for (const std::string& l : lines) all += l + "\n";
  for (const char* want : {"scene       table5_1_cons...", "distance    2.0 mm", "penetration 0.00 mm",
                           "contact     no", "force       0.50 N", "speed       250 mm/s", "frame       16.7 ms",
                           "haptic      998 Hz", "jitter p99  45 us"})
    EXPECT_NE(all.find(want), std::string::npos) << "missing '" << want << "' in\n" << all;
  EXPECT_EQ(all.find("baking"), std::string::npos) << "a finished bake shows no line:\n" << all;
  EXPECT_EQ(all.find("gpu frame"), std::string::npos) << "no timer result yet: no line\n" << all;
  r.gpu_frame_ms = 3.25;
  all.clear();
  for (const std::string& l : hud_lines(r)) all += l + "\n";
  EXPECT_NE(all.find("frame       16.7 ms\ngpu frame   3.2 ms\n"), std::string::npos) << all;
  // Touching: contact yes and the pressed depth, the distance line says so too (one state).
  r.probe = probe_readout({std::nullopt, true, {0.0, 0.0, 6.0}, {0.0, 0.0, 8.0}});
  all.clear();
  for (const std::string& l : hud_lines(r)) all += l + "\n";
  for (const char* want : {"distance    touching", "contact     yes", "pressed     2.0 mm", "frame       16.7 ms\ngpu frame"})
    EXPECT_NE(all.find(want), std::string::npos) << "missing '" << want << "' in\n" << all;
}

TEST(HudTest, BakeProgressShowsUntilTheTileIsReady) {
  HudReadouts r;
  r.bake_progress = 0.4;
  std::string all;
  for (const std::string& l : hud_lines(r)) all += l + "\n";
  EXPECT_NE(all.find("texture     baking 40 %"), std::string::npos) << all;
}

// A pressed button and the scene's flags show only when there are such things.
TEST(HudTest, ButtonAndFlagsShowWhenTheSceneHasThem) {
  HudReadouts r;
  std::string all;
  for (const std::string& l : hud_lines(r)) all += l + "\n";
  EXPECT_EQ(all.find("button"), std::string::npos) << all;
  EXPECT_EQ(all.find("flags"), std::string::npos) << all;
  EXPECT_EQ(all.find("view"), std::string::npos) << all;
  r.button = 1;
  r.button_depth_mm = 2.14;
  r.button_travel_mm = 3.0;
  r.flags = "";
  all.clear();
  for (const std::string& l : hud_lines(r)) all += l + "\n";
  EXPECT_NE(all.find("button      #1 in 2.1 of 3.0 mm"), std::string::npos) << all;
  EXPECT_NE(all.find("flags on    none"), std::string::npos) << all;
  r.flags = "light, door";
  all.clear();
  for (const std::string& l : hud_lines(r)) all += l + "\n";
  EXPECT_NE(all.find("flags on    light, door"), std::string::npos) << all;
  r.view_mm = glm::dvec3(151.4, 0.0, -2.0);
  all.clear();
  for (const std::string& l : hud_lines(r)) all += l + "\n";
  EXPECT_NE(all.find("view        +151 +0 -2 mm"), std::string::npos) << all;
  EXPECT_EQ(all.find("rolled"), std::string::npos) << "no rolling, no line:\n" << all;
  r.rolled_deg = 69.8;
  all.clear();
  for (const std::string& l : hud_lines(r)) all += l + "\n";
  EXPECT_NE(all.find("rolled      70 deg"), std::string::npos) << all;
  // A surface embedded in 4D: its turn, and the legend line of its 4D-depth colours (the colours
  // themselves are drawn over the gap between "far" and "near").
  EXPECT_EQ(all.find("4D depth"), std::string::npos) << "no 4D surface, no legend:\n" << all;
  r.turn4_deg = std::array<double, 6>{10.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  all.clear();
  for (const std::string& l : hud_lines(r)) all += l + "\n";
  EXPECT_NE(all.find("4D xy xz xw 10 0 0 deg"), std::string::npos) << all;
  EXPECT_NE(all.find("4D depth    far" + std::string(14, ' ') + "near"), std::string::npos) << all;
}

TEST(RunKeysTest, EveryKeyOfTheWindowIsInTheTableOnce) {
  // The bindings of app/window/window_input.cpp and the mouse device, by the words the table uses.
  for (const char* keys : {"mouse", "Shift+scroll", "PgUp / PgDn", "right drag", "scroll", "C, Shift+C", "Bksp", "Home",
                           "1-3 / Shift", "4-6 / Shift",
                           "M", "P / D", "S", "F1", "H, ?", "Esc, Q"}) {
    int found = 0;
    for (const RunKey& k : run_keys()) found += std::strcmp(k.keys, keys) == 0;
    EXPECT_EQ(found, 1) << keys;
  }
}

TEST(RunKeysTest, TwoColumnsHoldTheSameRowsAsOne) {
  const std::string one = run_keys_text("  ", 1), two = run_keys_text("", 2);
  const auto lines = [](const std::string& s) { return std::count(s.begin(), s.end(), '\n'); };
  EXPECT_EQ(lines(one), static_cast<long>(run_keys().size()));
  EXPECT_EQ(lines(two), static_cast<long>((run_keys().size() + 1) / 2));
  for (const RunKey& k : run_keys()) {
    EXPECT_NE(one.find(std::string("  ") + k.keys), std::string::npos) << k.keys;
    EXPECT_NE(two.find(k.action), std::string::npos) << k.action;
  }
}

}  // namespace
}  // namespace ps
