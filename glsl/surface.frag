#version 450 core
// Surface pass (thesis Table 4.2 step 3), MRT:
//   0 color   RGBA8   : lit surface blended with the pseudo-shadow (gamma-encoded)
//   1 normal  RGBA32F : (visible front-facing normal, 1) -> mean = reference plane (step 4)
//   2 aov     RGBA32F : (intensity x footprint coverage, signed distance d mm, texture value in
//                       sigmas, resistance);
//                       d is NaN where no probe is above the fragment (the distance AOV's
//                       documented "no probe" value, src/render/renderer.h)
//   3 filter  R32F    : where the texture is evaluated with PS_GABOR_FILTER 1 or 2, how much the
//                       filter attenuates lambda_min (gabor_filter_need); 0 elsewhere. Its
//                       maximum decides whether the next frame may skip the filter.
// Variants: PS_SHADOW (0: probe beyond this surface's influence, pseudo-shadow compiled out),
//           PS_TEXTURED (0: untextured material, Gabor compiled out), PS_GABOR_STRATIFIED,
//           PS_GABOR_BAKED (the texture read from the material's baked tile), PS_GABOR_FILTER
//           (1: the texture filtered over the pixel's footprint; 2: the filter skipped this
//           frame, its need still measured).
// The bodies' pseudo-shadows (lib/body_shadow.glsl) and the probe's cast shadow
// (lib/cast_shadow.glsl, render.cast_shadow) darken the colour target only, in every variant;
// the AOVs and the normal stay the probe's.
#include "lib/surface_block.glsl"
#include "lib/pseudo_shadow.glsl"
#include "lib/body_shadow.glsl"
#include "lib/cast_shadow.glsl"

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
layout(location = 2) in vec3 v_color;  // per-vertex colour (4D depth on fourd surfaces), else 1
layout(location = 3) in float v_w4;    // 4D depth w (fourd surfaces), else 0

layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_aov;
layout(location = 3) out float o_filter_need;

// "No probe here" distance inside this shader (compares like a very large distance: no
// intensity, no texture). Written to the AOV as NaN, never to the colour target.
const float kFar = 1.0e30;
// The distance AOV's value there: NaN (image statistics count NaNs apart instead of averaging
// in 1e30). A function, not a constant: GLSL 4.50 has no NaN literal.
float no_probe_distance() { return uintBitsToFloat(0x7fc00000u); }

// render.cast_shadow: the probe's hard shadow removes the lit (Lambert) term where the light is
// blocked and leaves the ambient one, as a real shadow does. A uniform branch (the derivatives
// inside stay defined); off, lambert is untouched and the image keeps its bytes.
vec3 shade_surface(vec3 n) {
  vec3 albedo = u_albedo.rgb * v_color;
  if (u_albedo.a > 0.5) albedo *= texture(u_albedo_tex, (v_world.xy - u_albedo_scale.yz) / u_albedo_scale.x).rgb;
  float lambert = max(dot(n, -u_light_dir.xyz), 0.0);
  if (u_cast_sphere.w > 0.0)
    lambert *= 1.0 - cast_shadow_coverage(u_cast_sphere, v_world, u_light_dir.xyz,
                                          pixel_extent_across(v_world, u_light_dir.xyz));
  return albedo * u_light_color.rgb * (u_light_dir.w + (1.0 - u_light_dir.w) * lambert);
}

// The probe depth map read bilinearly by hand: its "no probe" texels (kFar) must not be blended
// with real heights, so they are left out and their share becomes the footprint's coverage.
// Returns (h_probe mm, coverage in [0, 1]); coverage 0 outside the probe's footprint. The
// filter smooths the footprint's edge and the intensity bands at any depth-map size.
vec2 probe_height(vec2 uv) {
  vec2 p = ((uv - u_window.xy) / (2.0 * u_window.z) + 0.5) * u_window.w - 0.5;
  ivec2 base = ivec2(floor(p));
  vec2 f = p - vec2(base);
  float h_sum = 0.0, w_sum = 0.0;
  int covered = 0;
  for (int k = 0; k < 4; ++k) {
    ivec2 o = ivec2(k & 1, k >> 1);
    ivec2 t = base + o;
    if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, ivec2(u_window.w)))) continue;
    float h = texelFetch(u_probe_depth, t, 0).r;
    if (h >= kFar) continue;
    float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
    h_sum += w * h;
    w_sum += w;
    ++covered;
  }
  // Inside the footprint the coverage is exactly 1 (the float weights sum to 1 +- an ulp; an
  // intensity of 1 - ulp at contact would no longer be opaque).
  if (covered == 4) return vec2(h_sum / w_sum, 1.0);
  return w_sum > 0.0 ? vec2(h_sum / w_sum, w_sum) : vec2(kFar, 0.0);
}

