// The pseudo-shadow on a surface embedded in 4D falls on the probe's sheet only (docs/fourd.md):
// the Roman surface with the probe 0.5 mm above one sheet near the double line, where another
// sheet crosses it at a w 1.7 lower. Told the probe's sheet, the frame has shadow pixels; told
// a w no sheet has, none at all (every fragment is masked); told the crossing sheet's w, the
// shadow is not the same (it lands on the other sheet's fragments only). Both backends.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "render/renderer.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"

namespace ps {
namespace {

class FourdGLTest : public test::GlTest {};

std::uint32_t shadow_pixels(const Scene& scene, double sheet_w) {
  auto r = Renderer::create(scene, {});
  EXPECT_TRUE(r) << r.error().message;
  if (!r) return 0;
  r.value()->set_probe_sheet(0, sheet_w);
  const Status s = r.value()->render_frame();
  EXPECT_TRUE(s) << s.error().message;
  return r.value()->stats().shadow_pixels;
}

TEST_P(FourdGLTest, PseudoShadowStaysOnTheProbesSheet) {
  auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/fourd/roman.toml",
                          {"render.size=[128,128]", "probe.position=[20.13,-2.55,3.99]",
                           "camera.position=[20,-60,80]", "camera.target=[20,0,0]"});
  ASSERT_TRUE(scene) << scene.error().message;
  // This sheet: the sphere point (0.04, cos 15, sin 15); the crossing sheet has w = -that.
  const double w = (std::cos(M_PI / 6)) / (1.0 + 0.04 * 0.04);
  const std::uint32_t own = shadow_pixels(scene.value(), w), none = shadow_pixels(scene.value(), 10.0),
                      other = shadow_pixels(scene.value(), -w);
  std::printf("shadow pixels: own sheet %u, no sheet %u, the crossing sheet %u\n", own, none, other);
  EXPECT_GT(own, 20u);
  EXPECT_EQ(none, 0u);
  EXPECT_NE(other, own);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(FourdGLTest);

}  // namespace
}  // namespace ps
