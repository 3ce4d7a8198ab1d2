// Incremental frames (render/frame_key.h): with the camera still, a moving probe redraws only
// the last and the new shadow rectangles, and the frame is the same bits as a full redraw; a
// change the frame key holds (camera orbit, the view's pose carrying the light, a 4D sheet) or
// an overlay makes the next frame redraw every pixel. Each frame is drawn by two renderers, one
// with RendererOptions::incremental off, and compared with tolerance zero (same inputs, same
// draws per pixel: see tests/haptics/incremental_walks_gl_test.cpp).
#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/aov.h"
#include "render/renderer.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"
#include "support/shipped.h"

namespace ps {
namespace {

class IncrementalGLTest : public test::GlTest {};

using test::shipped;

using test::same_bits;

// The same frames drawn incrementally and in full.
struct Pair {
  std::unique_ptr<Renderer> inc, full;

  explicit Pair(const Scene& s) {
    RendererOptions on, off;
    on.expected_frames = off.expected_frames = 4;  // short: no tile bake
    off.incremental = false;
    auto a = Renderer::create(s, on);
    auto b = Renderer::create(s, off);
    EXPECT_TRUE(a.ok() && b.ok());
    if (a.ok() && b.ok()) {
      inc = std::move(a.value());
      full = std::move(b.value());
    }
  }
  // Draws `in` with both, checks every output is the same bits, returns the incremental stats.
  FrameStats frame(const FrameInput& in, const std::string& where) {
    for (Renderer* r : {inc.get(), full.get()}) EXPECT_TRUE(r->render(in).ok()) << where;
    EXPECT_TRUE(same_bits(inc->read_color(), full->read_color())) << where << " colour";
    for (const std::string& aov : aov_names())
      EXPECT_TRUE(same_bits(inc->read_aov(aov).value(), full->read_aov(aov).value())) << where << " AOV " << aov;
    const FrameStats &s = inc->stats(), &t = full->stats();
    EXPECT_EQ(s.probe_position, t.probe_position) << where;
    EXPECT_EQ(s.reference_normal, t.reference_normal) << where;
    EXPECT_EQ(s.shadow_pixels, t.shadow_pixels) << where;
    EXPECT_FALSE(t.incremental) << where;
    return s;
  }
};

FrameInput probe_at(const glm::dvec3& p) {
  FrameInput in;
  in.probe = ProbeMotion{p, glm::dvec3(20.0, 0.0, 0.0)};
  return in;
}

TEST_P(IncrementalGLTest, StillCameraWithAMovingProbeDrawsFewerPixels) {
  const Scene s = shipped("default", 256, 256);
  Pair pair(s);
  ASSERT_TRUE(pair.inc && pair.full);
  const int whole = 256 * 256;
  int shadowed = 0;
  for (int f = 0; f < 6; ++f) {
    const FrameStats st = pair.frame(probe_at(s.probe.position + glm::dvec3(1.5 * f, 0.5 * f, 0.0)), "frame " + std::to_string(f));
    shadowed += st.shadow_pixels > 0;
    if (f == 0) {
      EXPECT_FALSE(st.incremental);  // nothing kept yet
      EXPECT_EQ(st.drawn_pixels, whole);
      continue;
    }
    EXPECT_TRUE(st.incremental) << f;
    // Two overlapping shadow rectangles: the probe's 16 mm window seen at 256^2 is about 95 px
    // wide; their bounding box stays under a quarter of the image (`render --size 256x256
    // --frames 2` drew 8,288 of 65,536 pixels on its second frame).
    EXPECT_LT(st.drawn_pixels, whole / 4) << f;
    EXPECT_GT(st.drawn_pixels, static_cast<std::int64_t>(st.shadow_pixels)) << f;
  }
  EXPECT_EQ(shadowed, 6);
}

// A probe lifted out of reach: no shadow rectangle in either frame, nothing is redrawn.
TEST_P(IncrementalGLTest, NoShadowInEitherFrameDrawsNothing) {
  const Scene s = shipped("default", 128, 128);
  Pair pair(s);
  ASSERT_TRUE(pair.inc && pair.full);
  const glm::dvec3 far = s.probe.position + glm::dvec3(0.0, 0.0, 200.0);
  pair.frame(probe_at(far), "frame 0");
  const FrameStats st = pair.frame(probe_at(far + glm::dvec3(5.0, 0.0, 0.0)), "frame 1");
  EXPECT_EQ(st.shadow_pixels, 0u);
  EXPECT_TRUE(st.incremental);
  EXPECT_EQ(st.drawn_pixels, 0);
}

struct Cause {
  std::string name, scene;
  std::function<void(Renderer&, FrameInput&)> change;  // applied before the third frame
};

std::vector<Cause> causes() {
  return {
      {"camera orbit", "default",
       [](Renderer& r, FrameInput& in) {
         Camera c = r.camera();
         c.position = glm::dvec3(c.position.y * 0.3, c.position.y, c.position.z);
         in.camera = c;
       }},
      {"view pose (camera and light)", "default",
       [](Renderer&, FrameInput& in) {
         const double a = 0.05;  // rad about z: turns the camera and the light (carried_direction)
         in.view = ViewPose{glm::dvec3(2.0, 0.0, 0.0), glm::dmat3(std::cos(a), std::sin(a), 0.0, -std::sin(a),
                                                                  std::cos(a), 0.0, 0.0, 0.0, 1.0)};
       }},
      {"overlay (the probe drawn)", "default", [](Renderer&, FrameInput& in) { in.show = ViewFlags{true, false, false}; }},
      {"4D sheet", "fourd/flat_torus", [](Renderer&, FrameInput& in) { in.sheet = ProbeSheet{0, 0.37}; }},
  };
}

// Frame 0 full, frame 1 incremental, frame 2 after the change: everything redrawn; for an
// overlay (drawn after the surfaces) it is frame 3 that must redraw everything.
TEST_P(IncrementalGLTest, EachInvalidationRedrawsEverything) {
  for (const Cause& c : causes()) {
    const Scene s = shipped(c.scene, 128, 128);
    Pair pair(s);
    ASSERT_TRUE(pair.inc && pair.full) << c.name;
    const glm::dvec3 p = s.probe.position;
    EXPECT_FALSE(pair.frame(probe_at(p), c.name + " frame 0").incremental);
    EXPECT_TRUE(pair.frame(probe_at(p + glm::dvec3(1, 0, 0)), c.name + " frame 1").incremental) << c.name;
    FrameInput in = probe_at(p + glm::dvec3(2, 0, 0));
    for (Renderer* r : {pair.inc.get(), pair.full.get()}) c.change(*r, in);
    const FrameStats two = pair.frame(in, c.name + " frame 2");
    const FrameStats three = pair.frame(probe_at(p + glm::dvec3(3, 0, 0)), c.name + " frame 3");
    const FrameStats& redrawn = c.name.starts_with("overlay") ? three : two;
    EXPECT_FALSE(redrawn.incremental) << c.name;
    EXPECT_EQ(redrawn.drawn_pixels, 128 * 128) << c.name;
  }
}

PS_INSTANTIATE_HEADLESS_BACKENDS(IncrementalGLTest);

}  // namespace
}  // namespace ps
