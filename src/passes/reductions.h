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
#pragma once

#include <cstdint>
#include <string>

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

struct ReductionsPass {
  struct Params {
    double weight_exponent = 20.0;  // c
    bool weighted = true;           // false: no weighted displacement (exact-max frames)
    // Sum the rows over the box of penetrating pixels only (the same bits: the other terms are
    // zero). false: whole rows of the shadow rectangle, the reference the tests compare with.
    bool penetrating_box = true;
  };

  Status init(const std::string& glsl_root, const SurfacePass& surface);
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
  // Grows rows_ssbo_ to `rows` vec4s at least.
  void reserve_rows(int rows);
  // Rows first .. first + count - 1 of rows_ssbo_, as a compute pass wrote them, added in double.
  glm::dvec4 sum_rows(int first, int count) const;

  gl::Program max_, rows_, weights_, normal_rows_;
  gl::VertexArray empty_vao_;  // core profile draws need a bound VAO
  // rows_ssbo_: one vec4 per image row, written and read back within one call (run()'s
  // displacement rows, mean_normal()'s normal rows).
  gl::Buffer ubo_, ssbo_, rows_ssbo_;
  int rows_capacity_ = 0;
  gl::Buffer normal_ubo_;  // mean_normal's block (ubo_ keeps run()'s for displacement_aov)
};


}  // namespace ps
