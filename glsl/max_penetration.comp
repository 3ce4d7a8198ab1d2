#version 450 core
// Exact maximum penetration (the thesis's "ideal" displacement, §4.5.4 / §5.1): max of -d over
// all fragments with d < 0. One invocation walks one image row (lib/reduce_rows.glsl) and issues
// one atomic per row: llvmpipe runs work-group barriers and per-fragment atomics very slowly (a
// shared-memory tree reduction measured 37 ms at 512^2, this loop well under 2 ms). The fragment
// path's twin: max_penetration_rows.frag.
#include "lib/reduce_block.glsl"
#include "lib/max_block.glsl"
#include "lib/displacement_weight.glsl"
#include "lib/reduce_rows.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D u_aov;  // (intensity, d, texture, resistance)
layout(binding = 2) uniform sampler2D u_filter_need;  // R32F, SurfacePass::filter_need()

void main() {
  // Rows and columns of u_rect only: outside it no pixel is in the shadow.
  int y = u_rect.y + int(gl_GlobalInvocationID.x);
  if (y >= u_rect.w) return;
  PenetrationRow r = penetration_row(u_aov, u_filter_need, y);
  if (r.n_cov == 0u) return;
  atomicAdd(covered_fragments, r.n_cov);
  // need >= 0: the uint order is the float order.
  if (r.need > 0.0) atomicMax(max_filter_need_bits, floatBitsToUint(r.need));
  if (r.n_pen == 0u) return;
  atomicAdd(penetrating_fragments, r.n_pen);
  atomicMax(max_penetration_bits, floatBitsToUint(r.pen));
  atomicMax(max_resisted_penetration_bits, floatBitsToUint(r.res));
  atomicMin(penetrating_box.x, r.x_lo);
  atomicMin(penetrating_box.y, y);
  atomicMax(penetrating_box.z, r.x_hi);
  atomicMax(penetrating_box.w, y);
}
