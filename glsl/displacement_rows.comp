#version 450 core
// Weighted-average displacement (thesis §4.5.4, step 3g), per image row: one invocation walks
// one row and writes (sum of w * disp, sum of w) for it; the host adds the rows in double.
//   displacement = resistance * (-d) * normal,  weight = (1 - d)^c,
// with the weight rescaled by (1 + max penetration)^-c (in log space) so it lies in (0, 1] and
// cannot overflow; the factor cancels in sum(w * disp) / sum(w). Runs after
// max_penetration.comp, whose maximum it reads. Row sums instead of a full-screen target and
// its mip chain: no RGBA32F image of the screen's size (64 MiB + mips at 2048^2) and no mipmap
// pass. glsl/displacement_weights.frag writes the same per-pixel values for the
// `displacement` AOV, on request only.
#include "lib/reduce_block.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D u_aov;     // (intensity, d, texture, resistance)
layout(binding = 1) uniform sampler2D u_normal;  // (normal, covered)

layout(std430, binding = 1) writeonly buffer RowBlock {
  vec4 row_sums[];  // per row: (sum w * disp, sum w)
};

void main() {
  int y = int(gl_GlobalInvocationID.x);
  if (y >= u_size.y) return;
  float max_pen = uintBitsToFloat(max_penetration_bits);
  vec4 sum = vec4(0.0);
  for (int x = 0; x < u_size.x; ++x) {
    vec4 aov = texelFetch(u_aov, ivec2(x, y), 0);
    float pen = -aov.y;
    if (!(aov.x > 0.0 && pen > 0.0)) continue;
    float w = exp(u_params.x * (log(1.0 + min(pen, max_pen)) - log(1.0 + max_pen)));
    vec3 disp = aov.w * pen * texelFetch(u_normal, ivec2(x, y), 0).xyz;
    sum += vec4(w * disp, w);
  }
  row_sums[y] = sum;
}
