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
  if (size.x < w || size.y < h) return draw_reduced(draws, plan, rect, scale);
  last_reduced_ = false;
  stats_.surface_scale = 1.0;  // a scale too close to 1 to drop a pixel draws whole
  return surface_.run(draws, plan.shadow_active ? &probe_depth_.depth() : nullptr, scene_.render.background, rect,
                      redraw_rect(draws, rect));
}

// Small image, upsampled; then the footprint's rectangle drawn whole over it with its shadow
// variants: the pseudo-shadow keeps its edge and its texture's contrast, and the reductions
// (which read only that rectangle) see the same values a whole frame would give them. The next
// frame redraws every pixel (the targets hold the upsampled image, which no key describes).
Status Renderer::draw_reduced(const std::vector<SurfaceDraw>& draws, const FramePlan& plan, const PixelRect& rect,
                              double scale) {
  const int w = scene_.render.width, h = scene_.render.height;
  const glm::ivec2 size(std::max(1, static_cast<int>(std::lround(w * scale))),
                        std::max(1, static_cast<int>(std::lround(h * scale))));
  // The overlays are depth-tested against the surfaces: the depth is upsampled only for them.
  const bool overlays = view_->show.probe || !world_view_.empty(scene_, *view_);
  if (Status s = surface_.run_reduced(draws, scene_.render.background, size, overlays); !s) return s;
  std::int64_t drawn = static_cast<std::int64_t>(size.x) * size.y;
  if (!rect.empty()) {
    if (Status s = surface_.run(draws, plan.shadow_active ? &probe_depth_.depth() : nullptr, scene_.render.background,
                                rect, rect);
        !s)
      return s;
    drawn += static_cast<std::int64_t>(rect.width()) * rect.height();
  }
  history_.invalidate();
  last_reduced_ = true;
  stats_.drawn_pixels = drawn;
  stats_.incremental = false;
  return ok_status();
}

}  // namespace ps
