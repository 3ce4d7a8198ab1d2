// Pointing by ray (devices/pointer_map.h, pointer_hit; app/session/free_height.h, first_hit):
// the mouse's probe hovers over the visible surface under the cursor, so its pseudo-shadow (the
// probe projected along the plane's normal) is centred on the pointer over raised parts too, on
// a perspective camera. The expected points are closed-form ray/box/plane intersections, not the
// sphere tracing under test. No GL, no window.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "app/session/free_height.h"
#include "devices/pointer_map.h"
#include "scene/scene_io.h"
#include "support/felt.h"
#include "world/haptic_scene.h"

namespace ps {
namespace {

// A 40 x 40 mm block standing 30 mm out of the plane z = 0 (Weight's back button and Suzanne's
// brow are raised like this above their pointer planes).
constexpr const char* kBlockOnPlane =
    "[probe]\nradius_mm = 8.0\n[materials.m]\nlambda_min = 0.5\n"
    "[[surfaces]]\ntype = \"plane\"\nsize_mm = [4000.0, 4000.0]\nmaterial = \"m\"\n"
    "[[surfaces]]\ntype = \"box\"\ncenter = [0.0, 0.0, 15.0]\nsize_mm = [40.0, 40.0, 30.0]\nmaterial = \"m\"\n";
constexpr double kTop = 30.0, kHalf = 20.0, kRadius = 8.0;

// The default camera (45 degrees down, perspective) looking at the plane's origin.
PointerView perspective_view(const FreeHeight* floor) {
  PointerView v;
  v.camera.position = {0.0, -120.0, 120.0};
  v.camera.fov_y_deg = 40.0;
  v.window_size = {640.0, 480.0};
  v.aspect = 640.0 / 480.0;
  v.probe_radius_mm = kRadius;
  v.floor = floor;
  return v;
}

// Closed form: where the ray first meets the block's top or the plane (the block's sides are
// not asked about: the tests point at neither).
std::optional<glm::dvec3> visible_point(const PointerRay& ray) {
  const glm::dvec3 d = ray.far_mm - ray.near_mm;
  const double t_top = (kTop - ray.near_mm.z) / d.z;
  const glm::dvec3 top = ray.near_mm + t_top * d;
  if (std::abs(top.x) < kHalf && std::abs(top.y) < kHalf) return top;
  const glm::dvec3 floor = ray.near_mm + (-ray.near_mm.z / d.z) * d;
  if (std::abs(floor.x) < kHalf + 1.0 && std::abs(floor.y) < kHalf + 1.0) return std::nullopt;  // a side face
  return floor;
}

// Over the block's top and over the plane around it, every pointer position puts the probe
// straight above the visible point under the cursor, at the person's height above that
// surface, so the shadow's centre projects back onto the pointer. Tolerances: 0.02 mm, the ray
// march and the lowering each stop within 0.01 mm of a surface; 0.05 px follows from that at
// this camera's scale (~3 px per mm at the target).
TEST(PointingTest, TheShadowIsUnderThePointerOverRaisedParts) {
  FreeHeight floor;
  floor.set_scene(felt(kBlockOnPlane));
  floor.set_top_mm(200.0);
  const PointerView view = perspective_view(&floor);
  const double h = 2.0;
  int on_top = 0, on_plane = 0;
  for (double y = 40.0; y < 480.0; y += 40.0)
    for (double x = 40.0; x < 640.0; x += 40.0) {
      const std::optional<glm::dvec3> q = visible_point(pointer_ray(view, {x, y}));
      if (!q) continue;
      // Over the plane within R + h of the block the lowered probe keeps h from the block's edge.
      const bool top = q->z > 1.0;
      if (!top && std::max(std::abs(q->x), std::abs(q->y)) < kHalf + kRadius + h + 0.5) continue;
      PointerMap map;
      const glm::dvec3 centre = map.absolute(view, {x, y}, h);
      SCOPED_TRACE(testing::Message() << "pointer " << x << "," << y);
      EXPECT_NEAR(centre.x, q->x, 0.02);
      EXPECT_NEAR(centre.y, q->y, 0.02);
      EXPECT_NEAR(centre.z, q->z + kRadius + h, 0.02);
      const glm::dvec2 shadow = project_to_window(view, *q);
      EXPECT_NEAR(glm::length(shadow - glm::dvec2(x, y)), 0.0, 0.05);
      (top ? on_top : on_plane)++;
    }
  EXPECT_GE(on_top, 8);
  EXPECT_GE(on_plane, 40);
}

// What the old mapping did (the plane's hit, then dropped straight down onto the block): at the
// block's centre the shadow lands tens of pixels from the pointer. The test above fails there.
TEST(PointingTest, ThePlanesHitAloneMissesTheRaisedTop) {
  const PointerView view = perspective_view(nullptr);
  const glm::dvec2 pointer = project_to_window(view, {0.0, 0.0, kTop});
  const std::optional<glm::dvec3> plane_hit = intersect_plane(pointer_ray(view, pointer), PlaneAxes{});
  ASSERT_TRUE(plane_hit);
  const glm::dvec2 dropped = project_to_window(view, {plane_hit->x, plane_hit->y, kTop});
  EXPECT_GT(glm::length(dropped - pointer), 30.0);
}

// Where only the plane is under the pointer, the mapping is exactly today's (the same bits), so
// walks over flat scenes replay unchanged; where the ray meets nothing, the plane's hit too.
TEST(PointingTest, AFlatSceneMapsExactlyAsWithoutAFloor) {
  FreeHeight floor;
  floor.set_scene(felt("[materials.m]\nlambda_min = 0.5\n[[surfaces]]\ntype = \"plane\"\nsize_mm = [4000.0, 4000.0]\n"
                       "material = \"m\"\n"));
  FreeHeight nothing;
  nothing.set_scene(felt("[materials.m]\nlambda_min = 0.5\n[[surfaces]]\ntype = \"sphere\"\n"
                         "center = [0.0, 0.0, -900.0]\nradius_mm = 1.0\nmaterial = \"m\"\n"));
  for (const FreeHeight* f : {&floor, &nothing})
    for (double x = 10.0; x < 640.0; x += 70.0)
      for (double y = 10.0; y < 480.0; y += 70.0) {
        const std::optional<glm::dvec3> with = pointer_hit(perspective_view(f), {x, y});
        const std::optional<glm::dvec3> without = pointer_hit(perspective_view(nullptr), {x, y});
        ASSERT_EQ(with.has_value(), without.has_value());
        if (!with) continue;
        EXPECT_EQ(with->x, without->x);
        EXPECT_EQ(with->y, without->y);
        EXPECT_EQ(with->z, without->z);
      }
}

// A dome: a sphere of 40 mm standing 30 mm out of the plane z = 0 (the torus's and Suzanne's
// slopes are curved like this). Lowered straight over the point under the pointer, the probe
// would touch the dome R sin(slope) uphill of it - 5.7 mm at 45 degrees for this 8 mm probe,
// ~17 px on this camera - and the shadow's dark core (where the probe is nearest the surface)
// would sit there. Lowered over the point (R + h) sin(slope) downhill instead, it is nearest the
// pointed point itself, h away along the dome's normal. Expected values are closed form (ray/sphere, the sphere's normal); 0.05 mm: the
// ray march and the lowering each stop within 0.01 mm of a surface, and the normal is read
// 0.5 mm in front of the surface.
TEST(PointingTest, OverASlopeTheProbeTouchesThePointUnderThePointer) {
  constexpr double kDomeR = 40.0;
  const glm::dvec3 centre(0.0, 0.0, -10.0);
  FreeHeight floor;
  floor.set_scene(felt(
      "[probe]\nradius_mm = 8.0\n[materials.m]\nlambda_min = 0.5\n"
      "[[surfaces]]\ntype = \"plane\"\nsize_mm = [4000.0, 4000.0]\nmaterial = \"m\"\n"
      "[[surfaces]]\ntype = \"sphere\"\ncenter = [0.0, 0.0, -10.0]\nradius_mm = 40.0\nmaterial = \"m\"\n"));
  floor.set_top_mm(200.0);
  const PointerView view = perspective_view(&floor);
  int slopes = 0;
  for (const glm::dvec3 dir : {glm::dvec3(0.6, -0.5, 0.62), glm::dvec3(-0.7, -0.3, 0.65), glm::dvec3(0.2, 0.1, 0.97),
                               glm::dvec3(-0.5, 0.2, 0.84), glm::dvec3(0.75, 0.0, 0.66)}) {
    const glm::dvec2 pointer = project_to_window(view, centre + kDomeR * glm::normalize(dir));
    // Closed form: the ray's first meeting with the dome.
    const PointerRay ray = pointer_ray(view, pointer);
    const glm::dvec3 d = glm::normalize(ray.far_mm - ray.near_mm);
    const glm::dvec3 oc = ray.near_mm - centre;
    const double b = glm::dot(oc, d);
    const glm::dvec3 seen = ray.near_mm + (-b - std::sqrt(b * b - (glm::dot(oc, oc) - kDomeR * kDomeR))) * d;
    if (seen.z < 0.5) continue;  // under the plane: not on a slope
    const glm::dvec3 normal = glm::normalize(seen - centre);
    SCOPED_TRACE(testing::Message() << "slope " << std::acos(normal.z) * 180.0 / M_PI << " deg");
    PointerMap map;
    // Touching (h = 0): the centre is R along the dome's normal from the pointed point.
    EXPECT_NEAR(glm::length(map.absolute(view, pointer, 0.0) - (seen + kRadius * normal)), 0.0, 0.05);
    // Hovering (h = 2 mm): 2 mm further along the dome's normal, so the pointed point is still
    // the nearest (a sphere of R + h lowered the same way touches it).
    EXPECT_NEAR(glm::length(map.absolute(view, pointer, 2.0) - (seen + (kRadius + 2.0) * normal)), 0.0, 0.05);
    ++slopes;
  }
  EXPECT_GE(slopes, 4);
}

// Lowered straight over the pointed point (the rule before), the same dome's 45-degree slope
// puts the touched point more than 5 mm uphill: the test above fails there.
TEST(PointingTest, LoweredStraightOverASlopeTheProbeTouchesUphill) {
  FreeHeight floor;
  floor.set_scene(felt(
      "[probe]\nradius_mm = 8.0\n[materials.m]\nlambda_min = 0.5\n"
      "[[surfaces]]\ntype = \"sphere\"\ncenter = [0.0, 0.0, -10.0]\nradius_mm = 40.0\nmaterial = \"m\"\n"));
  floor.set_top_mm(200.0);
  const glm::dvec3 on_slope = glm::dvec3(0.0, 0.0, -10.0) + 40.0 * glm::normalize(glm::dvec3(1.0, 0.0, 1.0));
  const double lift = floor.lift_mm({on_slope.x, on_slope.y, 0.0}, {0.0, 0.0, 1.0}, kRadius);
  const glm::dvec3 probe(on_slope.x, on_slope.y, lift + kRadius);
  const glm::dvec3 touched = glm::dvec3(0.0, 0.0, -10.0) + 40.0 * glm::normalize(probe - glm::dvec3(0.0, 0.0, -10.0));
  EXPECT_GT(glm::length(touched - on_slope), 5.0);
}

// A moved workspace ([navigation] travelled 60 mm along x): the ray is marched through the
// world, the block now sits at workspace x = -60, and its top is still found under the pointer.
TEST(PointingTest, TheRayIsMarchedInTheWorldOfAMovedWorkspace) {
  FreeHeight floor;
  floor.set_scene(felt(kBlockOnPlane));
  floor.set_pose(glm::dmat3(1.0), {60.0, 0.0, 0.0});
  const PointerView view = perspective_view(&floor);
  const glm::dvec2 pointer = project_to_window(view, {-60.0, 5.0, kTop});
  const std::optional<glm::dvec3> hit = floor.first_hit(pointer_ray(view, pointer));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(glm::length(*hit - glm::dvec3(-60.0, 5.0, kTop)), 0.0, 0.02);
}

// A 30 x 30 mm button in the top face of a floor slab (the face at z = 0).
constexpr const char* kButtonInFloor =
    "[probe]\nradius_mm = 8.0\n[materials.m]\nlambda_min = 0.5\n"
    "[[surfaces]]\ntype = \"box\"\ncenter = [0.0, 0.0, -5.0]\nsize_mm = [160.0, 100.0, 10.0]\nmaterial = \"m\"\n"
    "[[buttons]]\ncenter = [-25.0, 0.0, 0.0]\nsize_mm = [30.0, 30.0]\nstiffness_n_per_mm = 0.2\ntravel_mm = 3.0\n"
    "action = \"flag:light\"\n";

// A button is a hole in its face with a pocket behind it (world/buttons.h); pointing at it finds
// its face, not the pocket's far wall: seen at 45 degrees the ray would reach the pocket's
// bottom 4.5 mm down and 4.5 mm further on (Weight's button: 7.8 mm, and its press failed).
TEST(PointingTest, AButtonsFaceIsSolidForPointing) {
  FreeHeight floor;
  floor.set_scene(felt(kButtonInFloor));
  const PointerView view = perspective_view(&floor);
  for (const glm::dvec3 at : {glm::dvec3(-25.0, 0.0, 0.0), glm::dvec3(-30.0, 8.0, 0.0), glm::dvec3(-15.0, -10.0, 0.0)}) {
    const std::optional<glm::dvec3> hit = floor.first_hit(pointer_ray(view, project_to_window(view, at)));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(glm::length(*hit - at), 0.0, 0.02) << at.x << "," << at.y;
  }
}

// A pointer plane facing the camera (Illusion's: its normal 45 degrees between the floor's and the
// view's) over a button in the floor: the probe hovers along the button's own normal from the
// pointed point, so its shadow (the nearest point, straight below) is under the pointer; lowered
// along the plane's normal instead it came to rest (R + h) tan 45 degrees = 9 mm off, 26 px in
// the Illusion window. Expected: the closed-form ray/face point plus (R + h) along +z; 0.05 mm as
// above (the lowering stops within 0.01 mm of the plate).
TEST(PointingTest, OverAButtonUnderATiltedPlaneTheProbeHoversAlongTheFacesNormal) {
  FreeHeight floor;
  floor.set_scene(felt(kButtonInFloor));
  floor.set_top_mm(200.0);
  PointerView view = perspective_view(&floor);
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.0, -1.0, 1.0));
  // Through the camera target 20 mm above the floor, as Illusion's (a face on the plane itself maps
  // by the plane's own hit: AFlatSceneMapsExactlyAsWithoutAFloor).
  view.plane = {glm::dvec3(0.0, 0.0, 20.0), glm::dvec3(1.0, 0.0, 0.0), glm::cross(n, glm::dvec3(1.0, 0.0, 0.0)), n};
  constexpr double h = 1.0;
  for (const glm::dvec3 at : {glm::dvec3(-25.0, 0.0, 0.0), glm::dvec3(-32.0, 6.0, 0.0), glm::dvec3(-18.0, -8.0, 0.0)}) {
    SCOPED_TRACE(testing::Message() << "at " << at.x << "," << at.y);
    PointerMap map;
    const glm::dvec3 centre = map.absolute(view, project_to_window(view, at), h);
    EXPECT_NEAR(glm::length(centre - (at + glm::dvec3(0.0, 0.0, kRadius + h))), 0.0, 0.05);
  }
}