// d along the surface's own normal n (render.shadow_distance = "surface_normal"): the first
// s >= 0 where the ray p + s n reaches the probe's underside as the depth map holds it (a height
// field over the reference plane, the probe filling the column above it). Only the ray's stretch
// inside the depth-map window and between the probe's lowest and highest heights can meet it,
// and only up to the influence distance (beyond, the intensity is 0). Steps of half the gap
// left (at least a quarter texel, at most two texels sideways; two texels sideways where no
// probe is below, so a ray may graze past a corner of the footprint), then 10 bisections.
// The probe fills the column above its underside: a ray that enters that column through its
// side (the probe's silhouette) meets it there. On a receiver tilted steeply against the
// reference plane, rays graze the silhouette and the footprint's far edge comes out ragged
// (docs/architecture.md, "Distance on curved receivers"). Returns
// (d mm, coverage) like probe_height; (kFar, 0) when the ray misses or the surface faces away.
float gap_along(vec2 uv0, vec2 dir, float h0, float dz, float s, out float coverage) {
  vec2 h = probe_height(uv0 + s * dir);
  coverage = h.y;
  return h.x >= kFar ? kFar : h.x - (h0 + s * dz);
}

vec2 normal_distance(vec3 p, vec3 n, vec2 uv0) {
  float h0 = dot(p, u_ref_n.xyz);
  vec2 hc = probe_height(uv0);
  float dz = dot(n, u_ref_n.xyz);
  vec2 dir = vec2(dot(n, u_ref_t.xyz), dot(n, u_ref_b.xyz));
  // Within 1e-6 rad of the reference normal (a plane facing the probe, to float rounding): the
  // ray moves < 1e-5 mm sideways over 10 mm, so it is the reference-plane distance, bit for bit.
  if (dot(dir, dir) < 1e-12) return hc.x >= kFar ? hc : vec2(hc.x - h0, hc.y);
  if (hc.x < kFar && hc.x - h0 <= 0.0) return vec2(hc.x - h0, hc.y);  // inside the probe already
  if (dz <= 0.0) return vec2(kFar, 0.0);
  float texel = 2.0 * u_window.z / u_window.w, hor = length(dir);
  float s_in = 0.0, s_out = u_intensity.w;
  for (int k = 0; k < 2; ++k) {
    float lo = u_window[k] - u_window.z, hi = u_window[k] + u_window.z;
    if (abs(dir[k]) < 1e-12) {
      if (uv0[k] < lo || uv0[k] > hi) return vec2(kFar, 0.0);
      continue;
    }
    float a = (lo - uv0[k]) / dir[k], b = (hi - uv0[k]) / dir[k];
    s_in = max(s_in, min(a, b));
    s_out = min(s_out, max(a, b));
  }
  // Below the probe's lowest height the ray cannot meet it; above its highest, over the probe,
  // it has (the column above the underside is the probe's).
  s_in = max(s_in, (u_ref_t.w - h0) / dz);
  s_out = min(s_out, max(0.0, (u_ref_b.w - h0) / dz) + 2.0 * texel);
  if (s_in > s_out) return vec2(kFar, 0.0);
  float s = s_in, s_prev = s_in, cov = 0.0;
  for (int i = 0; i < 256; ++i) {
    float g = gap_along(uv0, dir, h0, dz, s, cov);
    if (g <= 0.0) {
      float a = s_prev, b = s, cov_b = cov, c;
      for (int j = 0; j < 10; ++j) {
        float m = 0.5 * (a + b);
        if (gap_along(uv0, dir, h0, dz, m, c) <= 0.0) {
          b = m;
          cov_b = c;
        } else {
          a = m;
        }
      }
      return vec2(0.5 * (a + b), cov_b);
    }
    if (s >= s_out) break;
    s_prev = s;
    s = min(s_out, s + (g >= kFar ? 2.0 * texel / hor : clamp(0.5 * g, 0.25 * texel, 2.0 * texel / hor)));
  }
  return vec2(kFar, 0.0);
}

