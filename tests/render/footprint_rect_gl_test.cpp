// The footprint's screen rectangle (FramePlan::shadow_rect): the surface pass runs the
// pseudo-shadow variants and clears and writes the AOV target only inside it, the shadow's
// reductions read only inside it, and read_aov() fills the rest with the "no probe" values.
// Every output of a frame must be the same bits as with all of that over the whole image
// (RendererOptions::footprint_rect = false), which is how the frame was computed before the
// rectangle existed. The tolerance is zero, and why it can be: outside the rectangle no
// fragment can be inside the depth map's window, so its colour composites as rgb * (1 - 0),
// its AOV is (0, NaN, 0) by definition, and its terms in the reductions are exact zeros (a
// zero term leaves a float sum's bits unchanged; max and counts ignore it).
// The probe moves between frames, far enough that a frame's rectangle leaves the last one's:
// the AOV texture keeps the older frame's values there, which must never show.
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/scenes.h"
#include "scene/camera.h"
#include "render/renderer.h"
#include "scene/scene_io.h"
#include "support/expect_reductions.h"
#include "support/gl_test.h"
#include "support/shipped.h"

namespace ps {
namespace {

class FootprintRectGLTest : public test::GlTest {};

struct Case {
  std::string name;
  Scene scene;
  std::vector<glm::dvec3> probe_path;  // one position per frame
};

using test::shipped;

std::vector<Case> cases() {
  std::vector<Case> c;
  {
    Scene s = shipped("default", 160, 128);
    const glm::dvec3 p = s.probe.position;
    // 20 mm along x leaves the 16 mm footprint's rectangle; then half-way back.
    c.push_back({"default", s, {p, p + glm::dvec3(20, 0, 0), p + glm::dvec3(10, 0, -0.5)}});
    // Partly off the image's left edge (about 43 mm of plank are in view).
    c.push_back({"default_at_edge", s, {p + glm::dvec3(-22, 0, 0), p + glm::dvec3(-24, 6, 0)}});
    // The eye just above the plank, inside the window's reach: corners behind it, whole image.
    Scene low = s;
    low.camera.position = {0.0, -5.0, 2.0};
    low.camera.target = {0.0, 10.0, 0.0};
    c.push_back({"default_eye_in_window", low, {p, p + glm::dvec3(3, 4, 0)}});
  }
  {
    Scene s = shipped("torus_capsule", 160, 120);  // capsule, exact-max displacement, curved
    const glm::dvec3 p = s.probe.position;
    c.push_back({"torus_capsule", s, {p, p + glm::dvec3(25, 8, 0), p + glm::dvec3(5, 0, -0.3)}});
  }
  {
    Scene s = shipped("materials_demo", 160, 120);  // several surfaces and materials, a hidden one
    const glm::dvec3 p = s.probe.position;
    c.push_back({"materials_demo", s, {p, p + glm::dvec3(-30, 10, 0), p + glm::dvec3(40, -5, 0)}});
  }
  {
    Scene s = shipped("table5_1_monkey_head", 160, 120);  // a mesh seen in perspective
    const glm::dvec3 p = s.probe.position;
    c.push_back({"monkey_head", s, {p, p + glm::dvec3(12, 0, 3)}});
  }
  {
    Scene s = shipped("heightfield", 160, 120);
    const glm::dvec3 p = s.probe.position;
    c.push_back({"heightfield", s, {p, p + glm::dvec3(-15, 20, 0)}});
  }
  {
    Scene s = test::flat_plane_scene(7.5);  // orthographic, sunk 0.5 mm
    s.render.displacement = DisplacementMethod::kWeightedAverage;
    c.push_back({"flat_ortho", s, {s.probe.position, {14, -9, 7.0}, {-3, 2, 8.5}}});
  }
  return c;
}

// Bitwise: NaN equals NaN of the same bits, and -0 differs from +0.
int differing_values(const Image& a, const Image& b, std::string& first) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
    first = "sizes differ";
    return -1;
  }
  int n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    if (std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(float)) != 0) {
      if (n++ == 0) {
        const size_t px = i / a.channels;
        first = "pixel (" + std::to_string(px % a.width) + ", " + std::to_string(px / a.width) + ") channel " +
                std::to_string(i % a.channels) + ": " + std::to_string(a.pixels[i]) + " vs " +
                std::to_string(b.pixels[i]);
      }
    }
  return n;
}

void expect_same_frame(const Renderer& rect, const Renderer& whole, const std::string& where) {
  std::string first;
  EXPECT_EQ(differing_values(rect.read_color(), whole.read_color(), first), 0) << where << " colour, first " << first;
  for (const std::string& aov : aov_names()) {
    auto a = rect.read_aov(aov), b = whole.read_aov(aov);
    ASSERT_TRUE(a.ok() && b.ok()) << where << " " << aov;
    EXPECT_EQ(differing_values(a.value(), b.value(), first), 0) << where << " AOV " << aov << ", first " << first;
  }
  test::expect_same_reductions(rect.stats(), whole.stats(), where);
}

