// The per-frame plan (CPU, no GL): what is skipped when.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "support/scenes.h"
#include "scene/camera.h"
#include "render/plan.h"

namespace ps {
namespace {

std::vector<Aabb> plane_bounds() { return {Aabb{{-100, -100, 0}, {100, 100, 0}}}; }

TEST(PlanTest, NearProbeShadowsAndTextures) {
  const Scene s = test::flat_plane_scene(10.0);
  const FramePlan p = make_plan(s, plane_bounds(), {{0, 0, 10}, 8}, make_plane_frame({0, 0, 1}), 256);
  EXPECT_TRUE(p.shadow_active);
  EXPECT_TRUE(p.surfaces[0].shadow);
  EXPECT_TRUE(p.surfaces[0].textured);
  EXPECT_TRUE(p.skipped.empty());
  EXPECT_NEAR(p.surfaces[0].distance_mm, 2.0, 1e-12);
  EXPECT_GT(p.window.half_size_mm, 8.0);
  EXPECT_LT(p.window.half_size_mm, 8.1);
}

TEST(PlanTest, ProbeSunkFarBelowTheSurfaceStillShadows) {
  // 1000 mm under the plane: the bounding sphere is far from the plane's box, but along the
  // reference normal the probe is penetrating (d = -1000) and must be pushed out.
  const Scene s = test::flat_plane_scene(-1000.0);
  const FramePlan p = make_plan(s, plane_bounds(), {{0, 0, -1000}, 8}, make_plane_frame({0, 0, 1}), 256);
  EXPECT_TRUE(p.shadow_active);
  EXPECT_TRUE(p.surfaces[0].shadow);
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
  EXPECT_TRUE(p.surfaces[0].shadow);
  EXPECT_FALSE(p.surfaces[0].textured);
  s.materials[0].textured = true;
  s.materials[0].gabor.a_min = s.materials[0].gabor.a_max = 0.0;  // zero amplitude: nothing to draw
  p = make_plan(s, plane_bounds(), {{0, 0, 10}, 8}, make_plane_frame({0, 0, 1}), 256);
  EXPECT_FALSE(p.surfaces[0].textured);
}

// The influence distance is a strict bound (d < influence shadows; the shader's curve is 0 at
// d >= influence too): probes 0.01 mm either side of it, and exactly on it. 0.01 mm is far above
// double rounding at 50 mm (~1e-14 mm) and far below any other scale of the scene.
TEST(PlanTest, InfluenceDistanceBoundary) {
  const Scene s = test::flat_plane_scene(10.0);
  const double influence = s.materials[0].influence_distance_mm;
  ASSERT_EQ(influence, 50.0);  // the default the numbers below are read against
  const double r = s.probe.radius_mm;
  const auto plan_at = [&](double gap_mm) {
    return make_plan(s, plane_bounds(), {{0, 0, r + gap_mm}, r}, make_plane_frame({0, 0, 1}), 256);
  };
  const FramePlan inside = plan_at(influence - 0.01);
  EXPECT_NEAR(inside.surfaces[0].distance_mm, influence - 0.01, 1e-12);
  EXPECT_TRUE(inside.shadow_active);
  EXPECT_TRUE(inside.surfaces[0].shadow);
  EXPECT_TRUE(inside.surfaces[0].textured);
  EXPECT_TRUE(inside.skipped.empty());
  for (const double gap : {influence, influence + 0.01}) {
    const FramePlan outside = plan_at(gap);
    EXPECT_FALSE(outside.shadow_active) << "gap " << gap << " mm";
    EXPECT_FALSE(outside.surfaces[0].shadow) << "gap " << gap << " mm";
    EXPECT_FALSE(outside.surfaces[0].textured) << "gap " << gap << " mm";
  }
  // The same boundary for a material with its own, shorter influence distance.
  Scene near = s;
  near.materials[0].influence_distance_mm = 3.0;
  const auto near_plan = [&](double gap_mm) {
    return make_plan(near, plane_bounds(), {{0, 0, r + gap_mm}, r}, make_plane_frame({0, 0, 1}), 256);
  };
  EXPECT_TRUE(near_plan(2.99).surfaces[0].shadow);
  EXPECT_FALSE(near_plan(3.01).surfaces[0].shadow);
}

// A probe beside the plane's edge, below its top: the footprint test of sunk_below() reaches
// the influence distance sideways (probe radius + influence from the box's projection).
TEST(PlanTest, SunkProbeBesideTheEdgeUsesTheInfluenceDistance) {
  const Scene s = test::flat_plane_scene(-20.0);
  const double influence = s.materials[0].influence_distance_mm, r = s.probe.radius_mm;
  const auto plan_at = [&](double x) {
    return make_plan(s, plane_bounds(), {{x, 0, -20}, r}, make_plane_frame({0, 0, 1}), 256);
  };
  // Footprint disc edge to the plane's edge (x = 100): x - 100 - r.
  EXPECT_TRUE(plan_at(100.0 + r + influence - 0.01).surfaces[0].shadow);
  EXPECT_FALSE(plan_at(100.0 + r + influence + 0.01).surfaces[0].shadow);
}

// A body casts on a surface only when nearer than the receiving material's influence distance
// to its box: 0.01 mm either side, above the plane and beside its edge; order kept, NaN dropped.
TEST(PlanTest, BodiesInReachUseTheInfluenceDistance) {
  const Aabb plane = plane_bounds()[0];
  const double r = 3.0;
  const std::vector<SphereCaster> bodies{{{0, 0, r + 49.99}, r}, {{0, 0, r + 50.01}, r},
                                         {{100.0 + r + 9.99, 0, 0}, r}, {{100.0 + r + 10.01, 0, 0}, r},
                                         {{0, 0, std::nan("")}, r}, {{5, 5, r}, r}};
  const std::vector<SphereCaster> far = bodies_in_reach(bodies, plane, 50.0);
  ASSERT_EQ(far.size(), 4u);
  EXPECT_EQ(far[0].centre, bodies[0].centre);
  EXPECT_EQ(far[1].centre, bodies[2].centre);
  EXPECT_EQ(far[2].centre, bodies[3].centre);
  EXPECT_EQ(far[3].centre, bodies[5].centre);
  const std::vector<SphereCaster> near = bodies_in_reach(bodies, plane, 10.0);
  ASSERT_EQ(near.size(), 2u);
  EXPECT_EQ(near[0].centre, bodies[2].centre);
  EXPECT_EQ(near[1].centre, bodies[5].centre);
  EXPECT_TRUE(bodies_in_reach({}, plane, 50.0).empty());
}

// The footprint's screen rectangle holds the projection of every point of a shadowed surface
// inside the depth map's window (sampled on the window's grid and over the surfaces' heights,
// tilted perspective view); it is empty when nothing is shadowed and the whole image when the
// eye is inside the window's reach.
TEST(PlanTest, ShadowRectHoldsTheWindowOnScreen) {
  Scene s = test::flat_plane_scene(9.0);
  s.camera.projection = Projection::kPerspective;
  s.camera.position = {30.0, -60.0, 45.0};
  s.render.width = 200;
  s.render.height = 150;
  const std::vector<Aabb> box{Aabb{{-100, -100, -3}, {100, 100, 2}}};  // heights -3 .. 2
  const PlaneFrame f = make_plane_frame(glm::normalize(glm::dvec3(0.1, -0.2, 1.0)));
  const FramePlan p = make_plan(s, box, {{4, -2, 9}, 8}, f, 256);
  ASSERT_TRUE(p.shadow_active);
  const PixelRect& r = p.shadow_rect;
  ASSERT_FALSE(r.empty());
  EXPECT_LT(r.width() * r.height(), 200 * 150 * 6 / 10);  // a bound, not the image
  const glm::dmat4 vp = view_projection(s.camera, 200.0 / 150.0);
  const double half = p.window.half_size_mm;
  int inside = 0;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j)
      for (double h : {-3.0, -0.5, 2.0}) {
        const double u = p.window.center_uv.x + half * (i / 10.0 - 1.0), v = p.window.center_uv.y + half * (j / 10.0 - 1.0);
        // A point of plane coordinates (u, v) at height h along n; keep it on the box's slab.
        const glm::dvec3 x = u * f.t + v * f.b + h * f.n;
        if (x.z < -3.0 || x.z > 2.0) continue;
        const glm::dvec4 c = vp * glm::dvec4(x, 1.0);
        const double px = (c.x / c.w * 0.5 + 0.5) * 200, py = (c.y / c.w * 0.5 + 0.5) * 150;
        if (px < 0 || px >= 200 || py < 0 || py >= 150) continue;
        ++inside;
        EXPECT_TRUE(r.contains(static_cast<int>(px), static_cast<int>(py))) << px << "," << py;
      }
  EXPECT_GT(inside, 300);
  // Nothing shadowed: empty. The eye inside the window's reach: the whole image.
  EXPECT_TRUE(make_plan(s, box, {{4, -2, 900}, 8}, f, 256).shadow_rect.empty());
  Scene eye = s;
  eye.camera.position = {4.0, -2.0, 1.0};
  eye.camera.target = {4.0, 20.0, 0.0};
  EXPECT_EQ(make_plan(eye, box, {{4, -2, 9}, 8}, f, 256).shadow_rect, PixelRect::whole(200, 150));
}

TEST(PlanTest, SphereAabbDistance) {
  EXPECT_DOUBLE_EQ(distance_sphere_aabb({{0, 0, 10}, 3}, {{-1, -1, -1}, {1, 1, 1}}), 6.0);
  EXPECT_DOUBLE_EQ(distance_sphere_aabb({{0, 0, 0}, 3}, {{-1, -1, -1}, {1, 1, 1}}), 0.0);
}

}  // namespace
}  // namespace ps
