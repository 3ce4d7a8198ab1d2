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

#include "app/session/session.h"
#include "devices/pointer_map.h"
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
  Camera camera;  // the camera the frame drew with
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
  auto done = replay_session(*renderer.value(), device, opt, [&](int, double t, const HapticState& s, const Renderer& r) {
    frames.push_back({t, s, r.scene().camera});
    return ok_status();
  });
  EXPECT_TRUE(done) << done.error().message;
  return frames;
}

glm::dvec3 view_at(const std::vector<Frame>& f, double t) {
  for (const Frame& x : f)
    if (x.t >= t - 1e-9) return x.state.view_offset_mm;
  return f.empty() ? glm::dvec3(0.0) : f.back().state.view_offset_mm;
}

// Field: the pointer pushed to an edge of the window for 1.5 s moves the view that way; back
// at the window's centre (inside the box) the view stops at once and does not move again: no
// drift, no overshoot. Every edge, the right one included. The bounds, 0.01 mm, are numerical
// noise: a rate control at rest moves by exactly zero.
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
    // The pointer leaves the edge at 2.0 s and is back at the centre at 2.02 s.
    const glm::dvec3 pushed = view_at(f, 2.0), back = view_at(f, 2.04), settled = view_at(f, 2.5), end = view_at(f, 4.5);
    std::printf("field %-6s: view after the push %+.1f %+.1f %+.1f mm, drift at rest %.4f mm (2.5 .. 4.5 s), "
                "overshoot %.2f mm\n", e.name, pushed.x, pushed.y, pushed.z, glm::length(end - settled),
                glm::length(settled - back));
    EXPECT_LT(glm::length(settled - back), 0.01) << e.name << ": no overshoot once the pointer is back inside";
    EXPECT_GT(glm::length(pushed), 50.0) << e.name << ": the view moves while the pointer is at the edge";
    EXPECT_LT(glm::length(end - settled), 0.01) << e.name << ": the view rests with the pointer";
    // Screen directions on the plane: right = +x, up the screen = +y (the camera looks along +y).
    if (e.fx > 0.9) { EXPECT_GT(pushed.x, 50.0); }
    if (e.fx < 0.1) { EXPECT_LT(pushed.x, -50.0); }
    if (e.fy < 0.1) { EXPECT_GT(pushed.y, 50.0); }
    if (e.fy > 0.9) { EXPECT_LT(pushed.y, -50.0); }
  }
}

// Weight: the hand circles (a pointer circle of a quarter window at 1 Hz for 2 s), then stops at
// the window's centre. Within 2 s the ball comes to rest: over the next second it moves less
// than 2 mm (its swing decays as e^-2 t: ~40 mm at the stop, under 1 mm 2 s later), it is in
// the window from half a second after the stop on, and the band never stretches past 60 mm.
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
  double late = 0.0, stretch = 0.0, off_centre = 0.0;
  glm::dvec3 at_4s(0.0);
  PointerView view;
  view.camera = f.front().camera;
  view.window_size = {kSize, kSize};
  bool in_view = true;
  for (const Frame& x : f) {
    const glm::dvec3 ball = x.state.body_mm[0];
    stretch = std::max(stretch, glm::length(ball - x.state.proxy_mm));
    const glm::dvec2 px = project_to_window(view, ball);
    if (x.t < 2.5) continue;  // while the hand flings it, it may swing out of the window
    in_view = in_view && px.x >= 0 && px.x < kSize && px.y >= 0 && px.y < kSize;
    off_centre = std::max(off_centre, glm::length(px / double(kSize) - 0.5));
    if (x.t >= 4.0 - 1e-9 && at_4s == glm::dvec3(0.0)) at_4s = ball;
    if (x.t >= 4.0) late = std::max(late, glm::length(ball - at_4s));
  }
  std::printf("weight: the ball moves %.3f mm between 2 and 3 s after the hand stops; largest band length %.1f mm; "
              "from 0.5 s after the stop at most %.2f of the window's width from its centre\n", late, stretch, off_centre);
  EXPECT_LT(late, 2.0);
  // The string holds the ball within 60 mm of the proxy it was stepped with, the one of the tick
  // before: the proxy moves up to 2 mm in a tick here (the pointer's 20 ms jump to the centre).
  EXPECT_LE(stretch, 60.0 + 2.0);
  EXPECT_TRUE(in_view);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(UniverseMouseGLTest);

}  // namespace
}  // namespace ps
