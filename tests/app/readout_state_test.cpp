// The probe readout's state machine (app/window/readout_state.h), the readouts log's JSON line
// (app/window/readouts_log.h) and the surface under the pointer (app/session/free_height.h). No GL, no window.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "app/session/free_height.h"
#include "app/window/readout_state.h"
#include "app/window/readouts_log.h"
#include "app/window/ui_layout.h"
#include "core/file_io.h"
#include "scene/scene_io.h"
#include "support/felt.h"
#include "world/haptic_scene.h"

namespace ps {
namespace {

TEST(ProbeReadoutTest, OutOfReachHoveringTouching) {
  ProbeReadoutInput in;
  EXPECT_EQ(probe_readout(in).state, ProbeState::kOutOfReach);
  EXPECT_EQ(probe_distance_text(probe_readout(in)), "out of reach");
  in.distance_mm = 1.26;
  const ProbeReadout hover = probe_readout(in);
  EXPECT_EQ(hover.state, ProbeState::kHovering);
  EXPECT_DOUBLE_EQ(hover.hover_mm, 1.26);
  EXPECT_EQ(probe_distance_text(hover), "1.3 mm");
  // The render mesh grazed without haptic contact: hovering at 0, never a negative distance.
  in.distance_mm = -0.4;
  EXPECT_EQ(probe_readout(in).state, ProbeState::kHovering);
  EXPECT_EQ(probe_readout(in).hover_mm, 0.0);
}

// The proxy held 4.6 mm from the hand (2.3 N through the coupling) with the contact flag off, as
// seen on a button held flush: touching, never "hovering 0.0 mm" with a force. A proxy that is
// where the hand is (0.01 mm: filter rounding), or where a field's pull puts it, is not held.
TEST(ProbeReadoutTest, AProxyHeldAwayFromTheHandIsTouching) {
  ProbeReadoutInput in;
  in.distance_mm = 0.0;
  in.hand_mm = {0.0, 0.0, -4.6};
  const ProbeReadout held = probe_readout(in);
  EXPECT_EQ(held.state, ProbeState::kTouching);
  EXPECT_NEAR(held.pressed_mm, 4.6, 1e-12);
  in.hand_mm = {0.0, 0.0, 0.01};
  EXPECT_EQ(probe_readout(in).state, ProbeState::kHovering);
  // A field's (or a body's, a wall's) pull holds the proxy 2 mm from the hand: no surface, hovering.
  in.hand_mm = {0.0, 0.0, -2.0};
  in.field_offset_mm = {0.0, 0.0, 2.0};
  EXPECT_EQ(probe_readout(in).state, ProbeState::kHovering);
  // A proxy catching up with a hand that jumped 14 mm in one tick (world::ProxyStep::
  // short_of_goal) is held by nothing: hovering, not "touching, pressed 14 mm" with no force.
  in.field_offset_mm = {0.0, 0.0, 0.0};
  in.hand_mm = {14.0, 0.0, 0.0};
  in.catching_up = true;
  EXPECT_EQ(probe_readout(in).state, ProbeState::kHovering);
  in.catching_up = false;
  EXPECT_EQ(probe_readout(in).state, ProbeState::kTouching);
}

// Contact decides first: never "out of reach" with contact (flat_torus's front sheet, issue 27),
// and the pressed depth is the hand's distance past the proxy (the plank pressed 8 x 0.5 mm).
TEST(ProbeReadoutTest, ContactIsTouchingWithThePressedDepth) {
  ProbeReadoutInput in;
  in.in_contact = true;
  in.proxy_mm = {1.0, 2.0, 8.0};
  in.hand_mm = {1.0, 2.0, 5.0};
  const ProbeReadout r = probe_readout(in);
  EXPECT_EQ(r.state, ProbeState::kTouching);
  EXPECT_DOUBLE_EQ(r.pressed_mm, 3.0);
  EXPECT_EQ(probe_distance_text(r), "touching");
  in.distance_mm = 4.0;  // a stale shadow distance does not outvote the contact
  EXPECT_EQ(probe_readout(in).state, ProbeState::kTouching);
  EXPECT_DOUBLE_EQ(probe_readout(in).held_mm, 3.0) << "no field: the surface holds all of it";
}

// Field's floor under a repelling charge: the charge pushes the hovering proxy 1.14 mm down (0.57 N
// through the 0.5 N/mm coupling) onto the floor, 1 mm below the hand. In contact and pressed
// 1.14 mm from the hand, but the floor holds only what the field does not explain (0.14 mm): the
// hand pushed nothing in. The hand pushed 2 mm further holds 2.14.
TEST(ProbeReadoutTest, AFieldsPushIsPressedButNotHeld) {
  ProbeReadoutInput in;
  in.in_contact = true;
  in.hand_mm = {-30.0, 3.0, 7.0};
  in.proxy_mm = {-30.0, 3.0, 6.0};
  in.field_offset_mm = {0.0, 0.0, -1.14};
  const ProbeReadout pushed = probe_readout(in);
  EXPECT_EQ(pushed.state, ProbeState::kTouching);
  EXPECT_NEAR(pushed.pressed_mm, 1.0, 1e-12);
  EXPECT_NEAR(pushed.held_mm, 0.14, 1e-12);
  in.hand_mm.z = 5.0;
  EXPECT_NEAR(probe_readout(in).held_mm, 2.14, 1e-12);
}

// The walks' `home` check reads it (tests/window/walk_checks.py): a rolled view left turned by
// 0.01 degree must read as turned, and a turn is the same angle about any axis. The truth here is
// glm's own axis-angle rotation, an independent construction.
TEST(ReadoutsLogTest, ViewTurnIsTheRotationsAngleAboutAnyAxis) {
  EXPECT_EQ(view_turn_deg(glm::dmat3(1.0)), 0.0);
  for (const double deg : {0.01, 1.0, 30.0, 90.0, 179.0})
    for (const glm::dvec3 axis : {glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), glm::normalize(glm::dvec3(1, -2, 0.5))}) {
      const glm::dmat3 r(glm::rotate(glm::dmat4(1.0), glm::radians(deg), axis));
      EXPECT_NEAR(view_turn_deg(r), deg, 1e-9) << deg << " degrees about " << axis.x << " " << axis.y << " " << axis.z;
    }
}

// --ui-report streamed (UiReportLog): 5000 frames, several 64 KiB blocks, publish the same bytes
// as the whole report made at once (ui_report_json), and the file is valid JSON with every frame;
// a log destroyed unclosed (a failed run) publishes nothing. Memory no longer grows with the run.
TEST(UiReportLogTest, StreamedReportIsTheWholeReportAndAFailedRunLeavesNone) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "ps_ui_report_log";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::vector<UiFrameReport> frames;
  for (std::uint64_t i = 0; i < 5000; ++i) {
    UiFrameReport f;
    f.frame = i;
    if (i % 3) f.shadow = UiRect{1.0f * i, 2, 3, 4};
    f.hud = UiRect::at(6, 6, 10.5f, 20);
    f.buttons.assign(i % 5, UiRect{10, 20, 30, 40});
    frames.push_back(f);
  }
  const std::string path = (dir / "ui.json").string();
  {
    UiReportLog log;
    ASSERT_TRUE(log.open(path));
    for (const UiFrameReport& f : frames) log.add(f);
    EXPECT_FALSE(std::filesystem::exists(path)) << "published only at close";
    ASSERT_TRUE(log.close(640, 480));
    EXPECT_EQ(log.frames(), 5000u);
  }
  const std::optional<std::string> got = read_whole_file(path);
  ASSERT_TRUE(got);
  EXPECT_EQ(*got, ui_report_json(640, 480, frames));
  const nlohmann::json j = nlohmann::json::parse(*got);
  EXPECT_EQ(j["frames"].size(), 5000u);
  EXPECT_EQ(j["window"], nlohmann::json::array({640, 480}));
  EXPECT_EQ(j["frames"][4999]["buttons"].size(), 4u);
  const std::string failed = (dir / "failed.json").string();
  {
    UiReportLog log;
    ASSERT_TRUE(log.open(failed));
    for (const UiFrameReport& f : frames) log.add(f);
  }
  EXPECT_FALSE(std::filesystem::exists(failed));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator{}), 1)
      << "no hidden file left beside it";
  std::filesystem::remove_all(dir);
}

