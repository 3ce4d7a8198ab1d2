// A real GLFW window (needs a display; under CTest it also runs through `xvfb-run -a`) renders
// a frame that matches the headless render of the same state exactly.
#include <gtest/gtest.h>

#include <cstdlib>

#include "gl/context.h"
#include "render/present.h"
#include "render/renderer.h"
#include "scene/scene_io.h"

namespace ps {
namespace {

Scene test_scene() {
  auto scene = parse_scene(default_scene_text(), "<default>", default_scene_base_dir(),
                           {"render.size=[160,120]", "probe.velocity=[120,0,0]"});
  EXPECT_TRUE(scene.ok());
  return scene.value();
}

Image render_with(gl::Backend backend, bool window_readback) {
  gl::ContextDesc desc{backend, 160, 120, "pseudoshadow window test", true, {}};
  auto ctx = gl::create_context(desc);
  if (!ctx) { ADD_FAILURE() << ctx.error().message; return {}; }
  auto r = Renderer::create(test_scene(), {});
  if (!r) { ADD_FAILURE() << r.error().message; return {}; }
  EXPECT_TRUE(r.value()->render_frame().ok());
  if (!window_readback) return r.value()->read_color();
  present_to_default_framebuffer(*r.value(), 160, 120);
  return read_back_buffer(160, 120);  // GL_BACK before the swap (docs/gl-stack.md)
}

TEST(WindowGLTest, WindowFrameMatchesHeadlessRender) {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0')
    GTEST_SKIP() << "no DISPLAY: a GLFW window needs an X server (run under xvfb-run -a)";
  const Image window = render_with(gl::Backend::kGlfw, true);
  const Image headless = render_with(gl::Backend::kEgl, false);
  ASSERT_EQ(window.width, headless.width);
  ASSERT_EQ(window.height, headless.height);
  ASSERT_EQ(window.pixels.size(), headless.pixels.size());
  size_t differ = 0;
  for (size_t i = 0; i < window.pixels.size(); ++i) differ += window.pixels[i] != headless.pixels[i];
  EXPECT_EQ(differ, 0u) << "window and headless frames differ in " << differ << " channel values";
}

}  // namespace
}  // namespace ps
