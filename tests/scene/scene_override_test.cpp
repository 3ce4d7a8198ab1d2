// --set KEY=VALUE overrides: present and absent keys, typos, validation under "--set KEY".
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene_io.h"
#include "scene_test_util.h"

namespace ps {
namespace {

using test::error_of;
using test::parse;

const std::string kScene = std::string(test::kMinimalScene) + R"(
[probe]
radius_mm = 8
[[surfaces]]
type = "sphere"
material = "wood"
radius_mm = 20
)";

TEST(SceneOverrideTest, OverridesPresentKeys) {
  Result<Scene> scene = parse(kScene, {"materials.wood.lambda_min=0.4", "probe.radius_mm=12",
                                       "surfaces.1.radius_mm=30"});
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->materials[0].gabor.lambda_min_mm, 0.4);
  EXPECT_EQ(scene->probe.radius_mm, 12.0);
  EXPECT_EQ(scene->surfaces[1].radius_mm, 30.0);
}

TEST(SceneOverrideTest, OverridesKeysTheFileOmitted) {
  Result<Scene> scene =
      parse(kScene, {"probe.position=[0,0,5]", "render.displacement=exact_max",
                     "camera.projection=\"orthographic\"", "materials.wood.theta_max=90",
                     "materials.wood.textured=false", "surfaces.0.size_mm=[50, 60]",
                     "render.size = [320, 240]"});
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->probe.position, glm::dvec3(0, 0, 5));
  EXPECT_EQ(scene->render.displacement, DisplacementMethod::kExactMax);
  EXPECT_EQ(scene->camera.projection, Projection::kOrthographic);
  EXPECT_NEAR(scene->materials[0].gabor.theta_max_rad, M_PI / 2.0, 1e-12);
  EXPECT_FALSE(scene->materials[0].textured);
  EXPECT_EQ(scene->surfaces[0].size_mm, glm::dvec2(50, 60));
  EXPECT_EQ(scene->render.width, 320);
}

TEST(SceneOverrideTest, GaborStrategyKeys) {
  Result<Scene> scene = parse(kScene, {"materials.wood.gabor_strategy=stratified",
                                       "materials.wood.stratified_impulses=2"});
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->materials[0].gabor.strategy, GaborParams::Strategy::kStratified);
  EXPECT_EQ(scene->materials[0].gabor.stratified_impulses, 2);
  EXPECT_FALSE(parse(kScene, {"materials.wood.gabor_strategy=fast"}));
  EXPECT_FALSE(parse(kScene, {"materials.wood.stratified_impulses=0"}));
}

TEST(SceneOverrideTest, GaborFilterKey) {
  Result<Scene> plain = parse(kScene, {});
  ASSERT_TRUE(plain) << plain.error().message;
  EXPECT_EQ(plain->materials[0].gabor.filter, GaborParams::Filter::kAnalytic);  // the default
  Result<Scene> scene = parse(kScene, {"materials.wood.gabor_filter=none"});
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->materials[0].gabor.filter, GaborParams::Filter::kNone);
  const std::string e = error_of(kScene, {"materials.wood.gabor_filter=box"});
  EXPECT_NE(e.find("gabor_filter"), std::string::npos) << e;
  EXPECT_NE(e.find("analytic"), std::string::npos) << e;  // names the accepted values
}

TEST(SceneOverrideTest, CanAddAMaterial) {
  Result<Scene> scene = parse(kScene, {"materials.felt.lambda_min=0.2",
                                       "surfaces.1.material=felt"});
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_EQ(scene->materials.size(), 2u);
  EXPECT_EQ(scene->materials[1].name, "felt");
  EXPECT_EQ(scene->surfaces[1].material_index, 1);
}

