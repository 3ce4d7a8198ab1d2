// Adaptive resolution while the view moves (Renderer::set_surface_scale, docs/adaptive.md): a
// reduced frame is close to the whole one, feeds the haptic side the same values, and the frames
// after the view comes to rest are the whole renderer's bit for bit. Each frame is drawn by two
// renderers of the same view, one never given a scale (what every headless command draws).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "render/aov.h"
#include "render/renderer.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"
#include "support/shipped.h"

namespace ps {
namespace {

class AdaptiveGLTest : public test::GlTest {};

using test::shipped;

using test::same_bits;

double rms_levels(const Image& a, const Image& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) sum += std::pow(static_cast<double>(a.pixels[i]) - b.pixels[i], 2);
  return 255.0 * std::sqrt(sum / static_cast<double>(a.pixels.size()));
}

struct Pair {
  std::unique_ptr<Renderer> whole, adaptive;
  explicit Pair(const Scene& s) {
    RendererOptions o;
    o.expected_frames = 16;  // short: no tile bake
    auto a = Renderer::create(s, o);
    auto b = Renderer::create(s, o);
    EXPECT_TRUE(a.ok() && b.ok());
    if (a.ok() && b.ok()) whole = std::move(a.value()), adaptive = std::move(b.value());
  }
  // One frame of each; the adaptive one at `scale` (moving and still alike).
  void frame(const FrameInput& in, double scale) {
    adaptive->set_surface_scale({scale, scale});
    EXPECT_TRUE(whole->render(in).ok());
    EXPECT_TRUE(adaptive->render(in).ok());
  }
};

// The view of frame i: the default scene's camera orbiting its target, 3 degrees a frame.
FrameInput orbit(const Scene& s, int i) {
  FrameInput in = probe_frame_input(s.probe.position, s.probe.velocity);
  Camera c = s.camera;
  const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(3.0 * i), c.up);
  c.position = c.target + glm::dvec3(turn * glm::dvec4(c.position - c.target, 0.0));
  in.camera = c;
  return in;
}

// The rolling torus's view turning about the vertical through its target, 3 degrees a frame: its
// visible normals change with the view, so the reference plane moves while the view does.
FrameInput turn(const Scene& s, int i) {
  const glm::dmat3 r(glm::rotate(glm::dmat4(1.0), glm::radians(3.0 * i), glm::dvec3(0.0, 0.0, 1.0)));
  const glm::dvec3 t = s.camera.target - r * s.camera.target;
  FrameInput in = probe_frame_input(r * s.probe.position + t, s.probe.velocity);
  in.view = ViewPose{t, r};
  return in;
}

// The first moving frame (both renderers hold the same reference plane): the reduced frame's
// footprint is drawn at full resolution, so every AOV and every value the haptic side is fed
// (max penetration, displacement, the pixels counted) are the whole frame's bits; the colour
// outside the footprint is upsampled and differs by a stated RMS.
TEST_P(AdaptiveGLTest, AReducedFrameFeedsTheHapticSideTheWholeFramesValues) {
  const Scene s = shipped("default", 320, 180);
  Pair p(s);
  ASSERT_TRUE(p.whole && p.adaptive);
  p.frame(orbit(s, 0), 1.0);
  p.frame(orbit(s, 1), 0.5);
  const FrameStats &a = p.adaptive->stats(), &w = p.whole->stats();
  EXPECT_TRUE(a.view_moved);
  EXPECT_EQ(a.surface_scale, 0.5);
  EXPECT_LT(a.drawn_pixels, 320 * 180 / 2);
  EXPECT_GT(w.shadow_pixels, 0u);
  EXPECT_EQ(a.max_penetration_mm, w.max_penetration_mm);
  EXPECT_EQ(a.displacement, w.displacement);
  EXPECT_EQ(a.probe_position, w.probe_position);
  EXPECT_EQ(a.reference_normal, w.reference_normal);
  EXPECT_EQ(a.shadow_pixels, w.shadow_pixels);
  EXPECT_EQ(a.penetrating_pixels, w.penetrating_pixels);
  // Every AOV but the normal, which covers the whole image (the small one here: it is read by
  // headless commands only, which never reduce a frame; the reductions read the footprint's).
  for (const std::string& aov : aov_names()) {
    if (aov != "normal") {
      EXPECT_TRUE(same_bits(p.adaptive->read_aov(aov).value(), p.whole->read_aov(aov).value())) << aov;
    }
  }
  const double rms = rms_levels(p.adaptive->read_color(), p.whole->read_color());
  EXPECT_GT(rms, 0.0);  // it was drawn reduced
  std::printf("reduced frame: RMS %.3f levels\n", rms);
  // Half the resolution, bilinear: the plank's wood albedo and its silhouette against the
  // background lose their finest detail; the pseudo-shadow itself is drawn whole. Measured 3.84
  // levels (8-bit) on llvmpipe, EGL and OSMesa alike; the bound of 8 leaves room for another
  // driver's blit filter, while an upsample gone wrong (the small image shifted, or not scaled to
  // the whole window) is far above it.
  EXPECT_LT(rms, 8.0);
}

