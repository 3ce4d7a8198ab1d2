// A material's intensity_lut in the shader (variant PS_INTENSITY_LUT): read by shadow_intensity()
// and the contact jump in lib/pseudo_shadow.glsl in place of floor + scale / (d + offset).
// CPU twin: lut_eval() in src/scene/lut.cpp (through src/reference/modulation.cpp).
#pragma once

#ifndef PS_INTENSITY_LUT
#define PS_INTENSITY_LUT 0
#endif

#if PS_INTENSITY_LUT
// The material's intensity_lut (src/scene/lut.h) replaces floor + scale / (d + offset): its rows
// (x = distance mm, y = intensity) in a uniform block, two per vec4, interpolated here as
// lut_eval() does on the CPU: linear between rows, the end rows' value outside them. The row is
// found by eight fixed halving steps, the same for every fragment (no divergent loop). What it
// costs: `bench --lut-cost` (docs/benchmarks.md; ~1.2x the surface pass of the default scene on
// llvmpipe; a grid of cells naming each cell's segment measured the same, so the simpler stays).
// Mirrored by IntensityLutBlock in src/passes/surface.h.
layout(std140, binding = 1) uniform IntensityLutBlock {
  vec4 u_lut_rows[128];  // row 2k in .xy, row 2k + 1 in .zw (kMaxLutRows = 256)
  uvec4 u_lut_count;     // x: rows (2..256)
};

vec2 lut_row(int i) {
  vec4 pair = u_lut_rows[i >> 1];
  return (i & 1) == 0 ? pair.xy : pair.zw;
}

float intensity_lut(float d) {
  int n = int(u_lut_count.x);
  vec2 first = lut_row(0), last = lut_row(n - 1);
  if (!(d > first.x)) return first.y;
  if (d >= last.x) return last.y;
  // The last row with x <= d (< n - 1, since d < last.x).
  int lo = 0;
  for (int step = 128; step > 0; step >>= 1)
    if (lo + step < n && lut_row(lo + step).x <= d) lo += step;
  vec2 a = lut_row(lo), b = lut_row(lo + 1);
  return a.y + (d - a.x) / (b.x - a.x) * (b.y - a.y);
}
#endif
