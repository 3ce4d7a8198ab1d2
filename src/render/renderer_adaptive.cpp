// The renderer's adaptive resolution (docs/adaptive.md): while the view moves, the surface pass is
// drawn small and upsampled, and the footprint's rectangle redrawn at full resolution over it.
#include <algorithm>
#include <cmath>

#include "render/renderer.h"

namespace ps {

// The scale is taken only where the frame can be drawn reduced and still feed the haptic side
// whole: the reductions must read the footprint's rectangle alone (footprint_rect), which the
// reduced frame redraws at full resolution.
double Renderer::frame_scale() {
  const bool moved = last_camera_ && !same_camera(*last_camera_, view_->camera);
  last_camera_ = view_->camera;
  double scale = moved ? surface_scale_.moving : surface_scale_.still;
  if (!options_.footprint_rect || !(scale > 0.0) || scale > 1.0) scale = 1.0;
  stats_.view_moved = moved;
  stats_.surface_scale = scale;
  return scale;
}

Status Renderer::draw_surfaces(const std::vector<SurfaceDraw>& draws, const FramePlan& plan, const PixelRect& rect) {
  const double scale = frame_scale();
  const int w = scene_.render.width, h = scene_.render.height;
  const glm::ivec2 size(std::clamp(static_cast<int>(std::lround(w * scale)), 1, w),
                        std::clamp(static_cast<int>(std::lround(h * scale)), 1, h));
  if (size.x < w || size.y < h) return draw_reduced(draws, plan, rect, size);
  last_reduced_ = nullptr;
  stats_.surface_scale = 1.0;  // a scale too close to 1 to drop a pixel draws whole
  return surface_.run(draws, plan.shadow_active ? &probe_depth_.depth() : nullptr, scene_.render.background, rect,
                      redraw_rect(draws, rect));
}

// The small pass of `size` (one per size, made at its first frame, sharing the programs).
Result<SurfacePass*> Renderer::reduced_pass(glm::ivec2 size) {
  auto [it, fresh] = reduced_passes_.try_emplace(std::make_pair(size.x, size.y));
  stats_.new_targets = fresh;
  if (fresh)
    if (Status s = it->second.init_sharing(surface_, {size.x, size.y}); !s) {
      reduced_passes_.erase(it);
      return s.error();
    }
  return &it->second;
}

// The small image (plain variants: no shadow at that resolution), upsampled; then the
// footprint's rectangle drawn whole over it with its shadow variants: the pseudo-shadow keeps its
// edge and its texture's contrast, and the reductions (which read only that rectangle) see the
// values a whole frame gives them. The next frame redraws every pixel (the targets hold an
// upsampled image, which no frame key describes).
Status Renderer::draw_reduced(const std::vector<SurfaceDraw>& draws, const FramePlan& plan, const PixelRect& rect,
                              glm::ivec2 size) {
  auto small = reduced_pass(size);
  if (!small) return small.error();
  if (Status s = small.value()->run(draws, nullptr, scene_.render.background, PixelRect{}); !s) return s;
  // The overlays are depth-tested against the surfaces: the depth is upsampled only for them.
  const bool overlays = probe_drawn() || !world_view_.empty(scene_, *view_);
  surface_.take_upsampled(*small.value(), overlays);
  std::int64_t drawn = static_cast<std::int64_t>(size.x) * size.y;
  if (!rect.empty()) {
    if (Status s = surface_.run(draws, plan.shadow_active ? &probe_depth_.depth() : nullptr, scene_.render.background,
                                rect, rect);
        !s)
      return s;
    drawn += static_cast<std::int64_t>(rect.width()) * rect.height();
  }
  history_.invalidate();
  last_reduced_ = small.value();
  stats_.drawn_pixels = drawn;
  stats_.incremental = false;
  return ok_status();
}

}  // namespace ps
