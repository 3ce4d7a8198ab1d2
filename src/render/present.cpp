#include "render/present.h"

#include <array>
#include <cstdint>
#include <vector>

#include "gl/gl.h"

namespace ps {

namespace {

// Every GL state the functions below change, saved at construction and restored at
// destruction (as Dear ImGui's backends do): the caller's own drawing - a HUD, the next frame -
// finds the state it left, and a caller's state (a scissor box left enabled, sRGB writes on,
// a pixel-pack buffer bound) cannot change what is shown or read.
class SavedPresentState {
 public:
  SavedPresentState() {
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_fbo_);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_fbo_);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack_buffer_);
    for (size_t i = 0; i < kPackNames.size(); ++i) glGetIntegerv(kPackNames[i], &pack_[i]);
    scissor_ = glIsEnabled(GL_SCISSOR_TEST);
    srgb_ = glIsEnabled(GL_FRAMEBUFFER_SRGB);
  }
  ~SavedPresentState() {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_fbo_));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_fbo_));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(pack_buffer_));
    for (size_t i = 0; i < kPackNames.size(); ++i) glPixelStorei(kPackNames[i], pack_[i]);
    set_enabled(GL_SCISSOR_TEST, scissor_);
    set_enabled(GL_FRAMEBUFFER_SRGB, srgb_);
  }
  SavedPresentState(const SavedPresentState&) = delete;
  SavedPresentState& operator=(const SavedPresentState&) = delete;

  // The state a blit or a tight RGB8 read-back needs, whatever the caller left.
  static void set_defaults() {
    glDisable(GL_SCISSOR_TEST);      // a blit is clipped by the scissor box
    glDisable(GL_FRAMEBUFFER_SRGB);  // the colour target is already gamma-encoded
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    for (GLenum name : kPackNames) glPixelStorei(name, name == GL_PACK_ALIGNMENT ? 1 : 0);
  }

 private:
  static constexpr std::array<GLenum, 4> kPackNames = {GL_PACK_ALIGNMENT, GL_PACK_ROW_LENGTH,
                                                       GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS};
  static void set_enabled(GLenum cap, GLboolean on) { on ? glEnable(cap) : glDisable(cap); }

  GLint read_fbo_ = 0, draw_fbo_ = 0, pack_buffer_ = 0;
  std::array<GLint, kPackNames.size()> pack_{};
  GLboolean scissor_ = GL_FALSE, srgb_ = GL_FALSE;
};

void blit_color(const Renderer& renderer, GLuint target, int dst_w, int dst_h) {
  const SavedPresentState saved;
  SavedPresentState::set_defaults();
  // A read FBO per call: creating one is ~microseconds, cheaper than caching GL state here.
  gl::Framebuffer fbo = gl::make_framebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, renderer.color_texture().id(), 0);
  glNamedFramebufferReadBuffer(fbo.id(), GL_COLOR_ATTACHMENT0);
  const int w = renderer.scene().render.width, h = renderer.scene().render.height;
  const bool same = w == dst_w && h == dst_h;
  glBlitNamedFramebuffer(fbo.id(), target, 0, 0, w, h, 0, 0, dst_w, dst_h, GL_COLOR_BUFFER_BIT,
                         same ? GL_NEAREST : GL_LINEAR);
}

}  // namespace

void present_to_default_framebuffer(const Renderer& renderer, int dst_w, int dst_h) {
  blit_color(renderer, 0, dst_w, dst_h);
}

void present_to_framebuffer(const Renderer& renderer, const gl::Framebuffer& target, int dst_w, int dst_h) {
  blit_color(renderer, target.id(), dst_w, dst_h);
}

Image read_back_buffer(int width, int height) {
  const SavedPresentState saved;
  SavedPresentState::set_defaults();
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  GLint read_buffer = GL_BACK;  // the default framebuffer's, restored below
  glGetIntegerv(GL_READ_BUFFER, &read_buffer);
  glReadBuffer(GL_BACK);
  std::vector<std::uint8_t> px(static_cast<size_t>(width) * height * 3);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, px.data());
  glReadBuffer(static_cast<GLenum>(read_buffer));
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
