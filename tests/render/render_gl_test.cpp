// Analytic checks of the whole frame on both headless backends: a sphere over a flat plane
// has a known distance and intensity; a flat plane has an exact reference normal; a constant
// texture has constant mip levels; a far probe skips the shadow work.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "support/scenes.h"
#include "reference/modulation.h"
#include "reference/probe_geometry.h"
#include "render/renderer.h"
#include "support/gl_test.h"
#include "support/shipped.h"

namespace ps {
namespace {

class PipelineGLTest : public test::GlTest {};

std::unique_ptr<Renderer> make_renderer(const Scene& s) {
  auto r = Renderer::create(s, {});
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
  return r.ok() ? std::move(r.value()) : nullptr;
}

TEST_P(PipelineGLTest, SphereOverPlaneDistanceAndIntensityAtCentre) {
  const Scene s = test::flat_plane_scene(10.0);  // lowest point of the sphere at z = 2
  auto r = make_renderer(s);
  ASSERT_TRUE(r);
  ASSERT_TRUE(r->render_frame().ok());
  const Image dist = r->read_aov("distance").value();
  const Image inten = r->read_aov("intensity").value();
  const PlaneFrame f = make_plane_frame({0, 0, 1});
  const CapsuleShape cap = capsule_of(s.probe);
  int checked = 0;
  for (int py = 0; py < 128; ++py)
    for (int px = 0; px < 128; ++px) {
      const glm::dvec2 w = test::pixel_to_world(s, px, py);
      const double rho = glm::length(w);
      if (rho > 0.9 * 8.0) continue;
      const double expect = capsule_lowest_height(cap, f, w.x, w.y);
      // The depth map is sampled at the nearest texel (texel = 2 * 8.06 / 256 = 0.063 mm);
      // inside rho < 0.9 r the sphere's slope is at most 0.9 / sqrt(1 - 0.81) = 2.07, so the
      // lookup may be off by slope * half a texel diagonal = 0.092 mm (+ float rounding).
      EXPECT_NEAR(dist.at(px, py, 0), expect, 0.1) << px << "," << py;
      ++checked;
    }
  EXPECT_GT(checked, 1500);  // pi (0.9 * 8 / 0.3125)^2 ~ 1660 pixels
  // Centre pixel (world (0.156, -0.156)): the slope there is 0.028, so the nearest-texel lookup
  // is off by at most 0.028 * 0.045 = 1.3e-3 mm; the intensity follows the thesis curve
  // 0.1 + 0.9 / (d + 1.25) whose slope at d = 2 is 0.085 (-> 1.1e-4).
  const glm::dvec2 c = test::pixel_to_world(s, 64, 64);
  const double d_centre = capsule_lowest_height(cap, f, c.x, c.y);
  EXPECT_NEAR(d_centre, 2.003, 1e-3);
  EXPECT_NEAR(dist.at(64, 64, 0), d_centre, 2e-3);
  EXPECT_NEAR(inten.at(64, 64, 0), 0.1 + 0.9 / (d_centre + 1.25), 3e-4);
  // Outside the probe's silhouette there is no pseudo-shadow, and no distance: the AOV's
  // documented "no probe" value is NaN (kNoProbeDistance).
  EXPECT_EQ(inten.at(2, 2, 0), 0.0f);
  EXPECT_TRUE(std::isnan(dist.at(2, 2, 0))) << dist.at(2, 2, 0);
}

TEST_P(PipelineGLTest, FlatPlaneReferenceNormalIsExact) {
  Scene s = test::flat_plane_scene(10.0);
  s.camera.projection = Projection::kPerspective;  // tilted view: normals still all +Z
  s.camera.position = {30.0, -80.0, 60.0};
  RendererOptions thesis;
  thesis.prime_reference_plane = false;
  auto made = Renderer::create(s, thesis);
  ASSERT_TRUE(made.ok()) << made.error().message;
  auto& r = made.value();
  // Thesis start: facing the viewer; after one frame: the mean visible normal, exactly +Z
  // (every visible normal is +Z: each row sums exact small integers, exactly).
  EXPECT_GT(glm::length(r->reference().n - glm::dvec3(0, 0, 1)), 0.1);
  ASSERT_TRUE(r->render_frame().ok());
  EXPECT_NEAR(r->reference().n.x, 0.0, 1e-7);
  EXPECT_NEAR(r->reference().n.y, 0.0, 1e-7);
  EXPECT_NEAR(r->reference().n.z, 1.0, 1e-7);
}

// The reference plane's normal is the mean visible normal: the normal target's (n, 1) summed by
// rows on the GPU (glsl/normal_rows.comp, the rows added in double) and normalised. Checked
// against the same target read back and summed here in double, on the torus seen in perspective
// (normals of every direction). Each GPU row sum is Kahan-compensated, within two float roundings
// (1.2e-7 relative) of the exact one, so the two directions agree to 1e-6. Measured: 1.9e-9; a
// plain float sum along the rows 1.5e-8 (its error grows with the row: 1920 pixels at 1080p);
// the top row left out 1.5e-3.
TEST_P(PipelineGLTest, ReferenceNormalIsTheMeanOfTheNormalTarget) {
  Scene s = test::shipped("torus_capsule", 320, 240);
  RendererOptions opts;
  opts.expected_frames = 4;  // short: no tile bake
  auto made = Renderer::create(s, opts);
  ASSERT_TRUE(made.ok()) << made.error().message;
  auto& r = made.value();
  ASSERT_TRUE(r->render_frame().ok());
  auto normals = r->read_aov(Aov::kNormal);
  ASSERT_TRUE(normals.ok()) << normals.error().message;
  glm::dvec3 sum(0.0);
  std::size_t covered = 0;
  for (int y = 0; y < normals->height; ++y)
    for (int x = 0; x < normals->width; ++x) {
      const glm::dvec3 n(normals->at(x, y, 0), normals->at(x, y, 1), normals->at(x, y, 2));
      sum += n;
      covered += glm::length(n) > 0.5;
    }
  ASSERT_GT(covered, 320u * 240u / 10);  // the torus is in view
  const glm::dvec3 expected = glm::normalize(sum), got = r->stats().reference_normal;
  std::printf("reference normal (%.9f %.9f %.9f), CPU mean (%.9f %.9f %.9f), |diff| %.2e\n", got.x, got.y, got.z,
              expected.x, expected.y, expected.z, glm::length(got - expected));
  EXPECT_LT(glm::length(got - expected), 1e-6);
  EXPECT_LT(glm::length(expected - glm::dvec3(0, 0, 1)), 0.99);  // not a trivial plane: sanity
}

TEST_P(PipelineGLTest, PrimedReferencePlaneIsExactBeforeTheFirstFrame) {
  Scene s = test::flat_plane_scene(10.0);
  s.camera.projection = Projection::kPerspective;
  s.camera.position = {30.0, -80.0, 60.0};
  auto r = make_renderer(s);  // primes by default
  ASSERT_TRUE(r);
  EXPECT_NEAR(glm::length(r->reference().n - glm::dvec3(0, 0, 1)), 0.0, 1e-7);
}

TEST_P(PipelineGLTest, FarProbeSkipsShadowWork) {
  const Scene s = test::flat_plane_scene(1000.0);  // far beyond the 50 mm influence distance
  auto r = make_renderer(s);
  ASSERT_TRUE(r);
  ASSERT_TRUE(r->render_frame().ok());
  const auto& skipped = r->stats().skipped;
  bool depth_skipped = false;
  for (const auto& line : skipped) depth_skipped = depth_skipped || line.rfind("probe_depth", 0) == 0;
  EXPECT_TRUE(depth_skipped);
  for (const auto& [name, ms] : r->stats().timings_ms) EXPECT_NE(name, "probe_depth");
  const Image inten = r->read_aov("intensity").value();
  for (float v : inten.pixels) ASSERT_EQ(v, 0.0f);
  EXPECT_EQ(r->stats().probe_position, s.probe.position);  // nothing pushed it
}

TEST_P(PipelineGLTest, ConstantTextureHasConstantMipLevels) {
  // glGenerateMipmap is an exact mean of power-of-two RGBA32F on llvmpipe (docs/gl-stack.md; the
  // reference normal was reduced so until its row sums, glsl/normal_rows.comp).
  for (glm::ivec2 size : {glm::ivec2(256, 256), glm::ivec2(256, 32)}) {
    const int levels = 9;
    gl::Texture t = gl::make_texture_2d(size.x, size.y, GL_RGBA32F, levels);
    const float value[4] = {0.3f, -1.7f, 12345.5f, 1e-20f};
    glClearTexImage(t.id(), 0, GL_RGBA, GL_FLOAT, value);
    glGenerateTextureMipmap(t.id());
    for (int level = 0; level < levels; ++level) {
      const int w = std::max(1, size.x >> level), h = std::max(1, size.y >> level);
      std::vector<float> px(static_cast<size_t>(w) * h * 4);
      glGetTextureImage(t.id(), level, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(px.size() * 4), px.data());
      for (size_t i = 0; i < px.size(); ++i) ASSERT_EQ(px[i], value[i % 4]) << "level " << level;
    }
  }
}

PS_INSTANTIATE_HEADLESS_BACKENDS(PipelineGLTest);

}  // namespace
}  // namespace ps
