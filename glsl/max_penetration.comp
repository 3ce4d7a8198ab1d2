#version 450 core
// Exact maximum penetration (the thesis's "ideal" displacement, §4.5.4 / §5.1): max of -d over
// all fragments with d < 0. One invocation walks one image row and issues one atomic per
// row: llvmpipe runs work-group barriers and per-fragment atomics very slowly (a shared-memory
// tree reduction measured 37 ms at 512^2, this loop well under 2 ms).
#include "lib/reduce_block.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D u_aov;  // (intensity, d, texture, resistance)
layout(binding = 2) uniform sampler2D u_filter_need;  // R32F, SurfacePass::filter_need()

void main() {
  // Rows and columns of u_rect only: outside it no pixel is in the shadow.
  int y = u_rect.y + int(gl_GlobalInvocationID.x);
  if (y >= u_rect.w) return;
  float pen = 0.0, res = 0.0, need = 0.0;
  uint n_pen = 0u, n_cov = 0u;
  int x_lo = u_rect.z, x_hi = u_rect.x - 1;  // the row's penetrating pixels
  for (int x = u_rect.x; x < u_rect.z; ++x) {
    vec4 aov = texelFetch(u_aov, ivec2(x, y), 0);
    if (!(aov.x > 0.0)) continue;
    ++n_cov;
    need = max(need, texelFetch(u_filter_need, ivec2(x, y), 0).r);  // >= 0: the uint order is the float order
    // `-d > 0` is false for NaN, so NaN never enters the maximum.
    if (-aov.y > 0.0) {
      pen = max(pen, -aov.y);
      res = max(res, -aov.y * max(aov.w, 0.0));
      ++n_pen;
      x_lo = min(x_lo, x);
      x_hi = x;
    }
  }
  if (n_cov == 0u) return;
  atomicAdd(covered_fragments, n_cov);
  if (need > 0.0) atomicMax(max_filter_need_bits, floatBitsToUint(need));
  if (n_pen == 0u) return;
  atomicAdd(penetrating_fragments, n_pen);
  atomicMax(max_penetration_bits, floatBitsToUint(pen));
  atomicMax(max_resisted_penetration_bits, floatBitsToUint(res));
  atomicMin(penetrating_box.x, x_lo);
  atomicMin(penetrating_box.y, y);
  atomicMax(penetrating_box.z, x_hi);
  atomicMax(penetrating_box.w, y);
}
