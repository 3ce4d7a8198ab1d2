// The texture at hand speed (docs/scene-format.md, "The texture at hand speed"): on every
// shipped scene whose surface is the plane z = 0, an ordinary mouse stroke (400 px/s, turned
// into mm/s with the scene's own camera at the contact point) in the scene's stroke direction
// brings the texture up (amplitude gain > 0.5), and the gain still follows the speed: nearly
// nothing at rest, less again at four times the speed. No GL.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "haptics/screen_scale.h"
#include "reference/modulation.h"
#include "scene/scene_io.h"

namespace ps {
namespace {

struct Gains {
  double rest, hand, fast;  // at 0, 400 and 1600 px/s
  double mm_per_px;
};

Gains stroke_gains(const std::string& scene_name) {
  auto loaded = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/" + scene_name + ".toml");
  EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error().message);
  if (!loaded.ok()) return {};
  const Scene& s = loaded.value();
  // The scene's velocity gives the stroke's direction; its contact point is below the probe.
  const glm::dvec3 dir = glm::normalize(s.probe.velocity);
  const glm::dvec3 contact(s.probe.position.x, s.probe.position.y, 0.0);
  const double mm_px = test::mm_per_pixel(s, contact, dir);
  const PlaneFrame plane = make_plane_frame({0.0, 0.0, 1.0});  // the plank's reference plane
  const Material& m = s.materials[0];
  return {speed_gain(m, plane, glm::dvec3(0.0)), speed_gain(m, plane, 400.0 * mm_px * dir),
          speed_gain(m, plane, 1600.0 * mm_px * dir), mm_px};
}

class HandSpeedTest : public ::testing::TestWithParam<std::string> {};

TEST_P(HandSpeedTest, OrdinaryStrokeBringsTheTextureUp) {
  const Gains g = stroke_gains(GetParam());
  std::printf("%s: %.4f mm/px; gain at rest %.4f, 400 px/s %.4f, 1600 px/s %.4f\n", GetParam().c_str(),
              g.mm_per_px, g.rest, g.hand, g.fast);
  EXPECT_GT(g.hand, 0.5);
  // The thesis's shape kept: exp(-6.25) = 0.0019 at rest for a peak of 2.5 bandwidths; 0.01
  // leaves room for a lambda range that reaches lower frequencies.
  EXPECT_LT(g.rest, 0.01);
  EXPECT_LT(g.fast, 0.5) << "the gain must fall again above the stroke's speed";
}

// The planar scenes (the curved ones have a reference plane that is not z = 0).
INSTANTIATE_TEST_SUITE_P(ShippedScenes, HandSpeedTest,
                         ::testing::Values("default", "table4_1_a", "table4_1_b", "table4_1_c", "table4_1_d",
                                           "table4_1_e", "table4_1_f", "table5_1_wood",
                                           "table5_1_construction_paper", "table5_1_sandpaper"));

TEST(HandSpeedCameraTest, DefaultCameraIsAboutAnEleventhOfAMillimetrePerPixel) {
  // The premise of the default scene's speed curve: 0.0845 mm per pixel at the plank
  // (59.4 mm from the eye, 40 degree field, 512 rows: 2 x 59.4 x tan 20 / 512).
  const Gains g = stroke_gains("default");
  // 2e-6 mm/px: the 1 um finite difference is ~1e-5 relative (screen_scale.h), ~1e-6 mm/px.
  EXPECT_NEAR(g.mm_per_px, 2.0 * std::sqrt(2.0 * 42.0 * 42.0) * std::tan(20.0 * M_PI / 180.0) / 512.0, 2e-6);
}

}  // namespace
}  // namespace ps
