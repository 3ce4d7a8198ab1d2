// Pseudo-shadow formulas (thesis §4.3.2). CPU twin: src/reference/modulation.{h,cpp}.
#pragma once

struct IntensityCurve {
  float floor_;      // intensity far away (thesis 0.1)
  float scale;       // thesis 0.9
  float offset_mm;   // thesis 1.25
  float influence_mm;  // no pseudo-shadow at or beyond this distance
};

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

// 1 at contact (d <= 0), floor + scale / (d + offset) above (or the material's lookup table),
// 0 beyond the influence distance.
float shadow_intensity(IntensityCurve c, float d) {
  if (!(d < c.influence_mm)) return 0.0;
  if (d <= 0.0) return 1.0;
#if PS_INTENSITY_LUT
  return clamp(intensity_lut(d), 0.0, 1.0);
#else
  return clamp(c.floor_ + c.scale / (d + c.offset_mm), 0.0, 1.0);
#endif
}

// Darkening (fraction of the surface's light removed, in [0, 1]) of the pseudo-shadow with the
// texture on (thesis §4.2: a shadow people discount). The texture modulates the darkening
// AROUND the untextured one, so over any ring it adds detail, not light:
//   D = I + A * s,  s = clamp(texture / contrast, -1, 1) (zero mean),
//   A = gain * min(I - I_onset, 1 - I)  for 0 < d < onset, 0 beyond the onset distance.
// A is 0 at the onset and grows with I, so the texture fades in with no ring; A <= 1 - I keeps
// D <= 1 (no clipping, so the mean stays I); A <= I - I_onset keeps D >= I_onset > 0 (darker
// than the receiver everywhere) and makes D non-decreasing as d falls for every s (both bounds
// are non-decreasing in I). At contact (d <= 0) the mean jumps halfway from I(0+) to 1 (the
// deliberate jump of §4.3.2) and the texture keeps an amplitude of that half: no pixel lightens.
// `coverage` in [0, 1] is the share of the probe's footprint at this point (filtered edge).
float pseudo_shadow_darkening(IntensityCurve c, float d, float coverage, float onset_mm,
                              float gain, float s) {
  float i = shadow_intensity(c, d);
  if (i <= 0.0) return 0.0;
  float amp = 0.0;
  if (d <= 0.0) {
#if PS_INTENSITY_LUT
    float half_gap = 0.5 * (1.0 - clamp(intensity_lut(0.0), 0.0, 1.0));
#else
    float half_gap = 0.5 * (1.0 - clamp(c.floor_ + c.scale / c.offset_mm, 0.0, 1.0));
#endif
    i = 1.0 - gain * half_gap;
    amp = gain * half_gap;
  } else if (d < onset_mm) {
    amp = gain * max(min(i - shadow_intensity(c, onset_mm), 1.0 - i), 0.0);
  }
  return coverage * (i + amp * clamp(s, -1.0, 1.0));
}

// The surface seen through the pseudo-shadow: never brighter than the surface.
vec3 composite_pseudo_shadow(vec3 surface_rgb, float darkening) {
  return surface_rgb * (1.0 - darkening);
}
