#version 450 core
// Surface pass (thesis Table 4.2 step 3), MRT:
//   0 color   RGBA8   : lit surface blended with the pseudo-shadow (gamma-encoded)
//   1 normal  RGBA32F : (visible front-facing normal, 1) -> mean = reference plane (step 4)
//   2 aov     RGBA32F : (intensity, signed distance d mm, texture value in sigmas, resistance);
//                       d is NaN where no probe is above the fragment (the distance AOV's
//                       documented "no probe" value, src/render/renderer.h)
// Variants: PS_SHADOW (0: probe beyond this surface's influence, pseudo-shadow compiled out),
//           PS_TEXTURED (0: untextured material, Gabor compiled out), PS_GABOR_STRATIFIED,
//           PS_GABOR_BAKED (the texture read from the material's baked tile).
#include "lib/surface_block.glsl"
#include "lib/pseudo_shadow.glsl"

#ifndef PS_SHADOW
#define PS_SHADOW 1
#endif
#ifndef PS_TEXTURED
#define PS_TEXTURED 1
#endif

layout(binding = 0) uniform sampler2D u_probe_depth;  // R32F: probe's lowest height h_p per texel
layout(binding = 1) uniform sampler2D u_albedo_tex;
#if PS_GABOR_BAKED
layout(binding = 2) uniform sampler2D u_gabor_tile;  // baked tile: RGBA32F (1), R16F (2) (passes/gabor_bake.h)
#endif

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;

layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_aov;

// "No probe here" distance inside this shader (compares like a very large distance: no
// intensity, no texture). Written to the AOV as NaN, never to the colour target.
const float kFar = 1.0e30;
// The distance AOV's value there: NaN (image statistics count NaNs apart instead of averaging
// in 1e30). A function, not a constant: GLSL 4.50 has no NaN literal.
float no_probe_distance() { return uintBitsToFloat(0x7fc00000u); }

vec3 shade_surface(vec3 n) {
  vec3 albedo = u_albedo.rgb;
  if (u_albedo.a > 0.5) albedo *= texture(u_albedo_tex, v_world.xy / u_albedo_scale.x).rgb;
  float lambert = max(dot(n, -u_light_dir.xyz), 0.0);
  return albedo * u_light_color.rgb * (u_light_dir.w + (1.0 - u_light_dir.w) * lambert);
}

// Signed probe-surface distance along the reference normal (mm); kFar outside the probe's
// orthographic footprint.
float probe_distance(vec2 uv, float h_surface) {
  vec2 st = (uv - u_window.xy) / (2.0 * u_window.z) + 0.5;
  if (any(lessThan(st, vec2(0.0))) || any(greaterThanEqual(st, vec2(1.0)))) return kFar;
  ivec2 texel = ivec2(st * u_window.w);
  float h_probe = texelFetch(u_probe_depth, texel, 0).r;
  return h_probe >= kFar ? kFar : h_probe - h_surface;
}

void main() {
  vec3 n = normalize(gl_FrontFacing ? v_normal : -v_normal);
  vec3 rgb = shade_surface(n);
  float intensity = 0.0, d = kFar, tex_sigmas = 0.0;
#if PS_SHADOW
  vec2 uv = vec2(dot(v_world, u_ref_t.xyz), dot(v_world, u_ref_b.xyz));
  d = probe_distance(uv, dot(v_world, u_ref_n.xyz));
  IntensityCurve curve = IntensityCurve(u_intensity.x, u_intensity.y, u_intensity.z, u_intensity.w);
  intensity = shadow_intensity(curve, d);
  float tex = 0.0;  // black shadow outside the onset distance
#if PS_TEXTURED
  // Only fragments inside the footprint and the onset distance pay for the Gabor sum.
  if (intensity > 0.0 && d < u_modulation.y) {
#if PS_GABOR_BAKED
    tex_sigmas = gabor_noise_baked(u_gabor_tile, u_gabor.tile, uv) / u_gabor.kernel.w;
#else
    tex_sigmas = gabor_noise(gabor_material(u_gabor), uv) / u_gabor.kernel.w;
#endif
    float shown = u_modulation.x * tex_sigmas / u_modulation.w;
    tex = clamp(0.5 + 0.5 * shown, 0.0, 1.0);
  }
#endif
  rgb = composite_pseudo_shadow(rgb, intensity, tex);
#endif
  o_color = vec4(pow(clamp(rgb, 0.0, 1.0), vec3(u_light_color.a)), 1.0);
  o_normal = vec4(n, 1.0);
  o_aov = vec4(intensity, d >= kFar ? no_probe_distance() : d, tex_sigmas, u_modulation.z);
}
