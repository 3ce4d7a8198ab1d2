// The GPU Gabor texture against the double-precision CPU twin, pixel by pixel.
#include <cmath>

#include <gtest/gtest.h>

#include "pipeline/scenes.h"
#include "reference/gabor.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace ps {
namespace {

class GaborGLTest : public test::GlTest {};

TEST_P(GaborGLTest, TextureAovMatchesCpuReference) {
  Scene s = test::flat_plane_scene(24.5);  // big probe (r = 25) touching the plane: wide footprint
  s.probe.radius_mm = 25.0;
  Material& m = s.materials[0];
  m.gabor.lambda_min_mm = 0.8;
  m.gabor.lambda_max_mm = 2.0;
  m.gabor.theta_min_rad = 0.0;
  m.gabor.theta_max_rad = 1.0;
  m.gabor.n_min = 20;
  m.gabor.n_max = 30;
  m.onset_distance_mm = 100.0;  // texture everywhere under the probe
  auto r = Renderer::create(s, {});
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_TRUE(r.value()->render_frame().ok());
  const Image tex = r.value()->read_aov("texture").value();
  const Image inten = r.value()->read_aov("intensity").value();
  const GaborSetup setup = make_gabor_setup(m.gabor);
  double max_err = 0.0;
  int n = 0;
  for (int py = 0; py < 128; py += 3)
    for (int px = 0; px < 128; px += 3) {
      if (inten.at(px, py, 0) <= 0.0f) continue;
      const glm::dvec2 w = test::pixel_to_world(s, px, py);
      const double expect = gabor_noise(m.gabor, setup, s.render.seed, w.x, w.y) / setup.sigma_unit;
      max_err = std::max(max_err, std::abs(tex.at(px, py, 0) - expect));
      ++n;
    }
  EXPECT_GT(n, 1000);
  // Float32 shader vs double reference. The fragment's world position comes from interpolated
  // float vertex positions (~1e-5 mm at 20 mm from the origin), a phase error of
  // 2 pi 1e-5 / 0.8 ~ 1e-4 rad per kernel, over ~30 overlapping kernels of a value normalised
  // by sigma: 5e-3 sigma bounds the sum with margin.
  EXPECT_LT(max_err, 5e-3) << "max error in sigmas over " << n << " pixels";
}

PS_INSTANTIATE_HEADLESS_BACKENDS(GaborGLTest);

}  // namespace
}  // namespace ps
