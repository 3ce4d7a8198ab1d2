// [[buttons]] on the haptic side (A Virtual Universe §2): the button's spring and its firing
// against the closed form, the hole and pocket it makes in its face for the god-object, and through
// the haptic loop (the drawn proxy resists by the coupling, flags toggle, events). No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "devices/pointer_map.h"
#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "scene/scene_io.h"
#include "world/buttons.h"
#include "world/god_object.h"
#include "world/haptic_scene.h"
#include "world_test_util.h"

namespace ps::world {
namespace {

constexpr double kR = 8.0;  // probe radius

Button flush_button(glm::dvec3 center = glm::dvec3(0.0), std::string action = "flag:light") {
  Button b;
  b.center = center;
  b.size_mm = {30.0, 20.0};
  b.stiffness_n_per_mm = 0.2;
  b.travel_mm = 3.0;
  b.action = action;
  b.action_kind = action.starts_with("scene:") ? ButtonActionKind::kScene : ButtonActionKind::kFlag;
  b.action_target = action.substr(action.find(':') + 1);
  return b;
}

// A floor plane (z = 0) with one button in it, as the scene parser lays it out: the button's
// plate appended to the surfaces, seen but not felt.
Scene floor_with_button(const Button& b) {
  Scene sc = test::scene_with(kR, {test::analytic(SurfaceType::kPlane)});
  sc.buttons = {b};
  if (b.action_kind == ButtonActionKind::kFlag) {
    sc.flags = {b.action_target};
    sc.buttons[0].flag = 0;
  }
  Surface plate = test::analytic(SurfaceType::kBox, b.center - glm::dvec3(0, 0, 0.25));
  plate.box_size_mm = {b.size_mm.x, b.size_mm.y, 1.0};
  plate.touchable = false;
  plate.button = 0;
  sc.surfaces.push_back(plate);
  return sc;
}

// Pressing straight down: below the travel the force is k depth along the normal and nothing
// fires; at the travel it fires once and the force stops; it fires again only after the probe
// has left the button. Pushing to just under the travel, any number of times, never fires.
TEST(ButtonSetTest, SpringUntilTheTravelThenFiresExactlyOnce) {
  const ButtonShape shape = ButtonShape::make(flush_button(), 5);
  ButtonSet set({shape}, kR);
  set.step({3.0, -2.0, kR + 2.0});  // hovering 2 mm over it: approached from the front
  auto press_to = [&](double depth_mm, int steps) {
    int fired = 0;
    for (int i = 0; i <= steps; ++i) {  // down, then back up to 2 mm above the face
      const double d = depth_mm * std::sin(M_PI * i / steps) - (i == steps ? 2.0 : 0.0);
      const ButtonStepResult r = set.step({3.0, -2.0, kR - d});
      fired += r.fired_count;
      const bool pressed_armed = d > 0.0 && d < 3.0 && set.armed(0);
      if (r.fired_count == 0 && pressed_armed) {
        EXPECT_NEAR(r.force_n.z, 0.2 * d, 1e-12) << i;
        EXPECT_EQ(r.pressed, 0);
        EXPECT_NEAR(r.depth_mm, d, 1e-12);
      } else if (d >= 3.0 || !set.armed(0)) {
        EXPECT_EQ(r.force_n, glm::dvec3(0.0)) << "no force once it gave way, step " << i;
      }
    }
    return fired;
  };
  for (int k = 0; k < 5; ++k) EXPECT_EQ(press_to(2.999, 200), 0) << "below the travel, press " << k;
  EXPECT_EQ(press_to(4.0, 200), 1);
  EXPECT_TRUE(set.armed(0));  // back out: re-armed
  EXPECT_EQ(press_to(4.0, 200), 1);
  // Beside the button nothing happens, however deep.
  const ButtonStepResult beside = set.step({20.0, 0.0, kR - 4.0});
  EXPECT_EQ(beside.fired_count, 0);
  EXPECT_EQ(beside.force_n, glm::dvec3(0.0));
}

// The button is a hole in its face: over it the god-object goes below the face, down to the
// pocket's bottom (travel x 1.5 below the face) and no further; beside it the face holds the
// proxy at R. Sliding sideways inside the pocket, the proxy stays within the rectangle.
TEST(ButtonGeometryTest, TheFaceGivesWayOnlyOverTheButtonDownToThePocket) {
  const Button b = flush_button();
  auto scene = HapticScene::build(floor_with_button(b));
  ASSERT_TRUE(scene);
  const double bottom = -kPocketDepthPerTravel * b.travel_mm;  // -4.5
  GodObject over(scene.value());
  over.reset({0, 0, 20});
  for (int i = 0; i <= 100; ++i) over.move({0, 0, 20 - 0.4 * i});  // the hand to z = -20
  EXPECT_NEAR(over.proxy().z, bottom + kR, 2e-3);  // resting on the pocket's bottom
  GodObject beside(scene.value());
  beside.reset({40, 0, 20});
  for (int i = 0; i <= 100; ++i) beside.move({40, 0, 20 - 0.4 * i});
  EXPECT_NEAR(beside.proxy().z, kR, 2e-3);
  // In the pocket, the hand sweeps sideways and down, far past the button's edge (x half 15,
  // y half 10). The proxy's sphere never cuts the holed face, measured on its own closed form:
  // over the button, the walls below the face (distance e to the rectangle's edge), the rim
  // above it (sqrt(e^2 + z^2)) and the bottom; beside it, the face itself (z). Tolerance: the
  // god-object's 0.002 mm, as for the other shapes. The pocket is shallower than the probe's
  // radius, so pushed sideways the ball rolls up over the rim and out, as a real one would.
  bool climbed_out = false;
  for (int i = 0; i <= 200; ++i) {
    over.move({0.5 * i, 0.25 * i, -1.0});
    const glm::dvec3 p = over.proxy();
    const bool is_over = std::abs(p.x) < 15.0 && std::abs(p.y) < 10.0;
    const double e = std::min(15.0 - std::abs(p.x), 10.0 - std::abs(p.y));
    const double clearance = is_over ? std::min(p.z > 0.0 ? std::hypot(e, p.z) : e, p.z - bottom) : p.z;
    ASSERT_GE(clearance, kR - 2e-3) << i;
    climbed_out = climbed_out || !is_over;
  }
  EXPECT_TRUE(climbed_out);
  // Closest point: from inside the pocket, the nearest wall or the bottom, with its normal
  // facing into the pocket; never the face's own points in the hole.
  const Contact c = scene->closest({13.0, 0.0, -1.0}, 100.0);
  ASSERT_TRUE(c.hit);
  EXPECT_NEAR(c.distance_mm, 2.0, 1e-12);
  EXPECT_NEAR(c.point.x, 15.0, 1e-12);
  EXPECT_NEAR(c.normal.x, -1.0, 1e-12);
  EXPECT_EQ(c.surface, 1);  // the plate: the button's material
  // Over the hole: the bottom (3 + 4.5 mm) when low, the rim (sqrt(10^2 + 10^2) < 10 + 4.5) high up.
  EXPECT_NEAR(scene->closest({0.0, 0.0, 3.0}, 100.0).distance_mm, 7.5, 1e-12);
  EXPECT_NEAR(scene->closest({0.0, 0.0, 10.0}, 100.0).distance_mm, std::sqrt(200.0), 1e-12);
  const Contact outside = scene->closest({40.0, 0.0, 3.0}, 100.0);
  EXPECT_NEAR(outside.distance_mm, 3.0, 1e-12);
  EXPECT_EQ(outside.surface, 0);
}

// Through the loop, a hand pressing the button with a mouse's coupling: the drawn proxy goes in
// by depth x k_c / (k_c + k_b) (the button resists); pressed to 2 mm of hand depth it never
// fires; pressed deeper it fires once (button_fired, then flag_toggled to 1), and a second press
// toggles the flag back. The replayed log of events is the same every run.
std::vector<HapticEvent> press_twice(double hand_depth_mm, HapticState* last, std::vector<double>* lag) {
  auto scene = HapticScene::build(floor_with_button(flush_button()));
  EXPECT_TRUE(scene);
  const double down = kR - hand_depth_mm;
  LogDevice device({{0.0, {2, 1, 20}, 0, true}, {1.0, {2, 1, down}, 0, true}, {2.0, {2, 1, down}, 0, true},
                    {3.0, {2, 1, 20}, 0, true}, {4.0, {2, 1, down}, 0, true}, {5.0, {2, 1, down}, 0, true},
                    {6.0, {2, 1, 20}, 0, true}},
                   true, "press");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &scene.value());
  std::vector<HapticEvent> events;
  for (int i = 0; i < 60; ++i) {
    loop.run_ticks(100);
    loop.events().drain([&](const HapticEvent& e) { events.push_back(e); });
    if (lag != nullptr && i == 15) {  // t = 1.6 s: the hand held 2 mm in
      const HapticState st = loop.state().read();
      lag->push_back(kR - st.proxy_mm.z);
    }
  }
  *last = loop.state().read();
  return events;
}

TEST(ButtonLoopTest, ResistsThroughTheCouplingThenFiresOncePerPress) {
  HapticState st;
  std::vector<double> lag;
  const std::vector<HapticEvent> shallow = press_twice(2.0, &st, &lag);
  for (const HapticEvent& e : shallow) EXPECT_NE(e.kind, EventKind::button_fired);
  ASSERT_EQ(lag.size(), 1u);
  // Fixed point of the coupling: p = x - k_b p / k_c, p = 2 x 0.5 / 0.7 (1e-6: converged).
  EXPECT_NEAR(lag[0], 2.0 * 0.5 / 0.7, 1e-6);
  EXPECT_EQ(st.flags, 0u);

  const std::vector<HapticEvent> deep = press_twice(6.0, &st, nullptr);
  std::vector<HapticEvent> fired, toggled;
  for (const HapticEvent& e : deep) {
    if (e.kind == EventKind::button_fired) fired.push_back(e);
    if (e.kind == EventKind::flag_toggled) toggled.push_back(e);
  }
  ASSERT_EQ(fired.size(), 2u);
  ASSERT_EQ(toggled.size(), 2u);
  EXPECT_EQ(fired[0].label_view(), "flag:light");
  EXPECT_EQ(toggled[0].label_view(), "light");
  EXPECT_EQ(toggled[0].value, 1.0);
  EXPECT_EQ(toggled[1].value, 0.0);
  EXPECT_EQ(toggled[0].tick, fired[0].tick);
  EXPECT_EQ(st.flags, 0u);
  // It fires when the proxy (not the hand) reaches the travel: the proxy is 3 mm in.
  EXPECT_NEAR(kR - fired[0].position_mm.z, 3.0, 0.05);
  // Deterministic: the same ticks every run.
  HapticState again;
  const std::vector<HapticEvent> repeat = press_twice(6.0, &again, nullptr);
  ASSERT_EQ(repeat.size(), deep.size());
  for (std::size_t i = 0; i < deep.size(); ++i) EXPECT_EQ(event_json(repeat[i]), event_json(deep[i])) << i;
}

// Sandia's push is along the button's normal: a probe that slides onto the button sideways with
// the hand pressed in (over the wall beside it, the proxy resting on the face) does not press it.
// The button holds it flush (a held button gives way by kHeldShare of the hand's depth) and never
// fires while the hand stays at the depth it slid in at; lifted clear of the face, the next push
// is a press and fires. (A push on from the hold is a press too: button_held_test.cpp.)
TEST(ButtonSetTest, ASlideAcrossTheFaceNeverFiresALiftAndPushDoes) {
  const ButtonShape shape = ButtonShape::make(flush_button(), 5);  // 30 x 20 mm around the origin
  ButtonSet set({shape}, kR, 0.5);
  int fired = 0;
  for (int i = 0; i <= 200; ++i) {  // from 40 mm left of it to its centre, on the face, hand 6 mm in
    const double x = -40.0 + 40.0 * i / 200.0;
    const double proxy_depth = x > -15.0 ? 6.0 * kHeldShare : 0.0;  // what the coupling leaves it
    const ButtonStepResult r = set.step({x, 0.0, kR - proxy_depth}, {x, 0.0, kR - 6.0});
    fired += r.fired_count;
    EXPECT_EQ(r.pressed, -1) << "a held button is not pressed, x " << x;
    if (x > -15.0) {
      // The hold's force, from the hand's depth: (1 - share) k_c x_hand (1e-12: arithmetic).
      EXPECT_NEAR(r.force_n.z, (1.0 - kHeldShare) * 0.5 * 6.0, 1e-12) << x;
      EXPECT_EQ(set.phase(0), ButtonPhase::kIdle);
    }
  }
  // Even the proxy at the full travel, not approached, the hand where it slid in: no firing.
  for (int i = 0; i < 50; ++i) fired += set.step({0.0, 0.0, kR - 3.5}, {0.0, 0.0, kR - 6.0}).fired_count;
  EXPECT_EQ(fired, 0);
  // Resting on the face is not clear of it; a quarter step above it is.
  set.step({0.0, 0.0, kR}, {0.0, 0.0, kR});
  EXPECT_EQ(set.phase(0), ButtonPhase::kIdle);
  set.step({0.0, 0.0, kR + kButtonClearMm}, {0.0, 0.0, kR + kButtonClearMm});
  EXPECT_EQ(set.phase(0), ButtonPhase::kReady);
  for (int i = 0; i <= 40; ++i) fired += set.step({0.0, 0.0, kR - 0.1 * i}).fired_count;  // down to 4 mm in
  EXPECT_EQ(fired, 1);
}

// A scene starts (at launch, after a button's or Backspace's switch) with every button not
// ready: a probe already in a button (the Backspace that left it sunk in the panel's Field
// button) cannot fire it in the first tick, nor later until it has left the button.
TEST(ButtonSetTest, NothingFiresUntilTheProbeHasLeftTheButtonAfterAStart) {
  const ButtonShape shape = ButtonShape::make(flush_button(), 5);
  for (const glm::dvec3 leave : {glm::dvec3(30.0, 0.0, kR - 1.0), glm::dvec3(0.0, 0.0, kR + 1.0)}) {
    ButtonSet set({shape}, kR, 0.5);  // as after a scene switch
    int fired = 0;
    for (int i = 0; i < 100; ++i) fired += set.step({0.0, 0.0, kR - 3.2}, {0.0, 0.0, kR - 5.0}).fired_count;
    EXPECT_EQ(fired, 0) << "sunk in it at the start";
    set.step(leave);  // sideways off it, or lifted 1 mm clear
    for (int i = 0; i <= 50; ++i) fired += set.step({0.0, 0.0, kR + 1.0 - 0.1 * i}).fired_count;  // then pushed from above
    EXPECT_EQ(fired, 1) << "one push after leaving it";
  }
  // Back from a world with the hand still deep: the new scene's proxy starts where the old one
  // was, high above the face, and falls to the hand. Not an approach: held, no firing (in `run`
  // this fired the button the probe came back over within 31 ms).
  ButtonSet set({shape}, kR, 0.5);
  int fired = 0;
  for (int i = 0; i <= 100; ++i) {
    const double proxy_z = std::max(kR - 3.2, kR + 15.0 - 0.5 * i);  // falling from 15 mm above
    fired += set.step({0.0, 0.0, proxy_z}, {0.0, 0.0, kR - 4.5}).fired_count;
  }
  EXPECT_EQ(fired, 0);
  // After a switch even proxy and hand both clear for a while (a hand still mapped through the
  // old scene's plane, then the new one's) do not ready it, nor a proxy that starts beside it
  // (where the old scene left it) and comes over it clear while the hand is deep: only the
  // hand leaving it sideways does: not even a push on from where it holds the probe (kHeldPushMm
  // counts only outside a switch), so PageDowns that go on after a switch press nothing there.
  ButtonSet switched({shape}, kR, 0.5, true);
  for (int i = 0; i < 50; ++i) fired += switched.step({0.0, 0.0, kR + 15.0}).fired_count;
  for (int i = 0; i <= 50; ++i) fired += switched.step({0.0, 0.0, kR + 1.0 - 0.1 * i}).fired_count;
  EXPECT_EQ(fired, 0) << "lifted, then pushed, without leaving it";
  ButtonSet teleported({shape}, kR, 0.5, true);
  for (int i = 0; i <= 100; ++i) {  // the proxy from 40 mm beside and 15 mm above onto the hand
    const double x = std::max(0.0, 40.0 - i), z = std::max(kR - 3.2, kR + 15.0 - 0.3 * i);
    fired += teleported.step({x, 0.0, z}, {0.0, 0.0, kR - 4.5}).fired_count;
  }
  EXPECT_EQ(fired, 0) << "a proxy arriving from the old scene's place";
  switched.step({30.0, 0.0, kR + 1.0});  // off it sideways
  for (int i = 0; i <= 50; ++i) fired += switched.step({0.0, 0.0, kR + 1.0 - 0.1 * i}).fired_count;
  EXPECT_EQ(fired, 1);
}

// The height control must reach the depth a button fires at: travel (k_c + k) / k_c.
TEST(ButtonSetTest, DeepestPressIsTheTravelThroughTheCoupling) {
  const ButtonShape shape = ButtonShape::make(flush_button(), 5);
  EXPECT_NEAR(deepest_press_mm({shape}, 0.5), 3.0 * 0.7 / 0.5, 1e-12);
  EXPECT_EQ(deepest_press_mm({}, 0.5), 0.0);
}

// The mouse's height steps (0.5 mm a PageDown from 1 mm above) reach a button's full travel once
// the range is sized by deepest_press_mm plus a step, as `run` sizes it: 11 presses for the
// panel's buttons (3 mm travel, 0.2 N/mm). With the fixed 4 mm range of before, the hand stopped
// at 4.0 mm, the proxy at 4.0 x 0.5 / 0.7 = 2.86 mm ("2.9 of 3.0 mm") and no press ever fired.
TEST(ButtonSetTest, PageDownReachesTheFullTravel) {
  const double coupling = HapticLoopParams{}.forces.coupling_n_per_mm;
  const ButtonShape shape = ButtonShape::make(flush_button(), 5);
  const double share = coupling / (coupling + shape.stiffness_n_per_mm);  // the proxy's part of the hand's depth
  auto presses_to_fire = [&](HeightControl h) {
    for (int presses = 1; presses <= 60; ++presses) {
      h.step(-1);
      if (-h.mm() * share >= shape.travel_mm) return presses;
    }
    return -1;  // never
  };
  const HeightParams params;
  EXPECT_EQ(presses_to_fire(HeightControl(params)), -1) << "the fixed range stops short";
  HeightControl sized(params);
  sized.reach_depth(deepest_press_mm({shape}, coupling) + params.step_mm);
  EXPECT_EQ(presses_to_fire(sized), 11);
}

// On the control panel through the loop: the hand pressed 4.5 mm into the wall beside the
// Weight button slides across it (a mouse moving with PageDown held down): nothing fires, the
// proxy stays within 0.1 mm of the face (held flush). Lifted 2 mm clear and pushed in again,
// it fires exactly once.
TEST(ButtonLoopTest, OnThePanelASlideDoesNotFireAPushDoes) {
  auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/universe/panel.toml");
  ASSERT_TRUE(scene) << scene.error().message;
  auto hs = HapticScene::build(scene.value());
  ASSERT_TRUE(hs) << hs.error().message;
  const double r = scene->probe.radius_mm, in = r - 4.5, up = r + 2.0;
  // The Weight button: centre (40, 35), 56 mm wide; the wall's face at z = 0.
  LogDevice device({{0.0, {90, 35, up}, 0, true}, {0.3, {90, 35, in}, 0, true}, {0.5, {90, 35, in}, 0, true},
                    {1.5, {40, 35, in}, 0, true}, {2.0, {40, 35, in}, 0, true}, {2.3, {40, 35, up}, 0, true},
                    {2.6, {40, 35, up}, 0, true}, {3.0, {40, 35, in}, 0, true}, {3.5, {40, 35, in}, 0, true}},
                   true, "slide then push");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &hs.value());
  int fired_sliding = 0, fired_pushing = 0;
  double deepest_held = 0.0;
  for (int i = 0; i < 3500; ++i) {
    loop.run_ticks(1);
    const HapticState st = loop.state().read();
    if (st.time_s > 1.0 && st.time_s < 2.0) deepest_held = std::max(deepest_held, r - st.proxy_mm.z);
    loop.events().drain([&](const HapticEvent& e) {
      if (e.kind == EventKind::button_fired) ++(e.time_s < 2.3 ? fired_sliding : fired_pushing);
    });
  }
  EXPECT_EQ(fired_sliding, 0);
  EXPECT_LT(deepest_held, 0.1) << "held flush: 2 % of the hand's 4.5 mm";
  EXPECT_EQ(fired_pushing, 1);
}

}  // namespace
}  // namespace ps::world