// path_clear: a probe sphere moved straight along a segment, checked against a clearance. Over
// the block's top at 3 mm (centre 30 + 8 + 3 above the plane): clear for a clearance of 2 mm,
// not for 3.1 (the march stops within 0.01 mm of the clearance; a path grazing it within 0.1 mm
// for 30 mm would take 300 steps of 0.1 mm, more than max_steps, and count as not clear); a segment through the block is never clear, and one that only starts or ends near it is
// checked at both ends.
TEST(PointingTest, APathIsClearOnlyWhereTheSphereKeepsTheClearance) {
  FreeHeight floor;
  floor.set_scene(felt(kBlockOnPlane));
  const double z = kTop + kRadius + 3.0;
  EXPECT_TRUE(floor.path_clear({-15.0, 0.0, z}, {15.0, 0.0, z}, kRadius, 2.0));
  EXPECT_FALSE(floor.path_clear({-15.0, 0.0, z}, {15.0, 0.0, z}, kRadius, 3.1));
  EXPECT_FALSE(floor.path_clear({-80.0, 0.0, 20.0}, {80.0, 0.0, 20.0}, kRadius, 0.0)) << "through the block";
  EXPECT_FALSE(floor.path_clear({-80.0, 0.0, z}, {0.0, 0.0, z}, kRadius, 3.1)) << "ends over the block";
  EXPECT_TRUE(floor.path_clear({0.0, 0.0, z}, {0.0, 0.0, z}, kRadius, 2.0)) << "no move";
  EXPECT_FALSE(floor.path_clear({0.0, 0.0, z}, {0.0, 0.0, z}, kRadius, 3.1)) << "no move, too near";
}

