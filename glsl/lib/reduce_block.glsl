// Uniform and storage contract of the reduction passes; mirrored in src/passes/reductions.h.
#pragma once

layout(std140, binding = 0) uniform ReduceBlock {
  ivec4 u_size;     // xy: image size; zw: power-of-two reduction target size
  vec4 u_params;    // x: weight exponent c (thesis 20); y: 1 = row sums over the penetrating box only
  ivec4 u_rect;     // x0, y0, x1, y1 (exclusive): the pixels that can hold a pseudo-shadow
};

// Maxima as float bits: for non-negative floats the uint order equals the float order, so
// atomicMax on the bits is an exact float max.
layout(std430, binding = 0) buffer MaxBlock {
  uint max_penetration_bits;            // max of -d over penetrating fragments (mm)
  uint max_resisted_penetration_bits;   // max of resistance * (-d)
  uint penetrating_fragments;
  uint covered_fragments;               // fragments inside the pseudo-shadow
  ivec4 penetrating_box;                // x0, y0, x1, y1 (inclusive) of the penetrating pixels
  uint max_filter_need_bits;            // max of the surface pass's filter need (its target 3)
};
