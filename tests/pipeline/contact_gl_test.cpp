// Hard contact (thesis §4.5.4, §5.1): residual penetration of a sphere probe into a plane after
// one frame of displacement. Exact max with resistance 1 must leave at most one depth-map
// texel; the thesis's weighted average (1 - d)^c leaves more, reported here per exponent c.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "pipeline/scenes.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace ps {
namespace {

constexpr double kPenetrationMm = 1.0;

// Residual penetration (mm) of the sphere into the plane z = 0 after one frame.
double residual_after_one_frame(Scene s) {
  auto r = Renderer::create(s, {});
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
  if (!r.ok()) return 1e30;
  EXPECT_TRUE(r.value()->render_frame().ok());
  return std::max(0.0, s.probe.radius_mm - r.value()->stats().probe_position.z);
}

class ContactGLTest : public test::GlTest {};

TEST_P(ContactGLTest, ExactMaxLeavesAtMostOneTexel) {
  Scene s = test::flat_plane_scene(8.0 - kPenetrationMm);
  s.render.displacement = DisplacementMethod::kExactMax;
  s.materials[0].resistance = 1.0;
  // Window = probe disc plus a texel margin (make_plan), so one texel is 2 r (1 + 2/N) / N.
  const int n = s.render.depth_map_size;
  const double texel_mm = 2.0 * s.probe.radius_mm * (1.0 + 2.0 / n) / n;
  const double residual = residual_after_one_frame(s);
  std::printf("[contact] exact max: residual %.4g mm (texel %.4g mm)\n", residual, texel_mm);
  EXPECT_LE(residual, texel_mm);
}

TEST_P(ContactGLTest, WeightedAverageResidualPerExponent) {
  double previous = 1e30;
  for (double c : {5.0, 10.0, 20.0, 40.0}) {
    Scene s = test::flat_plane_scene(8.0 - kPenetrationMm);
    s.render.displacement = DisplacementMethod::kWeightedAverage;
    s.render.weight_exponent = c;
    const double residual = residual_after_one_frame(s);
    std::printf("[contact] weighted average c = %g: residual %.4g mm of %.4g mm\n", c, residual,
                kPenetrationMm);
    RecordProperty("residual_mm_c" + std::to_string(static_cast<int>(c)), std::to_string(residual));
    // A larger exponent weights the deepest fragments more: the residual must shrink with c
    // and stay below the penetration (the average pushes out, never in).
    EXPECT_LT(residual, previous);
    EXPECT_LT(residual, kPenetrationMm);
    previous = residual;
  }
}

PS_INSTANTIATE_HEADLESS_BACKENDS(ContactGLTest);

}  // namespace
}  // namespace ps
