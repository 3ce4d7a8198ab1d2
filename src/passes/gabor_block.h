// std140 mirror of struct GaborBlock in glsl/lib/gabor_block.glsl: one material's Gabor texture
// as the surface pass (SurfaceBlock::gabor) and the Gabor bake pass (GaborBakeBlock) read it.
// make_gabor_block() is the only place the parameters are packed for the GPU.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "reference/gabor.h"
#include "scene/scene.h"

namespace ps {

struct GaborBlock {
  glm::vec4 amplitude_lambda;  // A_min, A_max, lambda_min mm, lambda_max mm
  glm::vec4 theta_density;     // theta_min rad, theta_max rad, n_min, n_max
  glm::vec4 kernel;            // kernel periods, cell mm, trunc factor, sigma_unit
  glm::vec4 tile;              // baked tile: period mm, texel mm, texels, period cells (0: none)
  glm::uvec4 counts;           // seed, max impulses per cell, stratified impulses per cell, tile levels (0: none)
  glm::vec4 filtering;         // pixel variance px^2, tile level sigma in its texels, footprint cap mm^2, most sub-boxes
};
static_assert(sizeof(GaborBlock) == 6 * 16, "GaborBlock must match std140 layout");


// `plan`: the material's baked tile (plan.ok == false: none, tile stays zero).
inline GaborBlock make_gabor_block(const GaborParams& g, const GaborSetup& s, const GaborBakePlan& plan,
                                   std::uint32_t seed) {
  GaborBlock b;
  b.amplitude_lambda = glm::vec4(glm::dvec4(g.a_min, g.a_max, g.lambda_min_mm, g.lambda_max_mm));
  b.theta_density = glm::vec4(glm::dvec4(g.theta_min_rad, g.theta_max_rad, g.n_min, g.n_max));
  b.kernel = glm::vec4(glm::dvec4(g.kernel_periods, s.cell_mm, s.trunc_factor, s.sigma_unit));
  b.tile = plan.ok ? glm::vec4(glm::dvec4(plan.period_mm, plan.texel_mm, plan.texels, plan.period_cells))
                   : glm::vec4(0.0f);
  b.counts = glm::uvec4(seed, static_cast<unsigned>(s.max_impulses), static_cast<unsigned>(s.stratified_count),
                        plan.ok ? static_cast<unsigned>(1 + plan.filtered_levels) : 0u);
  b.filtering = glm::vec4(glm::dvec4(g.filter_pixel_variance, plan.level_sigma_texels(), footprint_cap_mm2(g),
                                     kGaborFilterMaxSubsamples));
  return b;
}

}  // namespace ps
