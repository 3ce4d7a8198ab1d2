// Uniform contract of the reduction passes; mirrored in src/passes/reductions.h. The storage
// block of the compute path is lib/max_block.glsl (the fragment path has none: WebGL2).
#pragma once

layout(std140, binding = 0) uniform ReduceBlock {
  ivec4 u_size;     // xy: image size; zw: power-of-two reduction target size
  vec4 u_params;    // x: weight exponent c (thesis 20); y: 1 = row sums over the penetrating box only
  ivec4 u_rect;     // x0, y0, x1, y1 (exclusive): the pixels that can hold a pseudo-shadow
};
