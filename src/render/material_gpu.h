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
#include <vector>

#include "core/result.h"
#include "gl/objects.h"
#include "passes/gabor_bake.h"
#include "passes/gabor_block.h"
#include "render/tile_bake.h"
#include "scene/scene.h"

namespace ps {

struct SurfacePass;

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

// An upper bound on the pixels a frame textures: the pseudo-shadow's square window (as wide as
// the probe's bounding diameter `probe_diameter_mm`, plan.cpp) seen face-on at the probe's nearest
// distance to the camera (foreshortening only shrinks it), capped by the image.
double textured_pixels_bound(const RenderSettings& rs, const Camera& camera, const glm::dvec3& probe_mm,
                             double probe_diameter_mm);

// A renderer's materials on the GPU (index = Scene::materials) and the tiles still to bake for
// them (all at once unless sliced: render/tile_bake.h).
class MaterialSet {
 public:
  Status load(std::span<const Material> materials, const StrategyInputs& in);
  // Strategy "baked": one tile per material, baked here (or queued for advance() when
  // slice_ms > 0), i.e. again only when the material changes (every edit builds a new renderer).
  // `reuse`: an earlier renderer's set of the same seed, whose unchanged finished tiles are kept
  // (null: none).
  Status bake(const std::string& glsl_root, double slice_ms, const MaterialSet* reuse);
  // One band of the queued tiles (nothing when done), about as long as the last frame
  // (`last_frame_ms`; TileBaker::bake_slice); a finished tile replaces its material's per-pixel
  // sum from the next draw on.
  Status advance(const std::string& glsl_root, double last_frame_ms);
  const TileBaker& tiles() const { return tiles_; }
  // The filter's level of detail: each analytically filtered material's variant with the filter
  // skipped (PS_GABOR_FILTER=2), as the surfaces will draw it once its tile is there, built ahead
  // so a live session's switch to it does not stall a frame.
  Status warm_unfiltered(SurfacePass& surface, std::span<const Surface> surfaces) const;

  const MaterialGpu& operator[](std::size_t i) const { return materials_[i]; }
  auto begin() const { return materials_.begin(); }
  auto end() const { return materials_.end(); }

 private:
  void collect();
  std::vector<MaterialGpu> materials_;
  TileBaker tiles_;
};

}  // namespace ps