TEST(ReadoutsLogTest, OneJsonLineWithEveryField) {
  ReadoutsFrame f;
  f.frame = 7;
  f.t_s = 1.25;
  f.scene = "panel.toml";
  f.probe = {ProbeState::kTouching, 0.0, 1.5, 0.25};
  f.force_n = 0.75;
  f.view_offset_mm = {0.0, -12.5, 0.0};
  f.view_turn_deg = 12.5;
  f.hand_mm = {1.0, 2.0, 3.0};
  f.proxy_mm = {1.0, 2.0, 4.5};
  f.button = 2;
  f.button_depth_mm = 2.9;
  f.button_travel_mm = 3.0;
  f.flags = std::vector<std::string>{"light"};
  f.keys = 3;
  f.haptic_hz = 999.5;
  f.jitter_p99_us = 12.25;
  f.dent_mm = 2.5;
  f.pointer_px = glm::dvec2(256.5, 100.0);
  f.shadow_px = glm::dvec2(255.0, 102.25);
  f.surface_scale = 0.5;
  f.view_moved = true;
  const std::string line = readouts_json_line(f);
  EXPECT_EQ(line,
            "{\"frame\": 7, \"t_s\": 1.25, \"scene\": \"panel.toml\", \"state\": \"touching\", \"distance_mm\": 0, "
            "\"pressed_mm\": 1.5, \"held_mm\": 0.25, \"penetration_mm\": 0, \"buried_mm\": 0, \"contact\": true, \"force_n\": 0.75, "
            "\"view_offset_mm\": [0, -12.5, 0], \"view_turn_deg\": 12.5, \"hand_mm\": [1, 2, 3], \"proxy_mm\": [1, 2, 4.5], "
            "\"button\": {\"index\": 2, \"depth_mm\": 2.9, \"travel_mm\": 3}, \"flags\": [\"light\"], \"keys\": 3, "
            "\"haptic_hz\": 999.5, \"jitter_p99_us\": 12.25, \"dent_mm\": 2.5, \"pointer_px\": [256.5, 100], "
            "\"shadow_px\": [255, 102.25], \"surface_scale\": 0.5, \"view_moved\": true}");
  ReadoutsFrame out;  // out of reach: distance null, no button, a scene without flags
  const std::string far = readouts_json_line(out);
  EXPECT_NE(far.find("\"state\": \"out of reach\", \"distance_mm\": null"), std::string::npos) << far;
  EXPECT_NE(far.find("\"button\": null, \"flags\": null"), std::string::npos) << far;
  EXPECT_NE(far.find("\"dent_mm\": null, \"pointer_px\": null, \"shadow_px\": null, \"surface_scale\": 1, "
                     "\"view_moved\": false}"),
            std::string::npos)
      << far;  // no deformable surface, no pointer in the window, no shadow, a whole still frame
}

