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
  auto weights = gl::build_program({{"displacement_weights.comp"}, {}}, glsl_root);
  if (!weights) return weights.error();
  max_ = std::move(max.value());
  weights_ = std::move(weights.value());
  const glm::ivec2 p = surface.padded_size();
  displacement_ = gl::make_texture_2d(p.x, p.y, GL_RGBA32F, surface.mip_levels());
  ubo_ = gl::make_buffer(sizeof(ReduceBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  ssbo_ = gl::make_buffer(sizeof(MaxBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  return ok_status();
}

namespace {
GLuint groups(int n) { return static_cast<GLuint>((n + 15) / 16); }
}  // namespace

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
  glDispatchCompute(groups(surface.width()), groups(surface.height()), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(weights_.id());
  glBindImageTexture(0, displacement_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glDispatchCompute(groups(p.x), groups(p.y), 1);
  glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_BUFFER_UPDATE_BARRIER_BIT);
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
