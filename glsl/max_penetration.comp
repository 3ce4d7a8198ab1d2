#version 450 core
// Exact maximum penetration (the thesis's "ideal" displacement, §4.5.4 / §5.1): max of -d over
// all fragments with d < 0, reduced in shared memory, one atomic per work group.
#include "lib/reduce_block.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) uniform sampler2D u_aov;  // (intensity, d, texture, resistance)

shared uint s_pen[256];
shared uint s_res[256];

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  uint pen = 0u, res = 0u, n_pen = 0u, n_cov = 0u;
  if (all(lessThan(p, u_size.xy))) {
    vec4 aov = texelFetch(u_aov, p, 0);
    if (aov.x > 0.0) n_cov = 1u;
    // `-d > 0` is false for NaN, so NaN never enters the maximum.
    if (aov.x > 0.0 && -aov.y > 0.0) {
      pen = floatBitsToUint(-aov.y);
      res = floatBitsToUint(max(-aov.y * aov.w, 0.0));
      n_pen = 1u;
    }
  }
  uint i = gl_LocalInvocationIndex;
  s_pen[i] = pen;
  s_res[i] = res;
  barrier();
  for (uint stride = 128u; stride > 0u; stride >>= 1) {
    if (i < stride) {
      s_pen[i] = max(s_pen[i], s_pen[i + stride]);
      s_res[i] = max(s_res[i], s_res[i + stride]);
    }
    barrier();
  }
  if (n_pen != 0u) atomicAdd(penetrating_fragments, 1u);
  if (n_cov != 0u) atomicAdd(covered_fragments, 1u);
  if (i == 0u) {
    atomicMax(max_penetration_bits, s_pen[0]);
    atomicMax(max_resisted_penetration_bits, s_res[0]);
  }
}
