// A probe held flush on a button is pressed by PageDown (issue 42): on Poly's back button
// (scenes/universe/poly.toml) through the haptic loop, the hand as `run`'s mouse moves it (a
// height step is a 0.5 mm jump between two readings). Held flush, the button never fires while the
// hand keeps its depth; each PageDown after that pushes on, and the button fires exactly once
// however long the hand stays down. Before, 11 PageDowns on a probe resting flush did nothing: it
// had come in sideways, so the button held it and waited for it to leave. After a scene switch it
// still waits (the PageDowns may be the ones that pressed the old world's button). No GL.
#include <gtest/gtest.h>

#include <vector>

#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "scene/scene_io.h"
#include "world/buttons.h"
#include "world/haptic_scene.h"

namespace ps::world {
namespace {

// Poly's back button: face centre (-45, -25, -30), 24 mm square, flush with the floor's top
// (z = -30); the probe's radius is 6 mm, so a hand centred at z = -24 rests on the face.
constexpr double kFaceZ = -30.0, kRadius = 6.0;
constexpr glm::dvec3 kOnButton{-45.0, -25.0, 0.0};

HapticScene poly_haptics() {
  auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/universe/poly.toml");
  EXPECT_TRUE(scene) << scene.error().message;
  auto hs = HapticScene::build(scene.value());
  EXPECT_TRUE(hs) << hs.error().message;
  return std::move(hs.value());
}

glm::dvec3 hand_at(double x, double depth_mm) { return {x, kOnButton.y, kFaceZ + kRadius - depth_mm}; }

// From `t0`, `presses` PageDowns 0.15 s apart from hand depth `depth_mm` over the button (each a
// jump within 1 ms, as between two mouse readings), then held until `until`.
void page_downs(std::vector<DeviceSample>& s, double t0, double depth_mm, int presses, double until) {
  for (int k = 1; k <= presses; ++k) {
    const double t = t0 + 0.15 * k;
    s.push_back({t, hand_at(kOnButton.x, depth_mm + 0.5 * (k - 1)), 0, true});
    s.push_back({t + 0.001, hand_at(kOnButton.x, depth_mm + 0.5 * k), 0, true});
  }
  s.push_back({until, hand_at(kOnButton.x, depth_mm + 0.5 * presses), 0, true});
}

struct HeldRun {
  std::vector<double> fired_s;   // the button_fired events' times
  bool pressed_while_held = false;  // the button counted as pressed before the first PageDown
  double deepest_held_mm = 0.0;  // the proxy below the face before the first PageDown
};

// Runs the loop to the device's end; `switch_at` >= 0: the loop starts without a scene and Poly is
// handed over at that time with the hand placed where the device is, as `run` switches.
HeldRun run_loop(LogDevice& device, double first_press_s, double switch_at = -1.0) {
  const HapticScene poly = poly_haptics();
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, switch_at < 0.0 ? &poly : nullptr);
  HeldRun out;
  const int ticks = static_cast<int>(device.duration_s() * 1000.0);
  for (int i = 0; i < ticks; ++i) {
    if (i == static_cast<int>(switch_at * 1000.0))
      loop.replace_scene(std::shared_ptr<const HapticScene>(&poly, [](const HapticScene*) {}), "poly.toml",
                         device.read(switch_at).position_mm);
    loop.run_ticks(1);
    const HapticState st = loop.state().read();
    if (st.time_s > switch_at + 0.1 && st.time_s < first_press_s) {
      out.deepest_held_mm = std::max(out.deepest_held_mm, kFaceZ + kRadius - st.proxy_mm.z);
      out.pressed_while_held = out.pressed_while_held || st.button_pressed >= 0;
    }
    loop.events().drain([&](const HapticEvent& e) {
      if (e.kind == EventKind::button_fired) out.fired_s.push_back(e.time_s);
    });
  }
  return out;
}

// On the floor beside the button, pressed 1 mm in (one PageDown below touching), the pointer
// slides onto the button: held flush. Then 11 PageDowns (the report's count): the proxy follows
// the hand in and the button fires once, at the 7th (the hand 4.5 mm in, past the 4.2 mm its 3 mm
// travel needs through the coupling: 3 x (0.5 + 0.2) / 0.5); the 4 after it and the 1.4 s held
// down fire nothing more.
TEST(ButtonHeldTest, AProbeSlidOntoPolysButtonIsPressedByPageDownOnce) {
  std::vector<DeviceSample> s = {{0.0, hand_at(-75.0, 1.0), 0, true}, {1.0, hand_at(kOnButton.x, 1.0), 0, true}};
  page_downs(s, 2.0, 1.0, 11, 5.0);
  LogDevice device(s, true, "slide, then PageDown");
  const HeldRun r = run_loop(device, 2.1);
  EXPECT_FALSE(r.pressed_while_held) << "held flush, not pressed, while the hand keeps its depth";
  // Held flush: kHeldShare (2 %) of the hand's 1 mm, plus the god-object's 1e-3 mm epsilon.
  EXPECT_LT(r.deepest_held_mm, 0.03);
  ASSERT_EQ(r.fired_s.size(), 1u) << "11 PageDowns on a probe held flush";
  EXPECT_GT(r.fired_s[0], 2.0 + 0.15 * 7) << "not before the 7th press";
  EXPECT_LT(r.fired_s[0], 2.0 + 0.15 * 8) << "at the 7th press";
}

// The scene switched to with the pointer over the button: the hand is placed 1 mm over the face
// (the hover height) in the switch's tick, and the button waits for the hand to leave it sideways.
// 14 PageDowns (a person still pressing for the button that switched) take the probe in, held
// flush, and fire nothing: a push on from the hold counts only outside a switch. Lifted, moved
// off the button and back, the next 11 PageDowns press it from the front: once, at the 11th.
TEST(ButtonHeldTest, AfterASwitchPageDownPressesNothingUntilThePointerHasLeftTheButton) {
  std::vector<DeviceSample> s = {{0.0, hand_at(kOnButton.x, -1.0), 0, true}};
  page_downs(s, 1.0, -1.0, 14, 3.5);
  s.push_back({3.6, hand_at(kOnButton.x, -1.0), 0, true});  // PageUp back to the hover height
  s.push_back({4.0, hand_at(kOnButton.x, -1.0), 0, true});
  s.push_back({4.5, hand_at(-75.0, -1.0), 0, true});  // off the button sideways, over the floor
  s.push_back({5.0, hand_at(kOnButton.x, -1.0), 0, true});
  page_downs(s, 5.5, -1.0, 11, 8.0);
  LogDevice device(s, true, "switched to, PageDown, away and back, PageDown");
  const HeldRun r = run_loop(device, 1.1, 0.5);
  EXPECT_FALSE(r.pressed_while_held);
  ASSERT_EQ(r.fired_s.size(), 1u) << "none for the 14 after the switch, one for the 11 after leaving";
  EXPECT_GT(r.fired_s[0], 5.5 + 0.15 * 11) << "not before the 11th press after leaving";
  EXPECT_LT(r.fired_s[0], 5.5 + 0.15 * 12) << "at the 11th press";
}

}  // namespace
}  // namespace ps::world
