#version 450 core
// The fragment path of max_penetration.comp (ReductionMethod::kFragment; no compute, storage
// buffers or atomics, as WebGL2): one fragment per image row of a one-texel-wide RGBA32F target
// pair runs the same row (lib/reduce_rows.glsl) and writes it; ReductionsPass adds the rows up
// on the host. Counts and columns are below 2^24, exact as floats.
#include "lib/reduce_block.glsl"
#include "lib/displacement_weight.glsl"
#include "lib/reduce_rows.glsl"

layout(binding = 0) uniform sampler2D u_aov;  // (intensity, d, texture, resistance)
layout(binding = 2) uniform sampler2D u_filter_need;  // R32F, SurfacePass::filter_need()

layout(location = 0) out vec4 o_max;   // (max -d, max resistance * -d, max need, covered pixels)
layout(location = 1) out vec4 o_span;  // (penetrating pixels, first and last penetrating column, 0)

void main() {
  PenetrationRow r = penetration_row(u_aov, u_filter_need, int(gl_FragCoord.y));
  o_max = vec4(r.pen, r.res, r.need, float(r.n_cov));
  o_span = vec4(float(r.n_pen), float(r.x_lo), float(r.x_hi), 0.0);
}
