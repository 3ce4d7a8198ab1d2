#version 450 core
// The `displacement` AOV (rendered on request only): per fragment (w * disp, w), the values
// displacement_rows.comp sums for the frame's average (lib/displacement_weight.glsl).
#include "lib/reduce_block.glsl"
#include "lib/max_block.glsl"
#include "lib/displacement_weight.glsl"

layout(binding = 0) uniform sampler2D u_aov;     // (intensity, d, texture, resistance)
layout(binding = 1) uniform sampler2D u_normal;  // (normal, covered)

layout(location = 0) out vec4 o_weighted;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  o_weighted = vec4(0.0);
  if (any(greaterThanEqual(p, u_size.xy))) return;  // padding beyond the image
  o_weighted = weighted_displacement(u_aov, u_normal, p, uintBitsToFloat(max_penetration_bits));
}
