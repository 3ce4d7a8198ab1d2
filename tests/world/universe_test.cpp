// The Virtual Universe's worlds (scenes/universe) as the haptic side sees them, against closed
// forms: Field's force is the softened Coulomb sum of its charges and has a findable weak spot;
// Weight's ball bounces back with its restitution; every world has a button back to the panel,
// and the panel's four buttons lead to the four worlds. No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "render/world_markers.h"
#include "scene/scene_io.h"
#include "world/haptic_scene.h"

namespace ps::world {
namespace {

std::string universe(const std::string& name) { return std::string(PS_SOURCE_DIR) + "/scenes/universe/" + name; }

// The force at three points equals the sum over the file's charges of q d / (|d|^2 + s^2)^1.5
// (1e-12 relative: the same double arithmetic in another order); a grid search (0.25 mm, at the
// charges' height, away from the charges themselves where the softened law is 0 by symmetry)
// finds a point where the pushes and the pull cancel to under 1 % of the force nearby.
TEST(UniverseTest, FieldIsTheCoulombSumWithAWeakSpot) {
  auto scene = load_scene(universe("field.toml"));
  ASSERT_TRUE(scene) << scene.error().message;
  auto hs = HapticScene::build(scene.value());
  ASSERT_TRUE(hs) << hs.error().message;
  auto expect = [&](const glm::dvec3& p) {
    glm::dvec3 f(0.0);
    for (const Field& c : scene->fields) {
      const glm::dvec3 d = p - c.position;
      f += c.charge_n_mm2 * d / std::pow(glm::dot(d, d) + c.softening_mm * c.softening_mm, 1.5);
    }
    return f;
  };
  for (const glm::dvec3 p : {glm::dvec3(0, -30, 20), glm::dvec3(-20, 10, 25), glm::dvec3(45, 30, 15)}) {
    const glm::dvec3 got = hs->fields().force_n(p, glm::dvec3(0.0), 0.0), want = expect(p);
    EXPECT_GT(glm::length(want), 0.01);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-12 * glm::length(want)) << i;
  }
  double weakest = std::numeric_limits<double>::infinity();
  glm::dvec3 at(0.0);
  for (double x = -60.0; x <= 60.0; x += 0.25)
    for (double y = -40.0; y <= 60.0; y += 0.25) {
      const glm::dvec3 p(x, y, 20.0);
      bool near_charge = false;
      for (const Field& c : scene->fields) near_charge = near_charge || glm::length(p - c.position) < 8.0;
      if (near_charge) continue;
      const double f = glm::length(hs->fields().force_n(p, glm::dvec3(0.0), 0.0));
      if (f < weakest) weakest = f;
      if (f == weakest) at = p;
    }
  const double nearby = glm::length(hs->fields().force_n(at + glm::dvec3(10, 0, 0), glm::dvec3(0.0), 0.0));
  EXPECT_LT(weakest, 0.01 * nearby) << "weak spot at " << at.x << ", " << at.y;
}

// Weight, through the loop: the hand lowered so the ball reaches the floor. Just after its first
// impact the ball rises at e x the impact speed (e: the file's restitution), measured from its
// published positions one tick apart (5 %: that tick's gravity and band pull, 1 ms of ~20 m/s^2
// against ~400 mm/s). (The second impact need not be slower: the band stores and gives back
// energy between bounces.)
TEST(UniverseTest, WeightsBallBouncesWithItsRestitution) {
  auto scene = load_scene(universe("weight.toml"));
  ASSERT_TRUE(scene) << scene.error().message;
  auto hs = HapticScene::build(scene.value());
  ASSERT_TRUE(hs) << hs.error().message;
  ASSERT_EQ(hs->bodies().size(), 1u);
  const double e = hs->bodies()[0].restitution;
  LogDevice device({{0.0, {0, 0, 70}, 0, true}, {0.3, {0, 0, 45}, 0, true}, {3.0, {0, 0, 45}, 0, true}}, true, "lower");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &hs.value());
  std::vector<HapticEvent> impacts;
  double rebound_mm_s = 0.0;
  for (int i = 0; i < 2500 && impacts.empty(); ++i) {
    loop.run_ticks(1);
    const std::size_t before = impacts.size();
    loop.events().drain([&](const HapticEvent& ev) {
      if (ev.kind == EventKind::body_impact) impacts.push_back(ev);
    });
    if (before == 0 && impacts.size() == 1) {
      const double z0 = loop.state().read().body_mm[0].z;
      loop.run_ticks(1);
      rebound_mm_s = (loop.state().read().body_mm[0].z - z0) / 1e-3;
    }
  }
  ASSERT_GE(impacts.size(), 1u) << "the ball should reach the floor within 2.5 s";
  EXPECT_GT(impacts[0].value, 100.0);  // a real fall, not resting contact
  EXPECT_NEAR(rebound_mm_s, e * impacts[0].value, 0.05 * e * impacts[0].value);
}

