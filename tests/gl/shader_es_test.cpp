// No-GL tests of the GLSL 4.50 -> GLSL ES 3.00 rewrite (gl/shader_es.h): what it takes out and
// records, what it refuses with file:line, and that every shipped shader that has an ES form
// gets one whose records name what the shader declares.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "gl/shader.h"
#include "gl/shader_es.h"
#include "shader_dir_fixture.h"

namespace {

namespace fs = std::filesystem;
using ps::gl::preprocess_shader;
using ps::gl::Stage;
using ps::gl::to_glsl_es;

class ShaderEsTest : public ps::test::ShaderDirTest {};

bool has_line(const std::string& text, const std::string& line) {
  return ("\n" + text).find("\n" + line + "\n") != std::string::npos;
}

TEST_F(ShaderEsTest, BindingsAndLocationsBecomeRecordsAndVersionBecomes300Es) {
  const std::string path = write("a.frag",
                                 "#version 450 core\n"
                                 "layout(std140, binding = 3) uniform Block {\n  vec4 u_x;\n};\n"
                                 "layout(binding = 2) uniform sampler2D u_tex;  // a comment\n"
                                 "layout(location = 4) uniform ivec4 u_box;\n"
                                 "layout(location = 1) in vec3 v_normal;\n"
                                 "layout(location = 0) out vec4 o_color;\n"
                                 "void main() { precise vec4 s = u_x; o_color = s + texelFetch(u_tex, ivec2(u_box.xy), 0); }\n");
  auto src = preprocess_shader(path, {{"PS_A", "1"}}, dir_.string());
  ASSERT_TRUE(src.ok()) << src.error().message;
  auto es = to_glsl_es(src.value(), Stage::kFragment);
  ASSERT_TRUE(es.ok()) << es.error().message;
  const std::string& t = es->text;
  EXPECT_EQ(t.rfind("#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n", 0), 0u) << t;
  EXPECT_TRUE(has_line(t, "#define PS_A 1")) << t;  // the variant's defines stay
  EXPECT_TRUE(has_line(t, "layout(std140) uniform Block {")) << t;
  EXPECT_TRUE(has_line(t, "uniform sampler2D u_tex;  // a comment")) << t;
  EXPECT_TRUE(has_line(t, "uniform ivec4 u_box;")) << t;
  EXPECT_TRUE(has_line(t, "in vec3 v_normal;")) << t;  // a fragment input: matched by name in 3.00
  EXPECT_TRUE(has_line(t, "layout(location = 0) out vec4 o_color;")) << t;  // fragment outputs keep theirs
  EXPECT_EQ(t.find("precise"), std::string::npos) << t;
  EXPECT_EQ(t.find("binding"), std::string::npos) << t;
  using Records = std::vector<std::pair<std::string, int>>;
  EXPECT_EQ(es->sampler_units, (Records{{"u_tex", 2}}));
  EXPECT_EQ(es->block_bindings, (Records{{"Block", 3}}));
  EXPECT_EQ(es->uniform_locations, (Records{{"u_box", 4}}));
}

TEST_F(ShaderEsTest, VertexInputsKeepTheirLocationsAndOutputsLoseThem) {
  const std::string path = write("a.vert",
                                 "#version 450 core\nlayout(location = 2) in vec3 a_color;\n"
                                 "layout(location = 0) out vec3 v_color;\nvoid main() { v_color = a_color; }\n");
  auto src = preprocess_shader(path, {}, dir_.string());
  ASSERT_TRUE(src.ok());
  auto es = to_glsl_es(src.value(), Stage::kVertex);
  ASSERT_TRUE(es.ok()) << es.error().message;
  EXPECT_TRUE(has_line(es->text, "layout(location = 2) in vec3 a_color;")) << es->text;
  EXPECT_TRUE(has_line(es->text, "out vec3 v_color;")) << es->text;
}

TEST_F(ShaderEsTest, StorageBufferInAnIncludeIsRefusedWithItsFileAndLine) {
  write("lib/block.glsl", "#pragma once\n// the block\nlayout(std430, binding = 0) buffer B {\n  uint x;\n};\n");
  const std::string path = write("a.frag", "#version 450 core\n#include \"lib/block.glsl\"\nout vec4 o;\nvoid main() { o = vec4(x); }\n");
  auto src = preprocess_shader(path, {}, dir_.string());
  ASSERT_TRUE(src.ok()) << src.error().message;
  auto es = to_glsl_es(src.value(), Stage::kFragment);
  ASSERT_FALSE(es.ok());
  EXPECT_NE(es.error().message.find("lib/block.glsl:3: a storage buffer has no GLSL ES 3.00 form"), std::string::npos)
      << es.error().message;
}

TEST_F(ShaderEsTest, ComputeShaderIsRefusedNamingTheFragmentPath) {
  const std::string path = write("a.comp", "#version 450 core\nlayout(local_size_x = 64) in;\nvoid main() {}\n");
  auto src = preprocess_shader(path, {}, dir_.string());
  ASSERT_TRUE(src.ok());
  auto es = to_glsl_es(src.value(), Stage::kCompute);
  ASSERT_FALSE(es.ok());
  EXPECT_NE(es.error().message.find("a.comp: a compute shader has no GLSL ES 3.00 form"), std::string::npos);
  EXPECT_NE(es.error().message.find("ReductionMethod::kFragment"), std::string::npos);
}

TEST_F(ShaderEsTest, OtherVersionIsRefused) {
  const std::string path = write("a.frag", "#version 330 core\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n");
  auto src = preprocess_shader(path, {}, dir_.string());
  ASSERT_TRUE(src.ok());
  auto es = to_glsl_es(src.value(), Stage::kFragment);
  ASSERT_FALSE(es.ok());
  EXPECT_NE(es.error().message.find("expected #version 450 first"), std::string::npos) << es.error().message;
}

// Every shipped vertex and fragment shader has an ES form; each recorded name is declared in the text, each
// recorded unit or binding is the one the desktop source gave, and no layout(binding) is left.
TEST(ShippedShadersEs, EveryRasterShaderHasAnEsFormWithItsRecords) {
  const std::string root = ps::gl::default_glsl_root();
  int converted = 0, samplers = 0;
  for (const auto& entry : fs::directory_iterator(root)) {
    const std::string name = entry.path().filename().string(), ext = entry.path().extension().string();
    if (ext != ".vert" && ext != ".frag") continue;
    auto src = preprocess_shader(entry.path().string(), {}, root);
    ASSERT_TRUE(src.ok()) << name << ": " << src.error().message;
    auto es = to_glsl_es(src.value(), ps::gl::stage_from_path(name));
    ASSERT_TRUE(es.ok()) << name << ": " << es.error().message;
    EXPECT_EQ(es->text.find("binding"), std::string::npos) << name;
    for (const auto& [sampler, unit] : es->sampler_units) {
      EXPECT_NE(es->text.find("uniform sampler2D " + sampler + ";"), std::string::npos) << name << " " << sampler;
      EXPECT_NE(src->text.find("binding = " + std::to_string(unit) + ") uniform sampler2D " + sampler), std::string::npos)
          << name << " " << sampler;
      ++samplers;
    }
    for (const auto& [block, binding] : es->block_bindings)
      EXPECT_NE(es->text.find("layout(std140) uniform " + block), std::string::npos) << name << " " << block;
    ++converted;
  }
  EXPECT_GE(converted, 15);  // 15 vertex and fragment shaders today
  EXPECT_GE(samplers, 10);
}

}  // namespace
