// Storage contract of the compute reductions (glsl/max_penetration.comp, displacement_rows.comp); mirrored
// in src/passes/reductions.h (MaxBlock). The fragment path (glsl/*_rows.frag) writes per-row
// values instead and ReductionsPass reduces them on the host to the same block.
#pragma once

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
