// Shipped scenes parse; defaults match scene.h; units convert (degrees -> radians).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "scene/mesh.h"
#include "scene_test_util.h"

namespace ps {
namespace {

using test::parse;

std::vector<std::string> shipped_scenes() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(test::scenes_dir())) {
    if (entry.path().extension() == ".toml") paths.push_back(entry.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

TEST(SceneParseTest, EveryShippedSceneParses) {
  const auto paths = shipped_scenes();
  EXPECT_GE(paths.size(), 13u);
  for (const std::string& path : paths) {
    Result<Scene> scene = load_scene(path);
    EXPECT_TRUE(scene) << path << ": " << (scene ? "" : scene.error().message);
  }
}

TEST(SceneParseTest, EveryShippedSurfaceBuildsAMesh) {
  for (const std::string& path : shipped_scenes()) {
    Result<Scene> scene = load_scene(path);
    ASSERT_TRUE(scene) << path;
    for (const Surface& surface : scene->surfaces) {
      if (surface.type == SurfaceType::kMesh && !std::filesystem::exists(surface.mesh_file)) {
        continue;  // Suzanne needs assimp-testmodels; load_scene would have failed anyway
      }
      Result<Mesh> mesh = build_surface_mesh(surface);
      EXPECT_TRUE(mesh) << path << ": " << (mesh ? "" : mesh.error().message);
    }
  }
}

TEST(SceneParseTest, EmbeddedDefaultMatchesTheFileAndParses) {
  std::ifstream in(test::scenes_dir() + "/default.toml");
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(std::string(default_scene_text()), file) << "rebuild: the embedded copy is stale";
  Result<Scene> scene =
      parse_scene(default_scene_text(), "<embedded default>", default_scene_base_dir());
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->probe.radius_mm, 8.0);
  EXPECT_EQ(scene->probe.position.z, 7.0);  // penetrates the plane by 1 mm
  EXPECT_GT(glm::length(scene->probe.velocity), 0.0);
  EXPECT_TRUE(std::filesystem::exists(scene->materials[0].albedo_texture));
}

TEST(SceneParseTest, AbsentKeysKeepTheDefaultsOfSceneH) {
  Result<Scene> scene = parse(test::kMinimalScene);
  ASSERT_TRUE(scene) << scene.error().message;
  const Scene defaults;
  EXPECT_EQ(scene->camera.position, defaults.camera.position);
  EXPECT_EQ(scene->camera.fov_y_deg, 40.0);
  EXPECT_EQ(scene->light.ambient, defaults.light.ambient);
  EXPECT_EQ(scene->probe.radius_mm, 8.0);
  EXPECT_EQ(scene->render.width, 512);
  EXPECT_EQ(scene->render.depth_map_size, 256);
  EXPECT_EQ(scene->render.displacement, DisplacementMethod::kWeightedAverage);
  ASSERT_EQ(scene->materials.size(), 1u);
  const Material& m = scene->materials[0];
  EXPECT_EQ(m.name, "wood");
  EXPECT_EQ(m.gabor.lambda_min_mm, 0.1);
  EXPECT_EQ(m.gabor.lambda_max_mm, 0.5);  // default
  EXPECT_EQ(m.gabor.n_max, 30.0);
  EXPECT_EQ(m.peak_hz, 250.0);
  ASSERT_EQ(scene->surfaces.size(), 1u);
  EXPECT_EQ(scene->surfaces[0].type, SurfaceType::kPlane);
  EXPECT_EQ(scene->surfaces[0].material_index, 0);
  EXPECT_EQ(scene->surfaces[0].line, 5);
  EXPECT_EQ(scene->path, "s.toml");
}

TEST(SceneParseTest, ThetaDegreesBecomeRadians) {
  Result<Scene> scene = parse(std::string(test::kMinimalScene) +
                              "[materials.paper]\ntheta_min = 30\ntheta_max = 180.0\n");
  ASSERT_TRUE(scene) << scene.error().message;
  const Material& paper = scene->materials[1];
  EXPECT_NEAR(paper.gabor.theta_min_rad, M_PI / 6.0, 1e-12);
  EXPECT_NEAR(paper.gabor.theta_max_rad, M_PI, 1e-12);
}

TEST(SceneParseTest, ReversedThetaRangeIsAllowed) {
  Result<Scene> scene = parse(std::string(test::kMinimalScene) +
                              "[materials.paper]\ntheta_min = 150\ntheta_max = 30\n");
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_GT(scene->materials[1].gabor.theta_min_rad, scene->materials[1].gabor.theta_max_rad);
}

TEST(SceneParseTest, MaterialsKeepFileOrderAndSurfacesResolveThem) {
  Result<Scene> scene = parse(R"([materials.zinc]
[materials.apple]
[[surfaces]]
material = "apple"
[[surfaces]]
type = "sphere"
material = "zinc"
)");
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->materials[0].name, "zinc");
  EXPECT_EQ(scene->surfaces[0].material_index, 1);
  EXPECT_EQ(scene->surfaces[1].material_index, 0);
}

TEST(SceneParseTest, EnumsAndVectors) {
  Result<Scene> scene = parse(std::string(test::kMinimalScene) + R"(
[camera]
projection = "orthographic"
up = [0, 1, 0]
position = [0, 0, 100]
[probe]
shape = "capsule"
axis = [0, 0, 2]
[render]
size = [640, 480]
displacement = "exact_max"
seed = 4294967295
)");
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->camera.projection, Projection::kOrthographic);
  EXPECT_EQ(scene->probe.shape, ProbeShape::kCapsule);
  EXPECT_EQ(scene->probe.axis, glm::dvec3(0, 0, 1));  // normalised
  EXPECT_EQ(scene->render.width, 640);
  EXPECT_EQ(scene->render.height, 480);
  EXPECT_EQ(scene->render.displacement, DisplacementMethod::kExactMax);
  EXPECT_EQ(scene->render.seed, 4294967295u);
}

TEST(SceneParseTest, RelativeAndAbsolutePathsResolve) {
  Result<Scene> scene = parse(std::string(test::kMinimalScene) +
                              "[[surfaces]]\ntype = \"heightfield\"\nmaterial = \"wood\"\n"
                              "heightmap = \"" + std::string(PS_SOURCE_DIR) +
                              "/textures/heightfield.png\"\n");
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->surfaces[1].heightmap, std::string(PS_SOURCE_DIR) + "/textures/heightfield.png");
  Result<Scene> ok = parse("[materials.wood]\nalbedo_texture = \"../textures/wood.png\"\n"
                           "[[surfaces]]\nmaterial = \"wood\"\n");
  ASSERT_TRUE(ok) << ok.error().message;
  EXPECT_EQ(ok->materials[0].albedo_texture, std::string(PS_SOURCE_DIR) + "/textures/wood.png");
}

TEST(SceneParseTest, LoadSceneMissingFile) {
  Result<Scene> scene = load_scene("/nonexistent/scene.toml");
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().message, "/nonexistent/scene.toml: cannot open scene file: no such file");
}

}  // namespace
}  // namespace ps
