// The bodies' pseudo-shadows (glsl/lib/body_shadow.glsl, CPU twin reference/body_shadow.h):
// a uniform, untextured plane at z = 0 (normal +Z) under a ball of radius 6 mm, drawn as the
// renderer draws bodies (WorldView::run) and casting its analytic shadow. Pixels where the
// drawn ball may cover the plane are left out of every comparison (a ray through the pixel
// passes within kBallMarginPx pixels of the sphere): the shadow is what is tested, not the ball.
//   - the colour image against the twin, body alone (the probe out of reach: the PS_SHADOW=0
//     variant) and together with the probe's shadow;
//   - the probe's AOVs and stats are those of the frame without the body;
//   - lowering the body from beyond the influence distance through contact, no pixel lightens;
//   - never lighter than the receiver, ring means darkest at the foot, no darker border;
//   - nothing at all 0.01 mm beyond the influence distance, a shadow 0.01 mm inside it;
//   - bodies without positions cast nothing (byte-identical to the scene without bodies).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "support/scenes.h"
#include "reference/body_shadow.h"
#include "reference/modulation.h"
#include "scene/camera.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace ps {
namespace {

constexpr double kBallRadius = 6.0;
constexpr double kDisplayGamma = 2.2;  // the surface pass encodes with 1 / 2.2
constexpr double kBallMarginPx = 2.0;  // the drawn (tessellated, unfiltered) ball's silhouette
const glm::dvec2 kFoot{3.0, 1.5};      // the ball's foot on the plane, mm
constexpr double kSecondRadius = 2.5;  // ImageMatchesItsCpuTwin's second ball

// flat_plane_scene at `size`², its material untextured (every change of the colour image is a
// shadow), the probe out of reach unless `probe_z` is given, one body, and a camera that sees
// the plane at an angle so the shadow shows beside the ball: orthographic (the world position
// is affine in the pixel, so the pixel's extent on the plane is exact) or perspective.
Scene body_scene(int size, bool perspective, double probe_z = 1000.0) {
  Scene s = test::flat_plane_scene(probe_z);
  s.render.width = s.render.height = size;
  s.camera.position = {0.0, -60.0, 80.0};  // 37 degrees off the normal
  s.camera.up = {0.0, 0.0, 1.0};
  if (perspective) {
    s.camera.projection = Projection::kPerspective;
    s.camera.fov_y_deg = 2.0 * std::atan(20.0 / 100.0) * 180.0 / M_PI;
  }
  s.materials[0].textured = false;
  s.materials[0].resistance = 0.0;  // the probe stays where it is put
  Body b;
  b.radius_mm = kBallRadius;
  b.material = s.materials[0].name;
  s.bodies.push_back(b);
  return s;
}

glm::dvec3 ball_at_gap(double gap_mm) { return {kFoot.x, kFoot.y, kBallRadius + gap_mm}; }

struct Ray {
  glm::dvec3 origin, dir;
};

// The ray through the centre of pixel (px, py) (row 0 = top), from the near to the far plane.
Ray pixel_ray(const Scene& s, int px, int py) {
  const glm::dmat4 inv = glm::inverse(view_projection(s.camera, static_cast<double>(s.render.width) / s.render.height));
  const double x = (px + 0.5) / s.render.width * 2.0 - 1.0, y = 1.0 - (py + 0.5) / s.render.height * 2.0;
  const glm::dvec4 a = inv * glm::dvec4(x, y, -1.0, 1.0), b = inv * glm::dvec4(x, y, 1.0, 1.0);
  const glm::dvec3 o = glm::dvec3(a) / a.w;
  return {o, glm::normalize(glm::dvec3(b) / b.w - o)};
}

glm::dvec3 hit_plane(const Ray& r) { return r.origin - r.origin.z / r.dir.z * r.dir; }

// True where the drawn ball may cover the pixel: the ray passes within the margin of it.
bool ball_may_cover(const Scene& s, int px, int py, const glm::dvec3& centre, double radius_mm = kBallRadius) {
  const Ray r = pixel_ray(s, px, py);
  const glm::dvec3 q = centre - r.origin;
  const double miss = glm::length(q - glm::dot(q, r.dir) * r.dir);
  const double pixel_mm = glm::length(hit_plane(pixel_ray(s, px + 1, py)) - hit_plane(r));
  return miss < radius_mm + kBallMarginPx * pixel_mm;
}

// The pixel's largest extent on the plane: what the shader's dFdx/dFdy of the world position
// give where that position is affine in the pixel (orthographic camera).
double pixel_extent_mm(const Scene& s, int px, int py) {
  const glm::dvec3 p = hit_plane(pixel_ray(s, px, py));
  return std::max(glm::length(hit_plane(pixel_ray(s, px + 1, py)) - p),
                  glm::length(hit_plane(pixel_ray(s, px, py + 1)) - p));
}

// The receiver's linear colour (channel 0; the albedo is grey): albedo x (ambient + Lambert).
double receiver_linear(const Scene& s) {
  const Light& l = s.light;
  const double lambert = std::max(-glm::normalize(l.direction).z, 0.0);
  return s.materials[0].albedo.x * l.color.x * (l.ambient + (1.0 - l.ambient) * lambert);
}

struct Frame {
  Image color, intensity, distance, texture;
  FrameStats stats;
};

// One frame of `s` with the bodies at `bodies` (empty: none of the scene's bodies drawn or cast).
std::optional<Frame> render(const Scene& s, const std::vector<glm::dvec3>& bodies) {
  auto made = Renderer::create(s, {});
  if (!made.ok()) {
    ADD_FAILURE() << made.error().message;
    return std::nullopt;
  }
  Renderer& r = *made.value();
  FrameInput in;  // the bodies where given (none: the rest neither drawn nor cast), no markers
  in.bodies_mm = bodies;
  in.markers = std::vector<WorldMarker>{};  // not the start view's bands from the probe
  if (auto f = r.render(in); !f) {
    ADD_FAILURE() << f.error().message;
    return std::nullopt;
  }
  return Frame{r.read_color(), r.read_aov("intensity").value(), r.read_aov("distance").value(),
               r.read_aov("texture").value(), r.stats()};
}

// The colour image against the twin: 255 (L (1 - D))^(1/2.2) per pixel, L the receiver's
// linear colour from the scene, D the twin's darkening at the point the pixel's centre sees
// (the bodies' product, combined with the probe's own twin where the frame's AOVs show its
// shadow, as in ShadowDiscountGLTest.CompositeMatchesItsCpuTwin). Channel 0: the receiver is
// grey under white light, so the three channels are equal.
struct TwinComparison {
  double worst_levels = 0.0;
  int compared = 0, shadowed = 0;  // pixels left to compare; of them, in a body's shadow
  int overlapped = 0;              // in two shadows (both bodies', or a body's and the probe's)
};

TwinComparison compare_with_twin(const Scene& s, const Frame& f, const std::vector<SphereCaster>& casters) {
  const Material& m = s.materials[0];
  const glm::dvec3 up{0.0, 0.0, 1.0};
  const double lit = receiver_linear(s);
  TwinComparison t;
  for (int y = 0; y < s.render.height; ++y)
    for (int x = 0; x < s.render.width; ++x) {
      if (std::any_of(casters.begin(), casters.end(),
                      [&](const SphereCaster& c) { return ball_may_cover(s, x, y, c.centre, c.radius_mm); }))
        continue;
      const glm::dvec3 p = hit_plane(pixel_ray(s, x, y));
      const double edge = pixel_extent_mm(s, x, y);
      int casting = 0;
      for (const SphereCaster& c : casters) casting += body_shadow_darkening(m, c, p, up, edge) > 0.0;
      double dark = body_shadows_darkening(m, casters, p, up, edge);
      const double i = f.intensity.at(x, y, 0);
      if (i > 0.0) {  // the probe's shadow, from its AOVs (coverage = intensity / curve)
        const double d = f.distance.at(x, y, 0);
        ++casting;
        dark = combine_darkening(pseudo_shadow_darkening(m, d, i / shadow_intensity(m, d), f.stats.speed_gain, 0.0), dark);
      }
      t.shadowed += casting > (i > 0.0 ? 1 : 0);
      t.overlapped += casting > 1;
      const double want = 255.0 * std::pow(lit * (1.0 - dark), 1.0 / kDisplayGamma);
      t.worst_levels = std::max(t.worst_levels, std::abs(want - 255.0 * f.color.at(x, y, 0)));
      ++t.compared;
    }
  return t;
}

class BodyShadowGLTest : public test::GlTest {};

// Body alone (the probe out of reach: the PS_SHADOW=0 variant), above, on and through the
// receiver, over the probe's shadow, with a second body, and partly beyond the influence distance.
TEST_P(BodyShadowGLTest, ImageMatchesItsCpuTwin) {
  struct Case {
    const char* name;
    double gap_mm;                // the ball's lowest point above the plane (< 0: through it)
    bool probe = false;           // the probe's shadow overlaps
    bool second = false;          // a second, smaller ball 12 mm up in front: its shadow overlaps the first's
    double influence_mm = 50.0;   // the receiver's (the default)
  };
  const Case cases[] = {{"gap 4 mm", 4.0}, {"gap 1 mm", 1.0}, {"gap 0.2 mm", 0.2}, {"resting on it", 0.0},
                        {"sunk 2 mm", -2.0}, {"wholly below", -12.5}, {"gap 1 mm + probe", 1.0, true},
                        {"gap 1 mm + a second ball", 1.0, false, true},
                        // the disc ends inside the footprint: radius sqrt(6^2 - (10 - 6)^2) = 4.5 mm
                        {"gap 4 mm, influence 6 mm", 4.0, false, false, 6.0}};
  for (const Case& k : cases) {
    Scene s = body_scene(128, false, k.probe ? 8.0 + 1.5 : 1000.0);
    s.materials[0].influence_distance_mm = k.influence_mm;
    std::vector<SphereCaster> casters{{ball_at_gap(k.gap_mm), kBallRadius}};
    if (k.second) {
      s.bodies.push_back(s.bodies[0]);
      s.bodies[1].radius_mm = kSecondRadius;
      casters.push_back({{3.0, -3.0, kSecondRadius + 12.0}, kSecondRadius});
    }
    std::vector<glm::dvec3> centres;
    for (const SphereCaster& c : casters) centres.push_back(c.centre);
    const std::optional<Frame> f = render(s, centres);
    ASSERT_TRUE(f);
    const bool probe_skipped = std::find(f->stats.skipped.begin(), f->stats.skipped.end(),
                                         "probe_depth: probe beyond every surface's influence distance") !=
                               f->stats.skipped.end();
    EXPECT_EQ(probe_skipped, !k.probe) << k.name;
    const TwinComparison t = compare_with_twin(s, *f, casters);
    std::printf("[body twin] %s: %d px compared, %d in a body's shadow, %d in two shadows, worst %.3f levels\n",
                k.name, t.compared, t.shadowed, t.overlapped, t.worst_levels);
    EXPECT_GT(t.compared, 128 * 128 / 2) << k.name;
    if (k.gap_mm > -kBallRadius * 2.0) {
      EXPECT_GT(t.shadowed, 40) << k.name << ": the shadow must show beside the ball";
    } else {
      EXPECT_EQ(t.shadowed, 0) << k.name << ": hidden by the receiver, no shadow";
    }
    EXPECT_EQ(t.overlapped > 40, k.probe || k.second) << k.name << ": " << t.overlapped << " px in two shadows";
    // 0.5 level: the 8-bit rounding of the pixel; + 0.1 for the GPU's float evaluation (world
    // positions of ~20 mm to ~1e-6 relative, llvmpipe's pow and sqrt) and the filtered rim,
    // whose coverage moves by 1e-5 mm / 0.3125 mm per float error in the lateral distance.
    // Measured: 0.500 (a pixel exactly between two levels).
    EXPECT_LE(t.worst_levels, 0.6) << k.name;
  }
}

// The body changes the colour image only: the probe's AOVs, the displacement and the reduced
// reference plane are those of the frame without it, byte for byte.
TEST_P(BodyShadowGLTest, ProbeAovsAndStatsAreUnchanged) {
  const Scene s = body_scene(128, false, 8.0 + 0.5);
  const std::optional<Frame> with = render(s, {ball_at_gap(0.5)});
  const std::optional<Frame> without = render(s, {});
  ASSERT_TRUE(with && without);
  EXPECT_EQ(with->intensity.pixels, without->intensity.pixels);
  EXPECT_EQ(with->texture.pixels, without->texture.pixels);
  int darker = 0;
  for (size_t i = 0; i < with->distance.pixels.size(); ++i) {
    const float a = with->distance.pixels[i], b = without->distance.pixels[i];
    EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << "distance AOV at " << i;
  }
  for (int y = 0; y < s.render.height; ++y)
    for (int x = 0; x < s.render.width; ++x)
      if (!ball_may_cover(s, x, y, ball_at_gap(0.5)) && with->color.at(x, y, 0) < without->color.at(x, y, 0)) ++darker;
  EXPECT_GT(darker, 40);
  EXPECT_EQ(with->stats.displacement, without->stats.displacement);
  EXPECT_EQ(with->stats.reference_normal, without->stats.reference_normal);
  EXPECT_EQ(with->stats.shadow_pixels, without->stats.shadow_pixels);
  EXPECT_EQ(with->stats.max_penetration_mm, without->stats.max_penetration_mm);
}

// Lowering the ball from beyond the influence distance through contact into the plane, no
// pixel ever lightens (each step's ball pixels, and those of the step before, left out). The
// colour is a monotone function of the darkening through 8-bit rounding, hence no tolerance.
TEST_P(BodyShadowGLTest, DarkensMonotonicallyAsTheBodyApproaches) {
  for (bool perspective : {false, true}) {
    Scene s = body_scene(96, perspective);
    s.materials[0].influence_distance_mm = 12.0;  // a short reach: the whole approach in ~40 steps
    auto made = Renderer::create(s, {});
    ASSERT_TRUE(made.ok()) << made.error().message;
    Renderer& r = *made.value();
    std::optional<Image> prev;
    glm::dvec3 prev_ball{0.0};
    int lightened = 0, darkened = 0;
    for (double gap = 13.0; gap >= -3.0; gap -= 0.375) {
      const glm::dvec3 ball = ball_at_gap(gap);
      FrameInput in;
      in.bodies_mm = std::vector<glm::dvec3>{ball};
      ASSERT_TRUE(r.render(in).ok());
      Image c = r.read_color();
      if (prev)
        for (int y = 0; y < s.render.height; ++y)
          for (int x = 0; x < s.render.width; ++x) {
            if (ball_may_cover(s, x, y, ball) || ball_may_cover(s, x, y, prev_ball)) continue;
            for (int ch = 0; ch < 3; ++ch) {
              if (c.at(x, y, ch) > prev->at(x, y, ch)) {
                if (++lightened <= 5)
                  std::printf("[approach] perspective %d: pixel (%d, %d) lightened at gap %.3f mm\n", perspective, x, y, gap);
              }
              if (c.at(x, y, ch) < prev->at(x, y, ch)) ++darkened;
            }
          }
      prev = std::move(c);
      prev_ball = ball;
    }
    EXPECT_EQ(lightened, 0) << "perspective " << perspective;
    EXPECT_GT(darkened, 100) << "perspective " << perspective << ": the shadow must grow";
  }
}

double luma(const Image& c, int x, int y) {
  return 255.0 * (0.2126 * c.at(x, y, 0) + 0.7152 * c.at(x, y, 1) + 0.0722 * c.at(x, y, 2));
}

// Thesis §4.2 on the body's shadow, seen in perspective: no pixel is lighter than the receiver
// (the same frame without bodies); ring means around the foot (1 px wide on the plane) never
// darken outward (the darkest at the foot, gradual), and the border ring is no darker than the
// one inside it (no mark). Untextured: every pixel is a deterministic function of its distance
// from the foot, so a ring mean moves only by the pixels' 8-bit rounding: 0.5 level each side.
TEST_P(BodyShadowGLTest, NeverLighterDarkestAtTheFootNoMarkAtTheBorder) {
  for (double gap : {0.3, 2.0}) {
    const Scene s = body_scene(256, true);
    const glm::dvec3 ball = ball_at_gap(gap);
    const std::optional<Frame> with = render(s, {ball});
    const std::optional<Frame> without = render(s, {});
    ASSERT_TRUE(with && without);
    const double ring_mm = 40.0 / 256;
    std::vector<double> sum, n;
    int lighter = 0;
    for (int y = 0; y < s.render.height; ++y)
      for (int x = 0; x < s.render.width; ++x) {
        if (ball_may_cover(s, x, y, ball)) continue;
        for (int ch = 0; ch < 3; ++ch)
          if (with->color.at(x, y, ch) > without->color.at(x, y, ch)) ++lighter;
        const double dark = luma(without->color, x, y) - luma(with->color, x, y);
        if (!(dark > 0.0)) continue;
        const glm::dvec3 p = hit_plane(pixel_ray(s, x, y));
        const auto k = static_cast<size_t>(std::hypot(p.x - kFoot.x, p.y - kFoot.y) / ring_mm);
        if (k >= sum.size()) sum.resize(k + 1, 0.0), n.resize(k + 1, 0.0);
        sum[k] += dark, n[k] += 1.0;
      }
    EXPECT_EQ(lighter, 0) << "gap " << gap;
    // The shadow's radius is the ball's (6 mm = 38 rings); pixels beside the drawn ball only.
    ASSERT_GE(sum.size(), 36u) << "gap " << gap;
    double inner = -1.0, worst_rise = 0.0;
    for (size_t k = 0; k < sum.size(); ++k) {
      if (n[k] == 0.0) continue;
      const double mean = sum[k] / n[k];
      if (inner >= 0.0) worst_rise = std::max(worst_rise, mean - inner);
      inner = inner < 0.0 ? mean : std::min(inner, mean);
    }
    std::printf("[body rings] gap %.1f mm: %zu rings, worst outward rise %.3f levels\n", gap, sum.size(), worst_rise);
    EXPECT_LE(worst_rise, 1.0) << "gap " << gap << ": a ring is darker than one inside it";
  }
}

// The influence distance of the receiving material bounds the body's shadow exactly: its lowest
// point 0.01 mm beyond it leaves the image byte-identical to the scene without the body (the
// ball itself drawn out of view: the camera looks at the foot from straight above), 0.01 mm
// inside it darkens the pixel at the foot (the disc's radius is sqrt(2 r 0.01) = 0.35 mm there,
// a pixel is 0.31 mm). For the default 50 mm and a material's own 10 mm.
TEST_P(BodyShadowGLTest, NothingBeyondTheInfluenceDistance) {
  for (double influence : {50.0, 10.0}) {
    Scene s = body_scene(128, false);
    s.camera.position = {0.0, 0.0, 100.0};
    s.camera.up = {0.0, 1.0, 0.0};
    s.camera.near_mm = 100.0 - 1.0;  // sees the plane, not the ball above it
    s.materials[0].influence_distance_mm = influence;
    const glm::dvec2 foot = test::pixel_to_world(s, 64, 64);
    const std::optional<Frame> none = render(s, {});
    const std::optional<Frame> beyond = render(s, {{foot.x, foot.y, kBallRadius + influence + 0.01}});
    const std::optional<Frame> inside = render(s, {{foot.x, foot.y, kBallRadius + influence - 0.01}});
    ASSERT_TRUE(none && beyond && inside);
    EXPECT_EQ(beyond->color.pixels, none->color.pixels) << "influence " << influence;
    EXPECT_LT(inside->color.at(64, 64, 0), none->color.at(64, 64, 0)) << "influence " << influence;
    // Only the tiny disc (and its one-pixel rim) darkens, not the ball's whole footprint.
    int darker = 0;
    for (size_t i = 0; i < none->color.pixels.size(); ++i) darker += inside->color.pixels[i] < none->color.pixels[i];
    EXPECT_LE(darker, 3 * 9) << "influence " << influence << ": pixels darker, channels counted";
  }
}

// A scene's bodies cast nothing until they have positions: byte-identical to the scene without
// bodies (the renderer draws and casts only what FrameInput::bodies_mm gave it).
TEST_P(BodyShadowGLTest, BodiesWithoutPositionsCastNothing) {
  Scene s = body_scene(128, false, 8.0 + 1.0);
  s.bodies.push_back(s.bodies[0]);
  Scene bare = s;
  bare.bodies.clear();
  const std::optional<Frame> a = render(s, {}), b = render(bare, {});
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->color.pixels, b->color.pixels);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(BodyShadowGLTest);

}  // namespace
}  // namespace ps
