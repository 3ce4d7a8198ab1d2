// The renderer on OpenGL ES 3.0, the API a WebGL2 page has (gl/es30.h): the same frames drawn in
// Mesa's ES 3.0 context (EGL surfaceless) and in the 4.5 core context (twelve frames of four
// scenes, the default one also with its Gabor tile baked), compared output by output.
// On ES the host code's direct-state-access calls run through their bind-to-edit stand-ins, the
// shaders are their GLSL ES 3.00 text (gl/shader_es.h) and the reductions take the fragment path;
// on 4.5 nothing of that runs, except the fragment reductions, asked for there (on ES the pass
// takes them by itself) so that the one difference left is the API.
//
// Tolerances, and why they are not all zero: GLSL ES 3.00 has no `precise`, so the row sums of
// the reference plane's normal may be contracted differently (docs/gl-stack.md, "GLSL ES 3.00");
// the plane then moves by about 1e-8 (measured), and every value drawn along it (the AOVs'
// distances and the displacement) by as little. Bounds: the plane 1e-6, AOVs 2e-4 relative (a
// distance sampled one texel over in the probe's depth map moves by that much on the curved
// torus), displacement 1e-6 mm. The colour is 8-bit and must be the same bytes: a plane moved by
// 1e-8 changes no byte, and a wrong binding, a lost attachment or a wrong uniform changes many.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gl/context.h"
#include "gl/es30.h"
#include "render/aov.h"
#include "render/renderer.h"
#include "support/scenes.h"
#include "support/shipped.h"

