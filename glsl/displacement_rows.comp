#version 450 core
// Weighted-average displacement (thesis §4.5.4, step 3g), per image row: one invocation walks
// one row and writes (sum of w * disp, sum of w) for it (lib/reduce_rows.glsl); the host adds
// the rows in double. Runs after max_penetration.comp, whose maximum it reads. Row sums instead
// of a full-screen target and its mip chain: no RGBA32F image of the screen's size (64 MiB +
// mips at 2048^2) and no mipmap pass. glsl/displacement_weights.frag writes the same per-pixel
// values for the `displacement` AOV, on request only. The fragment path's twin:
// displacement_rows.frag.
#include "lib/reduce_block.glsl"
#include "lib/max_block.glsl"
#include "lib/displacement_weight.glsl"
#include "lib/reduce_rows.glsl"

layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2D u_aov;     // (intensity, d, texture, resistance)
layout(binding = 1) uniform sampler2D u_normal;  // (normal, covered)

layout(std430, binding = 1) writeonly buffer RowBlock {
  vec4 row_sums[];  // per row: (sum w * disp, sum w)
};

void main() {
  // Rows and columns of u_rect only: outside it no pixel is in the shadow.
  int y = u_rect.y + int(gl_GlobalInvocationID.x);
  if (y >= u_rect.w) return;
  // Only the box of penetrating pixels (found by max_penetration.comp) has non-zero terms.
  // (u_params.y == 0: whole rows of u_rect, the reference the tests compare this with.)
  ivec4 box = u_params.y != 0.0 ? penetrating_box : ivec4(u_rect.xy, u_rect.zw - 1);
  row_sums[y] = displacement_row(u_aov, u_normal, y, box, uintBitsToFloat(max_penetration_bits));
}
