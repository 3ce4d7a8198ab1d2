// Uniform contract of one material's Gabor texture, written once: a std140 struct that is a
// member of the surface pass's SurfaceBlock and of the Gabor bake pass's GaborBakeBlock (both
// named u_gabor). Mirrored by GaborBlock in src/passes/gabor_block.h, whose make_gabor_block()
// is the only place the parameters are packed; gabor_material() below the only place they are
// unpacked. Needs lib/gabor.glsl (included here).
#pragma once

#include "gabor.glsl"

struct GaborBlock {
  vec4 amplitude_lambda;  // x A_min, y A_max, z lambda_min mm, w lambda_max mm
  vec4 theta_density;     // x theta_min rad, y theta_max rad, z n_min, w n_max (impulses per kernel)
  vec4 kernel;            // x kernel periods, y cell mm, z trunc factor, w sigma_unit
  vec4 tile;              // baked tile: x period mm, y texel h mm, z texels, w period cells (0: none)
  uvec4 counts;           // x seed, y max impulses per cell, z stratified impulses per cell, w the
                          // baked tile's mip levels (0: none)
  vec4 filtering;         // analytic filter (PS_GABOR_FILTER): x pixel variance px^2, y tile level
                          // sigma in its texels, z footprint cap mm^2, w most sub-boxes per pixel
};

GaborMaterial gabor_material(GaborBlock b) {
  return GaborMaterial(b.amplitude_lambda.xy, b.amplitude_lambda.zw, b.theta_density.xy,
                       b.theta_density.zw, b.kernel.x, b.kernel.y, b.kernel.z, b.counts.x,
                       int(b.counts.y)
#if PS_GABOR_STRATIFIED
                       , int(b.counts.z)
#endif
                       );
}