// Motion at 0.5, then rest: the first still frame is whole (scale 1) and every frame after it is
// the whole renderer's bit for bit. The first one itself may differ where the reference plane
// moved with the view: a reduced frame keeps the plane of the last whole frame instead of
// reducing the small image's normals, and the first whole frame at rest reduces it again.
TEST_P(AdaptiveGLTest, TheFramesAtRestAreTheWholeFramesBitForBit) {
  struct Case {
    const char* scene;
    FrameInput (*motion)(const Scene&, int);
  };
  for (const Case& c : {Case{"default", orbit}, Case{"fourd/flat_torus_rolling", turn}}) {
    const Scene s = shipped(c.scene, 200, 120);
    Pair p(s);
    ASSERT_TRUE(p.whole && p.adaptive) << c.scene;
    p.frame(c.motion(s, 0), 1.0);
    EXPECT_FALSE(p.adaptive->stats().new_targets) << c.scene;  // the whole frame has its targets from the start
    for (int i = 1; i <= 5; ++i) {
      p.frame(c.motion(s, i), 0.5);
      EXPECT_EQ(p.adaptive->stats().surface_scale, 0.5) << c.scene << " frame " << i;
      // The first frame at 0.5 makes its targets: its time is not 0.5's cost (AdaptiveScale).
      EXPECT_EQ(p.adaptive->stats().new_targets, i == 1) << c.scene << " frame " << i;
      EXPECT_EQ(p.adaptive->stats().measures_full_redraw(), i != 1) << c.scene << " frame " << i;
    }
    for (int rest = 0; rest < 3; ++rest) {
      p.frame(c.motion(s, 5), 1.0);
      const FrameStats& a = p.adaptive->stats();
      EXPECT_FALSE(a.view_moved) << c.scene;
      EXPECT_EQ(a.surface_scale, 1.0) << c.scene;
      if (rest == 0) {
        EXPECT_FALSE(a.incremental) << c.scene;  // nothing is kept from a reduced frame
        continue;
      }
      EXPECT_TRUE(same_bits(p.adaptive->read_color(), p.whole->read_color())) << c.scene << " rest frame " << rest;
      for (const std::string& aov : aov_names())
        EXPECT_TRUE(same_bits(p.adaptive->read_aov(aov).value(), p.whole->read_aov(aov).value()))
            << c.scene << " rest frame " << rest << " AOV " << aov;
      EXPECT_EQ(a.max_penetration_mm, p.whole->stats().max_penetration_mm) << c.scene;
      EXPECT_EQ(a.displacement, p.whole->stats().displacement) << c.scene;
      EXPECT_EQ(a.reference_normal, p.whole->stats().reference_normal) << c.scene;
    }
  }
}

// A scale given for the still view does not reduce a frame whose view did not move only by
// accident: the renderer takes `still` then, `moving` when the camera changed.
TEST_P(AdaptiveGLTest, MovingAndStillScalesAreTakenByTheView) {
  const Scene s = shipped("default", 160, 90);
  Pair p(s);
  ASSERT_TRUE(p.whole && p.adaptive);
  p.adaptive->set_surface_scale({0.5, 1.0});
  ASSERT_TRUE(p.adaptive->render(orbit(s, 0)).ok());
  EXPECT_EQ(p.adaptive->stats().surface_scale, 1.0);  // the first frame: nothing to have moved from
  ASSERT_TRUE(p.adaptive->render(orbit(s, 1)).ok());
  EXPECT_EQ(p.adaptive->stats().surface_scale, 0.5);
  ASSERT_TRUE(p.adaptive->render(orbit(s, 1)).ok());
  EXPECT_EQ(p.adaptive->stats().surface_scale, 1.0);
  EXPECT_FALSE(p.adaptive->stats().view_moved);
}

// With the probe drawn (an overlay depth-tested against the surfaces) a reduced frame upsamples
// the depth too: the probe is drawn, where the whole frame draws it, to within the upsampling.
TEST_P(AdaptiveGLTest, OverlaysAreDrawnOverAReducedFrame) {
  const Scene s = shipped("default", 320, 180);
  Pair p(s);
  ASSERT_TRUE(p.whole && p.adaptive);
  FrameInput first = orbit(s, 0);
  first.show = ViewFlags{true, false, false};
  p.frame(first, 1.0);
  p.frame(orbit(s, 1), 0.5);
  EXPECT_EQ(p.adaptive->stats().surface_scale, 0.5);
  const double rms = rms_levels(p.adaptive->read_color(), p.whole->read_color());
  std::printf("reduced frame with the probe drawn: RMS %.3f levels\n", rms);
  EXPECT_LT(rms, 8.0);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(AdaptiveGLTest);

}  // namespace
}  // namespace ps
