#include "passes/reductions.h"

#include <bit>

#include "gl/shader.h"

namespace ps {

glm::dvec4 read_top_level(const gl::Texture& texture, int levels) {
  float px[4] = {0, 0, 0, 0};
  glGetTextureImage(texture.id(), levels - 1, GL_RGBA, GL_FLOAT, sizeof(px), px);
  return {px[0], px[1], px[2], px[3]};
}

Status ReductionsPass::init(const std::string& glsl_root, const SurfacePass& surface) {
  auto max = gl::build_program({{"max_penetration.comp"}, {}}, glsl_root);
  if (!max) return max.error();
  auto weights = gl::build_program({{"displacement_weights.vert", "displacement_weights.frag"}, {}}, glsl_root);
  if (!weights) return weights.error();
  max_ = std::move(max.value());
  weights_ = std::move(weights.value());
  const glm::ivec2 p = surface.padded_size();
  displacement_ = gl::make_texture_2d(p.x, p.y, GL_RGBA32F, surface.mip_levels());
  displacement_fbo_ = gl::make_framebuffer();
  glNamedFramebufferTexture(displacement_fbo_.id(), GL_COLOR_ATTACHMENT0, displacement_.id(), 0);
  if (glCheckNamedFramebufferStatus(displacement_fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return make_error("reductions: displacement framebuffer incomplete (RGBA32F)");
  empty_vao_ = gl::make_vertex_array();
  ubo_ = gl::make_buffer(sizeof(ReduceBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  ssbo_ = gl::make_buffer(sizeof(MaxBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  return ok_status();
}

ReductionResult ReductionsPass::run(const SurfacePass& surface, const Params& params, bool shadow) {
  ReductionResult r;
  const int levels = surface.mip_levels();
  glGenerateTextureMipmap(surface.normal().id());
  const glm::dvec4 n = read_top_level(surface.normal(), levels);
  r.normal_sum = glm::dvec3(n);
  r.normal_coverage = n.w;
  if (!shadow) return r;

  const glm::ivec2 p = surface.padded_size();
  const ReduceBlock block{{surface.width(), surface.height(), p.x, p.y},
                          {static_cast<float>(params.weight_exponent), 0, 0, 0}};
  glNamedBufferSubData(ubo_.id(), 0, sizeof(block), &block);
  const MaxBlock zero{};
  glNamedBufferSubData(ssbo_.id(), 0, sizeof(zero), &zero);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, ubo_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, ssbo_.id());
  glBindTextureUnit(0, surface.aov().id());
  glBindTextureUnit(1, surface.normal().id());

  glUseProgram(max_.id());
  glDispatchCompute(static_cast<GLuint>((surface.height() + 63) / 64), 1, 1);  // one invocation per row
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

  glBindFramebuffer(GL_FRAMEBUFFER, displacement_fbo_.id());
  glViewport(0, 0, p.x, p.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glUseProgram(weights_.id());
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glGenerateTextureMipmap(displacement_.id());

  const glm::dvec4 d = read_top_level(displacement_, levels);
  if (d.w > 0.0) r.weighted_displacement = glm::dvec3(d) / d.w;
  MaxBlock m;
  glGetNamedBufferSubData(ssbo_.id(), 0, sizeof(m), &m);
  r.max_penetration_mm = std::bit_cast<float>(m.max_penetration_bits);
  r.max_resisted_penetration_mm = std::bit_cast<float>(m.max_resisted_penetration_bits);
  r.penetrating_fragments = m.penetrating_fragments;
  r.covered_fragments = m.covered_fragments;
  return r;
}

}  // namespace ps
