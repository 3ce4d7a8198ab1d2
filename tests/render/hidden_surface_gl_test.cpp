// A surface with visible = false is not drawn (a hidden object is felt, not seen): the frame
// equals, byte for byte, the frame of the same scene with that surface moved far out of view,
// while the visible surface covers pixels (so the comparison can fail).
#include <gtest/gtest.h>

#include "support/scenes.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace ps {
namespace {

class HiddenSurfaceGLTest : public test::GlTest {};

Image colour_of(const Scene& s) {
  const auto r = test::render_one_frame(s);
  return r ? r->read_color() : Image{};
}

TEST_P(HiddenSurfaceGLTest, HiddenSurfaceDrawsNothing) {
  Scene base = test::flat_plane_scene(30.0);  // probe 22 mm above the plane: a faint shadow
  Surface sphere;
  sphere.type = SurfaceType::kSphere;
  sphere.material = "plain";
  sphere.radius_mm = 6.0;
  sphere.center = {-10.0, 5.0, 4.0};
  sphere.resolution = 16;
  base.surfaces.push_back(sphere);

  Scene hidden = base;
  hidden.surfaces[1].visible = false;
  Scene away = base;
  away.surfaces[1].center = {0.0, 0.0, -900.0};  // below the plane, hidden by it

  const Image shown = colour_of(base), without = colour_of(hidden), moved = colour_of(away);
  ASSERT_FALSE(shown.pixels.empty());
  ASSERT_EQ(shown.pixels.size(), without.pixels.size());
  EXPECT_EQ(without.pixels, moved.pixels) << "a hidden sphere leaves no pixel";
  int differing = 0;
  for (int y = 0; y < shown.height; ++y) {
    for (int x = 0; x < shown.width; ++x) {
      bool differs = false;
      for (int c = 0; c < shown.channels; ++c) differs |= shown.at(x, y, c) != without.at(x, y, c);
      differing += differs;
    }
  }
  // The 6 mm sphere spans ~pi 6^2 / (40 x 40 mm) of the 128^2 view: ~1200 pixels.
  EXPECT_GT(differing, 500) << "the visible sphere shows";
}

PS_INSTANTIATE_HEADLESS_BACKENDS(HiddenSurfaceGLTest);

}  // namespace
}  // namespace ps
