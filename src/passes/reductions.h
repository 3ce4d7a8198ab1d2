// Reductions (thesis Table 4.2 steps 4-5) over the surface pass's targets:
//   - reference normal: mean of the visible normals (xyz / w of the normal target's sum, by rows);
//   - exact maximum penetration (compute, glsl/max_penetration.comp): max of -d, and of
//     resistance * -d, over every pseudo-shadow fragment;
//   - both compute passes read only the surface pass's shadow_rect(): outside it every pixel
//     is (0, NaN, 0, 0) and adds exactly nothing (a zero term leaves a float sum's bits as they
//     are), so the results are those of the whole image, bit for bit;
//   - weighted-average displacement (thesis §4.5.4, compute, glsl/displacement_rows.comp): per
//     image row (sum w * disp, sum w), added here in double: sum(w * disp) / sum(w);
//   - the `displacement` AOV, on request (displacement_aov): the same per-pixel (w * disp, w)
//     drawn by glsl/displacement_weights.{vert,frag} into a texture made for the occasion.
// The normal target's rows are summed with Kahan's compensation and added in double: within a
// float rounding of the exact mean, as the power-of-two mip chain it replaced was.
// Two paths run the same per-row arithmetic (glsl/lib/reduce_rows.glsl) and give the same bits:
// compute shaders with atomics and storage buffers (the default), and fragment shaders that write
// one texel per row into one-texel-wide targets, reduced on the host (what WebGL2 can run: no
// compute, no storage buffers, no atomics). ReductionPathsGLTest compares the two.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "gl/objects.h"
#include "passes/surface.h"

namespace ps {

// std140 mirror of ReduceBlock in glsl/lib/reduce_block.glsl.
struct ReduceBlock {
  glm::ivec4 size;    // image w, h; padded w, h
  glm::vec4 params;   // x: weight exponent c; y: 1 = row sums over the penetrating box only
  glm::ivec4 rect;    // x0, y0, x1, y1: the surface pass's shadow_rect(), the pixels reduced
};
static_assert(sizeof(ReduceBlock) == 48, "ReduceBlock must match std140 layout");

// std430 mirror of MaxBlock.
struct MaxBlock {
  std::uint32_t max_penetration_bits = 0;
  std::uint32_t max_resisted_penetration_bits = 0;
  std::uint32_t penetrating_fragments = 0;
  std::uint32_t covered_fragments = 0;
  glm::ivec4 penetrating_box{1 << 30, 1 << 30, -1, -1};  // inclusive; empty as initialised
  std::uint32_t max_filter_need_bits = 0;
};
static_assert(sizeof(MaxBlock) == 36, "MaxBlock must match std430 layout");

struct ReductionResult {
  glm::dvec3 normal_sum{0.0};     // mean normal * coverage (not normalised)
  double normal_coverage = 0.0;   // fraction of the padded target covered by surfaces
  glm::dvec3 weighted_displacement{0.0};  // average(w * disp) / average(w), mm
  double max_penetration_mm = 0.0;
  double max_resisted_penetration_mm = 0.0;
  std::uint32_t penetrating_fragments = 0;
  std::uint32_t covered_fragments = 0;
  glm::ivec4 penetrating_box{1 << 30, 1 << 30, -1, -1};  // inclusive; empty as initialised
  // The largest gabor_filter_need over the shadow's covered pixels (0: no filtered texture
  // was evaluated): SurfacePass::filter_need() reduced.
  double max_filter_need = 0.0;
};

// How the rows are computed (both give the same bits).
enum class ReductionMethod {
  kCompute,   // glsl/*.comp: one invocation per row, atomics into a storage buffer
  kFragment,  // glsl/*_rows.frag: one fragment per row into a one-texel-wide target, read back
};

struct ReductionsPass {
  struct Params {
    double weight_exponent = 20.0;  // c
    bool weighted = true;           // false: no weighted displacement (exact-max frames)
    // Sum the rows over the box of penetrating pixels only (the same bits: the other terms are
    // zero). false: whole rows of the shadow rectangle, the reference the tests compare with.
    bool penetrating_box = true;
  };

  Status init(const std::string& glsl_root, const SurfacePass& surface,
              ReductionMethod method = ReductionMethod::kCompute);
  ReductionMethod method() const { return method_; }
  // The mean visible normal: the normal target's image region summed by rows on the GPU
  // (glsl/normal_rows.comp), the rows in double here. Fills normal_sum and normal_coverage only.
  ReductionResult mean_normal(const SurfacePass& surface);
  // The pseudo-shadow's reductions over surface.shadow_rect(): maximum penetration, weighted
  // displacement, fragment counts (normal_sum and normal_coverage stay zero).
  ReductionResult run(const SurfacePass& surface, const Params& params);
  // (w * disp, w) per pixel of the last run() with shadow (RGBA32F, the surface's padded size,
  // zero outside the shadow), drawn now; the surface pass's targets must still hold that frame.
  Result<gl::Texture> displacement_aov(const SurfacePass& surface) const;

 private:
  // Grows rows_ssbo_ (compute) or the row targets (fragment) to `rows` rows at least.
  void reserve_rows(int rows);
  // Rows first .. first + count - 1 of rows_ssbo_ (compute) or of row target 0 (fragment), as
  // the last pass wrote them, added in double.
  glm::dvec4 sum_rows(int first, int count) const;
  // The fragment path: `program` drawn into `fbo` over rows first .. first + count - 1 of the
  // row targets (one fragment per row), and rows of row_tex_[target] read back.
  void draw_rows(const gl::Program& program, const gl::Framebuffer& fbo, int first, int count) const;
  std::vector<glm::vec4> read_rows(int target, int first, int count) const;
  // The fragment path of run(): the rows of max_penetration_rows.frag reduced to the block the
  // compute path's atomics give, then displacement_rows.frag.
  MaxBlock run_fragment_max(const PixelRect& rect);

  ReductionMethod method_ = ReductionMethod::kCompute;
  gl::Program max_, rows_, weights_, normal_rows_;
  gl::VertexArray empty_vao_;  // core profile draws need a bound VAO
  // rows_ssbo_: one vec4 per image row, written and read back within one call (run()'s
  // displacement rows, mean_normal()'s normal rows).
  gl::Buffer ubo_, ssbo_, rows_ssbo_;
  int rows_capacity_ = 0;
  float last_max_penetration_ = 0.0f;  // the last run()'s, for displacement_aov
  gl::Buffer normal_ubo_;  // mean_normal's block (ubo_ keeps run()'s for displacement_aov)
  // The fragment path: its programs, and one-texel-wide RGBA32F row targets (rows_capacity_
  // high): max_rows_fbo_ draws (max, span) into row_tex_[0], row_tex_[1]; sums_fbo_ draws the
  // displacement or normal rows into row_tex_[0].
  gl::Program max_rows_frag_, rows_frag_, normal_rows_frag_;
  gl::Texture row_tex_[2];
  gl::Framebuffer max_rows_fbo_, sums_fbo_;
};


}  // namespace ps
