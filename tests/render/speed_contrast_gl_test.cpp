// Speed modulation of the texture (thesis §4.3.1, §4.5.3) through the whole frame: the contrast
// of the texture inside the pseudo-shadow, measured in the colour image, follows the
// amplitude gain exp(-(gap / bandwidth)^2) of the probe's speed. The texture's own value comes
// from the `texture` AOV (in sigmas, before the gain), so the gain is the one unknown:
//   colour_lin = surface_lin * (1 - D),  s = T / contrast,
//   D = I + gain * min(I - I(onset), 1 - I) * s     above the surface (0 < d < onset),
//   D = 1 - gain * h * (1 - s), h = (1 - I(0+)) / 2  at contact (d <= 0)
// (glsl/lib/pseudo_shadow.glsl, docs/architecture.md "Composite"), linear in gain and solved
// by least squares over the shadow's pixels. The expected gains are closed forms of the material below, not the renderer's
// own numbers.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "support/scenes.h"
#include "reference/modulation.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace ps {
namespace {

// The surface pass writes pow(rgb, 1 / 2.2) into an 8-bit target (SurfaceFrame::gamma).
constexpr double kDisplayGamma = 2.2;
constexpr double kContrastSigmas = 5.0;  // wide, so few pixels clamp (|T| < 4.5 sigma kept)

// One wavelength (0.5 mm), isotropic orientations: the gain depends on the in-plane speed only,
// f = v / 0.5 mm against the 250 Hz peak with a 100 Hz bandwidth.
Scene moving_probe_scene() {
  Scene s = test::flat_plane_scene(8.0 - 2.0);  // sunk 2 mm: a wide disc of intensity 1
  Material& m = s.materials[0];
  m.gabor.lambda_min_mm = m.gabor.lambda_max_mm = 0.5;
  m.gabor.theta_min_rad = 0.0;
  m.gabor.theta_max_rad = 3.141592653589793;
  m.gabor.strategy = GaborParams::Strategy::kNaive;  // no bake: the sum is what is shown
  m.peak_hz = 250.0;
  m.bandwidth_hz = 100.0;
  m.resistance = 0.0;  // the probe stays where it is put
  return s;
}

struct Contrast {
  double gain = 0.0;  // least-squares estimate
  int pixels = 0;
};

// Gain shown in the last frame of `r`, from its colour image and AOVs.
Contrast measured_gain(const Renderer& r) {
  const Image color = r.read_color();
  const Image tex = r.read_aov("texture").value();
  const Image inten = r.read_aov("intensity").value();
  const Image dist = r.read_aov("distance").value();
  const Material& m = r.scene().materials[0];
  const double onset = m.onset_distance_mm;
  const double i_onset = m.intensity_floor + m.intensity_scale / (onset + m.intensity_offset_mm);
  const double half_gap = 0.5 * (1.0 - (m.intensity_floor + m.intensity_scale / m.intensity_offset_mm));
  // The unshadowed surface: the view's corner lies 20 mm from the probe's axis, outside its
  // 8 mm footprint; the plane is flat under a directional light, so it is the same everywhere.
  EXPECT_EQ(inten.at(0, 0, 0), 0.0f);
  double num = 0.0, den = 0.0;
  Contrast c;
  for (int py = 0; py < color.height; ++py)
    for (int px = 0; px < color.width; ++px) {
      const double i = inten.at(px, py, 0), t = tex.at(px, py, 0), d = dist.at(px, py, 0);
      // Near the axis (intensity >= 0.8, whole texels: intensity = the curve's), inside the
      // onset distance, texture not clamped at the contrast's ends.
      if (!(i >= 0.8 && d < onset && std::abs(t) < 0.9 * kContrastSigmas)) continue;
      if (d > 0.0 && std::abs(i - shadow_intensity(m, d)) > 1e-5) continue;
      const double s = t / kContrastSigmas;
      // y = gain * x, from the two branches above.
      const double x = d <= 0.0 ? half_gap * (s - 1.0) : std::min(i - i_onset, 1.0 - i) * s;
      for (int ch = 0; ch < 3; ++ch) {
        const double s_lin = std::pow(color.at(0, 0, ch), kDisplayGamma);
        const double c_lin = std::pow(color.at(px, py, ch), kDisplayGamma);
        const double y = (1.0 - c_lin / s_lin) - (d <= 0.0 ? 1.0 : i);
        num += x * y;
        den += x * x;
      }
      ++c.pixels;
    }
  c.gain = den > 0.0 ? num / den : 0.0;
  return c;
}

class SpeedContrastGLTest : public test::GlTest {};

TEST_P(SpeedContrastGLTest, TextureContrastFollowsTheSpeedGain) {
  const Scene s = moving_probe_scene();
  RendererOptions opt;
  opt.contrast_sigmas = kContrastSigmas;
  auto rr = Renderer::create(s, opt);
  ASSERT_TRUE(rr.ok()) << rr.error().message;
  Renderer& r = *rr.value();
  const double at_rest = std::exp(-6.25);  // 0 Hz: gap 250 Hz = 2.5 bandwidths
  struct Case {
    glm::dvec3 velocity;  // mm/s
    double gain;
  } cases[] = {
      {{0.0, 0.0, 0.0}, at_rest},
      {{75.0, 0.0, 0.0}, std::exp(-1.0)},   // 150 Hz: one bandwidth below the peak
      {{0.0, 125.0, 0.0}, 1.0},             // 250 Hz: the peak
      {{-88.388347648, 88.388347648, 0.0}, 1.0},  // 125 mm/s diagonally: isotropic
      {{175.0, 0.0, 40.0}, std::exp(-1.0)}, // 350 Hz in the plane; motion along the normal ignored
      {{250.0, 0.0, 0.0}, at_rest},         // 500 Hz
  };
  for (const Case& k : cases) {
    ASSERT_TRUE(r.render(probe_frame_input(s.probe.position, k.velocity)).ok());
    const Contrast c = measured_gain(r);
    std::printf("[speed] v = (%g, %g, %g) mm/s: gain %.4f expected %.4f (stats %.4f, %d px)\n", k.velocity.x,
                k.velocity.y, k.velocity.z, c.gain, k.gain, r.stats().speed_gain, c.pixels);
    EXPECT_GT(c.pixels, 500);  // 912: intensity >= 0.8 within 2.4 mm of the axis
    // The renderer's per-frame gain against the closed form (and its CPU twin) in double.
    EXPECT_NEAR(r.stats().speed_gain, k.gain, 1e-9);
    EXPECT_NEAR(speed_gain(s.materials[0], r.reference(), k.velocity), k.gain, 1e-9);
    // The gain the image shows. 8-bit colour quantises `shown` by ~0.014 per level at this
    // brightness, averaged over ~900 pixels x 3 channels; measured deviations <= 0.0020 (at
    // rest, where the texture is nearly flat), 0.0010 at the peak. 0.008 is 4x that, far
    // below the differences between the cases (>= 0.37).
    EXPECT_NEAR(c.gain, k.gain, 0.008);
  }
}

// A speed_gain_lut (scene/lut.h) replaces the formula: the contrast the image shows follows the
// table, linear between its rows and flat beyond the last, through the same measurement.
TEST_P(SpeedContrastGLTest, TextureContrastFollowsTheSpeedGainTable) {
  Scene s = moving_probe_scene();
  s.materials[0].speed_gain_lut.points = {{0.0, 0.9}, {100.0, 0.3}, {200.0, 1.0}};
  RendererOptions opt;
  opt.contrast_sigmas = kContrastSigmas;
  auto rr = Renderer::create(s, opt);
  ASSERT_TRUE(rr.ok()) << rr.error().message;
  Renderer& r = *rr.value();
  struct Case {
    glm::dvec3 velocity;  // mm/s
    double gain;          // the table at the in-plane speed (isotropic texture, so blend = 1)
  } cases[] = {
      {{0.0, 0.0, 0.0}, 0.9},
      {{50.0, 0.0, 0.0}, 0.6},
      {{-70.710678118654752, 70.710678118654752, 0.0}, 0.3},  // 100 mm/s diagonally: a row
      {{0.0, 150.0, 0.0}, 0.65},
      {{400.0, 0.0, 0.0}, 1.0},  // beyond the last row: its value
  };
  for (const Case& k : cases) {
    ASSERT_TRUE(r.render(probe_frame_input(s.probe.position, k.velocity)).ok());
    const Contrast c = measured_gain(r);
    std::printf("[speed lut] v = (%g, %g, %g) mm/s: gain %.4f expected %.4f (stats %.4f, %d px)\n", k.velocity.x,
                k.velocity.y, k.velocity.z, c.gain, k.gain, r.stats().speed_gain, c.pixels);
    EXPECT_GT(c.pixels, 500);
    // Interpolation in double (1e-12) and the diagonal's rounding to 100 mm/s (1e-14 relative).
    EXPECT_NEAR(r.stats().speed_gain, k.gain, 1e-9);
    // The same image measurement and bound as TextureContrastFollowsTheSpeedGain (the table's
    // gains lie in the formula's range, so the 8-bit error does too).
    EXPECT_NEAR(c.gain, k.gain, 0.008);
  }
}

PS_INSTANTIATE_HEADLESS_BACKENDS(SpeedContrastGLTest);

}  // namespace
}  // namespace ps
