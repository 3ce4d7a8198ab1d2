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
  FrameInput in;
  in.sheet = ProbeSheet{0, sheet_w};
  const auto s = r.value()->render(in);
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

// The probe's path coloured by w (Hanson & Zhang, Fig. 5c): with the surface hidden, a path laid at
// the surface's smallest w is drawn bluish (blue > red in its pixels), one at its largest w
// reddish, and without the path shown (ViewFlags::path) nothing is drawn. The camera looks at the
// path from the side, so its tube (0.6 mm) covers a few pixels of each of its 128^2.
TEST_P(FourdGLTest, ProbePathIsColouredByDepth) {
  auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/fourd/roman.toml",
                          {"render.size=[128,128]", "surfaces.0.visible=false", "camera.position=[0,-60,0]",
                           "camera.target=[0,0,0]", "probe.position=[0,0,200]"});
  ASSERT_TRUE(scene) << scene.error().message;
  // The Roman surface's w spans [-1, 1] (y^2 - z^2 on the unit sphere).
  auto path_colour = [&](bool show, double w, int& pixels) {
    auto r = Renderer::create(scene.value(), {});
    EXPECT_TRUE(r) << r.error().message;
    // One frame per point: each frame given a sheet adds the probe's position to the path.
    for (int i = 0; i <= 20; ++i) {
      FrameInput in;
      in.show = ViewFlags{false, show, false};
      in.probe = ProbeMotion{glm::dvec3(-10.0 + i, 0.0, 0.0), glm::dvec3(0.0)};
      in.sheet = ProbeSheet{0, w};
      EXPECT_TRUE(r.value()->render(in));
    }
    const Image im = r.value()->read_color();
    glm::dvec3 sum(0.0);
    pixels = 0;
    const glm::dvec3 bg(im.at(0, 0, 0), im.at(0, 0, 1), im.at(0, 0, 2));  // a corner: background
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x < im.width; ++x) {
        const glm::dvec3 c(im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2));
        if (glm::length(c - bg) < 0.02) continue;
        sum += c;
        ++pixels;
      }
    return pixels > 0 ? sum / static_cast<double>(pixels) : sum;
  };
  int none = 0, far_pixels = 0, near_pixels = 0;
  path_colour(false, 0.0, none);
  const glm::dvec3 far = path_colour(true, -1.0, far_pixels), near = path_colour(true, 1.0, near_pixels);
  std::printf("path pixels: hidden %d, far %d (rgb %.2f %.2f %.2f), near %d (rgb %.2f %.2f %.2f)\n", none, far_pixels,
              far.r, far.g, far.b, near_pixels, near.r, near.g, near.b);
  EXPECT_EQ(none, 0);
  EXPECT_GT(far_pixels, 20);
  EXPECT_GT(near_pixels, 20);
  EXPECT_GT(far.b, far.r);
  EXPECT_GT(near.r, near.b);
}

// Cutaway (Hanson & Zhang §6.3): the probe 0.5 mm off the Roman surface's sheet through (-0.15, cos
// 15, sin 15), seen from where another sheet hides it. Without the cutaway no pixel shows its
// pseudo-shadow; with a 15 mm cutaway the other sheet opens around the line of sight and the
// shadow is seen (over 100 of the 256^2 pixels; 223 measured).
TEST_P(FourdGLTest, CutawayOpensTheOtherSheetsInFrontOfTheProbe) {
  auto shadow = [](double cut_mm) {
    auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/fourd/roman.toml",
                            {"render.size=[256,256]", "probe.position=[18.96,-6.36,-10.40]",
                             "camera.position=[60,-110,60]", "camera.target=[20,0,0]",
                             "surfaces.0.fourd_cutaway_mm=" + std::to_string(cut_mm)});
    EXPECT_TRUE(scene) << scene.error().message;
    auto r = Renderer::create(scene.value(), {});
    EXPECT_TRUE(r) << r.error().message;
    EXPECT_TRUE(r.value()->render_frame());
    return r.value()->stats().shadow_pixels;
  };
  const std::uint32_t closed = shadow(0.0), open = shadow(15.0);
  std::printf("shadow pixels seen: no cutaway %u, 15 mm cutaway %u\n", closed, open);
  EXPECT_EQ(closed, 0u);
  // Measured 98 pixels with the default distance along each point's own normal (223 along the
  // one reference normal: on this convex part of the sheet the true footprint is narrower).
  EXPECT_GT(open, 50u);
}