namespace ps {
namespace {

using test::shipped;

struct Case {
  std::string name;
  Scene scene;
  std::vector<glm::dvec3> probe_path;  // one position per frame
  int expected_frames = 3;             // 3: the per-pixel texture; 0: the Gabor tile baked
};

std::vector<Case> cases() {
  std::vector<Case> c;
  {
    Scene s = shipped("default", 160, 128);  // textured, weighted-average displacement
    const glm::dvec3 p = s.probe.position;
    c.push_back({"default", s, {p, p + glm::dvec3(20, 0, 0), p + glm::dvec3(10, 0, -0.5)}});
    c.push_back({"default_tile", s, {p, p + glm::dvec3(-15, 5, -0.2)}, 0});  // RGBA32F tile, filtered
  }
  {
    Scene s = shipped("torus_capsule", 160, 120);  // capsule probe, curved surface
    const glm::dvec3 p = s.probe.position;
    c.push_back({"torus_capsule", s, {p, p + glm::dvec3(25, 8, 0), p + glm::dvec3(5, 0, -0.3)}});
  }
  {
    Scene s = shipped("materials_demo", 160, 120);  // several surfaces, textures and materials
    const glm::dvec3 p = s.probe.position;
    c.push_back({"materials_demo", s, {p, p + glm::dvec3(-30, 10, 0)}});
  }
  {
    Scene s = shipped("table5_1_monkey_head", 160, 120);  // a mesh (vertex arrays) in perspective
    const glm::dvec3 p = s.probe.position;
    c.push_back({"monkey_head", s, {p, p + glm::dvec3(12, 0, 3)}});
  }
  return c;
}

struct FrameOut {
  std::vector<float> color;
  std::map<std::string, Image> aovs;
  FrameStats stats;
  glm::dvec3 plane_n{0.0};
  GLenum error = GL_NO_ERROR;
  int webgl_buffer_conflicts = 0;  // ES: bindings WebGL2 would refuse (gl/es30.h)
};

// Every frame of every case on a fresh context of the kind `desc` asks for. One context at a
// time: both are on the same EGL display, which a context's destruction terminates.
std::vector<FrameOut> render_all(const gl::ContextDesc& desc, std::string& version) {
  std::vector<FrameOut> out;
  auto context = gl::create_context(desc);
  EXPECT_TRUE(context.ok()) << (context.ok() ? "" : context.error().message);
  if (!context.ok()) return out;
  version = context.value()->version();
  for (const Case& c : cases()) {
    RendererOptions options;
    options.expected_frames = c.expected_frames;
    // Asked for on 4.5; on ES the default (compute) must be turned into it by the pass itself.
    if (!desc.es) options.reductions = ReductionMethod::kFragment;
    auto r = Renderer::create(c.scene, options);
    EXPECT_TRUE(r.ok()) << c.name << ": " << (r.ok() ? "" : r.error().message);
    if (!r.ok()) return out;
    for (const glm::dvec3& p : c.probe_path) {
      const auto rendered = r.value()->render(probe_frame_input(p, c.scene.probe.velocity));
      EXPECT_TRUE(rendered.ok()) << c.name << " on " << version << ": " << (rendered.ok() ? "" : rendered.error().message);
      FrameOut f;
      f.color = r.value()->read_color().pixels;
      for (const std::string& name : aov_names()) {
        auto aov = r.value()->read_aov(name);
        EXPECT_TRUE(aov.ok()) << c.name << " " << name;
        if (aov.ok()) f.aovs[name] = std::move(aov.value());
      }
      f.stats = r.value()->stats();
      f.plane_n = r.value()->reference().n;
      f.error = glGetError();
      f.webgl_buffer_conflicts = gl::es30_webgl_buffer_conflicts();
      out.push_back(std::move(f));
    }
  }
  return out;
}

// The largest |a - b| / max(1, |a|) over two images; NaN only where both are NaN (else infinity).
double max_relative_difference(const Image& a, const Image& b) {
  if (a.pixels.size() != b.pixels.size()) return INFINITY;
  double worst = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const double x = a.pixels[i], y = b.pixels[i];
    if (std::isnan(x) || std::isnan(y)) {
      if (!(std::isnan(x) && std::isnan(y))) return INFINITY;
      continue;
    }
    worst = std::max(worst, std::abs(x - y) / std::max(1.0, std::abs(x)));
  }
  return worst;
}

TEST(EsRendererGLTest, Es30DrawsTheCoreContextsFramesWithTheFragmentReductions) {
  gl::ContextDesc core_desc, es_desc;
  core_desc.backend = es_desc.backend = gl::Backend::kEgl;
  es_desc.es = true;
  std::string core_version, es_version;
  const std::vector<FrameOut> core = render_all(core_desc, core_version);
  const std::vector<FrameOut> es = render_all(es_desc, es_version);
  ASSERT_EQ(core.size(), 12u);
  ASSERT_EQ(es.size(), core.size()) << es_version;
  EXPECT_EQ(es_version.rfind("OpenGL ES", 0), 0u) << es_version;

  double worst_plane = 0, worst_aov = 0, worst_displacement = 0;
  int same_plane = 0, shadowed = 0, penetrating = 0;
  for (size_t i = 0; i < core.size(); ++i) {
    const FrameOut &a = core[i], &b = es[i];
    const std::string where = "frame " + std::to_string(i);
    EXPECT_EQ(b.error, static_cast<GLenum>(GL_NO_ERROR)) << where << ": a GL error on ES";
    EXPECT_EQ(a.error, static_cast<GLenum>(GL_NO_ERROR)) << where;
    EXPECT_EQ(b.webgl_buffer_conflicts, 0) << where << ": a buffer bound as WebGL2 would refuse";
    EXPECT_TRUE(a.color == b.color) << where << ": the colour bytes differ";
    const double plane = glm::length(a.plane_n - b.plane_n);
    worst_plane = std::max(worst_plane, plane);
    same_plane += plane == 0.0;
    EXPECT_LE(plane, 1e-6) << where;
    for (const auto& [name, image] : a.aovs) {
      ASSERT_TRUE(b.aovs.count(name)) << where << " " << name;
      const double d = max_relative_difference(image, b.aovs.at(name));
      worst_aov = std::max(worst_aov, d);
      EXPECT_LE(d, 2e-4) << where << " AOV " << name;
    }
    const double displacement = glm::length(a.stats.displacement - b.stats.displacement);
    worst_displacement = std::max(worst_displacement, displacement);
    EXPECT_LE(displacement, 1e-6) << where;
    EXPECT_NEAR(a.stats.max_penetration_mm, b.stats.max_penetration_mm, 1e-6) << where;
    EXPECT_EQ(a.stats.shadow_pixels, b.stats.shadow_pixels) << where;
    EXPECT_EQ(a.stats.penetrating_pixels, b.stats.penetrating_pixels) << where;
    shadowed += a.stats.shadow_pixels > 0;
    penetrating += a.stats.penetrating_pixels > 0;
  }
  // The comparison saw shadows and penetration, not empty frames.
  EXPECT_GE(shadowed, 8);
  EXPECT_GE(penetrating, 2);
  std::printf("ES 3.0 (%s) vs 4.5 core: colour equal; plane <= %.3g (%d of %zu frames exact), AOVs <= %.3g "
              "relative, displacement <= %.3g mm\n",
              es_version.c_str(), worst_plane, same_plane, core.size(), worst_aov, worst_displacement);
}

// An ES context is EGL's only: asked of OSMesa it is refused with a message that says so.
TEST(EsRendererGLTest, AnEsContextOnOsmesaIsRefusedByName) {
  gl::ContextDesc desc;
  desc.backend = gl::Backend::kOsmesa;
  desc.es = true;
  auto context = gl::create_context(desc);
  ASSERT_FALSE(context.ok());
  EXPECT_NE(context.error().message.find("ES needs the EGL backend"), std::string::npos) << context.error().message;
}

}  // namespace
}  // namespace ps
