// The probe view pass (P key / --show-probe): the probe is drawn where the haptic proxy is,
// shaded like its CPU twin below, hidden by the surfaces where it is sunk into them, and it
// changes nothing but the probe's own pixels: every AOV, the reference plane and the
// displacement are those of the same frame without it.
#include <cmath>
#include <cstring>
#include <map>
#include <utility>

#include <gtest/gtest.h>

#include "passes/probe_view.h"
#include "support/scenes.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace ps {
namespace {

double distance_to_segment(const glm::dvec3& p, const CapsuleShape& c) {
  const glm::dvec3 ab = c.b - c.a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - c.a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (c.a + t * ab));
}

TEST(ProbeViewMeshTest, CapsuleVerticesAndNormalsAreOnTheSurface) {
  for (const CapsuleShape c : {CapsuleShape{{1, 2, 3}, {1, 2, 3}, 8.0},            // sphere
                               CapsuleShape{{0, 0, 0}, {3, -4, 12}, 2.5}}) {       // tilted
    const Mesh m = make_capsule_mesh(c, ProbeViewPass::kSegments);
    ASSERT_FALSE(m.indices.empty());
    for (size_t i = 0; i < m.positions.size(); ++i) {
      const glm::dvec3 p(m.positions[i]);
      // float positions of a ~15 mm object: 1e-5 relative rounding.
      EXPECT_NEAR(distance_to_segment(p, c), c.radius, 1e-5 * (c.radius + glm::length(c.b)));
      EXPECT_NEAR(glm::length(glm::dvec3(m.normals[i])), 1.0, 1e-6);
    }
    // Area against the closed form 4 pi r^2 + 2 pi r L: the facets lie inside the surface, so a
    // little less; 64 segments and 16 rings per hemisphere lose (pi/64)^2/3 ~ 0.1 %.
    double area = 0.0;
    for (size_t t = 0; t < m.indices.size(); t += 3) {
      const glm::dvec3 a(m.positions[m.indices[t]]), b(m.positions[m.indices[t + 1]]),
          d(m.positions[m.indices[t + 2]]);
      area += 0.5 * glm::length(glm::cross(b - a, d - a));
    }
    const double exact = 4.0 * M_PI * c.radius * c.radius + 2.0 * M_PI * c.radius * glm::length(c.b - c.a);
    EXPECT_LT(area, exact);
    EXPECT_GT(area, exact * (1.0 - 3e-3));
  }
}

class ProbeViewGLTest : public test::GlTest {};

struct Frame {
  Image color, intensity, distance, normal;
  FrameStats stats;
};

Frame render(const Scene& s, bool show_probe) {
  auto made = Renderer::create(s, {});
  EXPECT_TRUE(made.ok()) << (made.ok() ? "" : made.error().message);
  if (!made.ok()) return {};
  Renderer& r = *made.value();
  EXPECT_TRUE(r.render([&] { FrameInput in; in.show = ViewFlags{show_probe, false, false}; return in; }()).ok());
  return {r.read_color(), r.read_aov("intensity").value(), r.read_aov("distance").value(),
          r.read_aov("normal").value(), r.stats()};
}

// CPU twin of glsl/probe_view.frag for the visible top of a sphere seen straight down.
double expected_probe_value(const Scene& s, const glm::dvec2& xy, int channel) {
  const glm::dvec3 c = s.probe.position;
  const double r = s.probe.radius_mm;
  const double dz = std::sqrt(r * r - glm::dot(xy - glm::dvec2(c), xy - glm::dvec2(c)));
  const glm::dvec3 n = glm::normalize(glm::dvec3(xy.x - c.x, xy.y - c.y, dz));
  const double lambert = std::max(glm::dot(n, -glm::normalize(s.light.direction)), 0.0);
  const double lit = ProbeViewPass::kColor[channel] * s.light.color[channel] *
                     (s.light.ambient + (1.0 - s.light.ambient) * lambert);
  return std::pow(std::clamp(lit, 0.0, 1.0), 1.0 / 2.2);
}

