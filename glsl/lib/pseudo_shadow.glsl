// Pseudo-shadow formulas (thesis §4.3.2). CPU twin: src/reference/modulation.{h,cpp}.
#pragma once

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
  return clamp(c.floor_ + c.scale / (d + c.offset_mm), 0.0, 1.0);
}

// Blend of surface, black shadow and texture. tex in [0,1] is the texture's brightness inside
// the onset distance (0 = plain black shadow). The result is never brighter than the surface:
// shadows that light up their receiver stop reading as shadows (thesis §4.2).
vec3 composite_pseudo_shadow(vec3 surface_rgb, float intensity, float tex) {
  return surface_rgb * (1.0 - intensity * (1.0 - tex));
}
