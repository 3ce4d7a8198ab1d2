#version 450 core
// The fragment path of displacement_rows.comp (ReductionMethod::kFragment): one fragment per
// image row writes the row's (sum of w * disp, sum of w) (lib/reduce_rows.glsl) into a
// one-texel-wide RGBA32F target. The maximum penetration and the box of penetrating pixels come
// as uniforms, from max_penetration_rows.frag's rows reduced on the host.
#include "lib/reduce_block.glsl"
#include "lib/displacement_weight.glsl"
#include "lib/reduce_rows.glsl"

layout(binding = 0) uniform sampler2D u_aov;     // (intensity, d, texture, resistance)
layout(binding = 1) uniform sampler2D u_normal;  // (normal, covered)
layout(location = 0) uniform float u_max_pen;    // mm, the frame's maximum penetration
layout(location = 1) uniform ivec4 u_box;        // x0, y0, x1, y1 (inclusive): the rows' columns

layout(location = 0) out vec4 o_row;

void main() { o_row = displacement_row(u_aov, u_normal, int(gl_FragCoord.y), u_box, u_max_pen); }
