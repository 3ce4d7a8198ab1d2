// `include`: material libraries, the override rule, cycles, missing files, errors at the
// included file's own line, --set on included materials, and the shipped library.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "scene_test_util.h"

namespace ps {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test under the build tree, with files written by the test so each
// expected line number can be read off the text right here.
class SceneIncludeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(PS_BINARY_DIR) / "scene_include_test" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "lib");
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  Result<Scene> load(const std::string& text, const std::vector<std::string>& sets = {}) {
    write("scene.toml", text);
    return load_scene((dir_ / "scene.toml").string(), sets);
  }
  std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
    Result<Scene> scene = load(text, sets);
    return scene ? std::string("<ok>") : scene.error().message;
  }
  std::string name(const std::string& file) const { return (dir_ / file).string(); }
  fs::path dir_;
};

const char* kLibrary = R"(# line 1
[materials.oak]
lambda_min = 0.3

[materials.oak.haptic]
stiffness_n_per_mm = 0.9

[materials.felt]
lambda_min = 0.4
)";

TEST_F(SceneIncludeTest, IncludedMaterialsAreUsableByName) {
  write("lib/a.toml", kLibrary);
  Result<Scene> scene = load("include = [\"lib/a.toml\"]\n[materials.own]\n"
                             "[[surfaces]]\nmaterial = \"oak\"\n");
  ASSERT_TRUE(scene) << scene.error().message;
  // The scene's own material first, then the used included one; unused 'felt' is not kept.
  ASSERT_EQ(scene->materials.size(), 2u);
  EXPECT_EQ(scene->materials[0].name, "own");
  EXPECT_EQ(scene->materials[1].name, "oak");
  EXPECT_EQ(scene->materials[1].gabor.lambda_min_mm, 0.3);
  EXPECT_EQ(scene->materials[1].haptic.stiffness_n_per_mm, 0.9);
  EXPECT_EQ(scene->surfaces[0].material_index, 1);
}

TEST_F(SceneIncludeTest, ALocalDefinitionReplacesTheIncludedOneWhole) {
  write("lib/a.toml", kLibrary);
  Result<Scene> scene = load("include = \"lib/a.toml\"\n[materials.oak]\nlambda_min = 0.45\n"
                             "[[surfaces]]\nmaterial = \"oak\"\n");
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_EQ(scene->materials.size(), 1u);
  EXPECT_EQ(scene->materials[0].gabor.lambda_min_mm, 0.45);
  EXPECT_EQ(scene->materials[0].haptic, HapticMaterial{}) << "no key merging";
}

TEST_F(SceneIncludeTest, ErrorsInAnIncludedFileCarryItsOwnFileAndLine) {
  write("lib/a.toml", "[materials.oak]\n\n[materials.oak.haptic]\nrestitution = 3\n");
  const std::string e = error_of("include = [\"lib/a.toml\"]\n[[surfaces]]\nmaterial = \"oak\"\n");
  EXPECT_EQ(e, name("lib/a.toml") + ":4: 'restitution' must be in [0, 1] (got 3)");
  write("lib/a.toml", "[materials.oak]\nlamda_min = 1\n");
  EXPECT_EQ(error_of("include = [\"lib/a.toml\"]\n[[surfaces]]\nmaterial = \"oak\"\n"),
            name("lib/a.toml") + ":2: unknown key 'lamda_min' in [materials.oak]; did you "
            "mean 'lambda_min'?");
  write("lib/a.toml", "[materials.oak\n");
  EXPECT_EQ(error_of("include = [\"lib/a.toml\"]\n").rfind(name("lib/a.toml") + ":1: syntax "
                                                           "error: ", 0), 0u);
  write("lib/a.toml", "[materials.oak]\n[camera]\nfov_y_deg = 3\n");
  EXPECT_EQ(error_of("include = [\"lib/a.toml\"]\n"),
            name("lib/a.toml") + ":2: an included file may hold only 'include' and "
            "[materials.NAME] tables (found 'camera')");
}