// Illusion: a path over the felt sphere's top along x is drawn as a path over the ellipsoid
// that is longer by the stretch factor (1e-9 relative: the map is linear there); far from the
// object the drawn probe is where it is felt.
TEST(UniverseTest, IllusionDrawsTheProbeStretchedNearTheObject) {
  auto scene = load_scene(universe("illusion.toml"));
  ASSERT_TRUE(scene) << scene.error().message;
  const Surface& sphere = scene->surfaces[0];
  ASSERT_EQ(sphere.type, SurfaceType::kSphere);
  const double s = sphere.visual_stretch.x, r = sphere.radius_mm + scene->probe.radius_mm;
  ASSERT_GT(s, 1.0);
  double felt = 0.0, drawn = 0.0;
  glm::dvec3 last_f(0.0), last_d(0.0);
  for (int i = 0; i <= 180; ++i) {  // over the top, in the x-z plane, the probe on the sphere
    const double a = M_PI * i / 180.0;
    const glm::dvec3 f = sphere.center + r * glm::dvec3(std::cos(a), 0.0, std::sin(a));
    const glm::dvec3 d = visual_position(scene.value(), f);
    if (i > 0) {
      felt += glm::length(f - last_f);
      drawn += glm::length(d - last_d);
    }
    EXPECT_NEAR(d.x - sphere.center.x, s * (f.x - sphere.center.x), 1e-9);
    last_f = f;
    last_d = d;
  }
  // Along x the drawn path covers s times the felt one; over the top, the arc of the ellipsoid.
  EXPECT_NEAR(glm::length(last_d - visual_position(scene.value(), sphere.center + glm::dvec3(r, 0, 0))),
              s * 2.0 * r, 1e-9);
  EXPECT_GT(drawn, felt * 1.2);
  const glm::dvec3 far = sphere.center + glm::dvec3(0, -200, 0);
  EXPECT_EQ(visual_position(scene.value(), far), far);
}

// The panel's four buttons lead to the four worlds, with pictures; every world has a button
// back to the panel.
TEST(UniverseTest, PanelLeadsToEveryWorldAndEachWorldBack) {
  auto panel = load_scene(universe("panel.toml"));
  ASSERT_TRUE(panel) << panel.error().message;
  ASSERT_EQ(panel->buttons.size(), 4u);
  std::vector<std::string> worlds;
  for (const Button& b : panel->buttons) {
    EXPECT_TRUE(b.picture);
    EXPECT_EQ(b.action_kind, ButtonActionKind::kScene);
    worlds.push_back(std::filesystem::path(b.action_target).filename().string());
  }
  EXPECT_EQ(worlds, (std::vector<std::string>{"illusion.toml", "weight.toml", "field.toml", "poly.toml"}));
  for (const std::string& w : worlds) {
    auto world = load_scene(universe(w));
    ASSERT_TRUE(world) << world.error().message;
    bool back = false;
    for (const Button& b : world->buttons)
      back = back || std::filesystem::path(b.action_target).filename() == "panel.toml";
    EXPECT_TRUE(back) << w << " has no button back to the panel";
  }
}

