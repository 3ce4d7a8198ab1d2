// Uniform contract of the Gabor bake pass: the material's GaborBlock (its tile member says
// which period to bake) and the mip level being baked (texel size, filter variance). Mirrored by GaborBakeBlock in
// src/passes/gabor_bake.h.
#pragma once

#include "gabor_block.glsl"

layout(std140, binding = 0) uniform GaborBakeBlock {
  GaborBlock u_gabor;
  vec4 u_level;  // the tile level being baked: x its texel h_L mm, y its filter variance mm^2 (0: none)
};
