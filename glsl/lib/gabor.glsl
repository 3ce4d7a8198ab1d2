// Sparse-convolution Gabor noise (thesis §4.3.1, Lagae et al. 2009). Definition and the CPU
// twin: src/reference/gabor.{h,cpp}. The random decisions here must stay bit-identical to it.
#pragma once

#ifndef PS_GABOR_STRATIFIED
#define PS_GABOR_STRATIFIED 0  // 1: fixed count per cell on a jittered grid (see the CPU twin)
#endif
#ifndef PS_GABOR_BAKE
#define PS_GABOR_BAKE 0  // 1: gabor_noise_sample (value + derivatives, periodic) for the bake pass
#endif
#ifndef PS_GABOR_BAKED
#define PS_GABOR_BAKED 0  // 1: gabor_noise_baked (Hermite lookup in the baked tile); 2: bilinear
#endif

const float kPi = 3.14159265358979;
const uint kLcgMultiplier = 3039177861u;  // r_{n+1} = 3039177861 r_n mod 2^32

struct GaborMaterial {
  vec2 amplitude;   // [A_min, A_max]
  vec2 lambda_mm;   // [lambda_min, lambda_max]
  vec2 theta_rad;   // [theta_min, theta_max]
  vec2 density;     // [n_min, n_max] impulses per kernel footprint
  float kernel_periods;  // W = kernel_periods * lambda
  float cell_mm;         // cell size = largest truncation radius
  float trunc_factor;    // kernels are cut where r^2 >= W^2 * trunc_factor
  uint seed;
  int max_impulses;      // cap per cell
#if PS_GABOR_STRATIFIED
  int stratified_count;  // impulses in every cell
#endif
};

uint gabor_cell_seed(ivec2 cell, uint seed) {
  uint h = (uint(cell.x) * 73856093u) ^ (uint(cell.y) * 19349663u) ^ (seed * 83492791u);
  return h == 0u ? 1u : h;
}

float lcg_uniform(inout uint state) {
  state *= kLcgMultiplier;
  return float(state) * (1.0 / 4294967296.0);
}

// An impulse's kernel draws after its position, in the CPU twin's order (draw_impulse in
// src/reference/gabor.cpp); w = the envelope width.
struct GaborKernel {
  float amp, lambda, theta, psi, w;
};
GaborKernel gabor_draw_kernel(GaborMaterial g, inout uint r) {
  GaborKernel k;
  k.amp = mix(g.amplitude.x, g.amplitude.y, lcg_uniform(r));
  k.lambda = mix(g.lambda_mm.x, g.lambda_mm.y, lcg_uniform(r));
  k.theta = mix(g.theta_rad.x, g.theta_rad.y, lcg_uniform(r));
  k.psi = 2.0 * kPi * lcg_uniform(r);
  k.w = g.kernel_periods * k.lambda;
  return k;
}

// Sum of the kernels of one cell at p, given relative to the cell's lower corner (mm).
float gabor_cell(GaborMaterial g, ivec2 cell, vec2 p) {
  uint r = gabor_cell_seed(cell, g.seed);
#if PS_GABOR_STRATIFIED
  int count = min(g.stratified_count, g.max_impulses);
  int grid = int(ceil(sqrt(float(g.stratified_count))));
  float inv_grid = 1.0 / float(grid);
#else
  float n = g.density.x + (g.density.y - g.density.x) * lcg_uniform(r);
  float expected = n * (1.0 / kPi);
  int count = clamp(int(floor(expected + lcg_uniform(r))), 0, g.max_impulses);
#endif
  float sum = 0.0;
  for (int k = 0; k < count; ++k) {
#if PS_GABOR_STRATIFIED
    vec2 jitter = vec2(lcg_uniform(r), lcg_uniform(r));
    vec2 d = p - (vec2(float(k % grid), float((k / grid) % grid)) + jitter) * inv_grid * g.cell_mm;
#else
    vec2 d = p - vec2(lcg_uniform(r), lcg_uniform(r)) * g.cell_mm;
#endif
    GaborKernel kern = gabor_draw_kernel(g, r);
    float r2 = dot(d, d);
    if (kern.w <= 0.0 || r2 >= kern.w * kern.w * g.trunc_factor) continue;
    float phase = 2.0 * kPi * dot(d, vec2(cos(kern.theta), sin(kern.theta))) / kern.lambda;
    sum += kern.amp * exp(-r2 / (kern.w * kern.w)) * cos(phase + kern.psi);
  }
  return sum;
}

// Raw noise at plane coordinates uv (mm): the 3x3 cells around uv hold every kernel reaching it.
float gabor_noise(GaborMaterial g, vec2 uv) {
  vec2 f = uv / g.cell_mm;
  ivec2 c = ivec2(floor(f));
  vec2 o = (f - vec2(c)) * g.cell_mm;
  float sum = 0.0;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      sum += gabor_cell(g, c + ivec2(i, j), o - vec2(i, j) * g.cell_mm);
  return sum;
}

#if PS_GABOR_BAKE
// Baking (glsl/gabor_bake.frag): value and derivatives (f, df/du, df/dv, d2f/dudv) of the
// periodic texture, cells hashed by their index wrapped into [-N/2, N/2). CPU twin:
// gabor_noise_derivatives in src/reference/gabor.cpp.
int gabor_wrap_cell(int c, int period_cells) {
  // Not `%`: GLSL leaves it undefined for negative operands (llvmpipe's answer broke the wrap).
  int half_n = period_cells / 2, k = c + half_n;
  int m = k - period_cells * int(floor(float(k) / float(period_cells)));
  if (m < 0) m += period_cells;  // float rounding of the quotient for |k| near 2^24
  if (m >= period_cells) m -= period_cells;
  return m - half_n;
}

