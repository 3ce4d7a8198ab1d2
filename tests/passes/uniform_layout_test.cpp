// Each pass's std140 uniform block in GLSL must match the C++ struct that fills it, member by
// member. glslang's reflection gives the GLSL offsets without a GL context (STYLE.md item 4).
#include <cstddef>
#include <map>
#include <memory>
#include <string>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <gtest/gtest.h>

#include "gl/shader.h"
#include "passes/gabor_bake.h"
#include "passes/gabor_block.h"
#include "passes/probe_depth.h"
#include "passes/probe_view.h"
#include "passes/reductions.h"
#include "passes/surface.h"

namespace ps {
namespace {

class GlslangProcess : public ::testing::Environment {
 public:
  void SetUp() override { glslang::InitializeProcess(); }
  void TearDown() override { glslang::FinalizeProcess(); }
};
const auto* const kEnv = ::testing::AddGlobalTestEnvironment(new GlslangProcess);

// Offsets of every uniform-block member of `file` (a fragment or compute shader), by name.
std::map<std::string, int> block_offsets(const std::string& file, EShLanguage stage,
                                         const gl::Defines& defines = {}) {
  auto src = gl::preprocess_shader(std::string(PS_SOURCE_DIR) + "/glsl/" + file, defines,
                                   std::string(PS_SOURCE_DIR) + "/glsl");
  EXPECT_TRUE(src.ok()) << (src.ok() ? "" : src.error().message);
  if (!src.ok()) return {};
  glslang::TShader shader(stage);
  const char* text = src->text.c_str();
  shader.setStrings(&text, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientOpenGL, 450);
  shader.setEnvClient(glslang::EShClientOpenGL, glslang::EShTargetOpenGL_450);
  shader.setAutoMapLocations(true);
  shader.setAutoMapBindings(true);
  EXPECT_TRUE(shader.parse(GetDefaultResources(), 450, false, EShMsgDefault)) << shader.getInfoLog();
  glslang::TProgram program;
  program.addShader(&shader);
  EXPECT_TRUE(program.link(EShMsgDefault)) << program.getInfoLog();
  // All members, also those the shader does not read (the layout covers them all).
  EXPECT_TRUE(program.buildReflection(EShReflectionAllBlockVariables));
  std::map<std::string, int> out;
  for (int i = 0; i < program.getNumUniformVariables(); ++i) {
    const glslang::TObjectReflection& u = program.getUniform(i);
    if (u.offset >= 0) out[u.name] = u.offset;
  }
  for (int i = 0; i < program.getNumBufferVariables(); ++i) {  // std430 storage blocks
    const glslang::TObjectReflection& b = program.getBufferVariable(i);
    if (b.offset >= 0) out[b.name] = b.offset;
  }
  return out;
}

// at(): a member missing from the GLSL block throws, failing the test with its name unknown;
// find() keeps the name in the message.
int offset_of(const std::map<std::string, int>& offsets, const std::string& glsl_name) {
  const auto it = offsets.find(glsl_name);
  EXPECT_NE(it, offsets.end()) << "no block member named " << glsl_name;
  return it == offsets.end() ? -1 : it->second;
}

#define EXPECT_MEMBER(offsets, glsl_name, Struct, member) \
  EXPECT_EQ(offset_of(offsets, glsl_name), static_cast<int>(offsetof(Struct, member))) << glsl_name

// Every member of the GaborBlock struct that Struct holds as `member` (named `glsl_prefix` in
// GLSL): std140 places a struct member at a multiple of 16 and its members after it.
#define EXPECT_GABOR_BLOCK(offsets, glsl_prefix, Struct, member)                                  \
  do {                                                                                             \
    const int base = static_cast<int>(offsetof(Struct, member));                                   \
    EXPECT_EQ(offset_of(offsets, glsl_prefix ".amplitude_lambda"), base + static_cast<int>(offsetof(GaborBlock, amplitude_lambda))); \
    EXPECT_EQ(offset_of(offsets, glsl_prefix ".theta_density"), base + static_cast<int>(offsetof(GaborBlock, theta_density)));       \
    EXPECT_EQ(offset_of(offsets, glsl_prefix ".kernel"), base + static_cast<int>(offsetof(GaborBlock, kernel)));                     \
    EXPECT_EQ(offset_of(offsets, glsl_prefix ".tile"), base + static_cast<int>(offsetof(GaborBlock, tile)));                         \
    EXPECT_EQ(offset_of(offsets, glsl_prefix ".counts"), base + static_cast<int>(offsetof(GaborBlock, counts)));                     \
    EXPECT_EQ(offset_of(offsets, glsl_prefix ".filtering"), base + static_cast<int>(offsetof(GaborBlock, filtering)));               \
  } while (false)

TEST(UniformLayoutTest, SurfaceBlockMatches) {
  const auto o = block_offsets("surface.frag", EShLangFragment);
  ASSERT_FALSE(o.empty());
  EXPECT_MEMBER(o, "u_view_proj", SurfaceBlock, view_proj);
  EXPECT_MEMBER(o, "u_light_dir", SurfaceBlock, light_dir);
  EXPECT_MEMBER(o, "u_light_color", SurfaceBlock, light_color);
  EXPECT_MEMBER(o, "u_ref_n", SurfaceBlock, ref_n);
  EXPECT_MEMBER(o, "u_ref_t", SurfaceBlock, ref_t);
  EXPECT_MEMBER(o, "u_ref_b", SurfaceBlock, ref_b);
  EXPECT_MEMBER(o, "u_window", SurfaceBlock, window);
  EXPECT_MEMBER(o, "u_albedo", SurfaceBlock, albedo);
  EXPECT_MEMBER(o, "u_albedo_scale", SurfaceBlock, albedo_scale);
  EXPECT_MEMBER(o, "u_intensity", SurfaceBlock, intensity);
  EXPECT_MEMBER(o, "u_modulation", SurfaceBlock, modulation);
  EXPECT_GABOR_BLOCK(o, "u_gabor", SurfaceBlock, gabor);
  EXPECT_MEMBER(o, "u_body_spheres", SurfaceBlock, body_spheres);
  EXPECT_MEMBER(o, "u_body_count", SurfaceBlock, body_count);
  EXPECT_MEMBER(o, "u_sheet", SurfaceBlock, sheet);
  EXPECT_MEMBER(o, "u_cutaway", SurfaceBlock, cutaway);
  EXPECT_MEMBER(o, "u_probe_a", SurfaceBlock, probe_a);
  EXPECT_MEMBER(o, "u_probe_b", SurfaceBlock, probe_b);
  EXPECT_MEMBER(o, "u_eye", SurfaceBlock, eye);
  EXPECT_MEMBER(o, "u_cast_sphere", SurfaceBlock, cast_sphere);
  EXPECT_MEMBER(o, "u_feedback", SurfaceBlock, feedback);
}

// The bodies' casters are read in every variant, also with the probe's shadow compiled out
// (a body casts its pseudo-shadow when the probe is out of reach), and the array's std140
// stride is one vec4, as in C++.
TEST(UniformLayoutTest, BodyCastersMatchInEveryVariant) {
  for (const gl::Defines& variant : {gl::Defines{{"PS_SHADOW", "0"}, {"PS_TEXTURED", "0"}},
                                     gl::Defines{{"PS_SHADOW", "1"}, {"PS_TEXTURED", "0"}},
                                     gl::Defines{{"PS_SHADOW", "1"}, {"PS_TEXTURED", "1"}}}) {
    const auto o = block_offsets("surface.frag", EShLangFragment, variant);
    ASSERT_FALSE(o.empty());
    EXPECT_MEMBER(o, "u_body_spheres", SurfaceBlock, body_spheres);
    EXPECT_MEMBER(o, "u_body_count", SurfaceBlock, body_count);
  }
  static_assert(sizeof(SurfaceBlock::body_spheres) == kMaxSceneBodies * 16, "one vec4 per body");
}

// The Gabor parameters' one contract (lib/gabor_block.glsl) as each pass that reads it sees it:
// the surface pass (every variant that evaluates the texture) and the bake pass.
TEST(UniformLayoutTest, GaborBlockMatchesInEveryPassThatReadsIt) {
  const auto bake = block_offsets("gabor_bake.frag", EShLangFragment);
  ASSERT_FALSE(bake.empty());
  EXPECT_GABOR_BLOCK(bake, "u_gabor", GaborBakeBlock, gabor);
  EXPECT_MEMBER(bake, "u_level", GaborBakeBlock, level);
  for (const gl::Defines& variant : {gl::Defines{}, gl::Defines{{"PS_GABOR_STRATIFIED", "1"}},
                                     gl::Defines{{"PS_GABOR_BAKED", "1"}}, gl::Defines{{"PS_GABOR_BAKED", "2"}},
                                     gl::Defines{{"PS_GABOR_FILTER", "1"}},
                                     gl::Defines{{"PS_GABOR_FILTER", "1"}, {"PS_GABOR_BAKED", "1"}},
                                     gl::Defines{{"PS_GABOR_FILTER", "1"}, {"PS_GABOR_BAKED", "2"}}}) {
    const auto surface = block_offsets("surface.frag", EShLangFragment, variant);
    ASSERT_FALSE(surface.empty());
    EXPECT_GABOR_BLOCK(surface, "u_gabor", SurfaceBlock, gabor);
  }
}

// The intensity_lut variant (lib/intensity_lut.glsl) compiles, shadowed and not (the bodies'
// shadows read the table too), its table's block matches IntensityLutBlock, and the surface
// block is as it was.
TEST(UniformLayoutTest, IntensityLutBlockMatchesAndKeepsTheSurfaceBlock) {
  for (const char* shadow : {"0", "1"}) {
    const auto o = block_offsets("surface.frag", EShLangFragment, {{"PS_INTENSITY_LUT", "1"}, {"PS_SHADOW", shadow}});
    ASSERT_FALSE(o.empty()) << "PS_SHADOW " << shadow;
    EXPECT_MEMBER(o, "u_lut_rows", IntensityLutBlock, rows);
    EXPECT_MEMBER(o, "u_lut_count", IntensityLutBlock, count);
    EXPECT_MEMBER(o, "u_intensity", SurfaceBlock, intensity);
    EXPECT_MEMBER(o, "u_eye", SurfaceBlock, eye);
  }
}

TEST(UniformLayoutTest, ProbeViewBlockMatches) {
  const auto o = block_offsets("probe_view.frag", EShLangFragment);
  ASSERT_FALSE(o.empty());
  EXPECT_MEMBER(o, "u_view_proj", ProbeViewBlock, view_proj);
  EXPECT_MEMBER(o, "u_model", ProbeViewBlock, model);
  EXPECT_MEMBER(o, "u_light_dir", ProbeViewBlock, light_dir);
  EXPECT_MEMBER(o, "u_light_color", ProbeViewBlock, light_color);
  EXPECT_MEMBER(o, "u_probe_color", ProbeViewBlock, probe_color);
}

TEST(UniformLayoutTest, ProbeDepthBlockMatches) {
  const auto o = block_offsets("probe_depth_analytic.frag", EShLangFragment);
  ASSERT_FALSE(o.empty());
  EXPECT_MEMBER(o, "u_model", ProbeDepthBlock, model);
  EXPECT_MEMBER(o, "u_ref_n", ProbeDepthBlock, ref_n);
  EXPECT_MEMBER(o, "u_ref_t", ProbeDepthBlock, ref_t);
  EXPECT_MEMBER(o, "u_ref_b", ProbeDepthBlock, ref_b);
  EXPECT_MEMBER(o, "u_window", ProbeDepthBlock, window);
  EXPECT_MEMBER(o, "u_cap_a", ProbeDepthBlock, cap_a);
  EXPECT_MEMBER(o, "u_cap_b", ProbeDepthBlock, cap_b);
  EXPECT_MEMBER(o, "u_height_range", ProbeDepthBlock, height_range);
}

TEST(UniformLayoutTest, ReduceBlockMatches) {
  const auto o = block_offsets("max_penetration.comp", EShLangCompute);
  ASSERT_FALSE(o.empty());
  EXPECT_MEMBER(o, "u_size", ReduceBlock, size);
  EXPECT_MEMBER(o, "u_params", ReduceBlock, params);
  EXPECT_MEMBER(o, "u_rect", ReduceBlock, rect);
  EXPECT_MEMBER(o, "max_penetration_bits", MaxBlock, max_penetration_bits);
  EXPECT_MEMBER(o, "max_resisted_penetration_bits", MaxBlock, max_resisted_penetration_bits);
  EXPECT_MEMBER(o, "penetrating_fragments", MaxBlock, penetrating_fragments);
  EXPECT_MEMBER(o, "covered_fragments", MaxBlock, covered_fragments);
  EXPECT_MEMBER(o, "penetrating_box", MaxBlock, penetrating_box);
  EXPECT_MEMBER(o, "max_filter_need_bits", MaxBlock, max_filter_need_bits);
}

}  // namespace
}  // namespace ps
