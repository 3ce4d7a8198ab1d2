// The haptic tick on a haptic scene (god-object + Embree closest-point queries) allocates
// nothing: an allocation on the 1 kHz thread can stall a tick. Counts every operator new.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
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

}  // namespace
}  // namespace ps::world
