// Each kind of scene error: exact "file:line: message" wording.
#include <gtest/gtest.h>

#include "scene_test_util.h"

namespace ps {
namespace {

using test::error_of;

// kMinimalScene has 6 lines; appended text starts at line 7.
std::string with(const std::string& extra) { return std::string(test::kMinimalScene) + extra; }

TEST(SceneErrorTest, SyntaxErrorHasFileAndLine) {
  const std::string e = error_of("[camera]\nfov_y_deg = 40\nposition = [0, 0\n");
  EXPECT_EQ(e.rfind("s.toml:3: syntax error: ", 0), 0u) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << "one line";
}

TEST(SceneErrorTest, UnknownKeySuggestsTheClosestKnownKey) {
  EXPECT_EQ(error_of(with("[materials.oak]\nlambda_max = 1\nlamda_min = 0.4\n")),
            "s.toml:9: unknown key 'lamda_min' in [materials.oak]; did you mean 'lambda_min'?");
  EXPECT_EQ(error_of(with("[camra]\n")),
            "s.toml:7: unknown key 'camra' in the scene; did you mean 'camera'?");
  EXPECT_EQ(error_of(with("[render]\ncolour_space = 1\n")),
            "s.toml:8: unknown key 'colour_space' in [render]");
  EXPECT_EQ(error_of(with("rezolution = 3\n")),
            "s.toml:7: unknown key 'rezolution' in [[surfaces]] #0; did you mean 'resolution'?");
}

TEST(SceneErrorTest, WrongTypes) {
  EXPECT_EQ(error_of(with("[probe]\nradius_mm = \"big\"\n")),
            "s.toml:8: 'radius_mm' must be a number");
  EXPECT_EQ(error_of(with("[render]\nframes = 2.5\n")), "s.toml:8: 'frames' must be an integer");
  EXPECT_EQ(error_of(with("[materials.x]\ntextured = 1\n")),
            "s.toml:8: 'textured' must be true or false");
  EXPECT_EQ(error_of(with("[probe]\nposition = [0, \"a\", 1]\n")),
            "s.toml:8: 'position' must be an array of 3 numbers");
  EXPECT_EQ(error_of(with("[camera]\nprojection = \"fisheye\"\n")),
            "s.toml:8: 'projection' must be one of perspective, orthographic (got 'fisheye')");
  EXPECT_EQ(error_of("camera = 3\n" + with("")), "s.toml:1: 'camera' must be a table");
}

// The feedback keys of [render] (render.pseudo_shadow, draw_probe, cast_shadow): booleans, read
// from the file and from --set; a wrong type names the file:line (or the --set) and the key.
TEST(SceneErrorTest, FeedbackKeysAreBooleans) {
  EXPECT_EQ(error_of(with("[render]\npseudo_shadow = 0\n")), "s.toml:8: 'pseudo_shadow' must be true or false");
  EXPECT_EQ(error_of(with("[render]\nsize = [64, 64]\ndraw_probe = \"yes\"\n")),
            "s.toml:9: 'draw_probe' must be true or false");
  EXPECT_EQ(error_of(with("[render]\ncast_shadow = [true]\n")), "s.toml:8: 'cast_shadow' must be true or false");
  EXPECT_NE(error_of(with(""), {"render.cast_shadow=1"}).find("'cast_shadow' must be true or false"),
            std::string::npos);
  const Result<Scene> defaults = test::parse(with(""));
  ASSERT_TRUE(defaults) << defaults.error().message;
  EXPECT_TRUE(defaults.value().render.pseudo_shadow);
  EXPECT_FALSE(defaults.value().render.draw_probe);
  EXPECT_FALSE(defaults.value().render.cast_shadow);
  const Result<Scene> set = test::parse(with("[render]\npseudo_shadow = false\ndraw_probe = true\n"),
                                        {"render.cast_shadow=true"});
  ASSERT_TRUE(set) << set.error().message;
  EXPECT_FALSE(set.value().render.pseudo_shadow);
  EXPECT_TRUE(set.value().render.draw_probe);
  EXPECT_TRUE(set.value().render.cast_shadow);
}

TEST(SceneErrorTest, ArraysOfTheWrongLength) {
  EXPECT_EQ(error_of(with("[probe]\nvelocity = [1, 2]\n")),
            "s.toml:8: 'velocity' must be an array of 3 numbers (got 2 elements)");
  EXPECT_EQ(error_of(with("[render]\nsize = [640]\n")),
            "s.toml:8: 'size' must be an array of 2 numbers (got 1 elements)");
}

TEST(SceneErrorTest, NanAndInfAreRejected) {
  EXPECT_EQ(error_of(with("[probe]\nradius_mm = nan\n")),
            "s.toml:8: 'radius_mm' must be finite (got nan)");
  EXPECT_EQ(error_of(with("[probe]\nposition = [0, -inf, 0]\n")),
            "s.toml:8: 'position' must be finite (got -inf)");
}

TEST(SceneErrorTest, OutOfRangeValuesNameTheLimit) {
  EXPECT_EQ(error_of(with("[probe]\nradius_mm = 0\n")),
            "s.toml:8: 'radius_mm' must be in (0, 100000] (got 0)");
  EXPECT_EQ(error_of(with("[render]\nframes = 0\n")),
            "s.toml:8: 'frames' must be in [1, 100000] (got 0)");
  EXPECT_EQ(error_of(with("[render]\nframes = 100001\n")),
            "s.toml:8: 'frames' must be in [1, 100000] (got 100001)");
  EXPECT_EQ(error_of(with("[render]\nsize = [9000, 10]\n")),
            "s.toml:8: 'size' must have both values in [1, 8192] (got 9000)");
  EXPECT_EQ(error_of(with("[render]\nsize = [8192, 4096]\n")),
            "s.toml:8: 'size' has 33554432 pixels, more than the limit of 16777216");
  EXPECT_EQ(error_of(with("[render]\ndepth_map_size = 300\n")),
            "s.toml:8: 'depth_map_size' must be a power of two in [16, 4096] (got 300)");
  EXPECT_EQ(error_of(with("[render]\ndepth_map_size = 8192\n")),
            "s.toml:8: 'depth_map_size' must be in [16, 4096] (got 8192)");
  EXPECT_EQ(error_of(with("[materials.x]\nn_max = 20000\n")),
            "s.toml:8: 'n_max' must be in [0, 10000] (got 20000)");
  EXPECT_EQ(error_of(with("[materials.x]\nlambda_min = -1\n")),
            "s.toml:8: 'lambda_min' must be in (0, 1000] (got -1)");
  EXPECT_EQ(error_of(with("[materials.x]\nresistance = -0.5\n")),
            "s.toml:8: 'resistance' must be in [0, 1] (got -0.5)");
  EXPECT_EQ(error_of(with("size_mm = [0, 10]\n")),
            "s.toml:7: 'size_mm' must be in (0, 100000] (got 0)");
}

TEST(SceneErrorTest, MinAboveMaxIsRejectedExceptForTheta) {
  EXPECT_EQ(error_of(with("[materials.x]\nlambda_min = 2\nlambda_max = 1\n")),
            "s.toml:8: 'lambda_min' (2) must be <= 'lambda_max' (1)");
  EXPECT_EQ(error_of(with("[materials.x]\nn_max = 5\n")),
            "s.toml:7: 'n_min' (20) must be <= 'n_max' (5)");  // n_min absent: table line
  EXPECT_EQ(error_of(with("[materials.x]\na_min = 0.9\na_max = 0.2\n")),
            "s.toml:8: 'a_min' (0.9) must be <= 'a_max' (0.2)");
  EXPECT_EQ(error_of(with("[materials.x]\ntheta_min = 90\ntheta_max = 0\n")), "<ok>");
}

TEST(SceneErrorTest, UnknownMaterialListsTheDefinedOnes) {
  EXPECT_EQ(error_of("[materials.wood]\n[materials.paper]\n[[surfaces]]\nmaterial = \"woood\"\n"),
            "s.toml:4: 'material' names unknown material 'woood'; defined materials: wood, paper");
  EXPECT_EQ(error_of("[materials.wood]\n[[surfaces]]\ntype = \"sphere\"\n"),
            "s.toml:2: 'material' is required; defined materials: wood");
}

TEST(SceneErrorTest, MaterialsAndSurfacesAreRequired) {
  EXPECT_EQ(error_of("[[surfaces]]\nmaterial = \"x\"\n"),
            "s.toml:1: the scene defines no materials; add at least one [materials.NAME] table");
  EXPECT_EQ(error_of("[materials.x]\n"),
            "s.toml:1: the scene defines no surfaces; add at least one [[surfaces]] table");
}

TEST(SceneErrorTest, MissingFilesNameTheResolvedPathAndTheLine) {
  const std::string scenes = test::scenes_dir();
  EXPECT_EQ(error_of(with("[[surfaces]]\ntype = \"mesh\"\nmaterial = \"wood\"\n"
                          "mesh_file = \"meshes/bunny.obj\"\n")),
            "s.toml:10: 'mesh_file' file not found: " + scenes + "/meshes/bunny.obj");
  // An absolute path inside the scene's tree (one outside it is refused first: path_policy_test).
  EXPECT_EQ(error_of(with("[materials.x]\nalbedo_texture = \"" + scenes + "/nonexistent/t.png\"\n")),
            "s.toml:8: 'albedo_texture' file not found: " + scenes + "/nonexistent/t.png");
  EXPECT_EQ(error_of(with("type = \"heightfield\"\nheightmap = \"../textures/nope.png\"\n")),
            "s.toml:8: 'heightmap' file not found: " + std::string(PS_SOURCE_DIR) +
                "/textures/nope.png");
  EXPECT_EQ(error_of(with("type = \"mesh\"\n")),
            "s.toml:5: 'mesh_file' is required when type = \"mesh\"");
}

TEST(SceneErrorTest, CrossKeyRules) {
  EXPECT_EQ(error_of(with("[camera]\nposition = [0, 0, 0]\n")),
            "s.toml:7: 'target' must differ from 'position'");  // absent: the table's line
  EXPECT_EQ(error_of(with("[camera]\nup = [0, 0, 1]\nposition = [0, 0, 10]\n")),
            "s.toml:8: 'up' must be non-zero and not parallel to the view direction "
            "(target - position)");
  EXPECT_EQ(error_of(with("type = \"torus\"\nradius_mm = 10\nminor_radius_mm = 10\n")),
            "s.toml:9: 'minor_radius_mm' must be < 'radius_mm' for a torus (a ring torus)");
}

}  // namespace
}  // namespace ps