TEST_F(SceneIncludeTest, UnusedIncludedMaterialsAreStillValidated) {
  write("lib/a.toml", "[materials.used]\n[materials.unused]\nn_max = -1\n");
  EXPECT_EQ(error_of("include = [\"lib/a.toml\"]\n[[surfaces]]\nmaterial = \"used\"\n"),
            name("lib/a.toml") + ":3: 'n_max' must be in [0, 10000] (got -1)");
}

TEST_F(SceneIncludeTest, AMissingFileNamesTheIncludingLine) {
  EXPECT_EQ(error_of("# comment\ninclude = [\"nope.toml\"]\n"),
            name("scene.toml") + ":2: 'include' file not found: " + name("nope.toml"));
  write("lib/a.toml", "include = [\"b.toml\"]\n");
  EXPECT_EQ(error_of("include = [\"lib/a.toml\"]\n"),
            name("lib/a.toml") + ":1: 'include' file not found: " + name("lib/b.toml"));
  EXPECT_EQ(error_of("include = [3]\n"),
            name("scene.toml") + ":1: 'include' must be a file name or an array of file names "
            "(e.g. include = [\"materials/virtual_universe.toml\"])");
}

// A renamed library keeps its old file for one release, holding only `renamed_to`: it loads the
// new file's materials and prints one line naming both files as messages name them.
TEST_F(SceneIncludeTest, ARenamedLibraryStandsForItsNewFileAndSaysSo) {
  write("lib/new.toml", kLibrary);
  write("lib/old.toml", "# moved\nrenamed_to = \"new.toml\"\n");
  const std::string surfaces = "[[surfaces]]\nmaterial = \"oak\"\n";
  ::testing::internal::CaptureStderr();
  Result<Scene> old_name = load("include = [\"lib/old.toml\"]\n" + surfaces);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(),
            name("lib/old.toml") + " was renamed to " + name("lib/new.toml") +
                "; the old name goes in the next release\n");
  ASSERT_TRUE(old_name) << old_name.error().message;
  ::testing::internal::CaptureStderr();
  Result<Scene> new_name = load("include = [\"lib/new.toml\"]\n" + surfaces);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << "the new name says nothing";
  ASSERT_TRUE(new_name) << new_name.error().message;
  EXPECT_EQ(old_name->materials, new_name->materials);
  EXPECT_EQ(old_name->materials[0].haptic.stiffness_n_per_mm, 0.9);
}

TEST_F(SceneIncludeTest, ARenamedLibraryHoldsNothingElse) {
  const std::string must = ":2: 'renamed_to' must be the only key of a renamed library, the new "
                           "file's name in the same folder (e.g. renamed_to = "
                           "\"virtual_universe.toml\")";
  write("lib/old.toml", "# moved\nrenamed_to = \"new.toml\"\n[materials.oak]\n");
  EXPECT_EQ(error_of("include = [\"lib/old.toml\"]\n"), name("lib/old.toml") + must);
  write("lib/old.toml", "# moved\nrenamed_to = \"../new.toml\"\n");
  EXPECT_EQ(error_of("include = [\"lib/old.toml\"]\n"), name("lib/old.toml") + must);
  write("lib/old.toml", "# moved\nrenamed_to = 3\n");
  EXPECT_EQ(error_of("include = [\"lib/old.toml\"]\n"), name("lib/old.toml") + must);
  write("lib/old.toml", "# moved\nrenamed_to = \"missing.toml\"\n");
  EXPECT_EQ(error_of("include = [\"lib/old.toml\"]\n"),
            name("lib/old.toml") + ":2: 'include' file not found: " + name("lib/missing.toml"));
}