// Checks one probe height; `visible_radius` is where the sphere's top meets the plane z = 0.
void check(const Scene& s, double visible_radius) {
  const Frame hidden = render(s, false), shown = render(s, true);
  ASSERT_EQ(shown.color.width, 128);
  // Nothing but colour changes: AOVs bit for bit, stats exactly.
  EXPECT_EQ(shown.intensity.pixels, hidden.intensity.pixels);
  // Compared as bytes: the distance AOV is NaN where no probe is above a pixel, and NaN != NaN.
  ASSERT_EQ(shown.distance.pixels.size(), hidden.distance.pixels.size());
  EXPECT_EQ(0, std::memcmp(shown.distance.pixels.data(), hidden.distance.pixels.data(),
                           shown.distance.pixels.size() * sizeof(float)));
  EXPECT_EQ(shown.normal.pixels, hidden.normal.pixels);
  EXPECT_EQ(shown.stats.reference_normal, hidden.stats.reference_normal);
  EXPECT_EQ(shown.stats.displacement, hidden.stats.displacement);
  EXPECT_EQ(shown.stats.probe_position, hidden.stats.probe_position);
  // The displayed probe is the proxy after this frame's push-out.
  Scene after = s;
  after.probe.position = shown.stats.probe_position;
  const glm::dvec2 centre(after.probe.position);
  int inside = 0, outside = 0;
  double worst = 0.0, worst_rho = 0.0;
  for (int py = 0; py < 128; ++py)
    for (int px = 0; px < 128; ++px) {
      const double rho = glm::length(test::pixel_to_world(s, px, py) - centre);
      // Half a pixel diagonal (0.22 mm) plus the tessellation's 0.12 % of r from each edge.
      if (rho < visible_radius - 0.25) {
        for (int ch = 0; ch < 3; ++ch) {
          const double want = expected_probe_value(after, test::pixel_to_world(s, px, py), ch);
          // Near the silhouette the steep facets sit further below the sphere along the view
          // ray (sag x sqrt(1 + slope^2), slope 3.9 at 0.97 r) and the dark side's gamma curve
          // is steep: weigh those errors by half, i.e. allow twice the tolerance there.
          const double err = std::abs(shown.color.at(px, py, ch) - want) *
                             (rho < 0.9 * visible_radius ? 1.0 : 0.5);
          if (err > worst) worst_rho = rho;
          worst = std::max(worst, err);
        }
        ++inside;
      } else if (rho > visible_radius + 0.25) {
        for (int ch = 0; ch < 3; ++ch)
          ASSERT_EQ(shown.color.at(px, py, ch), hidden.color.at(px, py, ch)) << px << "," << py;
        ++outside;
      }
    }
  // Interpolated vertex normals of a sphere mesh point exactly away from the centre at the
  // facet point; the facet lies at most r (1 - cos(pi/64)) = 0.01 mm below the true surface,
  // a normal error < 0.1 deg. What remains is float shading and 8-bit rounding: 1.5 / 255.
  EXPECT_LT(worst, 1.5 / 255.0) << "at " << worst_rho << " mm from the centre";
  EXPECT_GT(inside, static_cast<int>(0.8 * M_PI * std::pow(visible_radius / 0.3125, 2)));
  EXPECT_GT(outside, 8000);
}

TEST_P(ProbeViewGLTest, ProbeAboveThePlaneIsDrawnAndChangesNothingElse) {
  check(test::flat_plane_scene(10.0), 8.0);  // the whole disc of radius r is seen from above
}

TEST_P(ProbeViewGLTest, SunkProbeIsHiddenByTheSurface) {
  Scene s = test::flat_plane_scene(-4.0);
  s.materials[0].resistance = 0.0;  // no push-out: the probe stays 12 mm deep in the plane
  check(s, std::sqrt(8.0 * 8.0 - 4.0 * 4.0));  // only the cap above z = 0 shows: 6.93 mm
}

TEST_P(ProbeViewGLTest, DrawnWhereTheProxyIsAfterThePushOut) {
  Scene s = test::flat_plane_scene(6.0);  // 2 mm into the plane, resistance 1: pushed out
  s.render.displacement = DisplacementMethod::kExactMax;
  const Frame shown = render(s, true);
  EXPECT_GT(shown.stats.probe_position.z, 7.9);  // pushed up to touch the plane (z = 8)
  check(s, 8.0);  // and the full disc is drawn at the pushed-out position
}

PS_INSTANTIATE_HEADLESS_BACKENDS(ProbeViewGLTest);

}  // namespace
}  // namespace ps