constexpr const char* kSphereOnPlane =
    "[probe]\nradius_mm = 8.0\n[materials.m]\nlambda_min = 0.5\n"
    "[[surfaces]]\ntype = \"plane\"\nmaterial = \"m\"\n"
    "[[surfaces]]\ntype = \"sphere\"\ncenter = [0.0, 0.0, 0.0]\nradius_mm = 20.0\nmaterial = \"m\"\n";

// A sphere of radius 20 sticking out of the plane z = 0: over its top the lowered probe (R = 8)
// rests at centre height 28, lift 20; 12 mm off its axis at sqrt(28^2 - 12^2); beside it, on the
// plane (lift 0). Tolerance 0.02 mm: the lowering stops within touch_epsilon (0.01 mm) of contact.
TEST(FreeHeightTest, LiftIsTheSurfaceUnderThePointer) {
  FreeHeight floor;
  const glm::dvec3 n(0.0, 0.0, 1.0);
  EXPECT_EQ(floor.lift_mm({0.0, 0.0, 0.0}, n, 8.0), 0.0) << "no scene: the plane";
  floor.set_scene(felt(kSphereOnPlane));
  floor.set_top_mm(200.0);
  EXPECT_NEAR(floor.lift_mm({0.0, 0.0, 0.0}, n, 8.0), 20.0, 0.02);
  EXPECT_NEAR(floor.lift_mm({12.0, 0.0, 0.0}, n, 8.0), std::sqrt(28.0 * 28.0 - 144.0) - 8.0, 0.02);
  EXPECT_NEAR(floor.lift_mm({60.0, 0.0, 0.0}, n, 8.0), 0.0, 0.02);
  // The workspace moved 60 mm along x ([navigation]): its origin is now beside the sphere.
  floor.set_pose(glm::dmat3(1.0), {60.0, 0.0, 0.0});
  EXPECT_NEAR(floor.lift_mm({0.0, 0.0, 0.0}, n, 8.0), 0.0, 0.02);
  EXPECT_NEAR(floor.lift_mm({-60.0, 0.0, 0.0}, n, 8.0), 20.0, 0.02);
}