// Field's box (A Virtual Universe §5), through the loop on
// tests/haptics/data/universe_field_navigate.traj: 10 mm past the +x wall the view travels +x at 15
// x 10 = 150 mm/s (2 %: the Kalman filter takes a few ms to reach the held position), the wall
// pushes back with 0.5 N/mm x 10 mm, the hand's world position is its workspace position plus the
// view's offset, and back inside the box the view stays where it went. Pushed 30 mm past, the speed
// stops at max_speed_mm_s.
TEST(UniverseTest, FieldsBoxMovesTheViewWhileTheHandPushesAWall) {
  // The box universe_field_navigate.traj was written for (field.toml's is narrower now, so that
  // a mouse reaches its side walls: UniverseMouseGLTest).
  auto scene = load_scene(universe("field.toml"), {"navigation.box_size_mm=[130,100,60]"});
  ASSERT_TRUE(scene) << scene.error().message;
  const Navigation& nav = scene->navigation;
  ASSERT_TRUE(nav.enabled);
  ASSERT_EQ(nav.box_center.x + 0.5 * nav.box_size_mm.x, 65.0);
  auto hs = HapticScene::build(scene.value());
  ASSERT_TRUE(hs) << hs.error().message;
  auto log = load_sample_log(std::string(PS_SOURCE_DIR) + "/tests/haptics/data/universe_field_navigate.traj");
  ASSERT_TRUE(log) << log.error().message;
  LogDevice device(log.value(), true, "trajectory");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &hs.value());
  auto at = [&](double t) {
    while (loop.state().read().time_s < t - 1e-9) loop.run_ticks(1);
    return loop.state().read();
  };
  EXPECT_EQ(at(0.2).view_offset_mm, glm::dvec3(0.0));
  const HapticState a = at(0.4), b = at(1.3);
  EXPECT_NEAR((b.view_offset_mm.x - a.view_offset_mm.x) / 0.9, 150.0, 3.0) << b.view_offset_mm.x << " " << b.field_force_n.x;
  EXPECT_EQ(b.view_offset_mm.y, 0.0);
  EXPECT_EQ(b.view_offset_mm.z, 0.0);
  EXPECT_NEAR(b.field_force_n.x, -0.5 * 10.0, 0.1);
  EXPECT_NEAR(b.position_mm.x, 75.0 + b.view_offset_mm.x, 0.05);
  const HapticState c = at(1.5), d = at(2.0);
  EXPECT_GT(c.view_offset_mm.x, 140.0);
  EXPECT_EQ(c.view_offset_mm, d.view_offset_mm) << "inside the box the view stays";
  EXPECT_NEAR(d.position_mm.x, d.view_offset_mm.x, 0.05);

  LogDevice hard({{0.0, {95, 0, 20}, 0, true}, {1.0, {95, 0, 20}, 0, true}}, true, "hard");
  FakeClock clock2;
  HapticLoop loop2(hard, clock2, HapticLoopParams{}, &hs.value());
  loop2.run_ticks(501);
  const double x0 = loop2.state().read().view_offset_mm.x;
  loop2.run_ticks(400);
  EXPECT_NEAR((loop2.state().read().view_offset_mm.x - x0) / 0.4, nav.max_speed_mm_s, 1e-6);
}

// Field pushed 45 mm past its +x wall (a mouse at the window's edge), then 400 ticks held (run's
// pointer outside the window): the view runs at max_speed_mm_s, then stays where it was while
// the wall still pushes the hand back.
TEST(UniverseTest, FieldsViewHoldsWhileNavigationIsHeld) {
  auto field = load_scene(universe("field.toml"));
  ASSERT_TRUE(field) << field.error().message;
  auto hf = HapticScene::build(field.value());
  ASSERT_TRUE(hf) << hf.error().message;
  LogDevice hard({{0.0, {95, 0, 20}, 0, true}, {10.0, {95, 0, 20}, 0, true}}, true, "hard");
  FakeClock clock;
  HapticLoop loop(hard, clock, HapticLoopParams{}, &hf.value());
  loop.run_ticks(500);
  const glm::dvec3 x0 = loop.state().read().view_offset_mm;
  ASSERT_GT(x0.x, 50.0);
  loop.hold_navigation(true);
  loop.run_ticks(400);
  EXPECT_EQ(loop.state().read().view_offset_mm, x0) << "held: the view stays";
  EXPECT_LT(loop.state().read().field_force_n.x, -10.0) << "held: the wall still pushes";
  loop.hold_navigation(false);
  loop.run_ticks(100);
  EXPECT_GT(loop.state().read().view_offset_mm.x, x0.x + 20.0) << "released: the push moves it again";
}

