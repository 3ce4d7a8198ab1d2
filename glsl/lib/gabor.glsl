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
#ifndef PS_GABOR_FILTER
#define PS_GABOR_FILTER 0  // 1: analytic filtering over the pixel footprint (gabor_noise_filtered);
                           // 2: the same material, the filter skipped this frame (negligible:
                           // docs/architecture.md, "Texture filtering", level of detail)
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

// murmur3's 32-bit finaliser: a bijection of 32-bit words. CPU twin: fmix32 in gabor.cpp.
uint gabor_fmix32(uint h) {
  h = (h ^ (h >> 16)) * 0x85ebca6bu;
  h = (h ^ (h >> 13)) * 0xc2b2ae35u;
  return h ^ (h >> 16);
}
uint gabor_cell_hash(uint key, uint seed) {
  return gabor_fmix32(gabor_fmix32(key) ^ gabor_fmix32(seed + 0x9e3779b9u));  // kGaborSeedOffset
}
// The LCG's first state in a cell: its 16-bit-per-axis key hashed with the seed, distinct for
// every cell of the 65536-cell period; the key hashing to 0 takes the state of the key half a
// period away (0x80008000: kGaborHalfPeriodKey). Rule and proof: gabor_cell_seed in
// src/reference/gabor.h.
uint gabor_cell_seed(ivec2 cell, uint seed) {
  uint key = (uint(cell.x) & 0xffffu) | (uint(cell.y) << 16);
  uint h = gabor_cell_hash(key, seed);
  return h != 0u ? h : gabor_cell_hash(key ^ 0x80008000u, seed);
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

// The impulses of one cell, in the CPU twin's order (cell_sum in src/reference/gabor.cpp): how
// many, then for each its offset from p (relative to the cell's lower corner, mm) and its kernel.
struct GaborCellWalk {
  uint r;
  int count;
#if PS_GABOR_STRATIFIED
  int grid;
  float inv_grid;
#endif
};
GaborCellWalk gabor_cell_begin(GaborMaterial g, ivec2 cell) {
  GaborCellWalk w;
  w.r = gabor_cell_seed(cell, g.seed);
#if PS_GABOR_STRATIFIED
  w.count = min(g.stratified_count, g.max_impulses);
  w.grid = int(ceil(sqrt(float(g.stratified_count))));
  w.inv_grid = 1.0 / float(w.grid);
#else
  float n = g.density.x + (g.density.y - g.density.x) * lcg_uniform(w.r);
  float expected = n * (1.0 / kPi);
  w.count = clamp(int(floor(expected + lcg_uniform(w.r))), 0, g.max_impulses);
#endif
  return w;
}
vec2 gabor_impulse_offset(GaborMaterial g, inout GaborCellWalk w, int k, vec2 p) {
#if PS_GABOR_STRATIFIED
  vec2 jitter = vec2(lcg_uniform(w.r), lcg_uniform(w.r));
  return p - (vec2(float(k % w.grid), float((k / w.grid) % w.grid)) + jitter) * w.inv_grid * g.cell_mm;
#else
  return p - vec2(lcg_uniform(w.r), lcg_uniform(w.r)) * g.cell_mm;
#endif
}

// Sum of the kernels of one cell at p, given relative to the cell's lower corner (mm).
float gabor_cell(GaborMaterial g, ivec2 cell, vec2 p) {
  GaborCellWalk w = gabor_cell_begin(g, cell);
  float sum = 0.0;
  for (int k = 0; k < w.count; ++k) {
    vec2 d = gabor_impulse_offset(g, w, k, p);
    GaborKernel kern = gabor_draw_kernel(g, w.r);
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

#if PS_GABOR_FILTER || PS_GABOR_BAKE
// A kernel convolved with the normalised Gaussian of covariance S = (xx, xy, yy) mm^2 (Lagae et
// al. 2009 §5): amp exp(-d^T Q d / 2) cos(k . d + psi), Q = (C + S)^-1, C = (W^2/2) I,
// k = Q C k0, amp = A sqrt(|C| / |C + S|) exp(-c (|k0|^2 - k0 . k) / 2). CPU twin:
// filter_kernel in src/reference/gabor.cpp.
struct GaborFilteredKernel {
  float amp;
  vec3 q;  // (Q_xx, Q_xy, Q_yy)
  vec2 k;  // rad per mm
};
GaborFilteredKernel gabor_filter_kernel(GaborKernel kern, vec3 S) {
  float c = 0.5 * kern.w * kern.w;
  float a = c + S.x, b = S.y, d = c + S.z, det = a * d - b * b;
  vec2 k0 = (2.0 * kPi / kern.lambda) * vec2(cos(kern.theta), sin(kern.theta));
  GaborFilteredKernel f;
  f.q = vec3(d, -b, a) / det;
  f.k = c * vec2(f.q.x * k0.x + f.q.y * k0.y, f.q.y * k0.x + f.q.z * k0.y);
  f.amp = kern.amp * c * inversesqrt(det) * exp(-0.5 * c * (dot(k0, k0) - dot(k0, f.k)));
  return f;
}
#endif

#if PS_GABOR_FILTER
// gabor_cell with every kernel filtered by S, cut where its filtered envelope falls below the
// truncation (S = 0: gabor_cell). CPU twin: cell_sum_filtered in src/reference/gabor.cpp.
float gabor_cell_filtered(GaborMaterial g, ivec2 cell, vec2 p, vec3 S) {
  GaborCellWalk w = gabor_cell_begin(g, cell);
  float sum = 0.0;
  for (int k = 0; k < w.count; ++k) {
    vec2 d = gabor_impulse_offset(g, w, k, p);
    GaborKernel kern = gabor_draw_kernel(g, w.r);
    if (kern.w <= 0.0) continue;
    GaborFilteredKernel f = gabor_filter_kernel(kern, S);
    float q = f.q.x * d.x * d.x + 2.0 * f.q.y * d.x * d.y + f.q.z * d.y * d.y;
    if (q >= 2.0 * g.trunc_factor) continue;
    sum += f.amp * exp(-0.5 * q) * cos(dot(f.k, d) + kern.psi);
  }
  return sum;
}

float gabor_noise_filtered(GaborMaterial g, vec2 uv, vec3 S) {
  vec2 f = uv / g.cell_mm;
  ivec2 c = ivec2(floor(f));
  vec2 o = (f - vec2(c)) * g.cell_mm;
  float sum = 0.0;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      sum += gabor_cell_filtered(g, c + ivec2(i, j), o - vec2(i, j) * g.cell_mm, S);
  return sum;
}

// A pixel's box, split into k sub-boxes along its longer screen axis (k ~ the footprint's
// anisotropy, at most filtering.w): sub-box i is centred at uv + major * ((i + 0.5) / k - 0.5),
// and each is a Gaussian of covariance S = pixel_variance * (minor minor^T + major major^T / k^2),
// its eigenvalues capped at filtering.z. One Gaussian for a long, thin footprint leaks
// frequencies that the box kills (about 1 cycle per pixel along it): k Gaussians each 1/k as
// long follow the box out to k cycles per pixel. duv = (d uv / dx, d uv / dy), mm per pixel.
// CPU twin: gabor_pixel_split in src/reference/gabor.cpp.
struct GaborPixelSplit {
  vec2 major;  // the longer screen axis's (u, v) step over the whole pixel, mm
  int k;
  vec3 S;      // (xx, xy, yy) mm^2
};
vec3 gabor_cap_footprint(vec3 S, float cap) {
  float m = 0.5 * (S.x + S.z), h = 0.5 * (S.x - S.z);
  float rad = sqrt(h * h + S.y * S.y), l1 = m + rad, l2 = m - rad;
  if (l1 <= cap) return S;
  float a = 0.5 * atan(S.y, h);
  vec2 e = vec2(cos(a), sin(a));
  float m1 = min(l1, cap), m2 = min(l2, cap);
  return vec3(m1 * e.x * e.x + m2 * e.y * e.y, (m1 - m2) * e.x * e.y, m1 * e.y * e.y + m2 * e.x * e.x);
}
GaborPixelSplit gabor_pixel_split(mat2 duv, vec4 filtering) {
  bool x_major = dot(duv[0], duv[0]) >= dot(duv[1], duv[1]);
  vec2 major = x_major ? duv[0] : duv[1], minor = x_major ? duv[1] : duv[0];
  float ratio = sqrt(dot(major, major) / max(dot(minor, minor), 1e-30));
  GaborPixelSplit p;
  p.major = major;
  p.k = int(clamp(floor(ratio + 0.5), 1.0, max(filtering.w, 1.0)));
  vec2 sub = major / float(p.k);
  p.S = gabor_cap_footprint(filtering.x * vec3(minor.x * minor.x + sub.x * sub.x, minor.x * minor.y + sub.x * sub.y,
                                               minor.y * minor.y + sub.y * sub.y), filtering.z);
  return p;
}
vec2 gabor_sub_position(GaborPixelSplit p, vec2 uv, int i) {
  return uv + p.major * ((float(i) + 0.5) / float(p.k) - 0.5);
}
// How much the filter would attenuate the finest wavelength here: the exponent 2 pi^2 s2 /
// lambda_min^2 of exp(-2 pi^2 s2 f^2) at f = 1 / lambda_min, for s2 = the footprint's mean
// variance pixel_variance (|du/dx|^2 + |du/dy|^2) / 2 before the split and the cap, which only
// lower it (an upper bound for every sub-box). CPU twin: gabor_filter_need in
// src/reference/gabor_filter.cpp.
float gabor_filter_need(mat2 duv, float pixel_variance, float lambda_min) {
  return kPi * kPi * pixel_variance * (dot(duv[0], duv[0]) + dot(duv[1], duv[1])) / (lambda_min * lambda_min);
}

// The texture filtered over the pixel whose (u, v) derivatives are duv.
float gabor_noise_pixel(GaborMaterial g, vec4 filtering, vec2 uv, mat2 duv) {
  GaborPixelSplit p = gabor_pixel_split(duv, filtering);
  float sum = 0.0;
  for (int i = 0; i < p.k; ++i) sum += gabor_noise_filtered(g, gabor_sub_position(p, uv, i), p.S);
  return sum / float(p.k);
}
#endif

#if PS_GABOR_BAKE
#if PS_GABOR_STRATIFIED
#error "the bake pass samples the naive (Poisson) texture only: a stratified material is never baked"
#endif
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
  GaborCellWalk w = gabor_cell_begin(g, cell);
  vec4 sum = vec4(0.0);
  for (int k = 0; k < w.count; ++k) {
    vec2 d = gabor_impulse_offset(g, w, k, p);
    GaborKernel kern = gabor_draw_kernel(g, w.r);
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

// The filtered levels (S = sigma2 I): value and derivatives of the filtered kernels, with
// g = Q d: E_u = -g_u E, E_uv = (g_u g_v - Q_uv) E. CPU twin: cell_sample_filtered.
vec4 gabor_cell_sample_filtered(GaborMaterial g, ivec2 cell, vec2 p, float sigma2) {
  GaborCellWalk w = gabor_cell_begin(g, cell);
  vec4 sum = vec4(0.0);
  for (int k = 0; k < w.count; ++k) {
    vec2 d = gabor_impulse_offset(g, w, k, p);
    GaborKernel kern = gabor_draw_kernel(g, w.r);
    if (kern.w <= 0.0) continue;
    GaborFilteredKernel f = gabor_filter_kernel(kern, vec3(sigma2, 0.0, sigma2));
    vec2 gq = vec2(f.q.x * d.x + f.q.y * d.y, f.q.y * d.x + f.q.z * d.y);
    float q = dot(d, gq);
    if (q >= 2.0 * g.trunc_factor) continue;
    float e = f.amp * exp(-0.5 * q), ph = dot(f.k, d) + kern.psi, c = cos(ph), s = sin(ph);
    sum += e * vec4(c, -gq.x * c - s * f.k.x, -gq.y * c - s * f.k.y,
                    (gq.x * gq.y - f.q.y) * c + gq.x * s * f.k.y + gq.y * s * f.k.x - c * f.k.x * f.k.y);
  }
  return sum;
}

// The tile's sample at uv: the plain texture (sigma2 = 0, level 0) or filtered with the
// isotropic Gaussian of variance sigma2 (the filtered levels).
vec4 gabor_noise_sample(GaborMaterial g, vec2 uv, int period_cells, float sigma2) {
  vec2 f = uv / g.cell_mm;
  ivec2 c = ivec2(floor(f));
  vec2 o = (f - vec2(c)) * g.cell_mm;
  vec4 sum = vec4(0.0);
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      ivec2 cell = ivec2(gabor_wrap_cell(c.x + i, period_cells), gabor_wrap_cell(c.y + j, period_cells));
      vec2 p = o - vec2(i, j) * g.cell_mm;
      sum += sigma2 > 0.0 ? gabor_cell_sample_filtered(g, cell, p, sigma2) : gabor_cell_sample(g, cell, p);
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

#if PS_GABOR_FILTER == 1 && PS_GABOR_BAKED
// Filtered lookup in a tile with filtered levels (src/passes/gabor_bake.h): mip level L holds
// the texture filtered with an isotropic Gaussian of variance v_L = (kappa h_L)^2 (v_0 = 0),
// sampled at u_i = -period/2 + i h_L, h_L = period / (its texels). CPU twin of the levels:
// gabor_noise_derivatives(..., sigma2) in src/reference/gabor.cpp. tile as in gabor_noise_baked.
float gabor_tile_level(sampler2D tile_tex, vec4 tile, vec2 uv, int level) {
  float n = float(textureSize(tile_tex, level).x), h = tile.x / n;
  vec2 s = (uv + 0.5 * tile.x) / h;
#if PS_GABOR_BAKED == 2
  s = s - n * floor(s / n);
  return textureLod(tile_tex, (s + 0.5) / n, float(level)).r;  // GL_LINEAR_MIPMAP_NEAREST, level exactly
#else
  // The Hermite lookup of gabor_noise_baked on this level (its slopes are stored times h_L).
  vec2 i = floor(s), t = s - i;
  ivec2 i0 = ivec2(mod(i, n)), i1 = ivec2(mod(i + 1.0, n));
  vec4 h0 = vec4((1.0 + 2.0 * t) * (1.0 - t) * (1.0 - t), t * (1.0 - t) * (1.0 - t));
  vec4 h1 = vec4(t * t * (3.0 - 2.0 * t), -t * t * (1.0 - t));
  float f = 0.0;
  f += dot(texelFetch(tile_tex, ivec2(i0.x, i0.y), level), vec4(h0.x * h0.y, h0.z * h0.y, h0.x * h0.w, h0.z * h0.w));
  f += dot(texelFetch(tile_tex, ivec2(i1.x, i0.y), level), vec4(h1.x * h0.y, h1.z * h0.y, h1.x * h0.w, h1.z * h0.w));
  f += dot(texelFetch(tile_tex, ivec2(i0.x, i1.y), level), vec4(h0.x * h1.y, h0.z * h1.y, h0.x * h1.w, h0.z * h1.w));
  f += dot(texelFetch(tile_tex, ivec2(i1.x, i1.y), level), vec4(h1.x * h1.y, h1.z * h1.y, h1.x * h1.w, h1.z * h1.w));
  return f;
#endif
}

// The texture filtered over the pixel from the tile's levels: the pixel split as in
// gabor_noise_pixel; each sub-box's footprint, taken as isotropic with its mean variance s2,
// read from the two levels around s2 (beyond the last level: it and 0, the texture's mean),
// blended so that the blend attenuates the texture's mean frequency f0 = 2 / (lambda_min +
// lambda_max) as a filter of variance s2 does, exp(-2 pi^2 s2 f0^2). (Blending linearly in
// variance kept too much of the finer level: its unfiltered share aliases.) filtering:
// GaborBlock::filtering (y: a level's sigma in its texels, kappa); lambda_mm: (min, max); levels:
// the tile's level count (GaborBlock::counts.w; not textureQueryLevels, which GLSL ES 3.00 lacks).
float gabor_noise_baked_filtered(sampler2D tile_tex, vec4 tile, vec4 filtering, vec2 lambda_mm, vec2 uv,
                                 mat2 duv, int levels) {
  GaborPixelSplit p = gabor_pixel_split(duv, filtering);
  float s2 = 0.5 * (p.S.x + p.S.z);
  int last = levels - 1, lev = 0;
  float v_lo = 0.0, v_hi = 0.0;
  for (int L = 1; L <= last; ++L) {
    float sd = filtering.y * tile.x / float(textureSize(tile_tex, L).x);
    if (sd * sd > s2) {
      v_hi = sd * sd;
      break;
    }
    lev = L;
    v_lo = sd * sd;
  }
  bool fade = v_hi == 0.0;  // past the last level: towards the mean
  float f0 = 2.0 / (lambda_mm.x + lambda_mm.y), c = -2.0 * kPi * kPi * f0 * f0;
  float a_lo = exp(c * v_lo), a_hi = fade ? 0.0 : exp(c * v_hi);
  float t = fade && last == 0 ? 0.0 : clamp((a_lo - exp(c * s2)) / max(a_lo - a_hi, 1e-30), 0.0, 1.0);
  float sum = 0.0;
  for (int i = 0; i < p.k; ++i) {
    vec2 q = gabor_sub_position(p, uv, i);
    float lo = gabor_tile_level(tile_tex, tile, q, lev);
    float hi = fade ? 0.0 : gabor_tile_level(tile_tex, tile, q, lev + 1);
    sum += mix(lo, hi, t);
  }
  return sum / float(p.k);
}
#endif
