// The stages of the haptic tick on their own (no GL): the proxy models, the workspace and the
// effects' sum without a haptic scene. Equalities are exact: each stage is deterministic double
// arithmetic, and a replay's bytes depend on these bits.
#include <gtest/gtest.h>

#include <cmath>

#include "floor_model.h"
#include "haptics/effects/scene_effects.h"
#include "haptics/proxy_model.h"
#include "haptics/tick_feed.h"
#include "haptics/workspace.h"

namespace ps {
namespace {

SurfaceModel floor_plane() { return test::floor_model(2.0); }  // z = 0 under a 2 mm probe

TEST(PlaneProxyTest, StepIsComputeForceWithTheLastProxyAsStickPoint) {
  Snapshot<SurfaceModel> surface;
  surface.publish(floor_plane());
  PlaneProxy proxy(surface);
  const HapticsParams p;
  const glm::dvec3 placed(1.0, 2.0, 1.5), x1(1.5, 2.0, 1.0), x2(2.5, 2.2, 0.8), v(10.0, 0.0, -5.0);
  proxy.place(placed);
  const ForceResult a = proxy.step(p, x1, v, 0.001, glm::dvec3(0.0));
  const ForceResult want_a = compute_force(p, floor_plane(), x1, v, placed, 0.001);
  EXPECT_EQ(a.force_n, want_a.force_n);
  EXPECT_EQ(a.proxy_mm, want_a.proxy_mm);
  ASSERT_TRUE(a.in_contact);  // 1 mm into a plane under a 2 mm probe
  const ForceResult b = proxy.step(p, x2, v, 0.002, glm::dvec3(0.0));
  const ForceResult want_b = compute_force(p, floor_plane(), x2, v, a.proxy_mm, 0.002);
  EXPECT_EQ(b.force_n, want_b.force_n);
  EXPECT_EQ(b.proxy_mm, want_b.proxy_mm);
  EXPECT_EQ(proxy.probe_radius_mm(), 2.0);
  int surface_index = 7;
  double w4 = 0.0;
  EXPECT_FALSE(proxy.sheet(surface_index, w4));  // a plane has no 4D sheet
}

TEST(WorkspaceTest, WithoutASceneTheWorkspaceIsTheWorld) {
  Workspace ws;
  ws.restart(nullptr);
  HapticState s;
  s.position_mm = {1.0, 2.0, 3.0};
  s.velocity_mm_s = {4.0, 5.0, 6.0};
  const glm::dvec3 wall = ws.navigate(glm::dvec3(100.0, 0.0, 0.0), 0.001, s);
  EXPECT_EQ(wall, glm::dvec3(0.0));
  EXPECT_EQ(s.position_mm, glm::dvec3(1.0, 2.0, 3.0));
  EXPECT_EQ(s.velocity_mm_s, glm::dvec3(4.0, 5.0, 6.0));
  Snapshot<PublishedViewAxes> axes;
  glm::dvec3 tether(9.0);
  EXPECT_FALSE(ws.roll(nullptr, axes, 0.001, s, tether));  // nothing to add to the force
  EXPECT_EQ(ws.to_device(glm::dvec3(1.0, -2.0, 3.0)), glm::dvec3(1.0, -2.0, 3.0));
}

TEST(SceneEffectsTest, WithoutASceneTheProbeSumIsAdditionsIdentity) {
  Snapshot<LiveCharges> charges;
  SceneEffects effects(charges, 0.5);
  HapticState state;
  TickSample feed;
  EventQueue events(8);
  const EffectTick tick{nullptr, state, feed, events, 0.0, 0.001};
  const glm::dvec3 sum = effects.on_probe(tick);
  // -0.0: added to the walls' force it leaves every bit of it, a -0.0 component included.
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(sum[i] == 0.0 && std::signbit(sum[i]));
  const glm::dvec3 wall(-0.0, 1.0, 0.0);
  EXPECT_TRUE(std::signbit((wall + sum).x));
  // The effects on the hand find no sheet: no event, and out of contact no force is added.
  ForceResult contact;
  EffectTick after = tick;
  after.contact = &contact;
  glm::dvec3 force(-0.0, 2.0, 3.0);
  effects.on_hand(after, force);
  EXPECT_TRUE(std::signbit(force.x));
  EXPECT_EQ(force, glm::dvec3(0.0, 2.0, 3.0));
  EXPECT_EQ(events.drain([](const HapticEvent&) {}), 0u);
}

}  // namespace
}  // namespace ps
