#include "render/present.h"

#include <cstdint>
#include <vector>

#include "gl/gl.h"
#include "gl/objects.h"

namespace ps {

void present_to_default_framebuffer(const Renderer& renderer, int dst_w, int dst_h) {
  GLint prev_read = 0, prev_draw = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &prev_read);
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &prev_draw);
  // A read FBO per call: creating one is ~microseconds, cheaper than caching GL state here.
  gl::Framebuffer fbo = gl::make_framebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, renderer.color_texture().id(), 0);
  glNamedFramebufferReadBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
  const int w = renderer.scene().render.width, h = renderer.scene().render.height;
  const bool same = w == dst_w && h == dst_h;
  glBlitNamedFramebuffer(fbo.id(), 0, 0, 0, w, h, 0, 0, dst_w, dst_h, GL_COLOR_BUFFER_BIT,
                         same ? GL_NEAREST : GL_LINEAR);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(prev_read));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(prev_draw));
}

Image read_back_buffer(int width, int height) {
  GLint prev_read = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &prev_read);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<std::uint8_t> px(static_cast<size_t>(width) * height * 3);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, px.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(prev_read));
  Image img;
  img.width = width;
  img.height = height;
  img.channels = 3;
  img.pixels.resize(px.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        img.at(x, y, c) = px[(static_cast<size_t>(height - 1 - y) * width + x) * 3 + c] / 255.0f;
  return img;
}

}  // namespace ps
