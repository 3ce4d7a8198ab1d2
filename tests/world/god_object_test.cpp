// The god-object proxy driven along scripted device trajectories into and along analytic
// shapes and meshes (checked against closed-form signed distances and brute-force mesh
// distances), force shading across mesh edges, hidden and untouchable surfaces, and the haptic
// loop on a haptic scene.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>

#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "scene/mesh.h"
#include "world/god_object.h"
#include "world_test_util.h"

namespace ps::world {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The proxy may end a move up to contact_epsilon_mm (1e-3) inside the R-offset surface (a
// pushed-out slide is accepted down to that gap); twice that covers double rounding.
constexpr double kBehindTolMm = 2e-3;

// Down from above onto the top (z = top) to `depth` below it, then along X and back along Y.
std::vector<glm::dvec3> press_and_slide(double top, double depth, double half_span, double step) {
  std::vector<glm::dvec3> path;
  for (double z = top + 15.0; z > top - depth; z -= step) path.push_back({0.0, 0.0, z});
  const double z = top - depth;
  for (double x = 0.0; x < half_span; x += step) path.push_back({x, 0.0, z});
  for (double x = half_span; x > -half_span; x -= step) path.push_back({x, 0.0, z});
  for (double y = 0.0; y < half_span; y += step) path.push_back({-half_span, y, z});
  return path;
}

// Drives the proxy along `path`; `clearance` is the proxy centre's signed distance to the
// surface by an independent formula. Returns the largest |proxy - device| seen.
double drive(const HapticScene& scene, const std::vector<glm::dvec3>& path,
             const std::function<double(const glm::dvec3&)>& clearance, const char* what) {
  GodObject god(scene);
  const double r = scene.probe_radius_mm();
  double max_offset = 0.0;
  glm::dvec3 last = path.front();
  god.reset(last);
  for (const glm::dvec3& x : path) {
    const ProxyStep s = god.move(x);
    const double c = clearance(s.proxy_mm);
    EXPECT_GE(c, r - kBehindTolMm) << what << ": proxy behind the surface, device at " << x.x << "," << x.y << "," << x.z;
    // Between two samples the centre moves in a straight line; both ends at >= r - tol from
    // the surface and a move shorter than that means the segment did not cross it either.
    EXPECT_LT(glm::length(s.proxy_mm - last), 2.0 * (r - kBehindTolMm)) << what;
    if (c < r - kBehindTolMm) return max_offset;  // one failure is enough output
    last = s.proxy_mm;
    max_offset = std::max(max_offset, glm::length(s.proxy_mm - x));
  }
  return max_offset;
}

TEST(GodObjectTest, NeverPassesThroughASphere) {
  Surface s = test::analytic(SurfaceType::kSphere, {3.0, -2.0, 0.0});
  s.radius_mm = 30.0;
  auto scene = HapticScene::build(test::scene_with(8.0, {s}));
  ASSERT_TRUE(scene);
  const double max_offset = drive(*scene, press_and_slide(30.0 + 8.0, 6.0, 45.0, 0.2),
                                  [](const glm::dvec3& p) { return glm::length(p - glm::dvec3(3, -2, 0)) - 30.0; },
                                  "sphere");
  EXPECT_GT(max_offset, 5.0);  // it was pressed (6 mm behind the proxy at the top)
}

TEST(GodObjectTest, NeverPassesThroughABoxAndRestsOnItsFace) {
  Surface s = test::analytic(SurfaceType::kBox, {0.0, 0.0, -20.0}, {0.0, 0.0, 30.0});
  s.box_size_mm = {60.0, 50.0, 40.0};
  auto scene = HapticScene::build(test::scene_with(8.0, {s}));
  ASSERT_TRUE(scene);
  const glm::dmat3 rot = euler_xyz_deg(s.rotation_deg);
  auto box_clearance = [&](const glm::dvec3& p) {  // signed distance to a box (closed form)
    const glm::dvec3 q = glm::abs(glm::transpose(rot) * (p - s.center)) - 0.5 * s.box_size_mm;
    return glm::length(glm::max(q, 0.0)) + std::min(std::max({q.x, q.y, q.z}), 0.0);
  };
  drive(*scene, press_and_slide(8.0, 4.0, 50.0, 0.2), box_clearance, "box");
  // Frictionless, pressed 3 mm into the middle of the top face: the proxy is straight above.
  GodObject god(*scene);
  god.reset({5.0, 4.0, 20.0});
  const glm::dvec3 device{5.0, 4.0, 8.0 - 3.0};
  ProxyStep st = god.move(device);
  EXPECT_TRUE(st.in_contact);
  // 2e-3 mm: the contact epsilon (see kBehindTolMm).
  EXPECT_NEAR(glm::length(st.proxy_mm - (device + glm::dvec3(0, 0, 3.0))), 0.0, kBehindTolMm);
  EXPECT_NEAR(st.contact_normal.z, 1.0, 1e-6);
}

// A hand that jumps 200 mm along a floor in one tick (a mouse read after a stalled frame) while
// the proxy glides 1 mm over it: each approach step is the 1 mm gap to the floor, so one move
// covers about max_iterations mm (24). The proxy touches nothing, stops short of the goal and
// says so (short_of_goal: what the readouts need to tell a lagging proxy from a held one); later
// moves catch up and then it is at the goal, touching nothing, with nothing short.
TEST(GodObjectTest, AJumpLongerThanOneMoveIsCaughtUpWithoutContact) {
  Surface s = test::analytic(SurfaceType::kBox, {0.0, 0.0, -20.0});
  s.box_size_mm = {1000.0, 1000.0, 40.0};
  auto scene = HapticScene::build(test::scene_with(8.0, {s}));
  ASSERT_TRUE(scene);
  GodObject god(*scene);
  god.reset({0.0, 0.0, 9.0});
  const glm::dvec3 goal{200.0, 0.0, 9.0};
  ProxyStep st = god.move(goal);
  EXPECT_FALSE(st.in_contact);
  EXPECT_TRUE(st.short_of_goal);
  EXPECT_GT(glm::length(goal - st.proxy_mm), 100.0) << "more than one move's reach at a 1 mm gap";
  EXPECT_NEAR(st.proxy_mm.z, 9.0, 1e-9) << "gliding, never lower";
  int moves = 1;
  while (st.short_of_goal && moves < 50) st = god.move(goal), ++moves;
  EXPECT_FALSE(st.short_of_goal);
  EXPECT_FALSE(st.in_contact);
  EXPECT_NEAR(glm::length(goal - st.proxy_mm), 0.0, 1e-9);
  EXPECT_LT(moves, 20);
  // Pressed into the floor it is held, not short: in contact.
  st = god.move({200.0, 0.0, 6.0});
  EXPECT_TRUE(st.in_contact);
  EXPECT_FALSE(st.short_of_goal);
}

// Brute-force clearance of a mesh surface (every triangle), independent of the BVH.
std::function<double(const glm::dvec3&)> mesh_clearance(const HapticScene& scene) {
  return [&scene](const glm::dvec3& p) { return scene.meshes().closest_brute_force(p).distance_mm; };
}

TEST(GodObjectTest, NeverPassesThroughACoarseMeshSphere) {
  const std::string obj = test::write_sphere_obj("god_sphere", 30.0, 12);
  auto scene = HapticScene::build(test::scene_with(8.0, {test::mesh_surface(obj)}));
  ASSERT_TRUE(scene) << scene.error().message;
  drive(*scene, press_and_slide(30.0 + 8.0, 6.0, 45.0, 0.25), mesh_clearance(*scene), "mesh sphere");
}

TEST(GodObjectTest, NeverPassesThroughSuzanne) {
  if (!std::filesystem::exists(test::kSuzanne)) GTEST_SKIP() << "assimp-testmodels not installed";
  auto scene = HapticScene::build(test::scene_with(4.0, {test::mesh_surface(test::kSuzanne, glm::dvec3(0.0), 22.0)}));
  ASSERT_TRUE(scene) << scene.error().message;
  const MeshHit top = scene->meshes().closest_brute_force({0.0, 0.0, 100.0});
  drive(*scene, press_and_slide(top.point.z + 4.0, 5.0, 35.0, 0.25), mesh_clearance(*scene), "Suzanne");
}

// An open octagonal tube along Y (8 flat sides, 45 degrees between neighbours), as an OBJ.
std::string write_octagon_tube(double circumradius) {
  const std::string path = std::string(PS_BINARY_DIR) + "/tests/world/octagon_tube.obj";
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream out(path);
  for (double y : {-50.0, 50.0})
    for (int i = 0; i < 8; ++i) {
      const double a = 2.0 * kPi * i / 8;
      out << "v " << circumradius * std::cos(a) << ' ' << y << ' ' << circumradius * std::sin(a) << '\n';
    }
  for (int i = 0; i < 8; ++i) {  // quad i: ring 0 (y=-50) and ring 1 (y=+50); outward winding
    const int a0 = 1 + i, a1 = 1 + (i + 1) % 8, b0 = 9 + i, b1 = 9 + (i + 1) % 8;
    out << "f " << a0 << ' ' << b0 << ' ' << b1 << "\nf " << a0 << ' ' << b1 << ' ' << a1 << '\n';
  }
  return path;
}

// Largest angle (degrees) between the force directions of adjacent samples while the device
// circles the tube's axis at a constant radius, 0.5 mm inside the flat sides' middles.
double max_force_turn_deg(bool shading) {
  const double a = 20.0, probe_r = 1.0;
  auto scene = HapticScene::build(test::scene_with(probe_r, {test::mesh_surface(write_octagon_tube(a))}));
  EXPECT_TRUE(scene) << scene.error().message;
  GodObject god(*scene);
  HapticsParams p;
  p.force_shading = shading;
  const double rho = a * std::cos(kPi / 8) + probe_r - 0.5;
  glm::dvec3 last_dir(0.0);
  double worst = 0.0;
  god.reset({2.0 * rho * std::cos(kPi / 18), 0.0, 2.0 * rho * std::sin(kPi / 18)});  // outside, at 10 degrees
  for (double deg = 10.0; deg <= 170.0; deg += 0.5) {  // crosses the edges at 45, 90, 135
    const double t = deg * kPi / 180.0;
    const glm::dvec3 x{rho * std::cos(t), 0.0, rho * std::sin(t)};
    const ForceResult f = compute_proxy_force(p, god, x, glm::dvec3(0.0), 0.0);
    EXPECT_TRUE(f.in_contact) << deg;
    const glm::dvec3 dir = glm::normalize(f.force_n);
    if (last_dir != glm::dvec3(0.0))
      worst = std::max(worst, std::acos(std::clamp(glm::dot(dir, last_dir), -1.0, 1.0)) * 180.0 / kPi);
    last_dir = dir;
  }
  return worst;
}

TEST(ForceShadingTest, ForceDirectionIsContinuousAcrossEdgesOnlyWithShading) {
  // Sides span 45 degrees and are 2 a sin(22.5) = 15.3 mm wide. Shaded, the force turns with
  // the contact point: 45 degrees per 15.3 mm. The contact moves ~0.17 mm per 0.5-degree step,
  // except where the device passes under an edge: there it is 2.1 mm deep, more than R = 1 mm,
  // so the god-object itself moves to the next side, by < 2 mm: at most 45 x 2 / 15.3 = 5.9
  // degrees in one sample. Bound: 6 degrees.
  const double shaded = max_force_turn_deg(true);
  EXPECT_LT(shaded, 6.0);
  // Without shading the force follows the side's normal and turns by the full 45 degrees in
  // that one sample at each edge (as the proxy changes side): more than half of it, and more
  // than three times the shaded bound.
  const double flat = max_force_turn_deg(false);
  EXPECT_GT(flat, 22.5);
  EXPECT_GT(flat, 3.0 * shaded) << "shaded " << shaded << " deg, flat " << flat << " deg";
}

TEST(GodObjectTest, HiddenObjectDeflectsTheProxyUntouchableDoesNot) {
  Surface s = test::analytic(SurfaceType::kSphere);
  s.radius_mm = 20.0;
  s.visible = false;  // felt, not seen
  std::vector<glm::dvec3> through;
  for (double x = -40.0; x <= 40.0; x += 0.5) through.push_back({x, 0.0, 5.0});
  auto hidden = HapticScene::build(test::scene_with(5.0, {s}));
  ASSERT_TRUE(hidden);
  const double deflection = drive(*hidden, through, [](const glm::dvec3& p) { return glm::length(p) - 20.0; }, "hidden");
  EXPECT_GT(deflection, 10.0);  // the device passes the centre; the proxy goes around (>= 25 mm away)
  s.visible = true;
  s.touchable = false;  // seen, not felt
  auto ghost = HapticScene::build(test::scene_with(5.0, {s}));
  ASSERT_TRUE(ghost);
  GodObject god(*ghost);
  for (const glm::dvec3& x : through) {
    const ProxyStep st = god.move(x);
    EXPECT_FALSE(st.in_contact);
    EXPECT_EQ(st.proxy_mm, x);
  }
}

TEST(HapticLoopSceneTest, LoopOnAPlaneSceneHoldsTheProxyAndPushesBackWithTheMaterialsStiffness) {
  Surface plane = test::analytic(SurfaceType::kPlane);
  plane.size_mm = {200.0, 200.0};
  Scene sc = test::scene_with(8.0, {plane});
  sc.materials[0].haptic.stiffness_n_per_mm = 0.8;
  auto scene = HapticScene::build(sc);
  ASSERT_TRUE(scene);
  // Down from 20 mm to 4 mm (4 mm below the proxy's resting height R = 8), then held.
  LogDevice device({{0.0, {0, 0, 20}, 0, true}, {0.5, {0, 0, 4}, 0, true}, {2.0, {0, 0, 4}, 0, true}}, true, "press");
  FakeClock clock;
  HapticLoopParams params;
  params.keep_periods = 4000;
  HapticLoop loop(device, clock, params, &scene.value());
  loop.run_ticks(1999);
  const HapticState st = loop.state().read();
  EXPECT_TRUE(st.in_contact);
  EXPECT_EQ(st.contact_surface, 0);
  EXPECT_NEAR(st.proxy_mm.z, 8.0, kBehindTolMm);
  // At rest 4 mm in: F = stiffness x penetration = 0.8 x 4 = 3.2 N up (1e-2 N: the Kalman
  // estimate settles to within ~0.01 mm of a held position after 1.5 s).
  EXPECT_NEAR(st.force_n.z, 3.2, 1e-2);
  EXPECT_NEAR(st.force_n.x, 0.0, 1e-6);
}

// A live reload or a button's scene switch: the floor rises from z = 0 to z = 5 while the hand
// rests at z = 4 and the proxy centre at z = 8 (above the new floor, but within R of it; a
// plane is two-sided, so the floor stays below the proxy). The loop adopts the new scene at the
// next tick, queues one scene_switched event with that tick, pushes the proxy out onto the new
// floor (resting height 5 + R) and pushes the hand back with the new floor's stiffness
// (0.8 N/mm x 9 mm). Same tolerances as the test above.
TEST(HapticLoopSceneTest, ReplacedSceneIsAdoptedAtTheNextTickWithAnEvent) {
  Surface low = test::analytic(SurfaceType::kPlane);
  low.size_mm = {200.0, 200.0};
  Surface high = low;
  high.center = {0.0, 0.0, 5.0};
  Scene a = test::scene_with(8.0, {low});
  Scene b = test::scene_with(8.0, {high});
  b.materials[0].haptic.stiffness_n_per_mm = 0.8;
  auto first = HapticScene::build(a);
  auto second = HapticScene::build(b);
  ASSERT_TRUE(first && second);
  LogDevice device({{0.0, {0, 0, 20}, 0, true}, {0.5, {0, 0, 4}, 0, true}, {4.0, {0, 0, 4}, 0, true}}, true, "press");
  FakeClock clock;
  HapticLoopParams params;
  params.keep_periods = 5000;
  HapticLoop loop(device, clock, params, &first.value());
  loop.run_ticks(1500);
  EXPECT_NEAR(loop.state().read().proxy_mm.z, 8.0, kBehindTolMm);
  loop.events().drain([](const HapticEvent&) {});
  loop.replace_scene(std::make_shared<const HapticScene>(std::move(second.value())), "high.toml");
  EXPECT_EQ(loop.scene(), &first.value());  // not before the haptic thread's next tick
  loop.run_ticks(1);
  EXPECT_NE(loop.scene(), &first.value());
  std::vector<HapticEvent> events;
  loop.events().drain([&](const HapticEvent& e) { events.push_back(e); });
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events[0].kind, EventKind::scene_switched);
  EXPECT_EQ(events[0].tick, 1500u);
  EXPECT_EQ(events[0].label_view(), "high.toml");
  loop.run_ticks(1500);
  const HapticState st = loop.state().read();
  EXPECT_TRUE(st.in_contact);
  EXPECT_NEAR(st.proxy_mm.z, 13.0, kBehindTolMm);
  EXPECT_NEAR(st.force_n.z, 7.2, 1e-2);
}

// A scene the loop shares from its construction (the maze's live pass: its session core drops its
// own reference at a pass's end, before the haptic thread has adopted the next pass's scene) is
// kept while the loop may tick in it, and released as every replaced scene is: by the next
// replace_scene() call, on the caller's thread, never on the haptic thread. Given as a raw
// pointer, the first pass's scene was freed while the haptic thread still ticked in it.
TEST(HapticLoopSceneTest, ASharedSceneLivesUntilTheSwitchAfterTheOneThatReplacedIt) {
  Surface floor = test::analytic(SurfaceType::kPlane);
  floor.size_mm = {200.0, 200.0};
  auto built = HapticScene::build(test::scene_with(8.0, {floor}));
  auto second = HapticScene::build(test::scene_with(8.0, {floor}));
  auto third = HapticScene::build(test::scene_with(8.0, {floor}));
  ASSERT_TRUE(built && second && third);
  auto first = std::make_shared<const HapticScene>(std::move(built.value()));
  const std::weak_ptr<const HapticScene> watch = first;
  LogDevice device({{0.0, {0, 0, 9}, 0, true}, {1.0, {0, 0, 9}, 0, true}}, false, "hover");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, std::move(first));  // the caller keeps none
  loop.run_ticks(10);
  EXPECT_FALSE(watch.expired()) << "the loop ticks in it";
  loop.replace_scene(std::make_shared<const HapticScene>(std::move(second.value())), "second");
  EXPECT_FALSE(watch.expired()) << "in use until the next tick adopts the second scene";
  loop.run_ticks(10);
  EXPECT_EQ(loop.state().read().scene_serial, 1u) << "the second scene adopted";
  EXPECT_FALSE(watch.expired()) << "never released on the haptic thread";
  loop.replace_scene(std::make_shared<const HapticScene>(std::move(third.value())), "third");
  EXPECT_TRUE(watch.expired()) << "released by the next replace_scene(), on the caller's thread";
}