// The same distance in closed form for a sphere/capsule probe (u_probe_b.w = 1): the first s >= 0
// where p + s n enters the probe or the column above its underside, which is what the depth map
// describes, exactly instead of through the map's texels: through the underside (the ray meets
// the capsule: s_k) or through the column's side above the silhouette (the ray's trace on the
// plane enters the probe's outline at a height at or above the axis's height there: s_f). No
// march: the cost of the reference-plane distance plus one depth-map read for the footprint's
// coverage. CPU twin: capsule_column_distance() in src/reference/probe_geometry.cpp.
// Coordinates are plane coordinates (u, v, height) relative to end a.
float ray_capsule2(vec2 o, vec2 w, vec2 e, float r) {  // s >= 0 entering the outline, else kFar
  float ww = dot(w, w), ee = dot(e, e), best = kFar;
  if (ee > 0.0) {
    float ew = dot(e, w), eo = dot(e, o);
    float a = ee * ww - ew * ew, b = ee * dot(w, o) - eo * ew, c = ee * dot(o, o) - eo * eo - r * r * ee;
    float h = b * b - a * c;
    if (a > 0.0 && h >= 0.0) {
      float s = (-b - sqrt(h)) / a, y = eo + s * ew;
      if (s >= 0.0 && y > 0.0 && y < ee) best = s;
    }
  }
  for (int k = 0; k < 2; ++k) {
    vec2 oc = o - (k == 0 ? vec2(0.0) : e);
    float b = dot(oc, w), h = b * b - ww * (dot(oc, oc) - r * r);
    float s = (-b - sqrt(max(h, 0.0))) / ww;
    if (h >= 0.0 && s >= 0.0) best = min(best, s);
  }
  return best;
}
float ray_capsule3(vec3 o, vec3 w, vec3 e, float r) {  // w unit; s >= 0 entering the capsule, else kFar
  float ee = dot(e, e), best = kFar;
  if (ee > 0.0) {
    float ew = dot(e, w), eo = dot(e, o);
    float a = ee - ew * ew, b = ee * dot(w, o) - eo * ew, c = ee * dot(o, o) - eo * eo - r * r * ee;
    float h = b * b - a * c;
    if (a > 0.0 && h >= 0.0) {
      float s = (-b - sqrt(h)) / a, y = eo + s * ew;
      if (s >= 0.0 && y > 0.0 && y < ee) best = s;
    }
  }
  for (int k = 0; k < 2; ++k) {
    vec3 oc = o - (k == 0 ? vec3(0.0) : e);
    float b = dot(oc, w), h = b * b - (dot(oc, oc) - r * r);
    float s = -b - sqrt(max(h, 0.0));
    if (h >= 0.0 && s >= 0.0) best = min(best, s);
  }
  return best;
}
float segment_param2(vec2 x, vec2 e) {
  float ee = dot(e, e);
  return ee > 0.0 ? clamp(dot(x, e) / ee, 0.0, 1.0) : 0.0;
}
float segment_param3(vec3 x, vec3 e) {
  float ee = dot(e, e);
  return ee > 0.0 ? clamp(dot(x, e) / ee, 0.0, 1.0) : 0.0;
}
float silhouette_height(vec2 x, vec3 e) {
  return dot(e.xy, e.xy) > 0.0 ? segment_param2(x, e.xy) * e.z : min(0.0, e.z);
}
// The least distance between the half-line o + s w (s >= 0) and the segment 0 -> e on the plane.
float cross2(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }
float point_to_half_line(vec2 x, vec2 o, vec2 w) {
  return length(x - (o + max(dot(x - o, w) / dot(w, w), 0.0) * w));
}
float half_line_to_segment(vec2 o, vec2 w, vec2 e) {
  float den = cross2(w, e);
  if (den != 0.0) {
    float s = cross2(-o, e) / den, t = cross2(o, w) / -den;
    if (s >= 0.0 && t >= 0.0 && t <= 1.0) return 0.0;  // they cross
  }
  float d = min(point_to_half_line(vec2(0.0), o, w), point_to_half_line(e, o, w));
  return min(d, length(o - segment_param2(o, e) * e));
}