// A proxy pressed against the block's side while the hand hovers beyond the block is stranded;
// one the hand left on the same side, with nothing between, is not, however far. Closed forms:
// the block's faces at x = +-20 mm and its top at 30 mm, the sphere's radius 8 mm; from the top
// (0, 0, 39) to (60, 0, 8) the line is at z = 28.7 < 30 where it crosses the face x = 20.
TEST(PointingTest, AProxyBehindTheBlockIsStrandedOneInTheOpenIsNot) {
  FreeHeight floor;
  floor.set_scene(felt(kBlockOnPlane));
  const double hover = 1.0, reach = hover + 2.0;
  const glm::dvec3 hand{-60.0, 0.0, kRadius + hover};
  const glm::dvec3 against_side{kHalf + kRadius, 0.0, kRadius};  // touching the face x = 20
  EXPECT_TRUE(proxy_stranded(floor, hand, against_side, reach)) << "the block between";
  EXPECT_FALSE(proxy_stranded(floor, hand, {-kHalf - kRadius, 0.0, kRadius}, reach))
      << "against the near face, on the hand's side: 31 mm away, nothing between";
  EXPECT_FALSE(proxy_stranded(floor, hand, {-100.0, 0.0, kRadius}, reach)) << "on the floor, in the open";
  EXPECT_FALSE(proxy_stranded(floor, hand, hand + glm::dvec3(0.0, 0.0, -hover), reach)) << "within reach";
  EXPECT_FALSE(proxy_stranded(floor, {0.0, 0.0, kTop + kRadius + hover}, against_side, 100.0))
      << "beyond a larger reach";
  // Over the top instead of through the block: the hand above the top, the proxy on the far side.
  EXPECT_TRUE(proxy_stranded(floor, {0.0, 0.0, kTop + kRadius + hover}, {60.0, 0.0, kRadius}, reach))
      << "the straight way from the top down to the far floor cuts the block's edge";
}

