// The feedback conditions of a targeting experiment, as [render] keys (docs/scene-format.md):
//   - render.cast_shadow: the probe's hard shadow along the light against its CPU twin
//     (reference/cast_shadow.h) pixel by pixel, and where it lies (displaced from the probe's
//     foot by height x the light's slant, so a light direction ignored would fail);
//   - render.pseudo_shadow = false: the colour of a frame with the probe out of reach, while
//     the AOVs and the reductions (max penetration, displacement) stay the default frame's;
//   - render.draw_probe = true: byte-identical to the view's probe flag (`--show-probe`);
//   - the cast shadow follows the probe in incremental frames (it is in the frame key).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include <gtest/gtest.h>

#include "reference/cast_shadow.h"
#include "render/renderer.h"
#include "render/view.h"
#include "support/gl_test.h"
#include "support/scenes.h"

namespace ps {
namespace {

constexpr double kDisplayGamma = 2.2;  // the surface pass encodes with 1 / 2.2

struct Frame {
  Image color, intensity, distance, texture;
  FrameStats stats;
};

std::optional<Frame> render(const Scene& s, ViewFlags show = {}) {
  RendererOptions options;
  auto view = make_view(s, show);
  if (!view.ok()) {
    ADD_FAILURE() << view.error().message;
    return std::nullopt;
  }
  options.view = view.value();
  auto made = Renderer::create(s, options);
  if (!made.ok()) {
    ADD_FAILURE() << made.error().message;
    return std::nullopt;
  }
  Renderer& r = *made.value();
  if (auto f = r.render(FrameInput{}); !f) {
    ADD_FAILURE() << f.error().message;
    return std::nullopt;
  }
  return Frame{r.read_color(), r.read_aov("intensity").value(), r.read_aov("distance").value(),
               r.read_aov("texture").value(), r.stats()};
}

// A plane at z = 0 seen from straight above (orthographic, 40 mm over 128 px: 0.3125 mm a
// pixel, the world position affine in the pixel), untextured, a sphere probe of radius 4 mm
// centred `height_mm` above the foot (0, 0), and a slanted light: 0.5 mm along x and 0.25 mm
// along y per mm down, so the shadow's centre lies at height x (0.5, 0.25) from the foot.
constexpr double kProbeRadius = 4.0;
const glm::dvec3 kSlantedLight{0.5, 0.25, -1.0};

Scene cast_scene(double height_mm) {
  Scene s = test::flat_plane_scene(height_mm);
  s.probe.radius_mm = kProbeRadius;
  s.materials[0].textured = false;
  s.materials[0].resistance = 0.0;  // the probe stays where it is put
  s.light.direction = kSlantedLight;
  s.render.cast_shadow = true;
  s.render.pseudo_shadow = false;  // the cast shadow alone changes the colour
  return s;
}

struct CastComparison {
  double worst_levels = 0.0;
  int shadowed = 0;            // pixels the twin puts (partly) in shadow
  glm::dvec2 centroid{0.0};    // of the colour image's darkening, world mm
};

// The colour image against the twin: 255 (albedo colour (ambient + (1 - ambient) lambert
// (1 - coverage)))^(1/2.2) at the point each pixel's centre sees (channel 0; grey receiver, white
// light). The centroid is the darkening's, 1 - (linear colour / the unshadowed one), measured on
// the image, not on the twin.
CastComparison compare_cast(const Scene& s, const Image& color) {
  const Light& l = s.light;
  const double lambert = std::max(-glm::normalize(l.direction).z, 0.0);
  const double albedo = s.materials[0].albedo.x * l.color.x;
  const double pixel_mm = s.camera.ortho_height_mm / s.render.height;
  const double edge = extent_across({pixel_mm, 0.0, 0.0}, {0.0, -pixel_mm, 0.0}, l.direction);
  const SphereCaster probe{s.probe.position, s.probe.radius_mm};
  const double lit = albedo * cast_shadow_light(l.ambient, lambert, 0.0);
  CastComparison c;
  double dark_sum = 0.0;
  for (int y = 0; y < s.render.height; ++y)
    for (int x = 0; x < s.render.width; ++x) {
      const glm::dvec2 p = test::pixel_to_world(s, x, y);
      const double cov = cast_shadow_coverage(probe, {p, 0.0}, l.direction, edge);
      c.shadowed += cov > 0.0;
      const double want = 255.0 * std::pow(albedo * cast_shadow_light(l.ambient, lambert, cov), 1.0 / kDisplayGamma);
      c.worst_levels = std::max(c.worst_levels, std::abs(want - 255.0 * color.at(x, y, 0)));
      const double dark = std::max(1.0 - std::pow(static_cast<double>(color.at(x, y, 0)), kDisplayGamma) / lit, 0.0);
      // Only clear darkening: the 8-bit rounding of the unshadowed level is ~1 %.
      if (dark > 0.05) {
        c.centroid += dark * p;
        dark_sum += dark;
      }
    }
  if (dark_sum > 0.0) c.centroid /= dark_sum;
  return c;
}

class FeedbackGLTest : public test::GlTest {};

TEST_P(FeedbackGLTest, CastShadowMatchesItsCpuTwinWhereTheLightSays) {
  for (double height : {6.0, 12.0, 20.0}) {
    const Scene s = cast_scene(height);
    const std::optional<Frame> f = render(s);
    ASSERT_TRUE(f);
    const CastComparison c = compare_cast(s, f->color);
    const glm::dvec3 want_centre = cast_shadow_centre(s.probe.position, s.light.direction, {0.0, 0.0, 0.0}, {0, 0, 1});
    const double off_mm = glm::length(c.centroid - glm::dvec2(want_centre));
    std::printf("[cast twin] height %.0f mm: %d px shadowed, worst %.3f levels, centroid (%.3f, %.3f) mm, "
                "light's (%.3f, %.3f) mm, off by %.4f mm\n",
                height, c.shadowed, c.worst_levels, c.centroid.x, c.centroid.y, want_centre.x, want_centre.y, off_mm);
    // The shadow is an ellipse of semi-axes 4 and 4 x 1.146 mm (the light 29 degrees off the
    // normal): 57.6 mm^2, ~590 px of 0.3125 mm, plus its one-pixel rim.
    EXPECT_GT(c.shadowed, 500) << "height " << height;
    // 0.5 level: the 8-bit rounding of the pixel; + 0.1 for the GPU's float evaluation (world
    // positions of ~20 mm to ~1e-6 relative, llvmpipe's pow and sqrt) and the filtered rim, whose
    // coverage moves by ~1e-6 mm / 0.3 mm per float error in the distance from the ray.
    EXPECT_LE(c.worst_levels, 0.6) << "height " << height;
    // The centre is height x (0.5, 0.25) from the foot (0, 0) (5.6 mm at 10 mm): a light
    // ignored or taken straight down puts it at the foot. 0.1 mm (a third of a pixel): the
    // darkening's centroid over an ellipse sampled at pixel centres, its rim filtered
    // symmetrically, and the 5 % cut of the rim's faintest pixels.
    EXPECT_NEAR(want_centre.x, 0.5 * height, 1e-12);
    EXPECT_NEAR(want_centre.y, 0.25 * height, 1e-12);
    EXPECT_LE(off_mm, 0.1) << "height " << height;
  }
}

// The cast shadow is the colour's only: with it on, the AOVs and reductions are the frame's
// without it, and it leaves the pseudo-shadow to darken on top (both on).
TEST_P(FeedbackGLTest, CastShadowIsColourOnlyAndAddsToThePseudoShadow) {
  Scene s = cast_scene(kProbeRadius + 1.0);
  s.render.pseudo_shadow = true;
  Scene plain = s;
  plain.render.cast_shadow = false;
  const std::optional<Frame> with = render(s), without = render(plain);
  ASSERT_TRUE(with && without);
  EXPECT_EQ(with->intensity.pixels, without->intensity.pixels);
  EXPECT_EQ(with->stats.displacement, without->stats.displacement);
  EXPECT_EQ(with->stats.max_penetration_mm, without->stats.max_penetration_mm);
  int darker = 0, lighter = 0;
  for (size_t i = 0; i < with->color.pixels.size(); ++i) {
    darker += with->color.pixels[i] < without->color.pixels[i];
    lighter += with->color.pixels[i] > without->color.pixels[i];
  }
  EXPECT_GT(darker, 500 * 3);  // the ellipse's ~590 px, three channels
  EXPECT_EQ(lighter, 0);
}

// The cast shadow falls outside the pseudo-shadow's rectangle, so a moved probe must redraw it:
// incremental frames (the default) are byte-identical to frames that redraw every pixel.
TEST_P(FeedbackGLTest, CastShadowFollowsTheProbeInIncrementalFrames) {
  const Scene s = cast_scene(10.0);
  std::unique_ptr<Renderer> r[2];
  for (int i = 0; i < 2; ++i) {
    RendererOptions options;
    options.incremental = i == 0;
    auto made = Renderer::create(s, options);
    ASSERT_TRUE(made.ok()) << made.error().message;
    r[i] = std::move(made.value());
  }
  for (double x : {0.0, 3.0, 6.0}) {
    FrameInput in;
    in.probe = ProbeMotion{{x, 0.0, 10.0}, {0.0, 0.0, 0.0}};
    ASSERT_TRUE(r[0]->render(in).ok() && r[1]->render(in).ok());
    EXPECT_EQ(r[0]->read_color().pixels, r[1]->read_color().pixels) << "probe at x = " << x;
  }
}

// render.pseudo_shadow = false: the colour is the frame's with the probe far out of reach (no
// pseudo-shadow anywhere) byte for byte, and differs from the default's; the AOVs and the
// reductions that feed the haptic side are the default's byte for byte. A textured material
// (the Gabor sum runs, for the texture AOV) and a probe 1 mm into the plane (a penetration);
// 64 px (the naive Gabor sum of the default material is slow on llvmpipe).
TEST_P(FeedbackGLTest, PseudoShadowOffChangesTheColourOnly) {
  Scene on = test::flat_plane_scene(8.0 - 1.0);
  on.render.width = on.render.height = 64;
  on.materials[0].resistance = 0.0;
  Scene off = on;
  off.render.pseudo_shadow = false;
  Scene far = on;
  far.probe.position.z = 1000.0;
  const std::optional<Frame> a = render(on), b = render(off), c = render(far);
  ASSERT_TRUE(a && b && c);
  EXPECT_EQ(b->color.pixels, c->color.pixels) << "no pseudo-shadow in the colour";
  EXPECT_NE(b->color.pixels, a->color.pixels) << "the default draws it";
  EXPECT_EQ(b->intensity.pixels, a->intensity.pixels);
  EXPECT_EQ(b->texture.pixels, a->texture.pixels);
  for (size_t i = 0; i < a->distance.pixels.size(); ++i) {
    const float x = a->distance.pixels[i], y = b->distance.pixels[i];
    ASSERT_TRUE(x == y || (std::isnan(x) && std::isnan(y))) << "distance AOV at " << i;
  }
  EXPECT_GT(a->stats.max_penetration_mm, 0.5);
  EXPECT_EQ(b->stats.max_penetration_mm, a->stats.max_penetration_mm);
  EXPECT_EQ(b->stats.displacement, a->stats.displacement);
  EXPECT_EQ(b->stats.shadow_pixels, a->stats.shadow_pixels);
  EXPECT_EQ(b->stats.reference_normal, a->stats.reference_normal);
}

// render.draw_probe = true draws what the view's probe flag (`--show-probe`) draws, byte for
// byte, and either one alone draws it (the key OR the flag).
TEST_P(FeedbackGLTest, DrawProbeIsShowProbe) {
  Scene s = test::flat_plane_scene(8.0 + 3.0);
  s.render.width = s.render.height = 64;
  s.materials[0].textured = false;  // the probe's drawing is tested, not the texture
  s.camera.position = {0.0, -60.0, 80.0};  // at an angle: the probe's body shows beside its shadow
  s.camera.up = {0.0, 0.0, 1.0};
  Scene keyed = s;
  keyed.render.draw_probe = true;
  const std::optional<Frame> flag = render(s, ViewFlags{true, false, false});
  const std::optional<Frame> key = render(keyed);
  const std::optional<Frame> both = render(keyed, ViewFlags{true, false, false});
  const std::optional<Frame> none = render(s);
  ASSERT_TRUE(flag && key && both && none);
  EXPECT_EQ(key->color.pixels, flag->color.pixels);
  EXPECT_EQ(both->color.pixels, flag->color.pixels);
  EXPECT_NE(none->color.pixels, flag->color.pixels) << "the probe must show";
}

PS_INSTANTIATE_HEADLESS_BACKENDS(FeedbackGLTest);

}  // namespace
}  // namespace ps