vec4 gabor_cell_sample(GaborMaterial g, ivec2 cell, vec2 p) {
  uint r = gabor_cell_seed(cell, g.seed);
  float n = g.density.x + (g.density.y - g.density.x) * lcg_uniform(r);
  float expected = n * (1.0 / kPi);
  int count = clamp(int(floor(expected + lcg_uniform(r))), 0, g.max_impulses);
  vec4 sum = vec4(0.0);
  for (int k = 0; k < count; ++k) {
    vec2 d = p - vec2(lcg_uniform(r), lcg_uniform(r)) * g.cell_mm;
    GaborKernel kern = gabor_draw_kernel(g, r);
    float r2 = dot(d, d);
    if (kern.w <= 0.0 || r2 >= kern.w * kern.w * g.trunc_factor) continue;
    vec2 o = vec2(cos(kern.theta), sin(kern.theta));
    float f = 2.0 * kPi / kern.lambda, iw2 = 1.0 / (kern.w * kern.w);
    float e = kern.amp * exp(-r2 * iw2);
    float ph = f * dot(d, o) + kern.psi, c = cos(ph), s = sin(ph);
    sum += e * vec4(c, -2.0 * d.x * iw2 * c - s * f * o.x, -2.0 * d.y * iw2 * c - s * f * o.y,
                    4.0 * d.x * d.y * iw2 * iw2 * c + 2.0 * d.x * iw2 * s * f * o.y +
                        2.0 * d.y * iw2 * s * f * o.x - c * f * f * o.x * o.y);
  }
  return sum;
}

vec4 gabor_noise_sample(GaborMaterial g, vec2 uv, int period_cells) {
  vec2 f = uv / g.cell_mm;
  ivec2 c = ivec2(floor(f));
  vec2 o = (f - vec2(c)) * g.cell_mm;
  vec4 sum = vec4(0.0);
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      ivec2 cell = ivec2(gabor_wrap_cell(c.x + i, period_cells), gabor_wrap_cell(c.y + j, period_cells));
      sum += gabor_cell_sample(g, cell, o - vec2(i, j) * g.cell_mm);
    }
  return sum;
}
#endif

#if PS_GABOR_BAKED == 2
// Baked lookup, bilinear: the tile holds values only (R16F, GL_LINEAR, GL_REPEAT), sample i at
// u_i = -period/2 + i h, i.e. texel centre (i + 0.5) / texels. tile: (period mm, texel h mm,
// texels, period cells). CPU twin: gabor_noise_baked (plan.linear) in src/reference/gabor.cpp.
float gabor_noise_baked(sampler2D tile_tex, vec4 tile, vec2 uv) {
  vec2 s = (uv + 0.5 * tile.x) / tile.y;
  s = s - tile.z * floor(s / tile.z);  // into [0, texels): keeps the coordinate's float precision
  return texture(tile_tex, (s + 0.5) / tile.z).r;
}
#elif PS_GABOR_BAKED
// Baked lookup: bicubic Hermite interpolation of the tile's samples (f, f_u h, f_v h,
// f_uv h^2) at u_i = -period/2 + i h. tile: (period mm, texel h mm, texels, period cells). CPU twin:
// gabor_noise_baked in src/reference/gabor.cpp.
float gabor_noise_baked(sampler2D tile_tex, vec4 tile, vec2 uv) {
  vec2 s = (uv + 0.5 * tile.x) / tile.y;
  vec2 i = floor(s), t = s - i;
  ivec2 i0 = ivec2(mod(i, tile.z)), i1 = ivec2(mod(i + 1.0, tile.z));
  vec4 h0 = vec4((1.0 + 2.0 * t) * (1.0 - t) * (1.0 - t), t * (1.0 - t) * (1.0 - t));  // xy: value at 0 (u, v); zw: slope at 0
  vec4 h1 = vec4(t * t * (3.0 - 2.0 * t), -t * t * (1.0 - t));                         // xy: value at 1; zw: slope at 1
  vec4 s00 = texelFetch(tile_tex, ivec2(i0.x, i0.y), 0), s10 = texelFetch(tile_tex, ivec2(i1.x, i0.y), 0);
  vec4 s01 = texelFetch(tile_tex, ivec2(i0.x, i1.y), 0), s11 = texelFetch(tile_tex, ivec2(i1.x, i1.y), 0);
  // Corner (a, b): value weights wu_a wv_b; u-slope su_a wv_b; v-slope wu_a sv_b; twist su_a sv_b.
  float f = 0.0;
  f += dot(s00, vec4(h0.x * h0.y, h0.z * h0.y, h0.x * h0.w, h0.z * h0.w));
  f += dot(s10, vec4(h1.x * h0.y, h1.z * h0.y, h1.x * h0.w, h1.z * h0.w));
  f += dot(s01, vec4(h0.x * h1.y, h0.z * h1.y, h0.x * h1.w, h0.z * h1.w));
  f += dot(s11, vec4(h1.x * h1.y, h1.z * h1.y, h1.x * h1.w, h1.z * h1.w));
  return f;
}
#endif
