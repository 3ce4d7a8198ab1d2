#version 450 core
// Gabor bake pass: one period of the material's periodic Gabor texture into a tile, run once
// per material (src/passes/gabor_bake.h). Texel (i, j) samples u = -period/2 + i h,
// v = -period/2 + j h (h = texel size). The output has both tile forms' contents:
//   "baked"        RGBA32F target: (f, f_u h, f_v h, f_uv h^2), the value and its analytic
//                  derivatives scaled by h so the surface pass's bicubic Hermite lookup
//                  (PS_GABOR_BAKED 1, four texel fetches) works in texel units;
//   "baked_linear" R16F target: the value f alone (the target keeps .x), read by one bilinear,
//                  repeating texture fetch (PS_GABOR_BAKED 2).
// Mip level L >= 1 (filtered levels, GaborBakePlan::filtered_levels) samples at its own texel
// size h_L the texture filtered with an isotropic Gaussian of variance u_level.y.
#define PS_GABOR_BAKE 1
#include "lib/gabor_bake_block.glsl"

layout(location = 0) out vec4 o_sample;

void main() {
  GaborMaterial g = gabor_material(u_gabor);
  vec2 ij = floor(gl_FragCoord.xy);
  float h = u_level.x;
  vec2 uv = -0.5 * u_gabor.tile.x + ij * h;
  // Level 0 unfiltered; levels >= 1 filtered analytically (never box-averaged texels).
  vec4 s = gabor_noise_sample(g, uv, int(u_gabor.tile.w), u_level.y);
  o_sample = vec4(s.x, s.y * h, s.z * h, s.w * h * h);
}
