// No-GL tests of the GLSL preprocessor, the log mapper and parse_backend.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "gl/context.h"
#include "gl/shader.h"
#include "shader_dir_fixture.h"

namespace {

namespace fs = std::filesystem;
using ps::gl::preprocess_shader;

class ShaderPreprocessTest : public ps::test::ShaderDirTest {};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Replays the output as a GLSL >= 3.30 compiler numbers it (`#line n s`: the NEXT line is line n
// of string s) and checks every non-empty line is the same text as that line of that file.
void expect_lines_map_back(const ps::gl::ShaderSource& src) {
  std::vector<std::vector<std::string>> files;
  for (const auto& f : src.files) {
    std::ifstream in(f);
    std::stringstream s;
    s << in.rdbuf();
    files.push_back(lines_of(s.str()));
  }
  int line = 1, string = 0;
  for (const std::string& out : lines_of(src.text)) {
    int n = 0, s = 0;
    if (std::sscanf(out.c_str(), "#line %d %d", &n, &s) == 2) {
      EXPECT_EQ(n / ps::gl::kIncludeLineStride, s) << "line offset and source string agree";
      line = n % ps::gl::kIncludeLineStride;
      string = s;
      continue;
    }
    if (!out.empty() && out.rfind("#version", 0) != 0 && out.rfind("#define", 0) != 0) {
      ASSERT_LT(string, static_cast<int>(files.size()));
      ASSERT_LE(line, static_cast<int>(files[string].size())) << out;
      EXPECT_EQ(files[string][line - 1], out) << src.files[string] << ":" << line;
    }
    ++line;
  }
}

TEST_F(ShaderPreprocessTest, IncludesResolveRecursivelyAndLinesMapBack) {
  write("lib/inner.glsl", "// inner\nfloat inner() { return 1.0; }\n");
  write("lib/outer.glsl", "// outer\n#include \"inner.glsl\"\nfloat outer() { return inner(); }\n");
  const std::string root_file = write("a.frag",
      "#version 450 core\n#include \"lib/outer.glsl\"\nout vec4 c;\n"
      "void main() { c = vec4(outer()); }\n");
  auto src = preprocess_shader(root_file, {}, root());
  ASSERT_TRUE(src.ok()) << src.error().message;
  ASSERT_EQ(src->files.size(), 3u);
  EXPECT_EQ(src->files[0], root_file);
  EXPECT_EQ(fs::path(src->files[1]).filename(), "outer.glsl");
  EXPECT_EQ(fs::path(src->files[2]).filename(), "inner.glsl");  // found next to outer.glsl
  EXPECT_EQ(src->text.find("#include"), std::string::npos);
  EXPECT_NE(src->text.find("#line 100003 1"), std::string::npos);  // back in outer after inner
  EXPECT_NE(src->text.find("#line 3 0"), std::string::npos);       // back in the root
  expect_lines_map_back(src.value());
}

TEST_F(ShaderPreprocessTest, IncludeFallsBackToGlslRoot) {
  write("lib/common.glsl", "float common_fn() { return 0.0; }\n");
  fs::create_directories(dir_ / "sub");
  const std::string root_file = write("sub/b.frag", "#version 450\n#include \"lib/common.glsl\"\n");
  auto src = preprocess_shader(root_file, {}, root());
  ASSERT_TRUE(src.ok()) << src.error().message;
  EXPECT_NE(src->text.find("common_fn"), std::string::npos);
}

TEST_F(ShaderPreprocessTest, PragmaOnceSkipsSecondInclusion) {
  write("lib/once.glsl", "#pragma once\nfloat once_fn() { return 1.0; }\n");
  const std::string root_file = write("c.frag",
      "#version 450\n#include \"lib/once.glsl\"\n#include \"lib/once.glsl\"\nvoid main() {}\n");
  auto src = preprocess_shader(root_file, {}, root());
  ASSERT_TRUE(src.ok()) << src.error().message;
  const std::string& t = src->text;
  const size_t first = t.find("once_fn");
  ASSERT_NE(first, std::string::npos);
  EXPECT_EQ(t.find("once_fn", first + 1), std::string::npos);
  EXPECT_EQ(t.find("#pragma once"), std::string::npos);
  expect_lines_map_back(src.value());
}

TEST_F(ShaderPreprocessTest, MissingIncludeNamesFileAndLine) {
  const std::string root_file = write("d.frag", "#version 450\n\n#include \"lib/nope.glsl\"\n");
  auto src = preprocess_shader(root_file, {}, root());
  ASSERT_FALSE(src.ok());
  EXPECT_EQ(src.error().message, root_file + ":3: cannot open include \"lib/nope.glsl\"");
}

TEST_F(ShaderPreprocessTest, CycleHitsDepthLimit) {
  write("lib/x.glsl", "#include \"y.glsl\"\n");
  write("lib/y.glsl", "// y\n#include \"x.glsl\"\n");
  const std::string root_file = write("e.frag", "#version 450\n#include \"lib/x.glsl\"\n");
  auto src = preprocess_shader(root_file, {}, root());
  ASSERT_FALSE(src.ok());
  const std::string& m = src.error().message;
  EXPECT_NE(m.find("include depth > " + std::to_string(ps::gl::kMaxIncludeDepth) + " (cycle?)"),
            std::string::npos) << m;
  EXPECT_NE(m.find("glsl:"), std::string::npos) << "names the including file: " << m;
}

TEST_F(ShaderPreprocessTest, DefinesFollowVersionAndKeepRootLines) {
  const std::string root_file = write("f.frag",
      "// leading comment\n#version 450 core\nfloat f() { return float(A) + B; }\n");
  auto src = preprocess_shader(root_file, {{"A", "1"}, {"B", "2.5"}}, root());
  ASSERT_TRUE(src.ok()) << src.error().message;
  const auto lines = lines_of(src->text);
  ASSERT_GE(lines.size(), 4u);
  EXPECT_EQ(lines[0], "#version 450 core");
  EXPECT_EQ(lines[1], "#define A 1");
  EXPECT_EQ(lines[2], "#define B 2.5");
  EXPECT_EQ(lines[3], "#line 1 0");
  expect_lines_map_back(src.value());
}

TEST_F(ShaderPreprocessTest, MissingVersionAndMissingFile) {
  const std::string no_version = write("g.frag", "void main() {}\n");
  auto a = preprocess_shader(no_version, {}, root());
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.error().message, no_version + ": missing #version");
  auto b = preprocess_shader(root() + "/absent.frag", {}, root());
  ASSERT_FALSE(b.ok());
  EXPECT_EQ(b.error().message.rfind(root() + "/absent.frag: cannot open shader: ", 0), 0u)
      << b.error().message;
}

// Log lines captured from Mesa 22.3 llvmpipe and glslang 12 on this machine's shaders.
TEST(MapShaderLogTest, MesaAndGlslangLinesMapToFiles) {
  const std::vector<std::string> files = {"surface.frag", "lib/noise.glsl"};
  EXPECT_EQ(ps::gl::map_shader_log(
                "1:7(10): error: `undefined_thing' undeclared\n"
                "0:12(3): warning: `x' used uninitialized\n", files),
            "lib/noise.glsl:7: error: `undefined_thing' undeclared\n"
            "surface.frag:12: warning: `x' used uninitialized\n");
  EXPECT_EQ(ps::gl::map_shader_log(
                "ERROR: 1:3: 'undefined_thing' : undeclared identifier \n"
                "ERROR: 1 compilation errors.  No code generated.\n", files),
            "lib/noise.glsl:3: error: 'undefined_thing' : undeclared identifier \n"
            "ERROR: 1 compilation errors.  No code generated.\n");
  // Unknown source-string numbers stay numeric rather than naming a wrong file.
  EXPECT_EQ(ps::gl::map_shader_log("5:2(1): error: x\n", files), "5:2: error: x\n");
  // Mesa 22.3 reports source 0 for an error inside an included expression; the strided line
  // number still names the include (real log of tests/gl/data/broken_include.frag).
  EXPECT_EQ(ps::gl::map_shader_log("0:100005(10): error: `undefined_thing' undeclared\n", files),
            "lib/noise.glsl:5: error: `undefined_thing' undeclared\n");
  EXPECT_EQ(ps::gl::map_shader_log("ERROR: 1:100005: 'undefined_thing' : undeclared identifier\n",
                                   files),
            "lib/noise.glsl:5: error: 'undefined_thing' : undeclared identifier\n");
  EXPECT_EQ(ps::gl::map_shader_log("error: linking failed\n", files), "error: linking failed\n");
}

TEST(ParseBackendTest, AcceptsNamesAndRejectsOthers) {
  EXPECT_EQ(ps::gl::parse_backend("egl").value(), ps::gl::Backend::kEgl);
  EXPECT_EQ(ps::gl::parse_backend("osmesa").value(), ps::gl::Backend::kOsmesa);
  EXPECT_EQ(ps::gl::parse_backend("glfw").value(), ps::gl::Backend::kGlfw);
  EXPECT_EQ(ps::gl::parse_backend("auto").value(), ps::gl::Backend::kAuto);
  auto bad = ps::gl::parse_backend("vulkan");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().message,
            "unknown backend \"vulkan\" (expected auto, egl, osmesa or glfw)");
  EXPECT_STREQ(ps::gl::backend_name(ps::gl::Backend::kOsmesa), "osmesa");
}

TEST(StageFromPathTest, Extensions) {
  EXPECT_EQ(ps::gl::stage_from_path("a/b.vert"), ps::gl::Stage::kVertex);
  EXPECT_EQ(ps::gl::stage_from_path("b.frag"), ps::gl::Stage::kFragment);
  EXPECT_EQ(ps::gl::stage_from_path("c.comp"), ps::gl::Stage::kCompute);
}

TEST(MapShaderLogTest, AbsurdNumbersAreLeftUnmapped) {
  // Found by fuzz_glsl_include: std::stoul threw out_of_range on a 20-digit source number.
  const std::string log = "ERROR: 0444444444444444444444:5: x\n0:99999999999999999999999(3): y";
  EXPECT_EQ(ps::gl::map_shader_log(log, {"a.frag"}),
            "0444444444444444444444:5: error: x\n0:99999999999999999999999: y\n");
}

}  // namespace
