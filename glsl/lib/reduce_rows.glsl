// One image row of each reduction, shared by the compute path (max_penetration.comp,
// displacement_rows.comp, normal_rows.comp: one invocation per row, atomics and a storage
// buffer) and the fragment path (*_rows.frag: one fragment per row of a one-texel-wide target,
// what WebGL2 can run): both run this same arithmetic, so both give the same bits (tested by
// ReductionPathsGLTest). Needs lib/reduce_block.glsl (u_rect, u_params) and, for
// displacement_row, lib/displacement_weight.glsl.
#pragma once

// Row y of u_rect in the AOV target (intensity, d, texture, resistance) and the filter need.
struct PenetrationRow {
  float pen;    // max of -d over the row's penetrating pixels (0: none)
  float res;    // max of resistance * -d
  float need;   // max filter need over the row's covered pixels
  uint n_cov;   // pixels inside the pseudo-shadow
  uint n_pen;   // penetrating pixels
  int x_lo;     // first and last penetrating column (x_lo > x_hi: none)
  int x_hi;
};

PenetrationRow penetration_row(sampler2D aov_tex, sampler2D need_tex, int y) {
  PenetrationRow r = PenetrationRow(0.0, 0.0, 0.0, 0u, 0u, u_rect.z, u_rect.x - 1);
  for (int x = u_rect.x; x < u_rect.z; ++x) {
    vec4 aov = texelFetch(aov_tex, ivec2(x, y), 0);
    if (!(aov.x > 0.0)) continue;
    ++r.n_cov;
    r.need = max(r.need, texelFetch(need_tex, ivec2(x, y), 0).r);
    // `-d > 0` is false for NaN, so NaN never enters the maximum.
    if (-aov.y > 0.0) {
      r.pen = max(r.pen, -aov.y);
      r.res = max(r.res, -aov.y * max(aov.w, 0.0));
      ++r.n_pen;
      r.x_lo = min(r.x_lo, x);
      r.x_hi = x;
    }
  }
  return r;
}

// (sum of w * disp, sum of w) over row y's columns box.x .. box.z (inclusive), zero outside
// box's rows: only the box of penetrating pixels has non-zero terms, and a zero term leaves a
// float sum's bits unchanged, so the sums are those of whole rows.
vec4 displacement_row(sampler2D aov_tex, sampler2D normal_tex, int y, ivec4 box, float max_pen) {
  vec4 sum = vec4(0.0);
  if (y >= box.y && y <= box.w)
    for (int x = box.x; x <= box.z; ++x) sum += weighted_displacement(aov_tex, normal_tex, ivec2(x, y), max_pen);
  return sum;
}

// Row y of the normal target, (n, 1) per covered pixel and zero elsewhere, over u_size.x
// columns, with Kahan's compensated sum (`precise`: the compensation must not be simplified
// away): within a float rounding of the exact row sum.
vec4 normal_row(sampler2D normal_tex, int y) {
  precise vec4 sum = vec4(0.0), c = vec4(0.0);
  for (int x = 0; x < u_size.x; ++x) {
    precise vec4 v = texelFetch(normal_tex, ivec2(x, y), 0) - c;
    precise vec4 t = sum + v;
    c = (t - sum) - v;
    sum = t;
  }
  return sum;
}
