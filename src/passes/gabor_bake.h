// Gabor bake pass (strategy "baked"): evaluates one period of a material's periodic Gabor
// texture, with its derivatives, into an RGBA32F tile once per material; the surface pass's
// PS_GABOR_BAKED variant then reads it with a bicubic Hermite lookup instead of summing
// kernels per fragment.
//   inputs : material Gabor parameters, GaborSetup, GaborBakePlan (src/reference/gabor.h), seed
//   output : tile texture plan.texels^2 RGBA32F, texel (i, j) = (f, f_u h, f_v h, f_uv h^2) at
//            (-period/2 + i h, -period/2 + j h)
// Shaders: glsl/gabor_bake.frag (+ the full-screen triangle of displacement_weights.vert).
#pragma once

#include <cstdint>
#include <string>

#include "core/result.h"
#include "gl/objects.h"
#include "reference/gabor.h"
#include "scene/scene.h"

namespace ps {

Result<gl::Texture> bake_gabor_tile(const std::string& glsl_root, const GaborParams& g,
                                    const GaborSetup& setup, const GaborBakePlan& plan,
                                    std::uint32_t seed);

}  // namespace ps
