// The Virtual Universe's worlds driven as a person drives them with a mouse (issue 27 §4):
// a scripted pointer (devices/sample_log.h's PointerLogDevice: window pixels and a height,
// mapped through the scene's camera exactly like `run`'s mouse) replayed through `replay`'s
// session code on both headless backends. Field's view is a rate control that stops when the
// pointer rests inside its box and moves for every edge; Weight's ball stops circling once the
// hand stops and stays near the probe.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "app/session.h"
#include "devices/sample_log.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"
#include "world/haptic_scene.h"

namespace ps {
namespace {

class UniverseMouseGLTest : public test::GlTest {};

constexpr int kSize = 64;  // the image (and the pointer's window): small, the physics is the point

struct Frame {
  double t = 0.0;
  HapticState state;
};

// A pointer script: (time s, x, y as fractions of the window, height mm), held between points.
struct Point {
  double t, fx, fy, height_mm;
};

std::vector<Frame> drive(const std::string& file, const std::vector<Point>& script,
                         const std::vector<std::string>& sets = {}) {
  std::vector<Frame> frames;
  std::vector<std::string> all = {"render.size=[" + std::to_string(kSize) + "," + std::to_string(kSize) + "]",
                                  "render.depth_map_size=32"};
  all.insert(all.end(), sets.begin(), sets.end());
  auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/universe/" + file, all);
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return frames;
  auto haptic = world::HapticScene::build(scene.value());
  EXPECT_TRUE(haptic) << haptic.error().message;
  RendererOptions ro;
  ro.button_pictures = false;
  ro.expected_frames = 50;
  auto renderer = Renderer::create(scene.value(), ro);
  EXPECT_TRUE(renderer) << renderer.error().message;
  if (!haptic || !renderer) return frames;
  std::vector<DeviceSample> samples;
  for (const Point& p : script) samples.push_back({p.t, {p.fx * kSize, p.fy * kSize, p.height_mm}, 0, true});
  PointerLogDevice device(samples, "pointer:test");
  device.set_view(pointer_view(*renderer.value(), pointer_plane(*renderer.value())));
  ReplayOptions opt;
  opt.fps = 50.0;
  opt.haptic_scene = &haptic.value();
  auto r = replay_session(*renderer.value(), device, opt, [&](int, double t, const HapticState& s, const Renderer&) {
    frames.push_back({t, s});
    return ok_status();
  });
  EXPECT_TRUE(r) << r.error().message;
  return frames;
}

glm::dvec3 view_at(const std::vector<Frame>& f, double t) {
  for (const Frame& x : f)
    if (x.t >= t - 1e-9) return x.state.view_offset_mm;
  return f.empty() ? glm::dvec3(0.0) : f.back().state.view_offset_mm;
}

// Field: the pointer pushed to an edge of the window for 1.5 s moves the view that way; back
// at the window's centre (inside the box) the view stops within 0.3 s and does not move again:
// no drift, no overshoot. Every edge, the right one included. The drift bound, 0.01 mm over
// 2 s, is numerical noise: a rate control at rest moves by exactly zero.
TEST_P(UniverseMouseGLTest, FieldsViewMovesForEveryEdgeAndRestsWithThePointer) {
  struct Edge {
    const char* name;
    double fx, fy;
  };
  for (const Edge e : {Edge{"top", 0.5, 0.01}, Edge{"bottom", 0.5, 0.99}, Edge{"left", 0.01, 0.5},
                       Edge{"right", 0.99, 0.5}}) {
    const std::vector<Frame> f = drive("field.toml", {{0.0, 0.5, 0.5, 1.0}, {0.5, 0.5, 0.5, 1.0},
                                                      {0.52, e.fx, e.fy, 1.0}, {2.0, e.fx, e.fy, 1.0},
                                                      {2.02, 0.5, 0.5, 1.0}, {4.5, 0.5, 0.5, 1.0}});
    ASSERT_FALSE(f.empty());
    const glm::dvec3 pushed = view_at(f, 2.0), settled = view_at(f, 2.5), end = view_at(f, 4.5);
    std::printf("field %-6s: view after the push %+.1f %+.1f %+.1f mm, drift at rest %.4f mm (2.5 .. 4.5 s), "
                "overshoot %.2f mm\n", e.name, pushed.x, pushed.y, pushed.z, glm::length(end - settled),
                glm::length(settled - pushed));
    EXPECT_GT(glm::length(pushed), 50.0) << e.name << ": the view moves while the pointer is at the edge";
    EXPECT_LT(glm::length(end - settled), 0.01) << e.name << ": the view rests with the pointer";
    // Screen directions on the plane: right = +x, up the screen = +y (the camera looks along +y).
    if (e.fx > 0.9) EXPECT_GT(pushed.x, 50.0);
    if (e.fx < 0.1) EXPECT_LT(pushed.x, -50.0);
    if (e.fy < 0.1) EXPECT_GT(pushed.y, 50.0);
    if (e.fy > 0.9) EXPECT_LT(pushed.y, -50.0);
  }
}

// Weight: the hand circles (a pointer circle of a quarter window at 1 Hz for 2 s), then stops at
// the window's centre. Within 2 s the ball hangs still under the probe: its horizontal distance
// from the probe over the next second stays under 3 mm (the swing, decaying at e^-1.5 t from
// ~40 mm, is ~2 mm there; the band's stretch, 70 mm at most, bounds it all along).
TEST_P(UniverseMouseGLTest, WeightsBallStopsCirclingWhenTheHandStops) {
  std::vector<Point> script;
  for (int i = 0; i <= 100; ++i) {
    const double t = 0.02 * i, a = 2.0 * M_PI * t;
    script.push_back({t, 0.5 + 0.25 * std::cos(a), 0.5 + 0.25 * std::sin(a), 1.0});
  }
  script.push_back({2.02, 0.5, 0.5, 1.0});
  script.push_back({5.0, 0.5, 0.5, 1.0});
  const std::vector<Frame> f = drive("weight.toml", script);
  ASSERT_FALSE(f.empty());
  double late = 0.0, stretch = 0.0;
  for (const Frame& x : f) {
    const glm::dvec3 d = x.state.body_mm[0] - x.state.proxy_mm;
    stretch = std::max(stretch, glm::length(d));
    if (x.t >= 4.0) late = std::max(late, std::hypot(d.x, d.y));
  }
  std::printf("weight: ball's horizontal distance from the probe 2-3 s after the hand stops: max %.2f mm; "
              "largest band length %.1f mm\n", late, stretch);
  EXPECT_LT(late, 3.0);
  EXPECT_LE(stretch, 70.0 + 1e-6);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(UniverseMouseGLTest);

}  // namespace
}  // namespace ps
