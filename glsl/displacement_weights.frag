#version 450 core
// The `displacement` AOV (rendered on request only): per fragment (w * disp, w) with
//   displacement = resistance * (-d) * normal,  weight = (1 - d)^c
// (thesis §4.5.4), the weight rescaled by (1 + max penetration)^-c exactly as
// displacement_rows.comp does for the frame's average (the same expression, kept in step).
#include "lib/reduce_block.glsl"

layout(binding = 0) uniform sampler2D u_aov;     // (intensity, d, texture, resistance)
layout(binding = 1) uniform sampler2D u_normal;  // (normal, covered)

layout(location = 0) out vec4 o_weighted;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  o_weighted = vec4(0.0);
  if (any(greaterThanEqual(p, u_size.xy))) return;  // padding beyond the image
  vec4 aov = texelFetch(u_aov, p, 0);
  float pen = -aov.y;
  if (!(aov.x > 0.0 && pen > 0.0)) return;
  float max_pen = uintBitsToFloat(max_penetration_bits);
  float w = exp(u_params.x * (log(1.0 + min(pen, max_pen)) - log(1.0 + max_pen)));
  vec3 disp = aov.w * pen * texelFetch(u_normal, p, 0).xyz;
  o_weighted = vec4(w * disp, w);
}