// A scene switch with a placement (run's mouse, issue 27): the hand hovered 1 mm over a floor at
// z = 0 (centre z = 9, R = 8); the new scene has a 30 mm block there, so the kept proxy would sit
// 21 mm deep in it, farther than R from any face (GodObject::reset cannot push it out). Placed at
// the hover height over the block (z = 39) with the switch, the proxy starts there, free, and
// the hand's filter restarts at rest there. Tolerances as above.
TEST(HapticLoopSceneTest, ASwitchWithAPlacementNeverBuriesTheProxy) {
  Surface floor = test::analytic(SurfaceType::kPlane);
  floor.size_mm = {200.0, 200.0};
  Surface block = test::analytic(SurfaceType::kBox, {0.0, 0.0, 15.0});
  block.box_size_mm = {60.0, 60.0, 30.0};
  auto first = HapticScene::build(test::scene_with(8.0, {floor}));
  auto second = HapticScene::build(test::scene_with(8.0, {floor, block}));
  ASSERT_TRUE(first && second);
  LogDevice device({{0.0, {0, 0, 9}, 0, true}, {1.0, {0, 0, 39}, 0, true}, {4.0, {0, 0, 39}, 0, true}}, false, "hover");
  FakeClock clock;
  HapticLoopParams params;
  params.keep_periods = 5000;
  HapticLoop loop(device, clock, params, &first.value());
  loop.run_ticks(1000);  // up to t = 0.999: the hover sample
  EXPECT_NEAR(loop.state().read().proxy_mm.z, 9.0, kBehindTolMm);
  loop.replace_scene(std::make_shared<const HapticScene>(std::move(second.value())), "block.toml",
                     glm::dvec3(0.0, 0.0, 39.0));
  loop.run_ticks(1);
  HapticState st = loop.state().read();
  EXPECT_NEAR(st.proxy_mm.z, 39.0, kBehindTolMm);
  EXPECT_FALSE(st.in_contact);
  loop.run_ticks(500);
  st = loop.state().read();
  EXPECT_NEAR(st.proxy_mm.z, 39.0, kBehindTolMm);
  EXPECT_NEAR(st.position_mm.z, 39.0, 1e-6);  // at rest there: no swing from the old height
  EXPECT_FALSE(st.in_contact);
}

