#version 450 core
// Gabor bake pass: one period of the periodic texture into an RGBA32F tile, texel (i, j) =
// (f, f_u h, f_v h, f_uv h^2) at u = -period/2 + i h, v = -period/2 + j h (derivatives scaled by
// the texel size h so the Hermite lookup works in texel units). Run once per material.
#define PS_GABOR_BAKE 1
#include "lib/gabor.glsl"

layout(location = 0) uniform vec4 u_gabor_a;  // a_min, a_max, lambda_min, lambda_max
layout(location = 1) uniform vec4 u_gabor_b;  // theta_min, theta_max, n_min, n_max
layout(location = 2) uniform vec4 u_gabor_c;  // kernel periods, cell mm, trunc factor, -
layout(location = 3) uniform uvec4 u_seed;    // seed, max impulses, -, -
layout(location = 4) uniform vec4 u_tile;     // period mm, texel mm, texels, period cells

layout(location = 0) out vec4 o_sample;

void main() {
  GaborMaterial g = GaborMaterial(u_gabor_a.xy, u_gabor_a.zw, u_gabor_b.xy, u_gabor_b.zw,
                                  u_gabor_c.x, u_gabor_c.y, u_gabor_c.z, u_seed.x, int(u_seed.y));
  vec2 ij = floor(gl_FragCoord.xy);
  vec2 uv = -0.5 * u_tile.x + ij * u_tile.y;
  vec4 s = gabor_noise_sample(g, uv, int(u_tile.w));
  float h = u_tile.y;
  o_sample = vec4(s.x, s.y * h, s.z * h, s.w * h * h);
}
