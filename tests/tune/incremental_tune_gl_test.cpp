// A material edit in a tuning session (the window's parameter panel) builds a new Renderer, whose
// first frame keeps nothing of the last one: every pixel is redrawn (render/frame_key.h), and
// incremental frames resume after it.
#include <gtest/gtest.h>

#include "support/gl_test.h"
#include "tune/tune_session.h"

namespace ps {
namespace {

class IncrementalTuneGLTest : public test::GlTest {};

TEST_P(IncrementalTuneGLTest, MaterialEditRedrawsEverything) {
  TuneSource src;
  src.scene_path = PS_SOURCE_DIR "/scenes/table4_1_a.toml";
  src.overrides = {"render.size=[96,96]"};
  auto opened = TuneSession::open(src);
  ASSERT_TRUE(opened) << opened.error().message;
  TuneSession& s = *opened.value();
  auto step = [&s](double dx) {
    Renderer& r = s.renderer();
    EXPECT_TRUE(r.render(probe_frame_input(r.probe().position + glm::dvec3(dx, 0.0, 0.0), r.probe().velocity)));
    return r.stats();
  };
  EXPECT_FALSE(step(0.0).incremental);
  EXPECT_TRUE(step(1.0).incremental);
  ASSERT_TRUE(s.set("materials.table4_1_a.albedo", "[0.3, 0.5, 0.7]"));
  const FrameStats edited = step(1.0);
  EXPECT_FALSE(edited.incremental);
  EXPECT_EQ(edited.drawn_pixels, 96 * 96);
  const FrameStats next = step(1.0);
  EXPECT_TRUE(next.incremental);
  EXPECT_LT(next.drawn_pixels, 96 * 96);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(IncrementalTuneGLTest);

}  // namespace
}  // namespace ps
