// The ES 3.0 stand-ins (gl/es30.h) that the renderer's frames cannot show on their own, run in
// Mesa's ES 3.0 context and in a 4.5 core context with the same calls, which must give the same
// texels. glColorMaski: the surface pass masks its AOV and filter-need attachments outside the
// footprint's rectangle, and the frames read those inside it only, so a mask that did nothing
// would go unseen there (EsRendererGLTest compares the frames).
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gl/context.h"
#include "gl/es30.h"
#include "gl/gl.h"
#include "gl/objects.h"

namespace ps::gl {
namespace {

using Texel = std::array<std::uint8_t, 4>;

Texel read_texel(const Texture& t) {
  std::array<std::uint8_t, 4 * 4 * 4> px{};
  glGetTextureSubImage(t.id(), 0, 0, 0, 0, 4, 4, 1, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(px.size()), px.data());
  return {px[0], px[1], px[2], px[3]};
}

struct Seen {
  std::vector<Texel> second;  // the masked attachment after each step
  Texel first{};
  Texel other_second{};  // the other framebuffer's attachment 1, cleared while masked
  GLint width = 0;
  GLenum error = GL_NO_ERROR;
  Dialect dialect = Dialect::kCore45;
};

// Two RGBA8 attachments; attachment 1 masked, cleared, the framebuffer bound again, unmasked.
Seen masked_clears(bool es) {
  ContextDesc desc;
  desc.backend = Backend::kEgl;
  desc.es = es;
  auto context = create_context(desc);
  EXPECT_TRUE(context.ok()) << (context.ok() ? "" : context.error().message);
  Seen seen;
  if (!context.ok()) return seen;
  seen.dialect = dialect();
  const Texture a = make_texture_2d(4, 4, GL_RGBA8, 1), b = make_texture_2d(4, 4, GL_RGBA8, 1);
  const Texture c = make_texture_2d(4, 4, GL_RGBA8, 1), d = make_texture_2d(4, 4, GL_RGBA8, 1);
  const Framebuffer fbo = make_framebuffer(), other = make_framebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, a.id(), 0);
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT1, b.id(), 0);
  glNamedFramebufferTexture(other.id(), GL_COLOR_ATTACHMENT0, c.id(), 0);
  glNamedFramebufferTexture(other.id(), GL_COLOR_ATTACHMENT1, d.id(), 0);
  const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(fbo.id(), 2, both);
  glNamedFramebufferDrawBuffers(other.id(), 2, both);
  const float black[4] = {0, 0, 0, 1}, red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1}, blue[4] = {0, 0, 1, 1};
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, black);
  glClearNamedFramebufferfv(other.id(), GL_COLOR, 1, black);
  seen.second.push_back(read_texel(b));
  glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, red);
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, red);
  seen.second.push_back(read_texel(b));
  glBindFramebuffer(GL_FRAMEBUFFER, other.id());  // the mask is the context's, not the framebuffer's
  glClearNamedFramebufferfv(other.id(), GL_COLOR, 1, green);
  seen.other_second = read_texel(d);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, green);
  seen.second.push_back(read_texel(b));
  glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, blue);
  seen.second.push_back(read_texel(b));
  seen.first = read_texel(a);
  glGetTextureLevelParameteriv(b.id(), 0, GL_TEXTURE_WIDTH, &seen.width);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  seen.error = glGetError();
  return seen;
}

