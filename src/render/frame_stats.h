// What one frame did (Renderer::render's result): the pseudo-haptic outcome, the skips, the
// per-pass timings, the tile bake's progress and the deformable surfaces as drawn.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "world/deformable_surfaces.h"

namespace ps {

using DeformationStats = world::DeformationStats;  // the session steps the surfaces (frame/haptic_frame.h)

struct FrameStats {
  glm::dvec3 reference_normal{0.0, 0.0, 1.0};  // after this frame's update
  glm::dvec3 displacement{0.0};                // applied to the probe this frame, mm
  double max_penetration_mm = 0.0;
  glm::dvec3 probe_position{0.0};              // after the displacement
  double speed_gain = 0.0;                     // of the first shadowed material
  std::uint32_t shadow_pixels = 0, penetrating_pixels = 0;
  std::vector<std::pair<std::string, double>> timings_ms;
  // The pixels the surface pass drew this frame, and whether it kept the rest of the last frame
  // (RendererOptions::incremental; render/frame_key.h).
  std::int64_t drawn_pixels = 0;
  bool incremental = false;
  // Adaptive resolution (Renderer::set_surface_scale, docs/adaptive.md): the scale the surface
  // pass drew this frame at (1: whole; below 1 the footprint's rectangle still at full
  // resolution), and whether the frame's camera differed from the last frame's.
  double surface_scale = 1.0;
  bool view_moved = false;
  // The frame made the targets of a scale not drawn at before (one per size, kept): its time
  // includes that allocation and says nothing of the scale's cost.
  bool new_targets = false;
  // Whether this frame's time is what a redraw of every pixel at surface_scale costs: what the
  // adaptive scale (render/adaptive_scale.h) learns from.
  bool measures_full_redraw() const { return !incremental && !new_targets; }
  // GPU time of each pass (GL_TIME_ELAPSED), of the newest frame whose queries have come back:
  // gpu_timings_lag frames before this one (0 on llvmpipe, which finishes each pass; usually 1
  // on a GPU). Empty, lag -1: none back yet (docs/benchmarks.md, "GPU timers").
  std::vector<std::pair<std::string, double>> gpu_timings_ms;
  int gpu_timings_lag = -1;
  std::vector<std::string> skipped;
  // The Gabor tile bake, cumulative over the renderer's life. Times count from the start of
  // Renderer::create, in ms.
  double bake_ms = 0.0;          // spent baking tiles, the bake program's one build included
  double bake_progress = 1.0;    // share of the tiles' texels baked; 1: all ready (or none to bake)
  int frames_before_tiles = 0;   // frames drawn with the per-pixel sum while a tile was unfinished
  double first_frame_ms = -1.0;  // until the first frame was drawn; -1: none yet
  double tiles_ready_ms = -1.0;  // until the last tile was ready (create's time if none); -1: not yet
  DeformationStats deformation;  // the deformable surfaces as this frame drew them
  // Texture filtering's level of detail: this frame drew its filtered materials without the
  // filter (RendererOptions::filter_lod), and the largest need for it that the frame measured
  // (0: no filtered texture in the shadow).
  bool gabor_filter_skipped = false;
  double gabor_filter_need = 0.0;
};

}  // namespace ps