float capsule_column_distance(vec3 p, vec3 w) {
  vec3 e = u_probe_b.xyz - u_probe_a.xyz;
  float r = u_probe_a.w;
  vec3 near3 = segment_param3(p, e) * e;
  if (dot(p - near3, p - near3) <= r * r) return 0.0;  // inside the probe
  vec2 near2 = segment_param2(p.xy, e.xy) * e.xy;
  bool in_outline = dot(p.xy - near2, p.xy - near2) <= r * r;
  if (in_outline && p.z >= silhouette_height(p.xy, e)) return 0.0;  // above it
  float s_f = in_outline ? 0.0 : ray_capsule2(p.xy, w.xy, e.xy, r);
  if (s_f >= kFar) return kFar;
  vec3 q = p + s_f * w;
  if (s_f > 0.0 && q.z >= silhouette_height(q.xy, e)) return s_f;  // through the side
  return ray_capsule3(p, w, e, r);
}

// (d mm, coverage) as normal_distance, for u_probe_b.w = 1. A ray meets the column exactly when
// its trace on the plane reaches into the probe's outline (entering it below the silhouette it
// meets the probe, above it the column's side), so the edge of the shadowed points is where the
// trace only grazes the outline. The coverage is how deep the trace reaches into the outline,
// in depth-map texels: that edge smoothed over a texel, as the depth map's coverage smooths the
// reference-plane footprint's (for a ray along the reference normal it is the same edge, one
// texel inside the outline). The depth map's own coverage at the point met steps with its
// texels along the outline, and streaked the region met through the side on torus_capsule.
vec2 analytic_normal_distance(vec3 p, vec3 n, vec2 uv0) {
  float h0 = dot(p, u_ref_n.xyz);
  vec2 hc = probe_height(uv0);
  float dz = dot(n, u_ref_n.xyz);
  vec2 dir = vec2(dot(n, u_ref_t.xyz), dot(n, u_ref_b.xyz));
  // As normal_distance: along the reference normal, the reference-plane distance bit for bit;
  // inside the probe already, its (negative) reference-plane distance; facing away, no probe.
  if (dot(dir, dir) < 1e-12) return hc.x >= kFar ? hc : vec2(hc.x - h0, hc.y);
  if (hc.x < kFar && hc.x - h0 <= 0.0) return vec2(hc.x - h0, hc.y);
  if (dz <= 0.0) return vec2(kFar, 0.0);
  vec3 p0 = vec3(uv0, h0) - u_probe_a.xyz;
  float s = capsule_column_distance(p0, vec3(dir, dz));
  if (s > u_intensity.w) return vec2(kFar, 0.0);
  float texel = 2.0 * u_window.z / u_window.w;
  float depth = u_probe_a.w - half_line_to_segment(p0.xy, dir, u_probe_b.xy - u_probe_a.xy);
  float coverage = clamp(depth / texel, 0.0, 1.0);
  return coverage > 0.0 ? vec2(s, coverage) : vec2(kFar, 0.0);
}

// Cutaway (Hanson & Zhang §6.3): a fragment of another sheet than the probe's, within u_cutaway.w
// of the segment from the eye to the probe and in front of the probe, is not drawn.
bool cut_away() {
  if (u_cutaway.w <= 0.0 || abs(v_w4 - u_sheet.y) <= u_sheet.z) return false;
  vec3 probe = u_cutaway.xyz;
  vec3 dir = u_eye.w > 0.5 ? probe - u_eye.xyz : u_eye.xyz;  // eye -> probe
  float len2 = dot(dir, dir);
  if (len2 <= 0.0) return false;
  float t = dot(v_world - probe, dir) / len2;  // < 0: between the eye and the probe
  if (t >= 0.0 || (u_eye.w > 0.5 && t < -1.0)) return false;
  return length(v_world - (probe + t * dir)) < u_cutaway.w;
}