// The proxy's overlap with the geometry: free above the sphere, touching at R, 3 mm in (its
// centre 3 mm under the top: R - 5). Tolerance 1e-9: closed-form sphere distances.
TEST(FreeHeightTest, BuriedIsTheProbesOverlapWithTheGeometry) {
  const auto scene = felt(kSphereOnPlane);
  EXPECT_EQ(buried_mm(*scene, {0.0, 0.0, 40.0}), 0.0);
  EXPECT_NEAR(buried_mm(*scene, {0.0, 0.0, 28.0}), 0.0, 1e-9);
  EXPECT_NEAR(buried_mm(*scene, {0.0, 0.0, 25.0}), 3.0, 1e-9);
}

// Nothing under the pointer (a plane far below the reach): the mapping's plane, lift 0. A
// surface below the plane within reach: a negative lift, the probe goes down to it.
TEST(FreeHeightTest, NothingUnderThePointerIsThePlane) {
  FreeHeight floor;
  floor.set_top_mm(100.0);
  floor.set_scene(felt("[materials.m]\nlambda_min = 0.5\n[[surfaces]]\ntype = \"plane\"\ncenter = [0.0, 0.0, -1000.0]\n"
                       "material = \"m\"\n"));
  EXPECT_EQ(floor.lift_mm({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 8.0), 0.0);
  floor.set_scene(felt("[materials.m]\nlambda_min = 0.5\n[[surfaces]]\ntype = \"plane\"\ncenter = [0.0, 0.0, -30.0]\n"
                       "material = \"m\"\n"));
  EXPECT_NEAR(floor.lift_mm({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 8.0), -30.0, 0.02);
}

// Over a flush button the probe rests on its face, not in the pocket behind it (hovering must not
// press it): buttons_demo's slab top at z = 0, the button's pocket 4.5 mm deep.
TEST(FreeHeightTest, AButtonsFaceIsSolidForHovering) {
  FreeHeight floor;
  floor.set_top_mm(200.0);
  floor.set_scene(felt(
      "[probe]\nradius_mm = 8.0\n[materials.m]\nlambda_min = 0.5\n"
      "[[surfaces]]\ntype = \"box\"\ncenter = [0.0, 0.0, -5.0]\nsize_mm = [160.0, 100.0, 10.0]\nmaterial = \"m\"\n"
      "[[buttons]]\ncenter = [-25.0, 0.0, 0.0]\nsize_mm = [30.0, 30.0]\nstiffness_n_per_mm = 0.2\ntravel_mm = 3.0\n"
      "action = \"flag:light\"\n"));
  EXPECT_NEAR(floor.lift_mm({-25.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 8.0), 0.0, 0.02);
  EXPECT_NEAR(floor.lift_mm({25.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 8.0), 0.0, 0.02);
}

}  // namespace
}  // namespace ps
