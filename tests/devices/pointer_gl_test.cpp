// The probe is where the pointer is, as rendered: a scripted pointer (the same PointerLogDevice
// and mapping `run`'s mouse uses) stops at points across the window; at each stop the centroid
// of the rendered pseudo-shadow (the intensity AOV) must lie within a few pixels of the pointer,
// on a perspective and an orthographic camera at two zooms each.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/session/session.h"
#include "devices/sample_log.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"

namespace ps {
namespace {

class PointerGLTest : public test::GlTest {};

constexpr int kSize = 192;           // window = image, px
constexpr double kFps = 10.0;
constexpr double kLeg = 0.5;         // s per stop: 0.1 s moving, then held
// Stops, as fractions of the window: across it, off its centre in both directions.
const std::vector<glm::dvec2> kStops = {{0.30, 0.35}, {0.45, 0.62}, {0.62, 0.48}, {0.70, 0.30}, {0.38, 0.70}};

// Moves to stop k during [k leg, k leg + 0.1 s], then holds still; 1 mm above the plank (the
// start height of the mouse), no buttons.
std::string pointer_script() {
  std::string s = "# time_s x_px y_px height_mm buttons\n";
  char line[96];
  for (size_t k = 0; k < kStops.size(); ++k) {
    const glm::dvec2 p = kStops[k] * static_cast<double>(kSize);
    for (double t : {k * kLeg + (k == 0 ? 0.0 : 0.1), (k + 1) * kLeg - 1e-3}) {
      std::snprintf(line, sizeof line, "%.6f %.3f %.3f 1 0\n", t, p.x, p.y);
      s += line;
    }
  }
  return s;
}

// Centre of the shadow's darkening (intensity) on the plank, in window pixels. The shadow is a
// function on the surface, so its centre is its centroid there: each pixel's weight is its
// intensity times the area it covers on the plane (a perspective view draws the near half of a
// disc larger, so an unweighted centroid of the image lies ~3-7 px towards the viewer at these
// zooms). The centroid on the plane is then projected back to the window.
// `screen` returns the unweighted image centroid for the record.
glm::dvec2 shadow_centre(const Image& intensity, const PointerView& view, double& total, glm::dvec2& screen) {
  auto on_plane = [&](double x, double y) { return *intersect_plane(pointer_ray(view, {x, y}), view.plane); };
  glm::dvec3 sum(0.0);
  glm::dvec2 screen_sum(0.0);
  double weight = 0.0;
  total = 0.0;
  for (int y = 0; y < intensity.height; ++y)
    for (int x = 0; x < intensity.width; ++x) {
      const double v = intensity.at(x, y, 0);
      if (v <= 0.0) continue;
      const glm::dvec3 c00 = on_plane(x, y), c10 = on_plane(x + 1, y), c01 = on_plane(x, y + 1),
                       c11 = on_plane(x + 1, y + 1);
      const double area = 0.5 * glm::length(glm::cross(c11 - c00, c10 - c01));  // the pixel's quad
      sum += v * area * on_plane(x + 0.5, y + 0.5);
      weight += v * area;
      screen_sum += v * glm::dvec2(x + 0.5, y + 0.5);
      total += v;
    }
  if (!(weight > 0.0)) return glm::dvec2(-1.0);
  screen = screen_sum / total;
  return project_to_window(view, sum / weight);
}

// Half a pixel. The mapping itself is exact to 1e-6 px (pointer_map_test); what remains is the
// AOV's sampling of the shadow at pixel centres and its cut-off where the intensity reaches 0:
// measured on llvmpipe at most 0.06 px over all stops below. A probe off by one pixel of
// mapping, or the old fixed mm-per-pixel mapping (shadow ~3x as far as the pointer), fails.
constexpr double kTolerancePx = 0.5;

struct CameraCase {
  const char* name;
  std::vector<std::string> sets;
};

const std::vector<CameraCase>& camera_cases() {
  static const std::vector<CameraCase> cases = {
      {"perspective, default zoom", {}},
      {"perspective, zoomed in 1.5x", {"camera.position=[0,-28,28]"}},
      {"orthographic, 60 mm", {"camera.projection=\"orthographic\"", "camera.position=[0,0,200]", "camera.up=[0,1,0]",
                               "camera.ortho_height_mm=60"}},
      {"orthographic, 30 mm", {"camera.projection=\"orthographic\"", "camera.position=[0,0,200]", "camera.up=[0,1,0]",
                               "camera.ortho_height_mm=30"}},
  };
  return cases;
}

TEST_P(PointerGLTest, RenderedShadowCentreFollowsThePointer) {
  auto samples = parse_pointer_log(pointer_script(), "stops.ptr");
  ASSERT_TRUE(samples.ok()) << samples.error().message;
  for (const CameraCase& c : camera_cases()) {
    std::vector<std::string> sets = {"render.size=[192,192]", "render.depth_map_size=128"};
    sets.insert(sets.end(), c.sets.begin(), c.sets.end());
    auto scene = parse_scene(default_scene_text(), "<default>", default_scene_base_dir(), sets);
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    auto renderer = Renderer::create(scene.value(), {});
    ASSERT_TRUE(renderer.ok()) << renderer.error().message;
    PointerLogDevice device(samples.value(), "pointer:stops.ptr");
    const PointerView view = pointer_view(*renderer.value(), pointer_plane(*renderer.value()));
    device.set_view(view);
    ReplayOptions opt;
    opt.fps = kFps;
    int measured = 0;
    auto sink = [&](int i, double t, const HapticState&, const Renderer& r) -> Status {
      const int per_leg = static_cast<int>(kLeg * kFps);
      if (i % per_leg != per_leg - 1) return ok_status();  // the last frame of each stop
      const glm::dvec2 pointer = kStops[static_cast<size_t>(i / per_leg)] * static_cast<double>(kSize);
      auto aov = r.read_aov(Aov::kIntensity);
      if (!aov) return aov.error();
      double total = 0.0;
      glm::dvec2 screen(0.0);
      const glm::dvec2 centre = shadow_centre(aov.value(), view, total, screen);
      EXPECT_GT(total, 50.0) << c.name << " t=" << t << ": no visible shadow";
      const double dist = glm::length(centre - pointer);
      std::printf("[ pointer ] %-28s t=%.2f s pointer (%.1f, %.1f) shadow centre (%.2f, %.2f): %.2f px "
                  "(image centroid %.2f px)\n", c.name, t, pointer.x, pointer.y, centre.x, centre.y, dist,
                  glm::length(screen - pointer));
      EXPECT_LE(dist, kTolerancePx) << c.name << " t=" << t;
      ++measured;
      return ok_status();
    };
    auto result = replay_session(*renderer.value(), device, opt, sink);
    ASSERT_TRUE(result.ok()) << result.error().message;
    EXPECT_EQ(measured, static_cast<int>(kStops.size())) << c.name;
  }
}

// One backend: the mapping is CPU code and the backends' identical frames are checked elsewhere
// (backends_identical); two would double the cost of the slowest test here.
INSTANTIATE_TEST_SUITE_P(Headless, PointerGLTest, ::testing::Values(::ps::gl::Backend::kEgl),
                         ::ps::test::backend_param_name);

}  // namespace
}  // namespace ps