// A hover placement (the surface under a moving pointer rose): the hand is put at the new height
// with its velocity along the plane kept (the texture's speed) and none along the plane's normal,
// nor into the surface now under it. A stroke at 100 mm/s along x read at 20 Hz; placed 5 mm
// higher with a surface normal tilted against the stroke: the x speed keeps the part of the
// stroke that runs along that surface. Tolerance 25 %: HeldSamplesKeepTheStrokeSpeedBetweenPolls.
TEST(HapticLoopSceneTest, AHoverPlacementKeepsTheStrokeAlongTheSurface) {
  Surface floor = test::analytic(SurfaceType::kPlane);
  floor.size_mm = {400.0, 400.0};
  auto scene = HapticScene::build(test::scene_with(8.0, {floor}));
  ASSERT_TRUE(scene);
  std::vector<DeviceSample> polls;
  for (int i = 0; i <= 60; ++i) polls.push_back({0.05 * i, {100.0 * 0.05 * i - 150.0, 0, 20}, 0, true});
  LogDevice device(polls, false, "mouse at 20 Hz");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &scene.value());
  loop.run_ticks(1020);
  const glm::dvec3 hand = loop.state().read().position_mm + glm::dvec3(0.0, 0.0, 5.0);
  const glm::dvec3 slope = glm::normalize(glm::dvec3(-1.0, 0.0, 1.0));  // a face rising toward +x
  loop.place_hand(hand, {0.0, 0.0, 1.0}, slope);
  loop.run_ticks(1);
  const HapticState st = loop.state().read();
  EXPECT_NEAR(st.proxy_mm.z, hand.z, 1.0);  // one tick of coasting at most 0.1 mm along x
  EXPECT_NEAR(st.velocity_mm_s.x, 50.0, 0.25 * 50.0);  // 100 minus its part into the face
  EXPECT_GE(glm::dot(st.velocity_mm_s, slope), -1e-6);
}

}  // namespace
}  // namespace ps::world
