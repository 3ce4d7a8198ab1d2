// Sparse-convolution Gabor noise (thesis §4.3.1, Lagae et al. 2009). Definition and the CPU
// twin: src/reference/gabor.{h,cpp}. The random decisions here must stay bit-identical to it.
#pragma once

#ifndef PS_GABOR_STRATIFIED
#define PS_GABOR_STRATIFIED 0  // 1: fixed count per cell on a jittered grid (see the CPU twin)
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
    float amp = mix(g.amplitude.x, g.amplitude.y, lcg_uniform(r));
    float lambda = mix(g.lambda_mm.x, g.lambda_mm.y, lcg_uniform(r));
    float theta = mix(g.theta_rad.x, g.theta_rad.y, lcg_uniform(r));
    float psi = 2.0 * kPi * lcg_uniform(r);
    float w = g.kernel_periods * lambda;
    float r2 = dot(d, d);
    if (w <= 0.0 || r2 >= w * w * g.trunc_factor) continue;
    float phase = 2.0 * kPi * dot(d, vec2(cos(theta), sin(theta))) / lambda;
    sum += amp * exp(-r2 / (w * w)) * cos(phase + psi);
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
