// [materials.NAME.haptic] keys, texture waves, box surfaces, visible/touchable: values, exact
// "file:line: message" errors, and --set reaching the new keys.
#include <gtest/gtest.h>

#include "scene_test_util.h"

namespace ps {
namespace {

using test::error_of;
using test::parse;

// kMinimalScene has 6 lines; appended text starts at line 7.
std::string with(const std::string& extra) { return std::string(test::kMinimalScene) + extra; }

const char* kFeel = R"(
[materials.wood.haptic]
stiffness_n_per_mm = 0.8
stiffness_exponent = 0.5
damping_n_s_per_mm = 0.004
static_friction = 0.6
dynamic_friction = 0.4
friction_history_ticks = 12
stick_speed_mm_s = 3
magnetic_force_n = 1.5
magnetic_range_mm = 15
stickiness_n = 0.7
restitution = 0.25

[[materials.wood.haptic.texture]]
shape = "square"
amplitude_n = 0.2
period_mm = 4
direction = [3, 4]

[[materials.wood.haptic.texture]]
amplitude_n = 0.1
period_mm = 1.5
)";

TEST(SceneHapticTest, ReadsEveryHapticKeyAndWave) {
  Result<Scene> scene = parse(with(kFeel));
  ASSERT_TRUE(scene) << scene.error().message;
  const HapticMaterial& h = scene->materials[0].haptic;
  EXPECT_EQ(h.stiffness_n_per_mm, 0.8);
  EXPECT_EQ(h.stiffness_exponent, 0.5);
  EXPECT_EQ(h.damping_n_s_per_mm, 0.004);
  EXPECT_EQ(h.static_friction, 0.6);
  EXPECT_EQ(h.dynamic_friction, 0.4);
  EXPECT_EQ(h.friction_history_ticks, 12);
  EXPECT_EQ(h.stick_speed_mm_s, 3.0);
  EXPECT_FALSE(h.penetrable);
  EXPECT_EQ(h.magnetic_force_n, 1.5);
  EXPECT_EQ(h.magnetic_range_mm, 15.0);
  EXPECT_EQ(h.stickiness_n, 0.7);
  EXPECT_EQ(h.restitution, 0.25);
  ASSERT_EQ(h.texture.size(), 2u);
  EXPECT_EQ(h.texture[0].shape, HapticWave::Shape::kSquare);
  EXPECT_EQ(h.texture[0].amplitude_n, 0.2);
  EXPECT_EQ(h.texture[0].period_mm, 4.0);
  // [3, 4] normalised: a 3-4-5 triangle, exact in binary up to one rounding.
  EXPECT_DOUBLE_EQ(h.texture[0].direction.x, 0.6);
  EXPECT_DOUBLE_EQ(h.texture[0].direction.y, 0.8);
  EXPECT_EQ(h.texture[1].shape, HapticWave::Shape::kSine);  // defaults
  EXPECT_EQ(h.texture[1].direction, glm::dvec2(1.0, 0.0));
}

TEST(SceneHapticTest, AbsentHapticTableKeepsTheDefaults) {
  Result<Scene> scene = parse(test::kMinimalScene);
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->materials[0].haptic, HapticMaterial{});
}

TEST(SceneHapticTest, PenetrableMaterialWithViscosity) {
  Result<Scene> scene =
      parse(with("[materials.water.haptic]\npenetrable = true\nviscosity_n_s_per_mm = 0.02\n"));
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_TRUE(scene->materials[1].haptic.penetrable);
  EXPECT_EQ(scene->materials[1].haptic.viscosity_n_s_per_mm, 0.02);
}

TEST(SceneHapticTest, BadValuesAreErrorsAtTheirLine) {
  EXPECT_EQ(error_of(with("[materials.x.haptic]\nstiffness_n_per_mm = -1\n")),
            "s.toml:8: 'stiffness_n_per_mm' must be in [0, 100] (got -1)");
  EXPECT_EQ(error_of(with("[materials.x.haptic]\nrestitution = 1.5\n")),
            "s.toml:8: 'restitution' must be in [0, 1] (got 1.5)");
  EXPECT_EQ(error_of(with("[materials.x.haptic]\nstatic_friction = 0.2\ndynamic_friction = 0.5\n")),
            "s.toml:9: 'dynamic_friction' (0.5) must be <= 'static_friction' (0.2)");
  EXPECT_EQ(error_of(with("[materials.x.haptic]\nviscosity_n_s_per_mm = 0.1\n")),
            "s.toml:8: 'viscosity_n_s_per_mm' acts only inside a penetrable material; add "
            "'penetrable = true' (water, thick fluid)");
  EXPECT_EQ(error_of(with("[materials.x.haptic]\nmagnetic_force_n = 1\n")),
            "s.toml:7: 'magnetic_range_mm' must be > 0 when 'magnetic_force_n' is set (the "
            "attraction acts within this range)");  // absent key: the table's line
  EXPECT_EQ(error_of(with("[materials.x.haptic]\nfriction_history_ticks = 33\n")),
            "s.toml:8: 'friction_history_ticks' must be in [1, 32] (got 33)");
  EXPECT_EQ(error_of(with("[materials.x]\nhaptic = 3\n")),
            "s.toml:8: 'haptic' must be a table ([materials.x.haptic])");
}

