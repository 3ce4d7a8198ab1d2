#version 450 core
// The fragment path of normal_rows.comp (ReductionMethod::kFragment): one fragment per image row
// writes the row's Kahan-compensated sum of the normal target (lib/reduce_rows.glsl) into a
// one-texel-wide RGBA32F target; the rows are added in double on the host.
#include "lib/reduce_block.glsl"
#include "lib/displacement_weight.glsl"
#include "lib/reduce_rows.glsl"

layout(binding = 1) uniform sampler2D u_normal;  // RGBA32F: (n, 1) per covered pixel

layout(location = 0) out vec4 o_row;

void main() { o_row = normal_row(u_normal, int(gl_FragCoord.y)); }
