#include "passes/probe_depth.h"

#include <cassert>

#include "gl/shader.h"

namespace ps {

namespace {
constexpr float kFar = 1.0e30f;  // "no probe" height, must match kFar in the shaders
glm::vec4 v4(const glm::dvec3& v, double w = 0.0) { return glm::vec4(glm::dvec4(v, w)); }
}  // namespace

Status ProbeDepthPass::init(const std::string& glsl_root, const Params& params) {
  params_ = params;
  auto analytic = gl::build_program({{"probe_depth_analytic.vert", "probe_depth_analytic.frag"}, {}}, glsl_root);
  if (!analytic) return analytic.error();
  auto sphere = gl::build_program({{"probe_depth_analytic.vert", "probe_depth_analytic.frag"}, {{"PS_PROBE_SPHERE", "1"}}},
                                  glsl_root);
  if (!sphere) return sphere.error();
  auto mesh = gl::build_program({{"probe_depth_mesh.vert", "probe_depth_mesh.frag"}, {}}, glsl_root);
  if (!mesh) return mesh.error();
  analytic_ = std::move(analytic.value());
  sphere_ = std::move(sphere.value());
  mesh_ = std::move(mesh.value());
  depth_ = gl::make_texture_2d(params.size, params.size, GL_R32F);
  glTextureParameteri(depth_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(depth_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  depth_buffer_ = gl::make_renderbuffer(GL_DEPTH_COMPONENT32F, params.size, params.size);
  fbo_ = gl::make_framebuffer();
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, depth_.id(), 0);
  glNamedFramebufferRenderbuffer(fbo_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_buffer_.id());
  if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return make_error("probe depth pass: framebuffer incomplete (R32F + D32F)");
  ubo_ = gl::make_buffer(sizeof(ProbeDepthBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  empty_vao_ = gl::make_vertex_array();
  return ok_status();
}

// Whole (43 lines): the block, then every GL state the pass depends on, set at entry in the order
// the draw uses it (house rule 2); split, the state would be set in two places.
void ProbeDepthPass::run(const Inputs& in) {
  assert(in.frame && "ProbeDepthPass::run: a reference frame is required");
  const PlaneFrame& f = *in.frame;
  ProbeDepthBlock block;
  block.model = glm::mat4(in.probe.model);
  block.ref_n = v4(f.n);
  block.ref_t = v4(f.t);
  block.ref_b = v4(f.b);
  block.window = glm::vec4(glm::dvec4(in.window.center_uv, in.window.half_size_mm, params_.size));
  if (!in.probe.mesh) {
    const CapsuleShape& c = in.probe.capsule;
    block.cap_a = v4(to_plane(f, c.a), c.radius);
    block.cap_b = v4(to_plane(f, c.b));
  }
  block.height_range = glm::vec4(glm::dvec4(in.height_lo, in.height_hi, 0.0, 0.0));
  glNamedBufferSubData(ubo_.id(), 0, sizeof(block), &block);

  // All state this pass depends on is set here.
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, params_.size, params_.size);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDepthMask(GL_TRUE);
  const float far_height[4] = {kFar, 0.0f, 0.0f, 0.0f};
  const float one = 1.0f;
  glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, far_height);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, ubo_.id());
  if (!in.probe.mesh) {  // analytic: no depth test, so no depth clear
    glDisable(GL_DEPTH_TEST);
    // A capsule of length 0 is a sphere: its variant skips the cylinder and the second cap.
    const CapsuleShape& c = in.probe.capsule;
    glUseProgram(c.a == c.b ? sphere_.id() : analytic_.id());
    glBindVertexArray(empty_vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  } else {
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glUseProgram(mesh_.id());
    in.probe.mesh->draw();
  }
}

}  // namespace ps