TEST(SceneHapticTest, BadWavesAreErrorsAtTheirLine) {
  const std::string wave = "[[materials.x.haptic.texture]]\n";
  EXPECT_EQ(error_of(with(wave + "period_mm = 0\n")),
            "s.toml:8: 'period_mm' must be in (0, 100000] (got 0)");
  EXPECT_EQ(error_of(with(wave + "shape = \"triangle\"\n")),
            "s.toml:8: 'shape' must be one of sine, square (got 'triangle')");
  EXPECT_EQ(error_of(with(wave + "amplitude_n = 1\n" + wave + "direction = [0, 0]\n")),
            "s.toml:10: 'direction' must be non-zero");
  EXPECT_EQ(error_of(with("[materials.x.haptic]\ntexture = 1\n")),
            "s.toml:8: 'texture' must be an array of tables ([[materials.x.haptic.texture]])");
  std::string many;
  for (int i = 0; i < kMaxHapticWaves + 1; ++i) many += wave;
  EXPECT_EQ(error_of(with(many)), "s.toml:7: 'texture' has 17 waves, more than the limit of 16");
}

TEST(SceneHapticTest, UnknownHapticKeysSuggestTheClosest) {
  EXPECT_EQ(error_of(with("[materials.x.haptic]\nstifness_n_per_mm = 1\n")),
            "s.toml:8: unknown key 'stifness_n_per_mm' in [materials.x.haptic]; did you mean "
            "'stiffness_n_per_mm'?");
  EXPECT_EQ(error_of(with("[materials.x.haptic]\nrestitution_coefficient = 1\n")),
            "s.toml:8: unknown key 'restitution_coefficient' in [materials.x.haptic]; did you "
            "mean 'restitution'?");
  EXPECT_EQ(error_of(with("[[materials.x.haptic.texture]]\nperiod = 2\n")),
            "s.toml:8: unknown key 'period' in [[materials.x.haptic.texture]] #0; did you mean "
            "'period_mm'?");
}

TEST(SceneHapticTest, SetReachesHapticKeysAndWaves) {
  Result<Scene> scene = parse(with(kFeel), {"materials.wood.haptic.restitution=0.9",
                                            "materials.wood.haptic.texture.1.shape=square",
                                            "materials.oak.haptic.stickiness_n=2"});
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->materials[0].haptic.restitution, 0.9);
  EXPECT_EQ(scene->materials[0].haptic.texture[1].shape, HapticWave::Shape::kSquare);
  ASSERT_EQ(scene->materials.size(), 2u);
  EXPECT_EQ(scene->materials[1].haptic.stickiness_n, 2.0);
  EXPECT_EQ(error_of(with(kFeel), {"materials.wood.haptic.restitution=2"}),
            "--set materials.wood.haptic.restitution: 'restitution' must be in [0, 1] (got 2)");
  EXPECT_EQ(error_of(with(kFeel), {"materials.wood.haptic.stifness_n_per_mm=1"}),
            "--set materials.wood.haptic.stifness_n_per_mm: unknown key; close matches: "
            "stiffness_n_per_mm");
  EXPECT_EQ(error_of(with(kFeel), {"materials.wood.haptic.texture.2.period_mm=1"}),
            "--set materials.wood.haptic.texture.2.period_mm: no texture wave '2' "
            "(materials.wood.haptic has 2 texture waves, numbered from 0)");
  EXPECT_EQ(error_of(with(kFeel), {"materials.wood.feel.x=1"}),
            "--set materials.wood.feel.x: expected materials.NAME.KEY=VALUE (or "
            "materials.NAME.haptic.KEY, materials.NAME.haptic.texture.N.KEY)");
}

TEST(SceneHapticTest, VisibleTouchableAndBox) {
  Result<Scene> scene = parse(with("visible = false\n\n[[surfaces]]\ntype = \"box\"\n"
                                   "material = \"wood\"\nsize_mm = [10, 20, 30]\n"
                                   "touchable = false\n"));
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_FALSE(scene->surfaces[0].visible);
  EXPECT_TRUE(scene->surfaces[0].touchable);
  EXPECT_EQ(scene->surfaces[1].type, SurfaceType::kBox);
  EXPECT_EQ(scene->surfaces[1].box_size_mm, glm::dvec3(10, 20, 30));
  EXPECT_EQ(scene->surfaces[1].size_mm, Surface{}.size_mm) << "the plane extent is untouched";
  EXPECT_TRUE(scene->surfaces[1].visible);
  EXPECT_FALSE(scene->surfaces[1].touchable);
  EXPECT_EQ(error_of(with("type = \"box\"\nsize_mm = [10, 20]\n")),
            "s.toml:8: 'size_mm' must be an array of 3 numbers (got 2 elements)");
  EXPECT_EQ(error_of(with("type = \"box\"\nsize_mm = [10, 0, 2]\n")),
            "s.toml:8: 'size_mm' must be in (0, 100000] (got 0)");
  EXPECT_EQ(error_of(with("visible = \"no\"\n")), "s.toml:7: 'visible' must be true or false");
  Result<Scene> set = parse(with(""), {"surfaces.0.type=box", "surfaces.0.size_mm=[1,2,3]",
                                       "surfaces.0.visible=false"});
  ASSERT_TRUE(set) << set.error().message;
  EXPECT_EQ(set->surfaces[0].box_size_mm, glm::dvec3(1, 2, 3));
  EXPECT_FALSE(set->surfaces[0].visible);
}

}  // namespace
}  // namespace ps
