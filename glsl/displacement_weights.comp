#version 450 core
// Pseudo-haptic displacement per fragment (thesis §4.5.4, step 3g):
//   displacement = resistance * (-d) * normal,  weight = (1 - d)^c,
// stored as (weight * displacement, weight) for the mipmap average. The weight is rescaled by
// (1 + max penetration)^-c (computed in log space) so it lies in (0, 1] and cannot overflow;
// the factor cancels in average(weighted displacement) / average(weight).
#include "lib/reduce_block.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) uniform sampler2D u_aov;
layout(binding = 1) uniform sampler2D u_normal;
layout(binding = 0, rgba32f) uniform writeonly image2D u_displacement;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, u_size.zw))) return;
  vec4 result = vec4(0.0);
  if (all(lessThan(p, u_size.xy))) {
    vec4 aov = texelFetch(u_aov, p, 0);
    float pen = -aov.y;
    if (aov.x > 0.0 && pen > 0.0) {
      float max_pen = uintBitsToFloat(max_penetration_bits);
      float w = exp(u_params.x * (log(1.0 + min(pen, max_pen)) - log(1.0 + max_pen)));
      vec3 disp = aov.w * pen * texelFetch(u_normal, p, 0).xyz;
      result = vec4(w * disp, w);
    }
  }
  imageStore(u_displacement, p, result);
}
