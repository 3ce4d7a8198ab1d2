// The four properties that let people discount the pseudo-shadow as a shadow (thesis §4.2,
// docs/architecture.md "The composite"), measured in the colour image with the texture on and
// off: a lit uniform-albedo plane seen from above, a sphere probe (r = 8 mm) 1.5 mm over it
// moving at the speed where the material's texture peaks (full texture), 256^2. Darkening = unshadowed minus shadowed luma, in 8-bit levels of
// the gamma-encoded image, averaged over 1-pixel rings around the shadow's centre.
//   (a) moving from the edge to the centre, the ring means never decrease;
//   (b) every pixel of the footprint is darker than the receiver, border included;
//   (c) no step between neighbouring rings (the onset ring included), no dark mark at the border;
//   (d) lowering the probe, the centre pixel's darkness never decreases, at rest and at that speed.
// And the image against the CPU twin of the composite (reference/modulation.h), per pixel.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/scenes.h"
#include "reference/modulation.h"
#include "render/renderer.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"

namespace ps {
namespace {

constexpr int kSize = 256;
constexpr double kProbeZ = 8.0 + 1.5;          // sphere centre: 1.5 mm above the plane
constexpr double kDisplayGamma = 2.2;          // the surface pass encodes with 1 / 2.2

// Along x at peak_hz x mean lambda: the material's texture at full amplitude (gain 1), in
// mm/s. The shipped materials peak at a mouse stroke (docs/scene-format.md, "The texture at
// hand speed"); a fixed speed would leave most of them untextured.
glm::dvec3 texture_velocity(const Material& m) {
  return {m.peak_hz * 0.5 * (m.gabor.lambda_min_mm + m.gabor.lambda_max_mm), 0.0, 0.0};
}

Material default_wood() {
  auto s = parse_scene(default_scene_text(), "<embedded default>", default_scene_base_dir());
  EXPECT_TRUE(s.ok()) << s.error().message;
  return s.value().materials.at(0);
}

Material shipped_material(const std::string& file) {
  auto s = load_scene(default_scene_base_dir() + "/" + file);
  EXPECT_TRUE(s.ok()) << s.error().message;
  return s.value().materials.at(0);
}

Scene discount_scene(Material m, bool perspective, bool textured) {
  Scene s = test::flat_plane_scene(kProbeZ);
  s.render.width = s.render.height = kSize;
  if (perspective) {  // 100 mm away, 37 degrees off the normal: rings become ellipses on screen
    s.camera.projection = Projection::kPerspective;
    s.camera.position = {0.0, -60.0, 80.0};
    s.camera.up = {0.0, 0.0, 1.0};
    s.camera.fov_y_deg = 2.0 * std::atan(20.0 / 100.0) * 180.0 / 3.141592653589793;
  }
  m.albedo_texture.clear();  // uniform albedo: every luma change is the shadow's
  m.textured = textured;
  m.resistance = 0.0;        // the probe stays where it is put
  s.materials[0] = m;
  s.surfaces[0].material = m.name;
  return s;
}

double luma(const Image& c, int x, int y) {
  return 255.0 * (0.2126 * c.at(x, y, 0) + 0.7152 * c.at(x, y, 1) + 0.0722 * c.at(x, y, 2));
}

struct Ring {
  int n = 0;
  double sum = 0.0, sum2 = 0.0;
  double mean() const { return sum / n; }
  // Pixels closer than a texture wavelength are correlated: a ring holds about
  // n * (pixel / lambda)^2 independent samples of the texture, at least one.
  double std_error(double pixels_per_sample) const {
    const double n_eff = std::max(1.0, n / pixels_per_sample);
    return std::sqrt(std::max(sum2 / n - mean() * mean(), 0.0) / n_eff);
  }
};

struct Profile {
  std::vector<Ring> rings;    // ring k: k <= r / kRingMm < k + 1, r = distance from the axis
  int footprint = 0;          // pixels with intensity > 0
  int not_darker = 0;         // footprint pixels with intensity >= kClearlyShadowed, not darker
  int lighter = 0;            // footprint pixels lighter than the receiver
};

// An intensity of 0.02 darkens this plane by >= 2 levels: such a pixel must be visibly darker.
// Below it (the outermost, filtered edge texels) it must only never be lighter.
constexpr double kClearlyShadowed = 0.02;

// Distance (mm) on the plane z = 0 from the probe's axis to what pixel (x, y) sees: the ray
// through the pixel's centre met with the plane (orthographic: test::pixel_to_world).
double axis_distance_mm(const Scene& s, int x, int y) {
  if (s.camera.projection == Projection::kOrthographic) return glm::length(test::pixel_to_world(s, x, y));
  const Camera& c = s.camera;
  const glm::dvec3 fwd = glm::normalize(c.target - c.position);
  const glm::dvec3 right = glm::normalize(glm::cross(fwd, c.up));
  const glm::dvec3 up = glm::cross(right, fwd);
  const double t = std::tan(0.5 * c.fov_y_deg * 3.141592653589793 / 180.0);
  const double nx = (x + 0.5) / s.render.width * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / s.render.height * 2.0;
  const glm::dvec3 dir = fwd + nx * t * right + ny * t * up;  // square image: aspect 1
  const glm::dvec3 hit = c.position - c.position.z / dir.z * dir;
  return std::hypot(hit.x, hit.y);
}

// Ring width: one pixel of the orthographic view (40 mm / 256).
constexpr double kRingMm = 40.0 / kSize;

Profile ring_profile(const Renderer& r) {
  const Image color = r.read_color();
  const Image inten = r.read_aov("intensity").value();
  EXPECT_EQ(inten.at(0, 0, 0), 0.0f);  // the corner is 20 mm off axis, outside the 8 mm footprint
  const double lit = luma(color, 0, 0);
  Profile p;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double i = inten.at(x, y, 0);
      if (!(i > 0.0)) continue;
      const double dark = lit - luma(color, x, y);
      ++p.footprint;
      if (dark < 0.0) ++p.lighter;
      if (i >= kClearlyShadowed && !(dark > 0.0)) ++p.not_darker;
      const auto k = static_cast<size_t>(axis_distance_mm(r.scene(), x, y) / kRingMm);
      if (k >= p.rings.size()) p.rings.resize(k + 1);
      Ring& g = p.rings[k];
      ++g.n, g.sum += dark, g.sum2 += dark * dark;
    }
  return p;
}

// Texture noise in a ring mean: 4 standard errors of the difference of two ring means, counting
// independent samples per texture wavelength, plus 1 level for 8-bit rounding of the two means.
double noise_tolerance(const Ring& a, const Ring& b, double pixels_per_sample) {
  return 4.0 * std::hypot(a.std_error(pixels_per_sample), b.std_error(pixels_per_sample)) + 1.0;
}

struct Verdict {
  double centre = 0.0, border = 0.0;  // mean darkening of the innermost 3 rings and the outermost
  double worst_rise = 0.0;  // largest amount by which a ring is lighter than one outside it
  double max_step = 0.0;    // largest ring-to-ring change inside the footprint
  bool monotone = true, smooth = true, no_mark = true;
};

Verdict judge(const Profile& p, double pixels_per_sample) {
  Verdict v;
  const auto& g = p.rings;
  const size_t last = g.size() - 1;
  double c = 0.0;
  int cn = 0;
  for (size_t k = 0; k < 3 && k <= last; ++k) c += g[k].sum, cn += g[k].n;
  v.centre = c / cn;
  v.border = g[last].mean();
  for (size_t k = 0; k < last; ++k)
    for (size_t j = k + 1; j <= last; ++j) {
      const double rise = g[j].mean() - g[k].mean();
      v.worst_rise = std::max(v.worst_rise, rise);
      if (rise > noise_tolerance(g[k], g[j], pixels_per_sample)) v.monotone = false;
    }
  // The outermost ring is only partly covered (the filtered edge); it is the shadow's end, and
  // must be lighter than the ring inside it (a darker one would be a mark), not smooth with it.
  for (size_t k = 0; k + 2 <= last; ++k) {
    const double step = std::abs(g[k + 1].mean() - g[k].mean());
    v.max_step = std::max(v.max_step, step);
    if (step > noise_tolerance(g[k], g[k + 1], pixels_per_sample)) v.smooth = false;
  }
  if (g[last].mean() > g[last - 1].mean() + noise_tolerance(g[last], g[last - 1], pixels_per_sample)) v.no_mark = false;
  return v;
}

struct Case {
  const char* name;
  Material material;
  bool perspective, textured;
};

void check_rings(const Case& k) {
  const Scene s = discount_scene(k.material, k.perspective, k.textured);
  auto rr = Renderer::create(s, {});
  ASSERT_TRUE(rr.ok()) << rr.error().message;
  Renderer& r = *rr.value();
  ASSERT_TRUE(r.render(probe_frame_input(s.probe.position, texture_velocity(k.material))).ok());
  if (k.textured) {
    EXPECT_NEAR(r.stats().speed_gain, 1.0, 1e-9) << k.name << ": the texture must show fully";
  }
  const Profile p = ring_profile(r);
  ASSERT_GT(p.rings.size(), 40u);  // the 8 mm footprint spans ~51 px at 40 mm / 256 px
  const double lambda_px = k.material.gabor.lambda_max_mm / kRingMm;
  const Verdict v = judge(p, k.textured ? std::max(1.0, lambda_px * lambda_px) : 1.0);
  std::printf("[discount] %s: centre %.2f border %.2f /255, worst rise %.2f, max step %.2f, "
              "%d of %d px not darker, %d lighter (gain %.3f)\n",
              k.name, v.centre, v.border, v.worst_rise, v.max_step, p.not_darker, p.footprint,
              p.lighter, r.stats().speed_gain);
  EXPECT_TRUE(v.monotone) << k.name << ": a ring is lighter than one outside it by " << v.worst_rise;
  EXPECT_EQ(p.not_darker, 0) << k.name;
  EXPECT_EQ(p.lighter, 0) << k.name;
  EXPECT_TRUE(v.smooth) << k.name << ": ring-to-ring step " << v.max_step;
  EXPECT_TRUE(v.no_mark) << k.name << ": the border ring is darker than the ring inside it";
}

class ShadowDiscountGLTest : public test::GlTest {};

TEST_P(ShadowDiscountGLTest, RingProfilesReadAsAShadow) {
  const Material wood = default_wood();
  const Case cases[] = {
      {"wood, orthographic, textured", wood, false, true},
      {"wood, orthographic, untextured", wood, false, false},
      {"wood, perspective, textured", wood, true, true},
      {"wood, perspective, untextured", wood, true, false},
  };
  for (const Case& k : cases) check_rings(k);
}

TEST_P(ShadowDiscountGLTest, ShippedMaterialsReadAsAShadow) {
  for (const char* file : {"table5_1_construction_paper.toml", "table5_1_sandpaper.toml",
                           "table4_1_a.toml", "table4_1_f.toml"}) {
    const Material m = shipped_material(file);
    if (!m.textured) continue;
    check_rings({file, m, false, true});
  }
}

// Lowering the probe from beyond the onset distance through contact: the centre pixel's
// darkening never decreases. The texture under that pixel is fixed (it lives on the surface),
// so the only change is the probe's distance; 8-bit rounding is monotone, hence no tolerance.
TEST_P(ShadowDiscountGLTest, CentreDarkensAsTheProbeApproaches) {
  for (bool textured : {true, false})
    for (double speed : {0.0, texture_velocity(default_wood()).x}) {
      const Scene s = discount_scene(default_wood(), false, textured);
      auto rr = Renderer::create(s, {});
      ASSERT_TRUE(rr.ok()) << rr.error().message;
      Renderer& r = *rr.value();
      double lit = -1.0, prev = -1.0, prev_z = 0.0;
      int decreases = 0;
      for (double gap = 7.0; gap >= -0.5; gap -= 0.125) {
        const double z = 8.0 + gap;
        ASSERT_TRUE(r.render(probe_frame_input({0.0, 0.0, z}, {speed, 0.0, 0.0})).ok());
        const Image c = r.read_color();
        if (lit < 0.0) lit = luma(c, 0, 0);
        const double dark = lit - luma(c, kSize / 2, kSize / 2);
        if (dark < prev) {
          ++decreases;
          std::printf("[approach] textured %d, %g mm/s: darkening %.2f at gap %.3f mm, %.2f at %.3f\n",
                      textured, speed, dark, gap, prev, prev_z - 8.0);
        }
        prev = dark, prev_z = z;
      }
      EXPECT_EQ(decreases, 0) << "textured " << textured << ", " << speed << " mm/s";
    }
}

// The image against the CPU twin, pixel by pixel, from the frame's own AOVs (distance, texture,
// coverage = intensity AOV / untextured intensity) and the receiver's colour at the corner.
TEST_P(ShadowDiscountGLTest, CompositeMatchesItsCpuTwin) {
  const Scene s = discount_scene(default_wood(), false, true);
  RendererOptions opt;
  auto rr = Renderer::create(s, opt);
  ASSERT_TRUE(rr.ok()) << rr.error().message;
  Renderer& r = *rr.value();
  const Material& m = s.materials[0];
  for (double gap : {1.5, 0.4, -0.3}) {  // in the onset band, near contact, at contact
    ASSERT_TRUE(r.render(probe_frame_input({0.0, 0.0, 8.0 + gap}, texture_velocity(m))).ok());
    const Image c = r.read_color();
    const Image inten = r.read_aov("intensity").value();
    const Image dist = r.read_aov("distance").value();
    const Image tex = r.read_aov("texture").value();
    const double gain = r.stats().speed_gain;
    double worst = 0.0;
    int n = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const double i = inten.at(x, y, 0), d = dist.at(x, y, 0);
        if (!(i > 0.0)) continue;
        const double cov = i / shadow_intensity(m, d);
        const double dark = pseudo_shadow_darkening(m, d, cov, gain, tex.at(x, y, 0) / opt.contrast_sigmas);
        for (int ch = 0; ch < 3; ++ch) {
          const double lit = std::pow(c.at(0, 0, ch), kDisplayGamma);
          const double want = 255.0 * std::pow(lit * (1.0 - dark), 1.0 / kDisplayGamma);
          worst = std::max(worst, std::abs(want - 255.0 * c.at(x, y, ch)));
        }
        ++n;
      }
    std::printf("[twin] gap %.2f mm: %d px, worst %.3f levels\n", gap, n, worst);
    EXPECT_GT(n, 1000);
    // 0.5 level rounding of the pixel + <= 0.5 level carried from the rounded receiver colour
    // at the corner, + float evaluation on the GPU: 1.5 levels.
    EXPECT_LE(worst, 1.5) << "gap " << gap;
  }
}

PS_INSTANTIATE_HEADLESS_BACKENDS(ShadowDiscountGLTest);

}  // namespace
}  // namespace ps