void main() {
  if (cut_away()) discard;
  vec3 n = normalize(gl_FrontFacing ? v_normal : -v_normal);
  vec3 rgb = shade_surface(n);
  float intensity = 0.0, d = kFar, tex_sigmas = 0.0, filter_need = 0.0;
#if PS_SHADOW
  vec2 uv = vec2(dot(v_world, u_ref_t.xyz), dot(v_world, u_ref_b.xyz));
  vec2 hc;
  if (u_ref_n.w > 0.5) {
    // The footprint stays within the probe's window on the reference plane in both modes (the
    // plan's shadow_rect bounds it there): a point beside the window whose normal ray would reach
    // the probe, on a concave receiver, is no more shadowed than with the reference plane.
    hc = any(greaterThan(abs(uv - u_window.xy), vec2(u_window.z))) ? vec2(kFar, 0.0)
         : u_probe_b.w > 0.5 ? analytic_normal_distance(v_world, n, uv) : normal_distance(v_world, n, uv);
  } else {
    hc = probe_height(uv);
  }
  // A surface embedded in 4D: the pseudo-shadow falls on the probe's sheet only; where another
  // sheet crosses it in the image (another w), that sheet is "no probe here" (docs/fourd.md).
  if (u_sheet.x > 0.5 && abs(v_w4 - u_sheet.y) > u_sheet.z) hc = vec2(kFar, 0.0);
  if (u_ref_n.w > 0.5) {
    d = hc.x;
  } else {
    d = hc.x >= kFar ? kFar : hc.x - dot(v_world, u_ref_n.xyz);
  }
  IntensityCurve curve = IntensityCurve(u_intensity.x, u_intensity.y, u_intensity.z, u_intensity.w);
  intensity = hc.y * shadow_intensity(curve, d);
  float s = 0.0;  // texture in [-1, 1] contrasts; 0 = untextured
#if PS_TEXTURED
#if PS_GABOR_FILTER
  // The pixel's footprint in (u, v) (lib/gabor.glsl, analytic filtering): derivatives taken
  // here, in uniform control flow, not inside the branch below.
  mat2 duv = mat2(dFdx(uv), dFdy(uv));
#endif
  // Only fragments inside the footprint and the onset distance pay for the Gabor sum.
  if (intensity > 0.0 && d < u_modulation.y) {
#if PS_GABOR_FILTER
    filter_need = gabor_filter_need(duv, u_gabor.filtering.x, u_gabor.amplitude_lambda.z);
#endif
#if PS_GABOR_BAKED && PS_GABOR_FILTER == 1
    tex_sigmas = gabor_noise_baked_filtered(u_gabor_tile, u_gabor.tile, u_gabor.filtering,
                                            u_gabor.amplitude_lambda.zw, uv, duv, int(u_gabor.counts.w)) /
                 u_gabor.kernel.w;
#elif PS_GABOR_BAKED
    tex_sigmas = gabor_noise_baked(u_gabor_tile, u_gabor.tile, uv) / u_gabor.kernel.w;
#elif PS_GABOR_FILTER == 1
    tex_sigmas = gabor_noise_pixel(gabor_material(u_gabor), u_gabor.filtering, uv, duv) / u_gabor.kernel.w;
#else
    tex_sigmas = gabor_noise(gabor_material(u_gabor), uv) / u_gabor.kernel.w;
#endif
    s = tex_sigmas / u_modulation.w;
  }
#endif
  // render.pseudo_shadow = false: the shadow is still measured (intensity, d and the texture feed
  // the AOVs, and through them the reductions and the haptic side), only not composited. A
  // uniform, not the PS_SHADOW=0 variant: that variant writes no AOVs, which the reductions read.
  float darkening = pseudo_shadow_darkening(curve, d, hc.y, u_modulation.y, u_modulation.x, s);
  if (u_feedback.x > 0.5) rgb = composite_pseudo_shadow(rgb, darkening);
#endif
  // The bodies' pseudo-shadows, in every variant (also with the probe out of reach); colour only.
  rgb *= body_shadow_light(IntensityCurve(u_intensity.x, u_intensity.y, u_intensity.z, u_intensity.w),
                           v_world, u_ref_n.xyz);
  o_color = vec4(pow(clamp(rgb, 0.0, 1.0), vec3(u_light_color.a)), 1.0);
  o_normal = vec4(n, 1.0);
  o_aov = vec4(intensity, d >= kFar ? no_probe_distance() : d, tex_sigmas, u_modulation.z);
  o_filter_need = filter_need;
}
