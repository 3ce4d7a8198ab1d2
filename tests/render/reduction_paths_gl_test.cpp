// The reductions' two paths (passes/reductions.h): compute shaders with atomics into a storage
// buffer, and fragment shaders writing one texel per row, reduced on the host (what WebGL2 can
// run). Every output of every frame must be the same bits. The tolerance is zero, and why it
// can be: both paths run the same per-row functions (glsl/lib/reduce_rows.glsl) on the same
// texels; the host's maxima are float maxima, as the atomics' uint maxima of non-negative
// floats are; counts and columns travel as floats below 2^24 (exact); the row sums are added in
// double on the host in the same order by both. A difference anywhere — a row left out, a
// maximum taken over the wrong rows, a sum in another order — shows in the reference normal,
// the displacement or the pixels, and the next frames carry it on.
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/renderer.h"
#include "scene/camera.h"
#include "support/expect_reductions.h"
#include "support/gl_test.h"
#include "support/scenes.h"
#include "support/shipped.h"

namespace ps {
namespace {

class ReductionPathsGLTest : public test::GlTest {};

struct Case {
  std::string name;
  Scene scene;
  std::vector<glm::dvec3> probe_path;  // one position per frame
  bool footprint_rect = true;
};

using test::shipped;

std::vector<Case> cases() {
  std::vector<Case> c;
  {
    Scene s = shipped("default", 160, 128);  // weighted-average displacement, textured
    const glm::dvec3 p = s.probe.position;
    c.push_back({"default", s, {p, p + glm::dvec3(20, 0, 0), p + glm::dvec3(10, 0, -0.5)}});
    c.push_back({"default_whole_rows", s, {p, p + glm::dvec3(3, -2, -0.3)}, false});
    c.push_back({"default_at_edge", s, {p + glm::dvec3(-22, 0, 0), p + glm::dvec3(-24, 6, 0)}});
    c.push_back({"default_out_of_reach", s, {p + glm::dvec3(0, 0, 30)}});
  }
  {
    Scene s = shipped("torus_capsule", 160, 120);  // capsule, exact-max displacement, curved
    const glm::dvec3 p = s.probe.position;
    c.push_back({"torus_capsule", s, {p, p + glm::dvec3(25, 8, 0), p + glm::dvec3(5, 0, -0.3)}});
  }
  {
    Scene s = shipped("materials_demo", 160, 120);  // several surfaces and materials
    const glm::dvec3 p = s.probe.position;
    c.push_back({"materials_demo", s, {p, p + glm::dvec3(-30, 10, 0)}});
  }
  {
    Scene s = shipped("table5_1_monkey_head", 160, 120);  // a mesh seen in perspective
    const glm::dvec3 p = s.probe.position;
    c.push_back({"monkey_head", s, {p, p + glm::dvec3(12, 0, 3)}});
  }
  {
    Scene s = test::flat_plane_scene(7.5);  // orthographic, sunk 0.5 mm
    s.render.displacement = DisplacementMethod::kWeightedAverage;
    c.push_back({"flat_ortho", s, {s.probe.position, {14, -9, 7.0}, {-3, 2, 8.5}}});
  }
  return c;
}

// Bitwise: NaN equals NaN of the same bits, and -0 differs from +0.
int differing_values(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) return -1;
  int n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) n += std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(float)) != 0;
  return n;
}

TEST_P(ReductionPathsGLTest, FragmentRowsGiveTheComputePathsBitsInEveryOutput) {
  int shadowed = 0, penetrating = 0, displaced = 0;
  for (const Case& c : cases()) {
    RendererOptions compute, fragment;
    compute.expected_frames = fragment.expected_frames = 3;  // short: no tile bake
    compute.footprint_rect = fragment.footprint_rect = c.footprint_rect;
    fragment.reductions = ReductionMethod::kFragment;
    auto a = Renderer::create(c.scene, compute);
    auto b = Renderer::create(c.scene, fragment);
    ASSERT_TRUE(a.ok() && b.ok()) << c.name;
    // Priming already ran mean_normal on both: the first frames' planes must agree.
    EXPECT_EQ(a.value()->reference().n, b.value()->reference().n) << c.name << " primed plane";
    for (size_t f = 0; f < c.probe_path.size(); ++f) {
      const std::string where = c.name + " frame " + std::to_string(f);
      for (Renderer* r : {a.value().get(), b.value().get()})
        ASSERT_TRUE(r->render(probe_frame_input(c.probe_path[f], c.scene.probe.velocity)).ok()) << where;
      const Renderer &x = *a.value(), &y = *b.value();
      EXPECT_EQ(x.read_color().pixels, y.read_color().pixels) << where << " colour";
      for (const std::string& aov : aov_names()) {
        auto p = x.read_aov(aov), q = y.read_aov(aov);
        ASSERT_TRUE(p.ok() && q.ok()) << where << " " << aov;
        EXPECT_EQ(differing_values(p.value(), q.value()), 0) << where << " AOV " << aov;
      }
      test::expect_same_reductions(x.stats(), y.stats(), where);
      EXPECT_EQ(x.reference().n, y.reference().n) << where;
      shadowed += x.stats().shadow_pixels > 0;
      penetrating += x.stats().penetrating_pixels > 0;
      displaced += glm::length(x.stats().displacement) > 0.0;
    }
  }
  // The comparison saw shadows, penetration and a displacement, not empty frames.
  EXPECT_GE(shadowed, 12);
  EXPECT_GE(penetrating, 8);
  EXPECT_GE(displaced, 5);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(ReductionPathsGLTest);

}  // namespace
}  // namespace ps
