// The probe's ordinary cast shadow (render.cast_shadow): a hard shadow of its bounding sphere
// along the directional light, colour only. CPU twin and the law in words:
// src/reference/cast_shadow.{h,cpp}.
#pragma once

// Share in [0, 1] of the pixel at x hidden from the light by the sphere (xyz centre mm, w radius
// mm); light_dir: unit direction the light travels; edge_mm: the pixel's extent across the light.
float cast_shadow_coverage(vec4 sphere, vec3 x, vec3 light_dir, float edge_mm) {
  vec3 to_light = -light_dir;
  vec3 q = sphere.xyz - x;
  float t = dot(q, to_light);
  float r = sphere.w;
  if (t <= 0.0 && dot(q, q) >= r * r) return 0.0;  // the sphere behind x, x outside it
  float rho = length(q - t * to_light);
  return clamp((r - rho) / max(edge_mm, 1.0e-6) + 0.5, 0.0, 1.0);
}

// Largest extent (mm) of this fragment's pixel across dir (unit). Call in uniform control flow
// (screen-space derivatives).
float pixel_extent_across(vec3 x, vec3 dir) {
  vec3 dx = dFdx(x), dy = dFdy(x);
  return max(length(dx - dot(dx, dir) * dir), length(dy - dot(dy, dir) * dir));
}