TEST(SceneOverrideTest, UnknownKeyListsCloseMatches) {
  EXPECT_EQ(error_of(kScene, {"materials.wood.lamda_min=0.4"}),
            "--set materials.wood.lamda_min: unknown key; close matches: lambda_min");
  EXPECT_EQ(error_of(kScene, {"probe.radius=3"}),
            "--set probe.radius: unknown key; close matches: radius_mm");
  EXPECT_EQ(error_of(kScene, {"camra.fov_y_deg=3"}),
            "--set camra.fov_y_deg: unknown key; close matches: camera");
  EXPECT_EQ(error_of(kScene, {"light.xyz=1"}),
            "--set light.xyz: unknown key; known keys: direction, color, ambient");
}

TEST(SceneOverrideTest, BadValuesNameTheOverrideNotTheFile) {
  EXPECT_EQ(error_of(kScene, {"probe.radius_mm=-1"}),
            "--set probe.radius_mm: 'radius_mm' must be in (0, 100000] (got -1)");
  EXPECT_EQ(error_of(kScene, {"materials.wood.lambda_min=nan"}),
            "--set materials.wood.lambda_min: 'lambda_min' must be finite (got nan)");
  EXPECT_EQ(error_of(kScene, {"render.displacement=fastest"}),
            "--set render.displacement: 'displacement' must be one of weighted_average, "
            "exact_max (got 'fastest')");
  EXPECT_EQ(error_of(kScene, {"probe.position=[0,0]"}),
            "--set probe.position: 'position' must be an array of 3 numbers (got 2 elements)");
  EXPECT_EQ(error_of(kScene, {"surfaces.1.material=cork"}),
            "--set surfaces.1.material: 'material' names unknown material 'cork'; defined "
            "materials: wood");
}

TEST(SceneOverrideTest, MalformedOverrides) {
  EXPECT_EQ(error_of(kScene, {"probe.radius_mm"}),
            "--set probe.radius_mm: expected KEY=VALUE (e.g. probe.radius_mm=10)");
  EXPECT_EQ(error_of(kScene, {"surfaces.7.radius_mm=3"}),
            "--set surfaces.7.radius_mm: no surface '7' (the scene has 2 surfaces, numbered "
            "from 0)");
  EXPECT_EQ(error_of(kScene, {"materials.lambda_min=3"}),
            "--set materials.lambda_min: expected materials.NAME.KEY=VALUE (or "
            "materials.NAME.haptic.KEY, materials.NAME.haptic.texture.N.KEY)");
  // A bare section name (found by the scene fuzzer: it read past the path's one part).
  EXPECT_EQ(error_of(kScene, {"materials=3"}),
            "--set materials: expected materials.NAME.KEY=VALUE (or "
            "materials.NAME.haptic.KEY, materials.NAME.haptic.texture.N.KEY)");
}

// A relative file value in an override resolves against where it was written (docs/scene-format.md
// "Paths"): anchor_override_path makes it absolute against the given directory.
TEST(SceneOverridePaths, RelativeFileValueAnchored) {
  EXPECT_EQ(anchor_override_path("materials.wood.intensity_lut=my.lut", "/w"),
            "materials.wood.intensity_lut=\"/w/my.lut\"");
  EXPECT_EQ(anchor_override_path("materials.wood.speed_gain_lut = \"t/../g.lut\"", "/w"),
            "materials.wood.speed_gain_lut=\"/w/g.lut\"");
  EXPECT_EQ(anchor_override_path("surfaces.0.mesh_file=m.obj", "/w"), "surfaces.0.mesh_file=\"/w/m.obj\"");
  EXPECT_EQ(anchor_override_path("buttons.0.action=\"scene:b.toml\"", "/w"),
            "buttons.0.action=\"scene:/w/b.toml\"");
}

TEST(SceneOverridePaths, OtherValuesUnchanged) {
  for (const std::string text : {"materials.wood.intensity_lut=\"/abs/my.lut\"", "probe.radius_mm=12",
                                 "render.displacement=exact_max", "buttons.0.action=\"flag:lamp\"",
                                 "materials.wood.intensity_lut=\"\"", "no equals sign"}) {
    EXPECT_EQ(anchor_override_path(text, "/w"), text);
  }
}

}  // namespace
}  // namespace ps