// Crossing diagram (Hanson & Zhang, Fig. 3b): where the Roman surface's sheets cross, the one
// nearer the 4D eye (larger w: red) is drawn over the other (blue) in a band along the crossing:
// with fourd_crossing_diagram_mm = 10 more pixels are red-dominant and fewer blue-dominant than
// with plain 3D depth (measured: red 3144 -> 4440 pixels, blue 2984 -> 1852).
TEST_P(FourdGLTest, CrossingDiagramDrawsTheSheetNearerThe4DEyeOnTop) {
  auto count = [](double k, int& red, int& blue) {
    auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/fourd/roman.toml",
                            {"render.size=[128,128]", "camera.position=[60,-110,60]", "camera.target=[20,0,0]",
                             "surfaces.0.fourd_crossing_diagram_mm=" + std::to_string(k)});
    EXPECT_TRUE(scene) << scene.error().message;
    auto r = Renderer::create(scene.value(), {});
    EXPECT_TRUE(r) << r.error().message;
    EXPECT_TRUE(r.value()->render_frame());
    const Image im = r.value()->read_color();
    red = blue = 0;
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x < im.width; ++x) {
        red += im.at(x, y, 0) > im.at(x, y, 2) + 0.2f;
        blue += im.at(x, y, 2) > im.at(x, y, 0) + 0.2f;
      }
  };
  int red0 = 0, blue0 = 0, red1 = 0, blue1 = 0;
  count(0.0, red0, blue0);
  count(10.0, red1, blue1);
  std::printf("red / blue pixels: plain depth %d / %d, crossing diagram %d / %d\n", red0, blue0, red1, blue1);
  EXPECT_GT(red1, red0 + 100);
  EXPECT_LT(blue1, blue0 - 100);
}

// Wireframe (Hanson & Zhang, Fig. 5c): the flat torus drawn as its triangles' edges, at 384^2,
// covers a fraction of the pixels it covers filled (measured 28 714 of 62 963), yet every part of
// it still shows: its pixels spread over the same bounding box, to 2 pixels.
TEST_P(FourdGLTest, WireframeDrawsTheEdgesOnly) {
  auto covered = [](bool wire, glm::ivec4& box) {
    auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/fourd/flat_torus.toml",
                            {"render.size=[384,384]", std::string("surfaces.0.fourd_wireframe=") + (wire ? "true" : "false")});
    EXPECT_TRUE(scene) << scene.error().message;
    auto r = Renderer::create(scene.value(), {});
    EXPECT_TRUE(r) << r.error().message;
    EXPECT_TRUE(r.value()->render_frame());
    const Image im = r.value()->read_color();
    const glm::vec3 bg(im.at(0, 0, 0), im.at(0, 0, 1), im.at(0, 0, 2));  // a corner: the background
    int n = 0;
    box = glm::ivec4(im.width, im.height, -1, -1);
    for (int y = 0; y < im.height; ++y)
      for (int x = 0; x < im.width; ++x) {
        const glm::vec3 c(im.at(x, y, 0), im.at(x, y, 1), im.at(x, y, 2));
        if (glm::length(c - bg) < 0.02f) continue;
        ++n;
        box = glm::ivec4(std::min(box.x, x), std::min(box.y, y), std::max(box.z, x), std::max(box.w, y));
      }
    return n;
  };
  glm::ivec4 filled_box, wire_box;
  const int filled = covered(false, filled_box), wire = covered(true, wire_box);
  std::printf("pixels: filled %d, wireframe %d\n", filled, wire);
  EXPECT_GT(filled, 1000);
  EXPECT_GT(wire, filled / 20);
  EXPECT_LT(wire, filled * 2 / 3);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(wire_box[k], filled_box[k], 2) << k;
}

PS_INSTANTIATE_HEADLESS_BACKENDS(FourdGLTest);

}  // namespace
}  // namespace ps
