// The haptic tick on a haptic scene (god-object + Embree closest-point queries) allocates
// nothing: an allocation on the 1 kHz thread can stall a tick. Counts every operator new.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "world/haptic_scene.h"
#include "world_test_util.h"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace ps::world {
namespace {

TEST(HapticAllocTest, TicksAgainstAMeshSceneDoNotAllocate) {
  const std::string obj = test::write_sphere_obj("alloc_sphere", 30.0, 24);
  auto scene = HapticScene::build(test::scene_with(8.0, {test::mesh_surface(obj)}));
  ASSERT_TRUE(scene) << scene.error().message;
  // Into the top of the sphere and along it: contact, sliding, the local model every tick.
  LogDevice device({{0.0, {0, 0, 50}, 0, true}, {0.3, {0, 0, 34}, 0, true}, {1.0, {20, 5, 30}, 0, true}},
                   true, "press");
  FakeClock clock;
  HapticLoopParams params;
  params.keep_periods = 2000;
  HapticLoop loop(device, clock, params, &scene.value());
  loop.run_ticks(1);  // the first tick initialises the filter and the proxy
  const long before = g_allocations.load();
  loop.run_ticks(999);
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(loop.state().read().in_contact);
}

// Every material law the tick applies: a magnetic box (one extra radius-limited query per
// free-space tick), a water sphere (the inside test), a textured sticky plane.
// Fields (uniform, viscous, charges, gravity) and a bouncing body, evaluated every tick.
TEST(HapticAllocTest, TicksWithFieldsAndBodiesDoNotAllocate) {
  Scene sc = test::scene_with(8.0, {test::analytic(SurfaceType::kPlane)});
  Field u, v, q, g;
  u.type = FieldType::kUniform;
  u.fluctuation_n = {0.2, 0, 0};
  v.type = FieldType::kViscous;
  v.viscosity_n_s_per_mm = 0.01;
  v.bounded = true;
  v.size_mm = {100, 100, 100};
  q.type = FieldType::kCharge;
  q.charge_n_mm2 = -100;
  q.position = {10, 10, 20};
  g.type = FieldType::kGravity;
  sc.fields = {u, v, q, g};
  Body b;
  b.floor_z_mm = -20.0;
  sc.bodies = {b};
  auto scene = HapticScene::build(sc);
  ASSERT_TRUE(scene) << scene.error().message;
  LogDevice device({{0.0, {0, 0, 30}, 0, true}, {1.0, {30, 10, 4}, 0, true}}, true, "press");
  FakeClock clock;
  HapticLoopParams params;
  params.keep_periods = 2000;
  HapticLoop loop(device, clock, params, &scene.value());
  loop.run_ticks(1);
  const long before = g_allocations.load();
  loop.run_ticks(999);
  EXPECT_EQ(g_allocations.load() - before, 0);
  std::size_t impacts = 0;
  loop.events().drain([&](const HapticEvent& e) { impacts += e.kind == EventKind::body_impact; });
  EXPECT_GT(impacts, 0u);  // the body did bounce during the counted ticks
}

TEST(HapticAllocTest, TicksWithMaterialLawsDoNotAllocate) {
  Scene sc = test::scene_with(5.0, {});
  Material plain = sc.materials.front();
  Material magnet = plain, water = plain, rough = plain;
  magnet.haptic.magnetic_force_n = 2.0;
  magnet.haptic.magnetic_range_mm = 10.0;
  water.haptic.penetrable = true;
  water.haptic.viscosity_n_s_per_mm = 0.01;
  rough.haptic.stickiness_n = 0.5;
  rough.haptic.texture.push_back({HapticWave::Shape::kSquare, 0.2, 3.0, {0.6, 0.8}});
  sc.materials = {magnet, water, rough};
  Surface box = test::analytic(SurfaceType::kBox, {0, 0, 10});
  Surface ball = test::analytic(SurfaceType::kSphere, {40, 0, 20});
  ball.radius_mm = 15.0;
  ball.material_index = 1;
  Surface floor = test::analytic(SurfaceType::kPlane);
  floor.material_index = 2;
  sc.surfaces = {box, ball, floor};
  auto scene = HapticScene::build(sc);
  ASSERT_TRUE(scene) << scene.error().message;
  // Near the box's top, through the water, down onto the floor and along it.
  LogDevice device({{0.0, {0, 0, 32}, 0, true}, {0.2, {40, 0, 20}, 0, true}, {0.5, {40, 0, 3}, 0, true},
                    {1.0, {-20, 10, 3}, 0, true}},
                   true, "materials");
  FakeClock clock;
  HapticLoopParams params;
  params.keep_periods = 2000;
  HapticLoop loop(device, clock, params, &scene.value());
  loop.run_ticks(1);
  const long before = g_allocations.load();
  loop.run_ticks(999);
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_TRUE(loop.state().read().in_contact);
}

}  // namespace
}  // namespace ps::world
