// The per-frame plan (CPU, no GL): what is skipped when.
#include <gtest/gtest.h>

#include "pipeline/scenes.h"
#include "render/plan.h"

namespace ps {
namespace {

std::vector<Aabb> plane_bounds() { return {Aabb{{-100, -100, 0}, {100, 100, 0}}}; }

TEST(PlanTest, NearProbeShadowsAndTextures) {
  const Scene s = test::flat_plane_scene(10.0);
  const FramePlan p = make_plan(s, plane_bounds(), {{0, 0, 10}, 8}, make_plane_frame({0, 0, 1}), 256);
  EXPECT_TRUE(p.shadow_active);
  EXPECT_TRUE(p.surface_shadow[0]);
  EXPECT_TRUE(p.surface_textured[0]);
  EXPECT_TRUE(p.skipped.empty());
  EXPECT_NEAR(p.surface_distance_mm[0], 2.0, 1e-12);
  EXPECT_GT(p.window.half_size_mm, 8.0);
  EXPECT_LT(p.window.half_size_mm, 8.1);
}

TEST(PlanTest, ProbeSunkFarBelowTheSurfaceStillShadows) {
  // 1000 mm under the plane: the bounding sphere is far from the plane's box, but along the
  // reference normal the probe is penetrating (d = -1000) and must be pushed out.
  const Scene s = test::flat_plane_scene(-1000.0);
  const FramePlan p = make_plan(s, plane_bounds(), {{0, 0, -1000}, 8}, make_plane_frame({0, 0, 1}), 256);
  EXPECT_TRUE(p.shadow_active);
  EXPECT_TRUE(p.surface_shadow[0]);
  // Laterally beyond the plane's edge it stays skipped.
  const FramePlan q = make_plan(s, plane_bounds(), {{500, 0, -1000}, 8}, make_plane_frame({0, 0, 1}), 256);
  EXPECT_FALSE(q.shadow_active);
}

TEST(PlanTest, FarProbeSkipsEverything) {
  const Scene s = test::flat_plane_scene(100.0);
  const FramePlan p = make_plan(s, plane_bounds(), {{0, 0, 100}, 8}, make_plane_frame({0, 0, 1}), 256);
  EXPECT_FALSE(p.shadow_active);
  ASSERT_GE(p.skipped.size(), 3u);
  EXPECT_NE(p.skipped[0].find("beyond influence"), std::string::npos);
}

TEST(PlanTest, UntexturedMaterialCompilesGaborOut) {
  Scene s = test::flat_plane_scene(10.0);
  s.materials[0].textured = false;
  FramePlan p = make_plan(s, plane_bounds(), {{0, 0, 10}, 8}, make_plane_frame({0, 0, 1}), 256);
  EXPECT_TRUE(p.surface_shadow[0]);
  EXPECT_FALSE(p.surface_textured[0]);
  s.materials[0].textured = true;
  s.materials[0].gabor.a_min = s.materials[0].gabor.a_max = 0.0;  // zero amplitude: nothing to draw
  p = make_plan(s, plane_bounds(), {{0, 0, 10}, 8}, make_plane_frame({0, 0, 1}), 256);
  EXPECT_FALSE(p.surface_textured[0]);
}

TEST(PlanTest, SphereAabbDistance) {
  EXPECT_DOUBLE_EQ(distance_sphere_aabb({{0, 0, 10}, 3}, {{-1, -1, -1}, {1, 1, 1}}), 6.0);
  EXPECT_DOUBLE_EQ(distance_sphere_aabb({{0, 0, 0}, 3}, {{-1, -1, -1}, {1, 1, 1}}), 0.0);
}

}  // namespace
}  // namespace ps
