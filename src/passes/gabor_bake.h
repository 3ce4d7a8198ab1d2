// Gabor bake pass (strategies "baked", "baked_linear", and "auto" when it picks a tile):
// evaluates one period of a material's periodic Gabor texture into a tile, once per material,
// so the surface pass's PS_GABOR_BAKED variants read the tile instead of summing kernels per
// fragment. The tile comes in two forms (GaborBakePlan::linear, src/reference/gabor.h):
//   "baked"        RGBA32F, GL_NEAREST: texel (i, j) = (f, f_u h, f_v h, f_uv h^2), the value
//                  and its analytic derivatives (scaled by the texel size h), read by bicubic
//                  Hermite interpolation from four texel fetches (PS_GABOR_BAKED 1);
//   "baked_linear" R16F, GL_LINEAR: texel (i, j) = f alone, read by one bilinear, repeating
//                  texture fetch (PS_GABOR_BAKED 2).
// Both sample (-period/2 + i h, -period/2 + j h) and repeat (GL_REPEAT) with the period.
// With filtering (plan.filtered_levels > 0) the tile has mip levels 1 .. filtered_levels, each
// baked from the analytically filtered texture (GaborBakePlan, src/reference/gabor.h) at its
// own texel size, in the same form; the sampler then reads levels exactly (textureLod,
// texelFetch).
//   inputs : the material's GaborBlock (make_gabor_block with its plan) and GaborBakePlan
//   output : a new tile texture, plan.texels^2 (plus its filtered levels), in the plan's form
// The program is built once, in init(); run() once per tile, or make_tile() then run_rows()
// over consecutive row bands (the window bakes one band between frames so frames keep coming;
// a texel's value does not depend on the band it was drawn in, so the tile is the same).
// Shaders: glsl/gabor_bake.{vert,frag}; uniform contract glsl/lib/gabor_bake_block.glsl.
#pragma once

#include <string>

#include "core/result.h"
#include "gl/objects.h"
#include "passes/gabor_block.h"
#include "reference/gabor.h"

namespace ps {

// std140 mirror of glsl/lib/gabor_bake_block.glsl.
struct GaborBakeBlock {
  GaborBlock gabor;
  glm::vec4 level;  // x: the level's texel mm; y: its filter variance mm^2 (0 at level 0)
};
static_assert(sizeof(GaborBakeBlock) == sizeof(GaborBlock) + 16, "GaborBakeBlock must match std140 layout");

struct GaborBakePass {
  Status init(const std::string& glsl_root);
  bool ready() const { return static_cast<bool>(program_); }
  // block.tile must describe `plan` (make_gabor_block(..., plan, ...)); plan.ok must be true.
  Result<gl::Texture> run(const GaborBlock& block, const GaborBakePlan& plan);
  // The tile texture for `plan`, sampler state set, contents undefined until every row is baked.
  static gl::Texture make_tile(const GaborBakePlan& plan);
  // Bakes rows [row_begin, row_end) of mip level `level` of `tile` (from make_tile(plan)), all
  // columns.
  Status run_rows(const gl::Texture& tile, const GaborBlock& block, const GaborBakePlan& plan,
                  int row_begin, int row_end, int level = 0);

 private:
  gl::Program program_;
  gl::Framebuffer fbo_;        // the tile being baked is attached for the draw only
  gl::Buffer ubo_;
  gl::VertexArray empty_vao_;  // core profile draws need a bound VAO, even with no attributes
};

}  // namespace ps