TEST(Es30GLTest, AMaskedAttachmentKeepsItsTexelsAsOnTheDesktop) {
  const Seen core = masked_clears(false);
  const Seen es = masked_clears(true);
  EXPECT_EQ(core.dialect, Dialect::kCore45);
  EXPECT_EQ(es.dialect, Dialect::kEs30);
  // The desktop's answer first, from GL's rules (a masked attachment is not cleared).
  const std::vector<Texel> expected = {{0, 0, 0, 255}, {0, 0, 0, 255}, {0, 0, 0, 255}, {0, 0, 255, 255}};
  EXPECT_EQ(core.second, expected);
  EXPECT_EQ(es.second, expected);
  EXPECT_EQ(core.other_second, (Texel{0, 0, 0, 255}));
  EXPECT_EQ(es.other_second, core.other_second);
  EXPECT_EQ(core.first, (Texel{255, 0, 0, 255}));
  EXPECT_EQ(es.first, core.first);
  EXPECT_EQ(core.width, 4);
  EXPECT_EQ(es.width, 4);
  EXPECT_EQ(core.error, static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_EQ(es.error, static_cast<GLenum>(GL_NO_ERROR));
}

// The ES table holds ES 3.0 only: a 3.1 call (glDispatchCompute) stays null even though Mesa's
// ES context is 3.2, and a desktop DSA call has its stand-in.
TEST(Es30GLTest, TheEsTableHoldsEs30AndTheStandIns) {
  ContextDesc desc;
  desc.backend = Backend::kEgl;
  desc.es = true;
  auto context = create_context(desc);
  ASSERT_TRUE(context.ok()) << context.error().message;
  EXPECT_EQ(ps_glDispatchCompute, nullptr);
  EXPECT_EQ(ps_glTexStorage2DMultisample, nullptr);  // ES 3.1
  EXPECT_NE(ps_glNamedFramebufferTexture, nullptr);
  EXPECT_TRUE(ps_gl_is_es30("glTexStorage2D"));
  EXPECT_FALSE(ps_gl_is_es30("glProgramUniform1f"));
  EXPECT_FALSE(ps_gl_is_es30("glNamedFramebufferTexture"));
}

// WebGL2 fixes a buffer's kind at its first binding (index data or other data; its specification,
// 5.1) and refuses an index buffer that was filled on another target. Mesa's ES 3.0 has no such
// rule, so the stand-ins count what WebGL would refuse. A mesh's buffers are made the desktop way
// (created and filled, then attached): the index data must reach the buffer through its element
// binding, with nothing refused, and a binding against the kind must be counted.
std::vector<std::uint32_t> read_bound(GLenum target, size_t count) {
  std::vector<std::uint32_t> out(count);
  const auto size = static_cast<GLsizeiptr>(count * sizeof(std::uint32_t));
  if (const void* p = glMapBufferRange(target, 0, size, GL_MAP_READ_BIT)) {
    std::memcpy(out.data(), p, static_cast<size_t>(size));
    glUnmapBuffer(target);
  }
  return out;
}

TEST(Es30GLTest, BuffersKeepWebGLsKindsAndTheirData) {
  ContextDesc desc;
  desc.backend = Backend::kEgl;
  desc.es = true;
  auto context = create_context(desc);
  ASSERT_TRUE(context.ok()) << context.error().message;
  const std::vector<std::uint32_t> indices = {0, 1, 2, 2, 1, 3};
  const std::vector<float> vertices(40, 0.5f);
  const Buffer index_buffer = make_buffer(24, indices.data(), 0);
  const Buffer vertex_buffer = make_buffer(160, vertices.data(), GL_DYNAMIC_STORAGE_BIT);
  const std::uint32_t patch[2] = {7, 8};
  glNamedBufferSubData(index_buffer.id(), 8, 8, patch);  // edited before its first binding
  const VertexArray vao = make_vertex_array();
  glVertexArrayVertexBuffer(vao.id(), 0, vertex_buffer.id(), 0, 16);
  glVertexArrayElementBuffer(vao.id(), index_buffer.id());
  glEnableVertexArrayAttrib(vao.id(), 0);
  glVertexArrayAttribFormat(vao.id(), 0, 4, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao.id(), 0, 0);
  EXPECT_EQ(es30_webgl_buffer_conflicts(), 0) << "a mesh's buffers as the desktop makes them";
  glBindVertexArray(vao.id());
  EXPECT_EQ(read_bound(GL_ELEMENT_ARRAY_BUFFER, 6), (std::vector<std::uint32_t>{0, 1, 7, 8, 1, 3}));
  glBindVertexArray(0);
  glNamedBufferSubData(index_buffer.id(), 0, 4, &patch[1]);  // after: through COPY_WRITE, allowed
  glBindBuffer(GL_COPY_READ_BUFFER, index_buffer.id());
  EXPECT_EQ(read_bound(GL_COPY_READ_BUFFER, 2), (std::vector<std::uint32_t>{8, 1}));
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  EXPECT_EQ(es30_webgl_buffer_conflicts(), 0) << "an index buffer on the copy targets";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  // What WebGL refuses is counted: other data as indices, and indices as a uniform block.
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vertex_buffer.id());
  EXPECT_EQ(es30_webgl_buffer_conflicts(), 1);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, index_buffer.id());
  EXPECT_EQ(es30_webgl_buffer_conflicts(), 2);
}

}  // namespace
}  // namespace ps::gl