TEST_P(FootprintRectGLTest, EveryOutputEqualsTheWholeImagesBitForBit) {
  int shadowed_frames = 0;
  for (const Case& c : cases()) {
    RendererOptions rect_opts, whole_opts;
    rect_opts.expected_frames = whole_opts.expected_frames = 3;  // short: no tile bake
    whole_opts.footprint_rect = false;
    auto rect = Renderer::create(c.scene, rect_opts);
    auto whole = Renderer::create(c.scene, whole_opts);
    ASSERT_TRUE(rect.ok() && whole.ok()) << c.name;
    for (size_t f = 0; f < c.probe_path.size(); ++f) {
      const std::string where = c.name + " frame " + std::to_string(f);
      for (Renderer* r : {rect.value().get(), whole.value().get()}) {
        ASSERT_TRUE(r->render(probe_frame_input(c.probe_path[f], c.scene.probe.velocity)).ok()) << where;
      }
      expect_same_frame(*rect.value(), *whole.value(), where);
      if (rect.value()->stats().shadow_pixels > 0) ++shadowed_frames;
    }
  }
  EXPECT_GE(shadowed_frames, 14);  // the comparison saw pseudo-shadows, not empty frames
}

// After a frame whose footprint lies elsewhere, the old footprint's pixels read "no probe":
// intensity 0, distance NaN, texture 0 (the AOV texture still holds the old frame there).
TEST_P(FootprintRectGLTest, AovOutsideTheFootprintIsNoProbeAfterTheProbeMoved) {
  Scene s = test::flat_plane_scene(9.0);
  auto made = Renderer::create(s, {});
  ASSERT_TRUE(made.ok()) << made.error().message;
  Renderer& r = *made.value();
  ASSERT_TRUE(r.render_frame().ok());
  const Image before = r.read_aov(Aov::kIntensity).value();
  // 14 mm away: the 8 mm footprints do not overlap.
  ASSERT_TRUE(r.render(probe_frame_input({-10.0, 10.0, 9.0}, {})).ok());
  const Image inten = r.read_aov(Aov::kIntensity).value(), dist = r.read_aov(Aov::kDistance).value();
  const Image tex = r.read_aov(Aov::kTexture).value();
  int old_footprint = 0;
  for (int y = 0; y < before.height; ++y)
    for (int x = 0; x < before.width; ++x) {
      if (!(before.at(x, y, 0) > 0.0f)) continue;
      const glm::dvec2 w = test::pixel_to_world(s, x, y);
      if (glm::length(w - glm::dvec2(-10.0, 10.0)) < 8.5) continue;  // the new footprint
      ++old_footprint;
      EXPECT_EQ(inten.at(x, y, 0), 0.0f) << x << "," << y;
      EXPECT_TRUE(std::isnan(dist.at(x, y, 0))) << x << "," << y << ": " << dist.at(x, y, 0);
      EXPECT_EQ(tex.at(x, y, 0), 0.0f) << x << "," << y;
    }
  EXPECT_GT(old_footprint, 1500);  // pi (8 / 0.3125)^2 ~ 2060 pixels, less the overlap margin

  // The window's reused buffers (read_aov_into, every frame) give read_aov's bits, NaN included,
  // whatever they held before (here: the older frame, and a raw buffer of another size); a
  // second read into them keeps their storage (nothing allocated).
  Image reused = before;
  std::vector<float> raw(7, 1.0f);
  for (Aov aov : {Aov::kIntensity, Aov::kDistance, Aov::kTexture, Aov::kNormal}) {
    ASSERT_TRUE(r.read_aov_into(aov, reused, raw).ok());
    const Image fresh = r.read_aov(aov).value();
    ASSERT_EQ(reused.width, fresh.width);
    ASSERT_EQ(reused.height, fresh.height);
    ASSERT_EQ(reused.channels, fresh.channels);
    ASSERT_EQ(reused.pixels.size(), fresh.pixels.size());
    EXPECT_EQ(std::memcmp(reused.pixels.data(), fresh.pixels.data(), fresh.pixels.size() * sizeof(float)), 0)
        << aov_info(aov).name;
  }
  ASSERT_TRUE(r.read_aov_into(Aov::kIntensity, reused, raw).ok());
  const float* storage = reused.pixels.data();
  const float* raw_storage = raw.data();
  ASSERT_TRUE(r.read_aov_into(Aov::kDistance, reused, raw).ok());
  EXPECT_EQ(reused.pixels.data(), storage);
  EXPECT_EQ(raw.data(), raw_storage);
}

// The mean visible normal is reused while the camera stays and reduced again when it moves: a
// renderer whose camera moved gives the same plane as one created with the new camera.
TEST_P(FootprintRectGLTest, ReferenceNormalFollowsTheCamera) {
  Scene s = shipped("torus_capsule", 160, 120);  // curved: the mean normal depends on the view
  Scene moved = s;
  moved.camera.position = {40.0, -100.0, 70.0};
  RendererOptions two_frames;
  two_frames.expected_frames = 2;
  auto a = Renderer::create(s, two_frames);
  auto b = Renderer::create(moved, two_frames);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_TRUE(a.value()->render_frame().ok());
  const glm::dvec3 n_first = a.value()->reference().n;
  FrameInput in = probe_frame_input(s.probe.position, s.probe.velocity);
  in.camera = moved.camera;
  ASSERT_TRUE(a.value()->render(in).ok());
  ASSERT_GT(a.value()->stats().shadow_pixels, 0u);  // the reductions ran
  EXPECT_GT(glm::length(n_first - b.value()->reference().n), 1e-3);  // the views differ
  EXPECT_EQ(a.value()->reference().n, b.value()->reference().n);
  bool reduced = false;
  for (const auto& [pass, ms] : a.value()->stats().timings_ms) reduced = reduced || pass == "reference_normal";
  EXPECT_TRUE(reduced);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(FootprintRectGLTest);

}  // namespace
}  // namespace ps