TEST_F(SceneIncludeTest, ACycleIsAnErrorNamingTheCycle) {
  write("lib/a.toml", "include = [\"b.toml\"]\n");
  write("lib/b.toml", "# b\ninclude = [\"a.toml\"]\n");
  EXPECT_EQ(error_of("include = [\"lib/a.toml\"]\n"),
            name("lib/b.toml") + ":2: include cycle: " + name("lib/a.toml") + " -> " +
                name("lib/b.toml") + " -> " + name("lib/a.toml"));
  write("lib/self.toml", "include = \"self.toml\"\n");
  EXPECT_EQ(error_of("include = [\"lib/self.toml\"]\n"),
            name("lib/self.toml") + ":1: include cycle: " + name("lib/self.toml") + " -> " +
                name("lib/self.toml"));
  // Through the scene itself.
  write("lib/back.toml", "include = \"../scene.toml\"\n");
  EXPECT_EQ(error_of("include = [\"lib/back.toml\"]\n"),
            name("lib/back.toml") + ":1: include cycle: " + name("scene.toml") + " -> " +
                name("lib/back.toml") + " -> " + name("scene.toml"));
}

TEST_F(SceneIncludeTest, TwoIncludesDefiningOneNameNeedTheSceneToChoose) {
  write("lib/a.toml", "[materials.oak]\nlambda_min = 0.3\n");
  write("lib/b.toml", "[materials.oak]\nlambda_min = 0.4\n");
  const std::string scene = "include = [\"lib/a.toml\", \"lib/b.toml\"]\n[[surfaces]]\n"
                            "material = \"oak\"\n";
  EXPECT_EQ(error_of(scene), name("scene.toml") + ":1: material 'oak' is defined differently in " +
                                 name("lib/a.toml") + " and " + name("lib/b.toml") +
                                 "; define [materials.oak] in " + name("scene.toml") +
                                 " to choose");
  EXPECT_EQ(error_of(scene + "[materials.oak]\nlambda_min = 0.5\n"), "<ok>");
  // A diamond (both include one file) defines 'oak' once: no conflict.
  write("lib/common.toml", "[materials.oak]\nlambda_min = 0.2\n");
  write("lib/a.toml", "include = \"common.toml\"\n");
  write("lib/b.toml", "include = \"common.toml\"\n");
  Result<Scene> diamond = load(scene);
  ASSERT_TRUE(diamond) << diamond.error().message;
  EXPECT_EQ(diamond->materials[0].gabor.lambda_min_mm, 0.2);
}

TEST_F(SceneIncludeTest, RelativePathsInALibraryResolveAgainstTheLibrary) {
  fs::copy_file(fs::path(PS_SOURCE_DIR) / "textures" / "paper.png", dir_ / "lib" / "paper.png");
  write("lib/a.toml", "[materials.oak]\nalbedo_texture = \"paper.png\"\n");
  Result<Scene> scene = load("include = [\"lib/a.toml\"]\n[[surfaces]]\nmaterial = \"oak\"\n");
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->materials[0].albedo_texture, name("lib/paper.png"));
}

TEST_F(SceneIncludeTest, SetReachesAnIncludedMaterial) {
  write("lib/a.toml", kLibrary);
  const std::string scene = "include = [\"lib/a.toml\"]\n[[surfaces]]\nmaterial = \"oak\"\n";
  Result<Scene> set = load(scene, {"materials.oak.haptic.restitution=0.5"});
  ASSERT_TRUE(set) << set.error().message;
  EXPECT_EQ(set->materials[0].haptic.restitution, 0.5);
  EXPECT_EQ(set->materials[0].haptic.stiffness_n_per_mm, 0.9) << "the other keys stay";
  EXPECT_EQ(error_of(scene, {"materials.oak.lambda_min=-1"}),
            "--set materials.oak.lambda_min: 'lambda_min' must be in (0, 1000] (got -1)");
  EXPECT_EQ(error_of(scene, {"include=[\"x.toml\"]"}),
            "--set include: includes cannot be set from the command line; edit the scene "
            "file's 'include' instead");
}

