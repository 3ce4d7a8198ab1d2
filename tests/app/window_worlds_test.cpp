// What a person with a mouse meets in `run`'s window, without a window (issue 27 §3, §5): the
// buttons' rectangles and labels on screen, text overlays kept off them, a panel that stays put
// while the pointer comes for it, and panel sliders that cannot offer a value the scene format
// refuses (app/window/button_overlay.h, app/window/ui_layout.h, app/window/panel_links.h).
#include <gtest/gtest.h>

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "app/window/button_overlay.h"
#include "app/window/panel_links.h"
#include "app/window/ui_layout.h"
#include "devices/pointer_map.h"
#include "scene/camera.h"
#include "scene/scene_io.h"

namespace ps {
namespace {

std::string scene_file(const std::string& name) { return std::string(PS_SOURCE_DIR) + "/scenes/" + name; }

std::vector<ButtonOverlay> panel_buttons(float w, float h) {
  auto scene = load_scene(scene_file("universe/panel.toml"));
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return {};
  const Scene& sc = scene.value();
  return project_buttons(sc, sc.camera, static_cast<double>(sc.render.width) / sc.render.height, w, h);
}

// The control panel's four buttons land on screen as four disjoint rectangles, each around the
// projection of its face's centre, labelled from the file (panel.toml's `label`s).
TEST(ButtonOverlayTest, ThePanelsButtonsAreFourLabelledRectanglesOnScreen) {
  const std::vector<ButtonOverlay> b = panel_buttons(1080.f, 600.f);
  ASSERT_EQ(b.size(), 4u);
  const std::vector<std::string> labels = {"Illusion", "Weight", "Field", "Poly"};
  auto scene = load_scene(scene_file("universe/panel.toml"));
  ASSERT_TRUE(scene);
  PointerView view;
  view.camera = scene->camera;
  view.aspect = 1080.0 / 600.0;
  view.window_size = {1080.0, 600.0};
  for (std::size_t i = 0; i < b.size(); ++i) {
    std::printf("button %s: [%.0f, %.0f, %.0f, %.0f]\n", b[i].label.c_str(), b[i].rect.x0, b[i].rect.y0, b[i].rect.x1, b[i].rect.y1);
    EXPECT_EQ(b[i].label, labels[i]);
    EXPECT_GT(b[i].rect.width(), 40.f) << "a 56 mm button is large on screen";
    const glm::dvec2 c = project_to_window(view, scene->buttons[i].center);
    EXPECT_TRUE(b[i].rect.x0 < c.x && c.x < b[i].rect.x1 && b[i].rect.y0 < c.y && c.y < b[i].rect.y1) << i;
    for (std::size_t j = 0; j < i; ++j) EXPECT_FALSE(intersects(b[i].rect, b[j].rect)) << i << " " << j;
  }
}

// A button's label defaults to its target's file name; a flag button's to the flag.
TEST(ButtonOverlayTest, LabelsDefaultToTheTargetsName) {
  auto worlds = load_scene(scene_file("universe/weight.toml"), {"buttons.0.label=\"\""});
  ASSERT_TRUE(worlds) << worlds.error().message;
  EXPECT_EQ(worlds->buttons[0].label, "panel");
  auto demo = load_scene(scene_file("buttons_demo.toml"));
  ASSERT_TRUE(demo) << demo.error().message;
  EXPECT_EQ(demo->buttons[0].label, demo->buttons[0].action_target);  // a flag: its name
  auto long_label = load_scene(scene_file("universe/weight.toml"), {"buttons.0.label=\"" + std::string(40, 'x') + "\""});
  ASSERT_FALSE(long_label);
  EXPECT_NE(long_label.error().message.find("label"), std::string::npos) << long_label.error().message;
}

// The boxes at least as large as `run` draws them (ImGui's 7 x 13 px font, 8 px padding;
// measured in `run --ui-report` on panel.toml: readouts 170 x 146, narrow help 205 x 289): the
// readouts 184 x 146; the help in two columns 408 x 159, in one column 212 x 289.
UiLayoutInput window_with(const std::vector<ButtonOverlay>& buttons, UiRect shadow) {
  UiLayoutInput in;
  in.width = 1080.f;
  in.height = 600.f;
  in.shadow = shadow;
  in.hud_w = 184.f;
  in.hud_h = 146.f;
  in.help = true;
  in.help_w = 408.f;
  in.help_h = 159.f;
  in.help_narrow_w = 212.f;
  in.help_narrow_h = 289.f;
  for (const ButtonOverlay& b : buttons) in.buttons.push_back(b.rect);
  return in;
}

// At start on the control panel, in its window (1080 x 600, the file's render.size), with the
// shadow in the middle or over a button, neither the help nor the readouts cover a button;
// with the help gone the readouts still do not.
TEST(UiLayoutTest, TextNeverCoversTheControlPanelsButtons) {
  const std::vector<ButtonOverlay> buttons = panel_buttons(1080.f, 600.f);
  ASSERT_EQ(buttons.size(), 4u);
  for (const UiRect shadow : {UiRect{490, 250, 590, 350}, UiRect{300, 80, 400, 180}, UiRect{680, 420, 780, 520}}) {
    UiLayoutInput in = window_with(buttons, shadow);
    const UiLayout start = layout_ui(in);
    ASSERT_TRUE(start.help && start.hud) << "both fit beside the buttons";
    EXPECT_TRUE(start.help_narrow) << "the wide help has no room beside the buttons";
    for (const ButtonOverlay& b : buttons) {
      EXPECT_FALSE(intersects(*start.help, b.rect)) << "help over " << b.label;
      EXPECT_FALSE(intersects(*start.hud, b.rect)) << "readouts over " << b.label;
    }
    EXPECT_FALSE(intersects(*start.help, *start.hud));
    in.help = false;
    const UiLayout later = layout_ui(in);
    ASSERT_TRUE(later.hud);
    for (const ButtonOverlay& b : buttons) EXPECT_FALSE(intersects(*later.hud, b.rect)) << "readouts over " << b.label;
  }
}

// A window of w x h with the panel shown and the default scene's readouts box.
UiLayoutInput shown_panel(float w, float h) {
  UiLayoutInput in;
  in.width = w;
  in.height = h;
  in.panel = true;
  in.panel_width = panel_width_for(in.width);
  in.panel_height = in.height;
  in.hud_w = 184.f;
  in.hud_h = 133.f;
  return in;
}

// The pointer walks from the window's centre to the panel on the right at 4 px a frame, its
// shadow (190 px wide, centred on it) reaching the strip long before the pointer: the panel
// stays on the right all the way and while the pointer is over it. Away from both strips, a
// shadow under the right strip still sends the panel left (the old rule).
TEST(UiLayoutTest, ThePanelStaysPutWhileThePointerComesForIt) {
  UiLayoutInput in = shown_panel(1280.f, 800.f);
  UiPlacement last;
  for (float x = 640.f; x <= 1270.f; x += 4.f) {
    in.pointer = std::make_pair(x, 400.f);
    in.shadow = UiRect{x - 95.f, 305.f, x + 95.f, 495.f};
    in.last = last;
    const UiLayout l = layout_ui(in);
    ASSERT_EQ(l.placement.panel_side, PanelSide::kRight) << "pointer at x " << x;
    last = l.placement;
  }
  // The pointer outside the window (it left to the desktop): the shadow decides again, once it
  // has wanted the other side for kPanelFlipDwellS without a break.
  in.pointer.reset();
  in.shadow = UiRect{1000.f, 305.f, 1190.f, 495.f};
  in.last = last;
  in.now_s = 10.0;
  const UiLayout wait = layout_ui(in);
  EXPECT_EQ(wait.placement.panel_side, PanelSide::kRight) << "not before the dwell";
  in.last = wait.placement;
  in.now_s = 10.0 + kPanelFlipDwellS;
  EXPECT_EQ(layout_ui(in).placement.panel_side, PanelSide::kLeft);
  // Just opened (not placed yet), with the pointer near the right strip: placed by the shadow.
  in.pointer = std::make_pair(1095.f, 400.f);
  in.last = UiPlacement{};
  EXPECT_EQ(layout_ui(in).placement.panel_side, PanelSide::kLeft);
}

// The pointer on the panel's slider flicks to the window's centre and back (issue 27's flicks,
// ~2000-4000 px/s, one or two 30 ms frames in the middle): the shadow measured on those frames is
// still under the right strip, but the panel waits kPanelFlipDwellS before it changes side, so
// the pointer finds it where it left it. (Without the dwell it went left at the first frame.)
TEST(UiLayoutTest, APointerFlickingAwayAndBackFindsThePanelWhereItWas) {
  UiLayoutInput in = shown_panel(512.f, 512.f);
  UiPlacement last;
  const auto frame = [&](float x, float shadow_x, double t) {
    in.pointer = std::make_pair(x, 157.f);
    in.shadow = UiRect{shadow_x - 95.f, 60.f, shadow_x + 95.f, 250.f};
    in.now_s = t;
    in.last = last;
    last = layout_ui(in).placement;
    return last.panel_side;
  };
  ASSERT_EQ(frame(256.f, 256.f, 0.0), PanelSide::kRight);  // opened with the shadow in the middle
  for (int i = 1; i <= 10; ++i) ASSERT_EQ(frame(428.f, 428.f, 0.03 * i), PanelSide::kRight) << "on the panel";
  // At the centre for two frames, the shadow lagging a frame behind the pointer.
  EXPECT_EQ(frame(256.f, 428.f, 0.33), PanelSide::kRight);
  EXPECT_EQ(frame(256.f, 400.f, 0.36), PanelSide::kRight);
  EXPECT_EQ(frame(428.f, 428.f, 0.39), PanelSide::kRight) << "back on the slider";
  // The pointer rests 80 px from the panel (the case) with the shadow under the strip:
  // the panel keeps its side however long it rests (within kPanelPointerKeepPx).
  double t = 0.42;
  for (; t < 4.0; t += 0.03) ASSERT_EQ(frame(278.f, 420.f, t), PanelSide::kRight) << "t " << t;
  // The pointer leaves the window (no pointer: nothing near either strip) less than
  // kPanelPointerMemoryS after it was over the panel: still kept.
  frame(428.f, 428.f, 5.0);
  const auto away = [&](double at) {
    in.pointer.reset();
    in.now_s = at;
    in.last = last;
    last = layout_ui(in).placement;
    return last.panel_side;
  };
  for (t = 5.03; t < 5.0 + kPanelPointerMemoryS - 0.01; t += 0.03) ASSERT_EQ(away(t), PanelSide::kRight) << "t " << t;
  // A shadow that rests under the panel with the pointer away for longer (a probe parked at the
  // right) sends it over after the dwell. (At 512 px no place in the window is 150 px from the
  // panel and clear of the other strip: there the panel moves only while the pointer is out.)
  for (; t < 5.0 + kPanelPointerMemoryS + kPanelFlipDwellS - 0.01; t += 0.03) ASSERT_EQ(away(t), PanelSide::kRight);
  EXPECT_EQ(away(5.0 + kPanelPointerMemoryS + kPanelFlipDwellS + 0.1), PanelSide::kLeft);
}

// A panel that must change side slides across instead of jumping (kPanelSlideS): its left edge
// goes from one strip to the other over the slide's time, each frame a step no longer than the
// eased slide's fastest (1.5 x the distance over kPanelSlideS, smoothstep's peak speed, for one
// frame's time, plus a pixel of float rounding), and rests there. While it waits for its dwell,
// and while the keep rule holds it, it does not move by a pixel.
TEST(UiLayoutTest, APanelThatChangesSideSlidesAcross) {
  UiLayoutInput in = shown_panel(1280.f, 800.f);
  UiPlacement last;
  const auto frame = [&](double t, std::optional<std::pair<float, float>> pointer, float shadow_x) {
    in.now_s = t;
    in.pointer = pointer;
    in.shadow = UiRect{shadow_x - 95.f, 305.f, shadow_x + 95.f, 495.f};
    in.last = last;
    const UiLayout l = layout_ui(in);
    last = l.placement;
    return l;
  };
  const float right = 1280.f - panel_width_for(1280.f);
  ASSERT_EQ(frame(0.0, std::make_pair(640.f, 400.f), 640.f).panel->x0, right);
  // The pointer 120 px from the panel (never over it) with the shadow under the strip, 4 s: the
  // keep rule, not a pixel of motion.
  for (double t = 0.02; t < 4.0; t += 0.02)
    ASSERT_EQ(frame(t, std::make_pair(800.f, 400.f), 1090.f).panel->x0, right) << "t " << t;
  // The pointer leaves the window: the panel waits out the dwell without motion, then slides.
  const double dt = 1.0 / 60.0, max_step = 1.5 * right * dt / kPanelSlideS + 1.0;
  double t = 4.0;
  for (; last.panel_side == PanelSide::kRight; t += dt) {
    ASSERT_LT(t, 4.0 + kPanelFlipDwellS + 0.1) << "the panel never went left";
    const UiLayout l = frame(t, std::nullopt, 1090.f);
    if (l.placement.panel_side == PanelSide::kRight) {
      ASSERT_EQ(l.panel->x0, right) << "t " << t;
    }
  }
  const double flipped = t - dt;
  float x = right;
  int between = 0;
  for (; t < flipped + kPanelSlideS + 0.5; t += dt) {
    const UiLayout l = frame(t, std::nullopt, 1090.f);
    ASSERT_EQ(l.placement.panel_side, PanelSide::kLeft);
    const float now = l.panel->x0;
    ASSERT_LE(now, x) << "t " << t << ": the slide turned back";
    ASSERT_LE(x - now, max_step) << "t " << t << ": a jump of " << x - now << " px";
    if (now > 0.f && now < right) ++between;
    if (t - flipped >= kPanelSlideS) {
      EXPECT_EQ(now, 0.f) << "t " << t << ": not arrived";
    }
    // The readouts went beside the left strip at the slide's start: they do not follow it.
    ASSERT_TRUE(l.hud);
    EXPECT_GE(l.hud->x0, panel_width_for(1280.f)) << "t " << t;
    x = now;
  }
  EXPECT_GE(between, static_cast<int>(kPanelSlideS / dt) - 2) << "frames drawn on the way across";
  EXPECT_FALSE(last.slide_since_s) << "at rest on the left";
}

// Every min/max pair the loader checks stays ordered: dragging lambda_min from 1 to 16.98 over a
// lambda_max of 1.6 (issue 27's drag) moves lambda_max along first, and every edit the panel
// makes leaves a scene the loader accepts.
TEST(PanelLinksTest, AMinSliderPastItsMaxMovesTheMaxAlong) {
  auto scene = load_scene(scene_file("default.toml"), {"materials.wood.lambda_min=1", "materials.wood.lambda_max=1.6"});
  ASSERT_TRUE(scene) << scene.error().message;
  const Material& wood = scene->materials[0];
  ASSERT_EQ(wood.name, "wood");
  const std::vector<PanelEdit> e = linked_edits(wood, "lambda_min", 16.98);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].key, "materials.wood.lambda_max");
  EXPECT_DOUBLE_EQ(e[0].value, 16.98);
  EXPECT_EQ(e[1].key, "materials.wood.lambda_min");
  EXPECT_EQ(linked_edits(wood, "lambda_min", 1.2).size(), 1u) << "inside the range: the partner stays";
  const std::vector<PanelEdit> down = linked_edits(wood, "lambda_max", 0.5);
  ASSERT_EQ(down.size(), 2u);
  EXPECT_EQ(down[0].key, "materials.wood.lambda_min");
  EXPECT_EQ(linked_edits(wood, "theta_min", 170.0).size(), 1u) << "reversed theta is allowed by the format";
}

