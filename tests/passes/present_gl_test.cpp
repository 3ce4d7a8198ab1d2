// present_to_framebuffer() copies the frame exactly whatever state the caller left, and leaves
// every GL state it touches as it found it.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "gl/gl.h"
#include "gl/objects.h"
#include "render/present.h"
#include "render/renderer.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"

namespace ps {
namespace {

constexpr int kW = 64, kH = 48;

class PresentGLTest : public test::GlTest {};

GLint get_int(GLenum name) {
  GLint v = -1;
  glGetIntegerv(name, &v);
  return v;
}

TEST_P(PresentGLTest, CopiesTheFrameAndRestoresTheCallersState) {
  auto scene = parse_scene(default_scene_text(), "<default>", default_scene_base_dir(),
                           {"render.size=[64,48]", "materials.0.gabor_strategy=naive"});
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  auto r = Renderer::create(scene.value(), {});
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_TRUE(r.value()->render_frame().ok());
  const Image expected = r.value()->read_color();

  gl::Texture target_tex = gl::make_texture_2d(kW, kH, GL_RGBA8);
  gl::Framebuffer target = gl::make_framebuffer();
  glNamedFramebufferTexture(target.id(), GL_COLOR_ATTACHMENT0, target_tex.id(), 0);
  const float black[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(target.id(), GL_COLOR, 0, black);

  // A caller's state that would clip the blit (scissor) or redirect a read-back (pack buffer,
  // row length), and bindings a HUD might rely on.
  gl::Framebuffer read_fbo = gl::make_framebuffer(), draw_fbo = gl::make_framebuffer();
  gl::Buffer pack = gl::make_buffer(1024, nullptr, GL_DYNAMIC_STORAGE_BIT);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, read_fbo.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw_fbo.id());
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 1, 1);
  glEnable(GL_FRAMEBUFFER_SRGB);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, pack.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 8);
  glPixelStorei(GL_PACK_ROW_LENGTH, 3);
  glPixelStorei(GL_PACK_SKIP_ROWS, 2);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 1);

  present_to_framebuffer(*r.value(), target, kW, kH);

  EXPECT_EQ(get_int(GL_READ_FRAMEBUFFER_BINDING), static_cast<GLint>(read_fbo.id()));
  EXPECT_EQ(get_int(GL_DRAW_FRAMEBUFFER_BINDING), static_cast<GLint>(draw_fbo.id()));
  EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
  EXPECT_TRUE(glIsEnabled(GL_FRAMEBUFFER_SRGB));
  EXPECT_EQ(get_int(GL_PIXEL_PACK_BUFFER_BINDING), static_cast<GLint>(pack.id()));
  EXPECT_EQ(get_int(GL_PACK_ALIGNMENT), 8);
  EXPECT_EQ(get_int(GL_PACK_ROW_LENGTH), 3);
  EXPECT_EQ(get_int(GL_PACK_SKIP_ROWS), 2);
  EXPECT_EQ(get_int(GL_PACK_SKIP_PIXELS), 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  // Every pixel arrived (a scissored blit would have copied one), unchanged (same size: nearest).
  glDisable(GL_SCISSOR_TEST);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  std::vector<std::uint8_t> px(static_cast<size_t>(kW) * kH * 4);
  glGetTextureImage(target_tex.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(px.size()), px.data());
  size_t differ = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c) {
        const float got = px[(static_cast<size_t>(kH - 1 - y) * kW + x) * 4 + c] / 255.0f;
        differ += got != expected.at(x, y, c);
      }
  EXPECT_EQ(differ, 0u) << "presented frame differs from read_color() in " << differ << " values";
}

PS_INSTANTIATE_HEADLESS_BACKENDS(PresentGLTest);

}  // namespace
}  // namespace ps
