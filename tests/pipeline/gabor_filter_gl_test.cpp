// Gabor texture anti-aliasing (issue: "Gabor texture without aliasing"; docs/architecture.md,
// "Texture filtering"): the filtered texture against the same view rendered 8 x 8 larger and
// box-filtered down, top-down and at a 15-degree grazing view, and against its CPU twin.
//
// The texture AOV (the Gabor value in sigmas) is compared, not the colour: inside the shadow the
// luminance is linear in it (pseudo_shadow_darkening: D = I + A s), and the AOV is that term
// alone, free of the shadow's own gradient, the gamma encoding and 8-bit rounding.
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/scenes.h"
#include "reference/gabor.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace ps {
namespace {

constexpr int kSize = 64;        // the image under test
constexpr int kSuper = 8;        // the reference: kSuper x kSuper samples per pixel
constexpr double kLambdaMm = 1.0;

enum class View { kTopDown, kGrazing };

// A plane under a huge sphere (r = 500 mm, 0.5 mm above it) whose shadow covers every pixel of
// both views; the texture shows everywhere (onset and influence far beyond). One wavelength,
// every orientation. lambda_px: the texture's wavelength in pixels at the image centre
// (across the view for the grazing one, whose depth axis squeezes it by sin 15 = 0.26 more).
Scene filter_scene(View view, double lambda_px, int size, GaborParams::Strategy strategy,
                   GaborParams::Filter filter) {
  Scene s = test::flat_plane_scene(500.5);
  s.probe.radius_mm = 500.0;
  s.surfaces[0].size_mm = {1200.0, 1200.0};
  s.render.width = s.render.height = size;
  Material& m = s.materials[0];
  m.onset_distance_mm = 1e4;
  m.influence_distance_mm = 1e5;
  m.gabor.lambda_min_mm = m.gabor.lambda_max_mm = kLambdaMm;
  m.gabor.theta_min_rad = 0.0;
  m.gabor.theta_max_rad = std::numbers::pi;
  m.gabor.n_min = 10.0;
  m.gabor.n_max = 20.0;
  m.gabor.strategy = strategy;
  m.gabor.bake_samples_per_lambda = strategy == GaborParams::Strategy::kBakedLinear ? 24 : 16;
  m.gabor.filter = filter;
  if (view == View::kTopDown) {
    s.camera.ortho_height_mm = kLambdaMm * kSize / lambda_px;
  } else {
    // Perspective, 10-degree field of view, the axis 15 degrees above the plane: across the
    // centre a pixel spans 2 D tan(5 deg) / kSize mm.
    s.camera.projection = Projection::kPerspective;
    s.camera.fov_y_deg = 10.0;
    const double dist = kLambdaMm * kSize / (2.0 * std::tan(5.0 * std::numbers::pi / 180.0) * lambda_px);
    const double a = 15.0 * std::numbers::pi / 180.0;
    s.camera.position = {0.0, -dist * std::cos(a), dist * std::sin(a)};
    s.camera.up = {0.0, 0.0, 1.0};
    s.camera.far_mm = 5000.0;
  }
  return s;
}

// The texture AOV of one frame (nullptr-safe: an empty image after a test failure).
Image render_texture(const Scene& s, const Renderer* reuse = nullptr, std::unique_ptr<Renderer>* keep = nullptr) {
  RendererOptions o;
  o.reuse_tiles_from = reuse;
  auto r = Renderer::create(s, o);
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
  if (!r.ok()) return {};
  EXPECT_TRUE(r.value()->render_frame().ok());
  Image tex = r.value()->read_aov("texture").value();
  const Image inten = r.value()->read_aov("intensity").value();
  int covered = 0;
  for (int y = 0; y < inten.height; ++y)
    for (int x = 0; x < inten.width; ++x) covered += inten.at(x, y, 0) > 0.0f;
  EXPECT_EQ(covered, inten.width * inten.height) << "the shadow must cover the whole view";
  if (keep) *keep = std::move(r.value());
  return tex;
}

// The reference, box-filtered down to kSize^2.
std::vector<double> box_down(const Image& big) {
  if (big.width != kSize * kSuper || big.height != kSize * kSuper) return {};  // the render failed
  std::vector<double> out(kSize * kSize, 0.0);
  for (int y = 0; y < kSize * kSuper; ++y)
    for (int x = 0; x < kSize * kSuper; ++x) out[(y / kSuper) * kSize + x / kSuper] += big.at(x, y, 0);
  for (double& v : out) v /= kSuper * kSuper;
  return out;
}

struct Compare {
  double rms_over_sd = 0.0;  // RMS(test - reference) / sd(reference)
  double var_ratio = 0.0;    // var(test) / var(reference)
};
Compare compare(const Image& test, const std::vector<double>& ref) {
  double mr = 0.0, mt = 0.0;
  const int n = kSize * kSize;
  for (int i = 0; i < n; ++i) mr += ref[i], mt += test.at(i % kSize, i / kSize, 0);
  mr /= n, mt /= n;
  double vr = 0.0, vt = 0.0, e2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double t = test.at(i % kSize, i / kSize, 0);
    vr += (ref[i] - mr) * (ref[i] - mr), vt += (t - mt) * (t - mt), e2 += (t - ref[i]) * (t - ref[i]);
  }
  return {std::sqrt(e2 / vr), vt / vr};
}

class GaborFilterGLTest : public test::GlTest {};

struct Case {
  View view;
  double lambda_px;
};

