#version 450 core
// Probe depth pass, analytic variant (sphere, capsule): for each texel of the window on the
// reference plane, the lowest height of the probe above that point (thesis Table 4.2 step 2),
// by ray-casting along +n. Output R32F; kFar where the ray misses.
// CPU twin: capsule_lowest_height() in src/reference/probe_geometry.cpp.
// Variant PS_PROBE_SPHERE=1: a sphere probe (a capsule of length 0), its one end cap alone:
// the same bits as the capsule code, whose other terms are a miss and the same cap again.
#include "lib/probe_depth_block.glsl"

#ifndef PS_PROBE_SPHERE
#define PS_PROBE_SPHERE 0
#endif

layout(location = 0) out float o_height;

const float kFar = 1.0e30;

float hit_sphere(vec3 o, vec3 c, float r) {  // ray direction (0, 0, 1)
  vec3 oc = o - c;
  float b = oc.z;
  float h = b * b - (dot(oc, oc) - r * r);
  return h < 0.0 ? kFar : -b - sqrt(h);
}

void main() {
  vec2 st = gl_FragCoord.xy / u_window.w;  // texel centre in [0, 1]
  vec2 uv = u_window.xy + (st - 0.5) * 2.0 * u_window.z;
  // Coordinates relative to end a keep float precision when the scene is far from the origin.
  vec3 pa = vec3(0.0), pb = u_cap_b.xyz - u_cap_a.xyz;
  float r = u_cap_a.w;
  float h0 = min(0.0, pb.z) - 2.0 * r - 1.0;
  vec3 ro = vec3(uv - u_cap_a.xy, h0);
#if PS_PROBE_SPHERE
  float best = hit_sphere(ro, pa, r);
#else
  vec3 ba = pb - pa, oa = ro - pa;
  float baba = dot(ba, ba), bard = ba.z, baoa = dot(ba, oa), rdoa = oa.z, oaoa = dot(oa, oa);
  float best = kFar;
  if (baba > 0.0) {
    float a = baba - bard * bard;
    float b = baba * rdoa - baoa * bard;
    float c = baba * oaoa - baoa * baoa - r * r * baba;
    float h = b * b - a * c;
    if (a > 0.0 && h >= 0.0) {
      float t = (-b - sqrt(h)) / a;
      float y = baoa + t * bard;
      if (y > 0.0 && y < baba) best = t;
    }
  }
  best = min(best, min(hit_sphere(ro, pa, r), hit_sphere(ro, pb, r)));
#endif
  o_height = best >= kFar ? kFar : u_cap_a.z + h0 + best;
}
