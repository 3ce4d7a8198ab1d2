#version 450 core
// The mean visible normal's row sums (thesis Table 4.2 step 4, the reference plane): one
// invocation adds up one image row of the surface pass's normal target (lib/reduce_rows.glsl,
// Kahan-compensated); the rows are added in double by ReductionsPass::mean_normal. It reads the
// image's w x h texels once, where the mip chain it replaces wrote and read the whole
// power-of-two target and its levels. The fragment path's twin: normal_rows.frag.
#include "lib/reduce_block.glsl"
#include "lib/displacement_weight.glsl"
#include "lib/reduce_rows.glsl"
layout(local_size_x = 64) in;
layout(binding = 1) uniform sampler2D u_normal;  // RGBA32F: (n, 1) per covered pixel
layout(std430, binding = 2) writeonly buffer NormalRows {
  vec4 normal_rows[];  // one per image row
};
void main() {
  int y = int(gl_GlobalInvocationID.x);
  if (y >= u_size.y) return;
  normal_rows[y] = normal_row(u_normal, y);
}
