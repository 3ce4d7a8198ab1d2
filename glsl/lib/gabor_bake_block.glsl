// Uniform contract of the Gabor bake pass: the material's GaborBlock alone (its tile member
// says which period to bake at which texel size). Mirrored by GaborBakeBlock in
// src/passes/gabor_bake.h.
#pragma once

#include "gabor_block.glsl"

layout(std140, binding = 0) uniform GaborBakeBlock {
  GaborBlock u_gabor;
};