// Field's back button lies beyond the box's -x and +y walls: a hand over it meets neither wall
// nor travel, so the proxy gets there, the view stays, and pressing fires the switch. Without it
// the walls held the proxy 25 mm short and the view flew away (-1.3 m).
TEST(UniverseTest, FieldsBackButtonIsReachedWithoutFlyingTheView) {
  auto field = load_scene(universe("field.toml"));
  ASSERT_TRUE(field) << field.error().message;
  auto hf = HapticScene::build(field.value());
  ASSERT_TRUE(hf) << hf.error().message;
  const glm::dvec3 button = hf.value().button_shapes().at(0).center;
  LogDevice hand({{0.0, button + glm::dvec3(0, 0, 20), 0, true}, {1.0, button + glm::dvec3(0, 0, 20), 0, true},
                  {2.0, button + glm::dvec3(0, 0, -4), 0, true}, {10.0, button + glm::dvec3(0, 0, -4), 0, true}},
                 true, "hand");
  FakeClock clock;
  HapticLoop loop(hand, clock, HapticLoopParams{}, &hf.value());
  loop.run_ticks(1000);
  const HapticState over = loop.state().read();
  EXPECT_EQ(over.view_offset_mm, glm::dvec3(0.0)) << "over the button: the view stays";
  EXPECT_LT(glm::length(glm::dvec2(over.proxy_mm - button)), 1.0) << "the proxy is over the button";
  bool fired = false;
  for (int i = 0; i < 15; ++i) {
    loop.run_ticks(100);
    loop.events().drain([&](const HapticEvent& e) { fired = fired || e.kind == EventKind::button_fired; });
  }
  EXPECT_TRUE(fired) << "pressed 4 mm below the face: the button fires";
  EXPECT_EQ(loop.state().read().view_offset_mm, glm::dvec3(0.0));
}

// Field's view stays in Field: after it travelled, a switch to the panel (no [navigation], the
// scene its button and Backspace go back to) publishes the panel's own view, and Home there
// keeps it (the leak drew the panel 90 mm off, its shadow ~390 px from the pointer).
TEST(UniverseTest, FieldsViewDoesNotLeakIntoThePanel) {
  auto field = load_scene(universe("field.toml"));
  auto panel = load_scene(universe("panel.toml"));
  ASSERT_TRUE(field && panel);
  auto hf = HapticScene::build(field.value());
  auto hp = HapticScene::build(panel.value());
  ASSERT_TRUE(hf && hp);
  LogDevice hard({{0.0, {95, 0, 20}, 0, true}, {10.0, {95, 0, 20}, 0, true}}, true, "hard");
  FakeClock clock;
  HapticLoop loop(hard, clock, HapticLoopParams{}, &hf.value());
  loop.run_ticks(500);
  ASSERT_GT(loop.state().read().view_offset_mm.x, 50.0);
  loop.replace_scene(std::make_shared<const HapticScene>(std::move(hp.value())), "panel.toml", glm::dvec3(0, 0, 20));
  loop.run_ticks(10);
  EXPECT_EQ(loop.state().read().view_offset_mm, glm::dvec3(0.0)) << "Field's view leaked into the panel";
  EXPECT_EQ(loop.state().read().view_rotation, glm::dmat3(1.0));
  loop.request_view_home();
  loop.run_ticks(10);
  EXPECT_EQ(loop.state().read().view_offset_mm, glm::dvec3(0.0));
}

}  // namespace
}  // namespace ps::world

namespace ps {
namespace {

// The rolling manifold's rubber band (docs/fourd.md): from the probe to the nearest point of the
// camera's line of sight through the screen centre, so perpendicular to that line (1e-12 mm:
// a handful of double products of ~100 mm values).
TEST(RubberBandMarkerTest, RunsFromTheProbeSquarelyToTheLineOfSight) {
  Camera cam;
  cam.position = {10.0, -100.0, 120.0};
  cam.target = {3.0, 4.0, -2.0};
  const glm::dvec3 axis = glm::normalize(cam.position - cam.target);
  for (const glm::dvec3 probe : {glm::dvec3(10.0, 5.0, 3.0), glm::dvec3(-40.0, 7.0, 12.0), cam.target + 30.0 * axis}) {
    const WorldMarker m = rubber_band_marker(probe, cam);
    EXPECT_EQ(m.a, probe);
    EXPECT_LT(glm::length(glm::cross(m.b - cam.target, axis)), 1e-12) << "b on the line of sight";
    EXPECT_NEAR(glm::dot(m.a - m.b, axis), 0.0, 1e-12) << "square to it";
  }
  EXPECT_LT(glm::length(rubber_band_marker(cam.target + 30.0 * axis, cam).b - (cam.target + 30.0 * axis)), 1e-12)
      << "on the line: no band";
}

}  // namespace
}  // namespace ps
