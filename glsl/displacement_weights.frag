#version 450 core
// The `displacement` AOV (rendered on request only): per fragment (w * disp, w), the values
// displacement_rows.comp sums for the frame's average (lib/displacement_weight.glsl).
// The frame's maximum penetration comes as a uniform (either reduction path gives it), so this
// shader has a GLSL ES 3.00 form too.
#include "lib/reduce_block.glsl"
#include "lib/displacement_weight.glsl"

layout(binding = 0) uniform sampler2D u_aov;     // (intensity, d, texture, resistance)
layout(binding = 1) uniform sampler2D u_normal;  // (normal, covered)
layout(location = 0) uniform float u_max_pen;    // mm, the last run()'s maximum penetration

layout(location = 0) out vec4 o_weighted;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  o_weighted = vec4(0.0);
  if (any(greaterThanEqual(p, u_size.xy))) return;  // padding beyond the image
  o_weighted = weighted_displacement(u_aov, u_normal, p, u_max_pen);
}
