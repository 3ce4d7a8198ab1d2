// What the renderer keeps per scene material (index = Scene::materials), built once at creation:
// what was decided on the CPU (the Gabor setup and strategy: auto's choice of a baked tile, or
// the per-pixel sum when that is less work for the frames expected), then what lives on the GPU
// (albedo texture, packed Gabor uniforms, the tile, the intensity table). The tiles themselves
// are baked by render/tile_bake.h; a tile of an earlier renderer is reused where the material's
// Gabor parameters, the seed and the plan are unchanged (a tuning edit of another value).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "core/result.h"
#include "gl/objects.h"
#include "passes/gabor_bake.h"
#include "passes/gabor_block.h"
#include "scene/scene.h"

namespace ps {

struct MaterialGpu {
  const Material* material = nullptr;  // the scene's, this state was made from (never copied)
  GaborSetup gabor_setup;
  GaborBakePlan bake_plan;    // ok == false: not baked (naive or stratified sum)
  std::string strategy_note;  // auto's choice or baked's fallback, for stats.skipped; empty: none
  GaborBlock gabor_block;     // the Gabor uniforms (with the tile plan), packed once
  gl::Texture albedo;         // empty: no albedo texture
  std::shared_ptr<gl::Texture> gabor_tile;  // null: none; shared with an earlier renderer's
  gl::Buffer intensity_lut;   // empty: no intensity_lut (the formula); passes/surface.h IntensityLutBlock
};

// What the strategy choice weighs besides the material.
struct StrategyInputs {
  // The pseudo-shadow's square window, as wide as the probe's bounding diameter (plan.cpp): a
  // baked tile chosen by "auto" must be at least that long so no shadow shows a repeat.
  double shadow_window_mm = 0.0;
  std::uint32_t seed = 0;
  int expected_frames = 0;  // RendererOptions::expected_frames (0: unknown, bake)
  // An upper bound on the pixels a frame textures (Renderer::textured_pixels_per_frame).
  double textured_pixels_per_frame = 0.0;
};

// The material's albedo texture, intensity table, Gabor setup, strategy and packed uniforms (no
// tile yet), pointing at `m`, which must outlive it. Needs a current GL context; a missing albedo
// file is an error.
Result<MaterialGpu> load_material_gpu(const Material& m, const StrategyInputs& in);

// A finished tile of `old` (the materials of an earlier renderer, still alive) made from the same
// Gabor parameters and plan; null if none. The seeds must be equal.
std::shared_ptr<gl::Texture> reusable_tile(std::span<const MaterialGpu> old, const Material& m,
                                           const GaborBakePlan& plan);

}  // namespace ps
