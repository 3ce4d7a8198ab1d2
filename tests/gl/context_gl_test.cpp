// GL tests of contexts and objects, run on EGL surfaceless and OSMesa.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <string>

#include "gl/context.h"
#include "gl/gl.h"
#include "gl/objects.h"
#include "support/gl_test.h"

namespace {

using ps::gl::Backend;

class ContextGLTest : public ps::test::GlTest {};

// Any driver: at least the 4.5 core profile the renderer asks for (a GPU driver may hand out a
// 4.6 context for that request), and a renderer string to report in --stats.
TEST_P(ContextGLTest, IsAtLeast45Core) {
  EXPECT_EQ(context().backend(), GetParam());
  EXPECT_TRUE(ps::gl::gl_loaded());
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_NE(profile & GL_CONTEXT_CORE_PROFILE_BIT, 0);
  EXPECT_FALSE(context().renderer().empty());
  EXPECT_EQ(context().version().rfind(std::to_string(major) + "." + std::to_string(minor), 0), 0u)
      << context().version();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The version llvmpipe reports is part of the stack docs/gl-stack.md describes: exactly 4.5.
// Only llvmpipe's number is known, so other drivers skip.
TEST_P(ContextGLTest, LlvmpipeIsExactly45) {
  if (!ps::test::is_llvmpipe(context())) GTEST_SKIP() << "not llvmpipe: " << context().renderer();
  EXPECT_EQ(context().version().rfind("4.5", 0), 0u) << context().version();
}

TEST_P(ContextGLTest, ClearRgba32fFboReadsBackExactly) {
  constexpr int kSize = 4;
  ps::gl::Texture color = ps::gl::make_texture_2d(kSize, kSize, GL_RGBA32F);
  ps::gl::Framebuffer fbo = ps::gl::make_framebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
  ASSERT_EQ(glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER),
            static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  // Values not representable in half precision or 8 bits: a float path must keep every bit.
  const std::array<GLfloat, 4> value = {0.1234567f, -3.5e7f, 1.0f / 3.0f, 65504.5f};
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, value.data());
  std::array<GLfloat, kSize * kSize * 4> pixels{};
  glGetTextureImage(color.id(), 0, GL_RGBA, GL_FLOAT, sizeof(pixels), pixels.data());
  for (int i = 0; i < kSize * kSize; ++i) {
    for (int c = 0; c < 4; ++c) {
      ASSERT_EQ(std::memcmp(&pixels[i * 4 + c], &value[c], sizeof(GLfloat)), 0)
          << "pixel " << i << " channel " << c << ": " << pixels[i * 4 + c];
    }
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_P(ContextGLTest, FullMipChainAndMoveOnlyHandles) {
  ps::gl::Texture t = ps::gl::make_texture_2d(500, 300, GL_RGBA8, 0);
  GLint levels = 0;
  glGetTextureParameteriv(t.id(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
  EXPECT_EQ(levels, 9);  // 500 -> 1 halving: 1 + floor(log2(500))
  const GLuint id = t.id();
  ps::gl::Texture moved = std::move(t);
  EXPECT_FALSE(t);
  EXPECT_EQ(moved.id(), id);
  moved.reset();
  EXPECT_EQ(glIsTexture(id), GL_FALSE);
  ps::gl::Buffer b = ps::gl::make_buffer(64, nullptr, GL_DYNAMIC_STORAGE_BIT);
  EXPECT_EQ(glIsBuffer(b.id()), GL_TRUE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

PS_INSTANTIATE_HEADLESS_BACKENDS(ContextGLTest);

// Several contexts in sequence in one process, alternating backends, each usable.
TEST(ContextLifetimeGLTest, CreateDestroyRepeatedly) {
  for (int i = 0; i < 6; ++i) {
    ps::gl::ContextDesc desc;
    desc.backend = i % 2 == 0 ? Backend::kEgl : Backend::kOsmesa;
    auto context = ps::gl::create_context(desc);
    ASSERT_TRUE(context.ok()) << "round " << i << ": " << context.error().message;
    ps::gl::Texture t = ps::gl::make_texture_2d(2, 2, GL_RGBA8);
    EXPECT_NE(t.id(), 0u);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << "round " << i;
    t.reset();  // GL objects die before their context
    context.value().reset();
    EXPECT_FALSE(ps::gl::gl_loaded()) << "destroying the context unloads the table";
  }
}

TEST(ContextLifetimeGLTest, AutoPicksEgl) {
  auto context = ps::gl::create_context({});
  ASSERT_TRUE(context.ok()) << context.error().message;
  EXPECT_EQ(context.value()->backend(), Backend::kEgl);
}

// Without a display GLFW must fail with one clear line, not crash.
TEST(ContextLifetimeGLTest, GlfwWithoutDisplayFailsClearly) {
  if (std::getenv("DISPLAY") != nullptr || std::getenv("WAYLAND_DISPLAY") != nullptr) {
    GTEST_SKIP() << "a display is available; this checks the headless failure message";
  }
  ps::gl::ContextDesc desc;
  desc.backend = Backend::kGlfw;
  auto context = ps::gl::create_context(desc);
  ASSERT_FALSE(context.ok());
  EXPECT_EQ(context.error().message.rfind("no OpenGL 4.5 context: glfw: glfwInit failed: ", 0), 0u)
      << context.error().message;
  EXPECT_EQ(context.error().message.find('\n'), std::string::npos);
}

}  // namespace
