#version 450 core
// The mean visible normal's row sums (thesis Table 4.2 step 4, the reference plane): one
// invocation adds up one image row of the surface pass's normal target, (n, 1) per covered
// pixel and zero elsewhere, with Kahan's compensated sum (`precise`: the compensation must not
// be simplified away), so each row sum is within a float rounding of the exact one; the rows are
// added in double by ReductionsPass::mean_normal. It reads the image's w x h texels once, where
// the mip chain it replaces wrote and read the whole power-of-two target and its levels.
#include "lib/reduce_block.glsl"
layout(local_size_x = 64) in;
layout(binding = 1) uniform sampler2D u_normal;  // RGBA32F: (n, 1) per covered pixel
layout(std430, binding = 2) writeonly buffer NormalRows {
  vec4 normal_rows[];  // one per image row
};
void main() {
  int y = int(gl_GlobalInvocationID.x);
  if (y >= u_size.y) return;
  precise vec4 sum = vec4(0.0), c = vec4(0.0);
  for (int x = 0; x < u_size.x; ++x) {
    precise vec4 v = texelFetch(u_normal, ivec2(x, y), 0) - c;
    precise vec4 t = sum + v;
    c = (t - sum) - v;
    sum = t;
  }
  normal_rows[y] = sum;
}