// A sphere wider than the closest-point query (R + h = 70 mm > 64 mm) is lowered onto the block
// as any other: the query reaches past the sphere. Closed form: over the block's centre the
// sphere rests on its top; 0.02 mm as above.
TEST(PointingTest, ASphereWiderThanTheQueryIsLoweredOntoTheSurface) {
  FreeHeight floor;
  floor.set_scene(felt(kBlockOnPlane));
  floor.set_top_mm(200.0);
  EXPECT_NEAR(floor.lift_mm({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 70.0), kTop, 0.02);
}

// A floor that counts how often the mapping asks it to lower the probe (lift_mm), passing
// every question on to a real FreeHeight.
class CountingFloor final : public SurfaceFloor {
 public:
  explicit CountingFloor(const FreeHeight& floor) : floor_(floor) {}
  double lift_mm(const glm::dvec3& hit, const glm::dvec3& n, double r) const override {
    ++lifts;
    return floor_.lift_mm(hit, n, r);
  }
  std::optional<glm::dvec3> first_hit(const PointerRay& ray) const override { return floor_.first_hit(ray); }
  FloorLowering lowering_point(const glm::dvec3& s, const glm::dvec3& n, double r, const glm::dvec3& eye) const override {
    return floor_.lowering_point(s, n, r, eye);
  }
  mutable int lifts = 0;

 private:
  const FreeHeight& floor_;
};

// One reading lowers the probe beside the pointed point (lowering_point) and hands over where
// it came to rest: the mapping takes that rest (no second lowering, lift_mm) and it equals a
// fresh lowering over that place; a relative move lowers afresh. Closed form on the dome
// (0.02 mm: each lowering stops within 0.01 mm of the surface; 0.05 mm for the centre, whose
// normal is also read 0.5 mm in front of the surface).
TEST(PointingTest, TheReadingsLoweringComesWithItsRest) {
  const std::string dome =
      "[probe]\nradius_mm = 8.0\n[materials.m]\nlambda_min = 0.5\n"
      "[[surfaces]]\ntype = \"sphere\"\ncenter = [0.0, 0.0, -10.0]\nradius_mm = 40.0\nmaterial = \"m\"\n";
  FreeHeight floor, fresh;
  floor.set_scene(felt(dome));
  fresh.set_scene(felt(dome));
  const glm::dvec3 c(0.0, 0.0, -10.0), n(0.0, 0.0, 1.0);
  const glm::dvec3 normal = glm::normalize(glm::dvec3(1.0, 0.0, 1.0));
  const glm::dvec3 on_slope = c + 40.0 * normal;
  const FloorLowering beside = floor.lowering_point(on_slope, n, kRadius, normal);
  EXPECT_NEAR(glm::length(beside.point - (on_slope + kRadius * glm::dvec3(normal.x, normal.y, 0.0))), 0.0, 0.05);
  ASSERT_TRUE(beside.centre.has_value()) << "lowered to decide: its rest comes with it";
  EXPECT_NEAR(glm::length(*beside.centre - (on_slope + kRadius * normal)), 0.0, 0.05) << "touches the pointed point";
  const glm::dvec3 on_plane(beside.point.x, beside.point.y, 0.0);
  EXPECT_NEAR(beside.centre->z - kRadius, fresh.lift_mm(on_plane, n, kRadius), 0.02);
  EXPECT_NEAR(glm::length(floor.last_normal() - normal), 0.0, 0.01) << "the hand coasts along the dome";

  // Through the mapping: the dome seen from above, pointed at its slope.
  floor.set_top_mm(200.0);
  CountingFloor counting(floor);
  PointerView view = perspective_view(nullptr);
  view.floor = &counting;
  view.camera.position = {0.0, 0.0, 300.0};
  view.camera.up = {0.0, 1.0, 0.0};
  PointerMap map;
  const glm::dvec3 centre = map.absolute(view, project_to_window(view, on_slope), 0.0);
  EXPECT_EQ(counting.lifts, 0) << "the reading's own lowering is taken";
  EXPECT_NEAR(glm::length(centre - (on_slope + kRadius * normal)), 0.0, 0.05);
  const glm::dvec3 moved = map.relative(view, {0.0, 0.0}, 0.1, 0.0);
  EXPECT_EQ(counting.lifts, 1) << "a relative move lowers afresh";
  EXPECT_NEAR(glm::length(moved - centre), 0.0, 0.02) << "the same place, lowered again, rests the same";
}

}  // namespace
}  // namespace ps
