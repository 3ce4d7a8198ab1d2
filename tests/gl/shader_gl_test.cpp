// GL tests of program building and of the shared render path on both headless backends.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/gl.h"
#include "gl/objects.h"
#include "gl/shader.h"
#include "support/gl_test.h"

namespace {

using ps::gl::Backend;

const std::string kData = PS_SOURCE_DIR "/tests/gl/data";

class ShaderGLTest : public ps::test::GlTest {};

TEST_P(ShaderGLTest, ErrorInIncludedFileNamesThatFileAndLine) {
  auto program = ps::gl::build_program({{"triangle.vert", "broken_include.frag"}, {}}, kData);
  ASSERT_FALSE(program.ok());
  const std::string& m = program.error().message;
  const std::string where = kData + "/lib/broken.glsl:5: error";
  EXPECT_EQ(m.rfind(where, 0), 0u) << "message should start with " << where << ", got:\n" << m;
  EXPECT_NE(m.find("undefined_thing"), std::string::npos) << m;
}

TEST_P(ShaderGLTest, GoodProgramLinksWithVariantDefine) {
  auto program =
      ps::gl::build_program({{"triangle.vert", "triangle.frag"}, {{"TINT", "vec4(1.0)"}}}, kData);
  ASSERT_TRUE(program.ok()) << program.error().message;
  EXPECT_GE(glGetUniformLocation(program->id(), "u_gain"), 0);
  // Without the define the variant does not compile, and says where.
  auto missing = ps::gl::build_program({{"triangle.vert", "triangle.frag"}, {}}, kData);
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().message.rfind(kData + "/lib/color.glsl:6: error", 0), 0u)
      << missing.error().message;
}

PS_INSTANTIATE_HEADLESS_BACKENDS(ShaderGLTest);

// Renders the fixture triangle into a 64x48 RGBA8 FBO and reads it back (row 0 = bottom);
// `renderer` receives the context's renderer string.
std::vector<unsigned char> render_triangle(Backend backend, std::string& renderer) {
  ps::gl::ContextDesc desc;
  desc.backend = backend;
  auto context = ps::gl::create_context(desc);
  EXPECT_TRUE(context.ok()) << context.error().message;
  if (!context.ok()) return {};
  renderer = context.value()->renderer();
  constexpr int kWidth = 64, kHeight = 48;
  std::vector<unsigned char> pixels(kWidth * kHeight * 4);
  {
    auto program = ps::gl::build_program(
        {{"triangle.vert", "triangle.frag"}, {{"TINT", "vec4(1.0, 0.9, 0.8, 1.0)"}}}, kData);
    EXPECT_TRUE(program.ok()) << program.error().message;
    if (!program.ok()) return {};
    ps::gl::Texture color = ps::gl::make_texture_2d(kWidth, kHeight, GL_RGBA8);
    ps::gl::Framebuffer fbo = ps::gl::make_framebuffer();
    ps::gl::VertexArray vao = ps::gl::make_vertex_array();
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, kWidth, kHeight);
    const GLfloat clear[4] = {0.25f, 0.0f, 0.0f, 1.0f};
    glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, clear);
    glUseProgram(program->id());
    glUniform1f(glGetUniformLocation(program->id(), "u_gain"), 0.75f);
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  return pixels;
}

// docs/gl-stack.md: llvmpipe renders byte-identical images behind EGL and OSMesa; the renderer
// relies on it (goldens are backend-independent), so any difference is a bug in our setup.
// That holds for one rasteriser behind both: where EGL drives a GPU (OSMesa is always
// software) the bytes may legitimately differ, so the test skips.
TEST(BackendParityGLTest, EglAndOsmesaRenderIdenticalBytes) {
  std::string egl_renderer, osmesa_renderer;
  const std::vector<unsigned char> egl = render_triangle(Backend::kEgl, egl_renderer);
  const std::vector<unsigned char> osmesa = render_triangle(Backend::kOsmesa, osmesa_renderer);
  ASSERT_FALSE(egl.empty());
  ASSERT_FALSE(osmesa.empty());
  if (egl_renderer.find("llvmpipe") == std::string::npos || osmesa_renderer.find("llvmpipe") == std::string::npos)
    GTEST_SKIP() << "byte parity is a property of llvmpipe on both backends; EGL: " << egl_renderer
                 << ", OSMesa: " << osmesa_renderer;
  ASSERT_EQ(egl.size(), osmesa.size());
  size_t differing = 0, covered = 0;
  for (size_t i = 0; i < egl.size(); i += 4) {
    differing += std::equal(&egl[i], &egl[i] + 4, &osmesa[i]) ? 0 : 1;
    covered += egl[i + 2] != 0 ? 1 : 0;  // the clear color has blue 0, the triangle not
  }
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(covered, egl.size() / 4 / 5) << "the triangle should cover a good part of the image";
  EXPECT_LT(covered, egl.size() / 4) << "and not all of it";
}

}  // namespace
