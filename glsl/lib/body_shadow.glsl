// Pseudo-shadows of the scene's bodies: spheres, so analytic (no depth map), untextured, colour
// only. CPU twin and the law in words: src/reference/body_shadow.{h,cpp}.
#pragma once

#include "surface_block.glsl"
#include "pseudo_shadow.glsl"

// Radius (mm) of the disc the sphere shadows around its foot; 0: none. `height_mm`: the sphere
// centre's height above the fragment along n. The disc ends where the sphere's lowest point
// reaches the influence distance, or where the sphere lies wholly below the fragment.
float body_shadow_radius(float height_mm, float radius_mm, float influence_mm) {
  float excess = max(max(height_mm - influence_mm, -height_mm), 0.0);
  return sqrt(max(radius_mm * radius_mm - excess * excess, 0.0));
}

// One body's darkening in [0, 1] at world point x; `sphere`: (centre mm, radius mm); n: the
// reference normal; edge_mm: the pixel's extent on the plane (the filter of the disc's edge).
float body_shadow_darkening(IntensityCurve c, vec4 sphere, vec3 x, vec3 n, float edge_mm) {
  vec3 q = sphere.xyz - x;
  float height = dot(q, n);
  float rho = length(q - height * n);
  float r = sphere.w;
  float disc = body_shadow_radius(height, r, c.influence_mm);
  float edge = max(edge_mm, 1.0e-6);
  float coverage = clamp(min((disc - rho) / edge + 0.5, 2.0 * disc / edge), 0.0, 1.0);
  if (coverage <= 0.0) return 0.0;
  float rho_in = min(rho, disc);
  float d = height - sqrt(max(r * r - rho_in * rho_in, 0.0));
  // The curve without its influence cut: the disc already ends there.
  IntensityCurve open_curve = IntensityCurve(c.floor_, c.scale, c.offset_mm, 3.0e38);
  return coverage * shadow_intensity(open_curve, d);
}

// Largest extent (mm) on the reference plane of this fragment's pixel. Call in uniform control
// flow (screen-space derivatives).
float pixel_extent_on_plane(vec3 x, vec3 n) {
  vec3 dx = dFdx(x), dy = dFdy(x);
  return max(length(dx - dot(dx, n) * n), length(dy - dot(dy, n) * n));
}

// The light the bodies leave at x: prod(1 - D_i) over the block's casters (1.0 with none, so a
// scene without bodies keeps its bytes). Multiplied onto the probe's composite, the shadows
// combine as 1 - (1 - D_probe) prod(1 - D_i): each caster only darkens.
float body_shadow_light(IntensityCurve c, vec3 x, vec3 n) {
  if (u_body_count.x == 0u) return 1.0;  // a uniform branch: the derivatives below stay defined
  float edge_mm = pixel_extent_on_plane(x, n);
  float light = 1.0;
  for (int i = 0; i < int(u_body_count.x); ++i)
    light *= 1.0 - body_shadow_darkening(c, u_body_spheres[i], x, n, edge_mm);
  return light;
}