// Every strategy the filter applies to, none and analytic, against one reference per case.
TEST_P(GaborFilterGLTest, FilteredTextureMatchesTheSupersampledReference) {
  using S = GaborParams::Strategy;
  using F = GaborParams::Filter;
  const Case cases[] = {{View::kTopDown, 1.5}, {View::kTopDown, 2.0}, {View::kTopDown, 3.0}, {View::kTopDown, 5.0},
                        {View::kTopDown, 8.0}, {View::kTopDown, 20.0}, {View::kGrazing, 2.0}, {View::kGrazing, 8.0}};
  std::unique_ptr<Renderer> tiles[2][2];  // [linear][filtered]: bakes shared across the cases
  for (const Case& c : cases) {
    const bool top = c.view == View::kTopDown;
    for (const S strategy : {S::kNaive, S::kBakedLinear, S::kBaked}) {
      // The reference is the strategy's own texture: beyond its period a baked tile repeats
      // and is not the naive texture (GaborGLTest.BakedTextureRepeatsBeyondItsPeriodLikeItsTwin).
      const std::vector<double> ref = box_down(render_texture(
          filter_scene(c.view, c.lambda_px, kSize * kSuper, strategy, F::kNone),
          strategy == S::kNaive ? nullptr : tiles[strategy == S::kBakedLinear][0].get()));
      if (ref.empty()) return;  // the render failed (reported)
      for (const F filter : {F::kNone, F::kAnalytic}) {
        const bool filtered = filter == F::kAnalytic;
        std::unique_ptr<Renderer>* keep = nullptr;
        if (strategy != S::kNaive) keep = &tiles[strategy == S::kBakedLinear][filtered];
        const Renderer* reuse = keep ? keep->get() : nullptr;
        std::unique_ptr<Renderer> kept;
        const Image img = render_texture(filter_scene(c.view, c.lambda_px, kSize, strategy, filter), reuse,
                                         keep ? &kept : nullptr);
        if (img.width != kSize) return;  // the render failed (reported)
        if (keep && !*keep) *keep = std::move(kept);
        const Compare cmp = compare(img, ref);
        const char* name = strategy == S::kNaive ? "naive" : strategy == S::kBaked ? "baked" : "baked_linear";
        std::printf("%-8s lambda %4.1f px  %-12s %-8s RMS/sd %.3f  var ratio %.3f\n", top ? "top-down" : "grazing",
                    c.lambda_px, name, filtered ? "analytic" : "none", cmp.rms_over_sd, cmp.var_ratio);
        if (!filtered) continue;
        // The targets: RMS <= 0.25 sd top-down, <= 0.35 sd grazing.
        EXPECT_LE(cmp.rms_over_sd, top ? 0.25 : 0.35) << name << " lambda " << c.lambda_px;
        // No over-blurring: at lambda >= 8 px the variance within 5 % of the reference's.
        if (c.lambda_px >= 8.0) {
          EXPECT_NEAR(cmp.var_ratio, 1.0, 0.05) << name << " lambda " << c.lambda_px;
        }
      }
    }
  }
}

// The GPU's filtered sum against the CPU twin (gabor_noise_pixel) with the footprint the camera
// gives: an orthographic view tilted 15 degrees above the plane has the same derivatives at
// every pixel, (h, 0) across and (0, h / sin 15) down, h = height / size, so the footprint is
// anisotropic (3.9 x: four sub-boxes) and known exactly.
TEST_P(GaborFilterGLTest, FilteredTextureAovMatchesCpuReference) {
  Scene s = filter_scene(View::kTopDown, 1.5, kSize, GaborParams::Strategy::kNaive, GaborParams::Filter::kAnalytic);
  const double a = 15.0 * std::numbers::pi / 180.0;
  s.camera.position = {0.0, -100.0 * std::cos(a), 100.0 * std::sin(a)};
  s.camera.up = {0.0, 0.0, 1.0};
  const Image tex = render_texture(s);
  if (HasFailure()) return;
  const GaborParams& g = s.materials[0].gabor;
  const GaborSetup setup = make_gabor_setup(g);
  const double h = s.camera.ortho_height_mm / kSize;
  const PixelSplit split = gabor_pixel_split(h, 0.0, 0.0, h / std::sin(a), g.filter_pixel_variance,
                                             footprint_cap_mm2(g), kGaborFilterMaxSubsamples);
  EXPECT_EQ(split.k, 4) << "1 / sin 15 = 3.9: four sub-boxes down the screen";
  double max_err = 0.0, sum2 = 0.0;
  int n = 0;
  for (int py = 0; py < kSize; ++py)
    for (int px = 0; px < kSize; ++px) {
      // The pixel centre's ray meets the plane at x across, y = (screen offset) / sin 15.
      const double x = (px + 0.5 - 0.5 * kSize) * h, y = (0.5 * kSize - py - 0.5) * h / std::sin(a);
      const double expect = gabor_noise_pixel(g, setup, s.render.seed, x, y, h, 0.0, 0.0, h / std::sin(a)) /
                            setup.sigma_unit;
      const double e = tex.at(px, py, 0) - expect;
      max_err = std::max(max_err, std::abs(e));
      sum2 += expect * expect;
      ++n;
    }
  std::printf("filtered GPU vs CPU twin: max |error| %.2e sigma over %d pixels (texture RMS %.3f sigma)\n", max_err,
              n, std::sqrt(sum2 / n));
  // Float32 against double: positions from interpolated float vertices (~1e-5 mm), phase
  // errors ~1e-4 rad per kernel over ~50 kernels, the footprint from float derivatives
  // (relative ~1e-6): as for the unfiltered sum (GaborGLTest.TextureAovMatchesCpuReference),
  // 5e-3 sigma.
  EXPECT_LT(max_err, 5e-3);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(GaborFilterGLTest);

}  // namespace
}  // namespace ps
