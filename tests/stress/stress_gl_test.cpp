// Numerical stress suite (label `stress`): every case renders a few frames of a tiny scene and
// requires finite, bounded values in the image, every AOV and every stats number. Plus a long
// run of a static scene whose reference plane must not drift.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "gl/context.h"
#include "reference/gabor.h"
#include "render/renderer.h"
#include "stress/stress_cases.h"

namespace ps {
namespace {

class StressGLTest : public ::testing::TestWithParam<test::StressCase> {
 protected:
  void SetUp() override {
    gl::ContextDesc desc;
    desc.backend = gl::Backend::kEgl;
    auto c = gl::create_context(desc);
    ASSERT_TRUE(c.ok()) << c.error().message;
    context_ = std::move(c.value());
  }
  std::unique_ptr<gl::Context> context_;
};

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Largest |raw noise| the capped sum can reach: 9 cells x cap impulses x max |A|.
double texture_bound_sigmas(const Material& m) {
  const GaborSetup s = make_gabor_setup(m.gabor);
  const double a = std::max(std::abs(m.gabor.a_min), std::abs(m.gabor.a_max));
  return 9.0 * s.max_impulses * a / s.sigma_unit * (1.0 + 1e-5) + 1e-6;
}

// allow_no_probe: the distance AOV, NaN (kNoProbeDistance) where no probe is above a pixel.
void check_image(const Renderer& r, const char* name, double lo, double hi, bool allow_no_probe) {
  auto img = r.read_aov(name);
  ASSERT_TRUE(img.ok()) << img.error().message;
  for (float v : img.value().pixels) {
    if (allow_no_probe && std::isnan(v)) continue;
    ASSERT_TRUE(std::isfinite(v)) << name;
    ASSERT_GE(v, lo) << name;
    ASSERT_LE(v, hi) << name;
  }
}

void check_stats(const Renderer& r) {
  const FrameStats& st = r.stats();
  ASSERT_TRUE(finite(st.reference_normal));
  EXPECT_NEAR(glm::length(st.reference_normal), 1.0, 1e-9);
  ASSERT_TRUE(finite(st.displacement));
  ASSERT_TRUE(finite(st.probe_position));
  ASSERT_TRUE(std::isfinite(st.max_penetration_mm));
  EXPECT_GE(st.max_penetration_mm, 0.0);
  EXPECT_GE(st.speed_gain, 0.0);
  EXPECT_LE(st.speed_gain, 1.0);
  // Both displacement methods push by at most resistance x the deepest penetration.
  const double res = std::max(1.0, r.scene().materials[0].resistance);
  EXPECT_LE(glm::length(st.displacement), res * st.max_penetration_mm * (1.0 + 1e-5) + 1e-9);
  for (const auto& [pass, ms] : st.timings_ms) EXPECT_TRUE(std::isfinite(ms)) << pass;
}

TEST_P(StressGLTest, FiniteAndBounded) {
  Scene s = test::stress_base_scene();
  GetParam().edit(s);
  auto rr = Renderer::create(s, {});
  ASSERT_TRUE(rr.ok()) << rr.error().message;
  Renderer& r = *rr.value();
  for (int i = 0; i < GetParam().frames; ++i) {
    ASSERT_TRUE(r.render_frame().ok());
    check_stats(r);
    if (GetParam().expect_push && i == 0) {
      const FrameStats& st = r.stats();
      const double push = glm::dot(st.displacement, st.reference_normal);
      EXPECT_GT(push, 0.5 * s.materials[0].resistance * st.max_penetration_mm);
    }
  }
  for (float v : r.read_color().pixels) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
  check_image(r, "intensity", 0.0, 1.0, false);
  check_image(r, "distance", -1e7, 1e7, true);
  const double tb = texture_bound_sigmas(s.materials[0]);
  check_image(r, "texture", -tb, tb, false);
  check_image(r, "normal", -1.0001, 1.0001, false);
  check_image(r, "displacement", -1e7, 1e7, false);
}

INSTANTIATE_TEST_SUITE_P(Cases, StressGLTest, ::testing::ValuesIn(test::stress_cases()),
                         [](const auto& info) { return info.param.name; });

TEST(StressLongRunGLTest, StaticSceneReferencePlaneDoesNotDrift) {
  gl::ContextDesc desc;
  desc.backend = gl::Backend::kEgl;
  auto ctx = gl::create_context(desc);
  ASSERT_TRUE(ctx.ok()) << ctx.error().message;
  Scene s = test::stress_base_scene();
  s.render.width = s.render.height = 16;
  s.surfaces[0].rotation_deg = {20.0, -10.0, 0.0};
  s.probe.position.z = 30.0;  // within influence (shadow drawn) but no contact: nothing moves
  RendererOptions o;
  o.time_passes = false;  // no glFinish per pass: 1e4 frames stay fast
  auto rr = Renderer::create(s, o);
  ASSERT_TRUE(rr.ok()) << rr.error().message;
  Renderer& r = *rr.value();
  ASSERT_TRUE(r.render_frame().ok());
  const glm::dvec3 n0 = r.stats().reference_normal, p0 = r.stats().probe_position;
  for (int i = 1; i < 10000; ++i) ASSERT_TRUE(r.render_frame().ok());
  // Same image every frame, so the mean normal must be reproduced exactly (float mip + double).
  EXPECT_LT(glm::length(r.stats().reference_normal - n0), 1e-12);
  EXPECT_EQ(r.stats().probe_position, p0);
}

}  // namespace
}  // namespace ps
