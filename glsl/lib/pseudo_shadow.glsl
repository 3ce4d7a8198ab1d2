// Pseudo-shadow formulas (thesis §4.3.2). CPU twin: src/reference/modulation.{h,cpp}.
#pragma once
#include "intensity_lut.glsl"
struct IntensityCurve {
  float floor_;      // intensity far away (thesis 0.1)
  float scale;       // thesis 0.9
  float offset_mm;   // thesis 1.25
  float influence_mm;  // no pseudo-shadow at or beyond this distance
};

// 1 at contact (d <= 0), floor + scale / (d + offset) above, 0 beyond the influence distance.
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