// The shipped library: every material parses, and each feels the way its name says
// (relations between materials, stated independently of the numbers in the file).
TEST(SceneLibraryTest, VirtualUniverseMaterialsParseAndDifferInFeel) {
  std::string text = "include = [\"materials/virtual_universe.toml\"]\n";
  const char* names[] = {"polished_wood", "rough_wood", "sandpaper", "cobblestone", "magnetic",
                         "water", "thick_fluid", "rubber", "plastic", "sticky"};
  for (const char* n : names) text += "[[surfaces]]\nmaterial = \"" + std::string(n) + "\"\n";
  Result<Scene> scene = test::parse(text);
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_EQ(scene->materials.size(), 10u);
  auto feel = [&](const std::string& n) -> const HapticMaterial& {
    return scene->materials[static_cast<std::size_t>(
                                std::find(std::begin(names), std::end(names), n) - names)]
        .haptic;
  };
  for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(scene->materials[i].name, names[i]);
  EXPECT_TRUE(feel("water").penetrable);
  EXPECT_TRUE(feel("thick_fluid").penetrable);
  EXPECT_GT(feel("thick_fluid").viscosity_n_s_per_mm, feel("water").viscosity_n_s_per_mm);
  EXPECT_GT(feel("magnetic").magnetic_force_n, 0.0);
  EXPECT_GT(feel("sticky").stickiness_n, 0.0);
  EXPECT_GT(feel("rough_wood").dynamic_friction, feel("polished_wood").dynamic_friction);
  EXPECT_GT(feel("sandpaper").dynamic_friction, feel("plastic").dynamic_friction);
  EXPECT_LT(feel("rubber").stiffness_n_per_mm, feel("plastic").stiffness_n_per_mm);
  for (const char* n : names) {
    if (std::string(n) != "rubber") {
      EXPECT_GT(feel("rubber").restitution, feel(n).restitution) << n;
    }
  }
  EXPECT_FALSE(feel("cobblestone").texture.empty());
  EXPECT_FALSE(feel("sandpaper").texture.empty());
}

// The library's old name works for one release: the same ten materials, and one line on stderr.
TEST(SceneLibraryTest, TheOldNameSeed002LoadsTheVirtualUniverseMaterialsAndSaysSo) {
  std::string surfaces;
  for (const char* n : {"polished_wood", "rough_wood", "sandpaper", "cobblestone", "magnetic",
                        "water", "thick_fluid", "rubber", "plastic", "sticky"}) {
    surfaces += "[[surfaces]]\nmaterial = \"" + std::string(n) + "\"\n";
  }
  auto parse = [&](const std::string& library) {  // named as a scene under scenes/ would be
    return parse_scene("include = [\"materials/" + library + "\"]\n" + surfaces, "scenes/s.toml",
                       test::scenes_dir());
  };
  ::testing::internal::CaptureStderr();
  Result<Scene> old_name = parse("seed002.toml");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(),
            "scenes/materials/seed002.toml was renamed to scenes/materials/virtual_universe.toml; "
            "the old name goes in the next release\n");
  ASSERT_TRUE(old_name) << old_name.error().message;
  Result<Scene> new_name = parse("virtual_universe.toml");
  ASSERT_TRUE(new_name) << new_name.error().message;
  ASSERT_EQ(old_name->materials.size(), 10u);
  EXPECT_EQ(old_name->materials, new_name->materials);
}

TEST(SceneLibraryTest, MaterialsDemoLoads) {
  Result<Scene> scene = load_scene(test::scenes_dir() + "/materials_demo.toml");
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_EQ(scene->surfaces.size(), 5u);
  EXPECT_EQ(scene->surfaces[3].type, SurfaceType::kBox);
  EXPECT_FALSE(scene->surfaces[4].visible);
  EXPECT_EQ(scene->materials.size(), 5u) << "only the library's materials the scene uses";
}

}  // namespace
}  // namespace ps