std::string number(double v) { return std::to_string(v); }

// Every slider's two ends, applied as the panel applies them (linked_edits, one --set each, in
// order), give a scene the loader accepts: the ranges lie inside the scene format's limits.
TEST(PanelLinksTest, EverySlidersEndsAreValidSceneValues) {
  auto base = load_scene(scene_file("default.toml"));
  ASSERT_TRUE(base) << base.error().message;
  for (const PanelParam& p : panel_material_params())
    for (const double v : {static_cast<double>(p.lo), static_cast<double>(p.hi)}) {
      std::vector<std::string> sets;
      for (const PanelEdit& e : linked_edits(base->materials[0], p.key, v)) sets.push_back(e.key + "=" + number(e.value));
      auto scene = load_scene(scene_file("default.toml"), sets);
      EXPECT_TRUE(scene) << p.key << " = " << v << ": " << (scene ? "" : scene.error().message);
    }
}

TEST(PanelLinksTest, MessagesSpeakOfThePanel) {
  EXPECT_EQ(panel_message("--set materials.wood.n_min: 'n_min' (5) must be <= 'n_max' (2)"),
            "panel: materials.wood.n_min: 'n_min' (5) must be <= 'n_max' (2)");
  EXPECT_EQ(panel_message("scenes/x.toml:3: bad"), "scenes/x.toml:3: bad");
}

}  // namespace
}  // namespace ps
