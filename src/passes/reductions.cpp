#include "passes/reductions.h"

#include <algorithm>
#include <cstring>
#include <utility>
#include <vector>

#include "gl/es30.h"
#include "gl/shader.h"

namespace ps {
namespace {

// std::bit_cast, which the libc++ of Debian's Emscripten (LLVM 14) lacks: the page builds this file.
template <class To, class From>
To bit_cast(const From& from) {
  static_assert(sizeof(To) == sizeof(From));
  To to;
  std::memcpy(&to, &from, sizeof to);
  return to;
}

}  // namespace

Status ReductionsPass::init(const std::string& glsl_root, const SurfacePass& surface, ReductionMethod method) {
  // ES 3.0 (WebGL2) has no compute shaders (gl/es30.h): the fragment path, the compute one's bits.
  method_ = gl::dialect() == gl::Dialect::kEs30 ? ReductionMethod::kFragment : method;
  // Each path builds only its own programs (a WebGL2 host has no compute shaders to build); the
  // displacement AOV's is common to both.
  const char* vert = "displacement_weights.vert";
  std::vector<std::pair<gl::Program*, gl::ProgramDesc>> programs = {{&weights_, {{vert, "displacement_weights.frag"}, {}}}};
  if (method_ == ReductionMethod::kFragment)
    programs.insert(programs.end(), {{&max_rows_frag_, {{vert, "max_penetration_rows.frag"}, {}}},
                                     {&rows_frag_, {{vert, "displacement_rows.frag"}, {}}},
                                     {&normal_rows_frag_, {{vert, "normal_rows.frag"}, {}}}});
  else
    programs.insert(programs.end(), {{&max_, {{"max_penetration.comp"}, {}}},
                                     {&rows_, {{"displacement_rows.comp"}, {}}},
                                     {&normal_rows_, {{"normal_rows.comp"}, {}}}});
  for (const auto& [program, desc] : programs) {
    auto built = gl::build_program(desc, glsl_root);
    if (!built) return built.error();
    *program = std::move(built.value());
  }
  normal_ubo_ = gl::make_buffer(sizeof(ReduceBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  empty_vao_ = gl::make_vertex_array();
  ubo_ = gl::make_buffer(sizeof(ReduceBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  ssbo_ = gl::make_buffer(sizeof(MaxBlock), nullptr, GL_DYNAMIC_STORAGE_BIT);
  reserve_rows(std::max(surface.height(), 1));
  return ok_status();
}

void ReductionsPass::reserve_rows(int rows) {
  if (rows <= rows_capacity_) return;
  rows_capacity_ = rows;
  if (method_ == ReductionMethod::kCompute) {
    rows_ssbo_ = gl::make_buffer(static_cast<GLsizeiptr>(rows) * sizeof(glm::vec4), nullptr, GL_DYNAMIC_STORAGE_BIT);
    return;
  }
  for (gl::Texture& t : row_tex_) t = gl::make_texture_2d(1, rows, GL_RGBA32F);
  max_rows_fbo_ = gl::make_framebuffer();
  glNamedFramebufferTexture(max_rows_fbo_.id(), GL_COLOR_ATTACHMENT0, row_tex_[0].id(), 0);
  glNamedFramebufferTexture(max_rows_fbo_.id(), GL_COLOR_ATTACHMENT1, row_tex_[1].id(), 0);
  const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(max_rows_fbo_.id(), 2, both);
  sums_fbo_ = gl::make_framebuffer();
  glNamedFramebufferTexture(sums_fbo_.id(), GL_COLOR_ATTACHMENT0, row_tex_[0].id(), 0);
}

void ReductionsPass::draw_rows(const gl::Program& program, const gl::Framebuffer& fbo, int first, int count) const {
  if (count <= 0) return;
  // The scissor keeps the fragments to the rows asked for (one column: one fragment per row).
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glViewport(0, 0, 1, rows_capacity_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, first, 1, count);
  glUseProgram(program.id());
  glBindVertexArray(empty_vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<glm::vec4> ReductionsPass::read_rows(int target, int first, int count) const {
  std::vector<glm::vec4> rows(static_cast<size_t>(std::max(count, 0)));
  if (!rows.empty())
    glGetTextureSubImage(row_tex_[target].id(), 0, 0, first, 0, 1, count, 1, GL_RGBA, GL_FLOAT,
                         static_cast<GLsizei>(rows.size() * sizeof(glm::vec4)), rows.data());
  return rows;
}

glm::dvec4 ReductionsPass::sum_rows(int first, int count) const {
  std::vector<glm::vec4> rows(static_cast<size_t>(std::max(count, 0)));
  if (method_ == ReductionMethod::kFragment)
    rows = read_rows(0, first, count);
  else if (!rows.empty())
    glGetNamedBufferSubData(rows_ssbo_.id(), static_cast<GLintptr>(first) * sizeof(glm::vec4),
                            static_cast<GLsizeiptr>(rows.size() * sizeof(glm::vec4)), rows.data());
  glm::dvec4 sum(0.0);
  for (const glm::vec4& row : rows) sum += glm::dvec4(row);
  return sum;
}

// Row sums on the GPU (glsl/normal_rows.comp), added here in double; divided by the padded
// target's texel count, as the mip chain's top level was (normal_coverage: the fraction of the
// padded target covered).
ReductionResult ReductionsPass::mean_normal(const SurfacePass& surface) {
  ReductionResult r;
  const int h = surface.height();
  reserve_rows(h);
  const glm::ivec2 p = surface.padded_size();
  const ReduceBlock block{{surface.width(), h, p.x, p.y}, {}, {}};
  glNamedBufferSubData(normal_ubo_.id(), 0, sizeof(block), &block);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, normal_ubo_.id());
  glBindTextureUnit(1, surface.normal().id());
  if (method_ == ReductionMethod::kFragment) {
    draw_rows(normal_rows_frag_, sums_fbo_, 0, h);
  } else {  // storage buffers: compute path only (ES 3.0 has none)
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, rows_ssbo_.id());
    glUseProgram(normal_rows_.id());
    glDispatchCompute(static_cast<GLuint>((h + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  }
  const glm::dvec4 n = sum_rows(0, h) / (static_cast<double>(p.x) * static_cast<double>(p.y));
  r.normal_sum = glm::dvec3(n);
  r.normal_coverage = n.w;
  return r;
}

// Whole (47 lines): bind, dispatch, read back: one sequence of GL calls whose barriers must sit
// between the dispatches and the reads they order; split, that order would span functions.
ReductionResult ReductionsPass::run(const SurfacePass& surface, const Params& params) {
  ReductionResult r;
  const glm::ivec2 p = surface.padded_size();
  const PixelRect& rect = surface.shadow_rect();
  const ReduceBlock block{{surface.width(), surface.height(), p.x, p.y},
                          {static_cast<float>(params.weight_exponent), params.penetrating_box ? 1.0f : 0.0f, 0, 0},
                          {rect.x0, rect.y0, rect.x1, rect.y1}};
  glNamedBufferSubData(ubo_.id(), 0, sizeof(block), &block);
  const MaxBlock zero{};
  glNamedBufferSubData(ssbo_.id(), 0, sizeof(zero), &zero);
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, ubo_.id());
  if (method_ == ReductionMethod::kCompute) {  // storage buffers: compute path only (ES 3.0 has none)
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, ssbo_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, rows_ssbo_.id());
  }
  glBindTextureUnit(0, surface.aov().id());
  glBindTextureUnit(1, surface.normal().id());
  glBindTextureUnit(2, surface.filter_need().id());
  // One invocation per row of the rectangle (none when it is empty).
  const auto groups = static_cast<GLuint>((rect.height() + 63) / 64);

  MaxBlock m;
  if (method_ == ReductionMethod::kFragment) {
    m = run_fragment_max(rect);
    if (params.weighted && !rect.empty()) {
      const glm::ivec4 box = params.penetrating_box ? m.penetrating_box
                                                    : glm::ivec4(rect.x0, rect.y0, rect.x1 - 1, rect.y1 - 1);
      glProgramUniform1f(rows_frag_.id(), 0, bit_cast<float>(m.max_penetration_bits));
      glProgramUniform4i(rows_frag_.id(), 1, box.x, box.y, box.z, box.w);
      draw_rows(rows_frag_, sums_fbo_, rect.y0, rect.height());
    }
  } else if (groups > 0) {
    glUseProgram(max_.id());
    glDispatchCompute(groups, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    if (params.weighted) {
      glUseProgram(rows_.id());
      glDispatchCompute(groups, 1, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    }
  }

  // Rows y0 .. y1 - 1 of the row sums (the others were not written this frame).
  const glm::dvec4 d = params.weighted ? sum_rows(rect.y0, std::min(rect.y1, rows_capacity_) - rect.y0) : glm::dvec4(0.0);
  if (d.w > 0.0) r.weighted_displacement = glm::dvec3(d) / d.w;
  if (method_ == ReductionMethod::kCompute) glGetNamedBufferSubData(ssbo_.id(), 0, sizeof(m), &m);
  last_max_penetration_ = bit_cast<float>(m.max_penetration_bits);
  r.max_penetration_mm = bit_cast<float>(m.max_penetration_bits);
  r.max_resisted_penetration_mm = bit_cast<float>(m.max_resisted_penetration_bits);
  r.penetrating_fragments = m.penetrating_fragments;
  r.covered_fragments = m.covered_fragments;
  r.max_filter_need = bit_cast<float>(m.max_filter_need_bits);
  return r;
}

// The rows of max_penetration_rows.frag reduced as the compute path's atomics reduce them: the
// maxima are float maxima (the atomics' uint order of non-negative floats is the float order),
// the counts sums, the box the columns' and rows' extremes over the rows with penetration.
MaxBlock ReductionsPass::run_fragment_max(const PixelRect& rect) {
  MaxBlock m;
  if (!rect.empty()) {
    draw_rows(max_rows_frag_, max_rows_fbo_, rect.y0, rect.height());
    const std::vector<glm::vec4> maxima = read_rows(0, rect.y0, rect.height());
    const std::vector<glm::vec4> spans = read_rows(1, rect.y0, rect.height());
    float pen = 0.0f, res = 0.0f, need = 0.0f;
    for (size_t i = 0; i < maxima.size(); ++i) {
      const glm::vec4& a = maxima[i];
      const glm::vec4& b = spans[i];
      if (a.w == 0.0f) continue;  // no covered pixel in the row
      m.covered_fragments += static_cast<std::uint32_t>(a.w);
      need = std::max(need, a.z);
      if (b.x == 0.0f) continue;  // no penetrating pixel
      const int y = rect.y0 + static_cast<int>(i);
      m.penetrating_fragments += static_cast<std::uint32_t>(b.x);
      pen = std::max(pen, a.x);
      res = std::max(res, a.y);
      m.penetrating_box = {std::min(m.penetrating_box.x, static_cast<int>(b.y)), std::min(m.penetrating_box.y, y),
                           std::max(m.penetrating_box.z, static_cast<int>(b.z)), std::max(m.penetrating_box.w, y)};
    }
    m.max_penetration_bits = bit_cast<std::uint32_t>(pen);
    m.max_resisted_penetration_bits = bit_cast<std::uint32_t>(res);
    m.max_filter_need_bits = bit_cast<std::uint32_t>(need);
  }
  return m;
}

Result<gl::Texture> ReductionsPass::displacement_aov(const SurfacePass& surface) const {
  const glm::ivec2 p = surface.padded_size();
  gl::Texture tex = gl::make_texture_2d(p.x, p.y, GL_RGBA32F);
  gl::Framebuffer fbo = gl::make_framebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, tex.id(), 0);
  if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    return make_error("reductions: displacement AOV framebuffer incomplete (RGBA32F)");
  // ubo_ still holds the last run()'s size and exponent; its maximum is kept here.
  glBindBufferBase(GL_UNIFORM_BUFFER, 0, ubo_.id());
  glProgramUniform1f(weights_.id(), 0, last_max_penetration_);
  glBindTextureUnit(0, surface.aov().id());
  glBindTextureUnit(1, surface.normal().id());
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glViewport(0, 0, p.x, p.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  const float clear[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, clear);
  // Only the shadow's rectangle: the surface pass wrote its AOV there only (elsewhere the
  // weights are zero, as cleared).
  const PixelRect& rect = surface.shadow_rect();
  if (!rect.empty()) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x0, rect.y0, rect.width(), rect.height());
    glUseProgram(weights_.id());
    glBindVertexArray(empty_vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_SCISSOR_TEST);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return tex;
}

}  // namespace ps
