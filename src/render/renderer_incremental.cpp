// The renderer's incremental frames (render/frame_key.h) and the overlays that end them.
#include "render/pass_timer.h"
#include "render/renderer.h"
#include "scene/camera.h"

namespace ps {

// The pixels the surface pass redraws this frame, and how many they are (FrameStats).
PixelRect Renderer::redraw_rect(const std::vector<SurfaceDraw>& draws, const PixelRect& shadow_rect) {
  const int w = scene_.render.width, h = scene_.render.height;
  const FrameKey key = make_frame_key({&draws, scene_.render.background, w, h, mesh_version_,
                                       materials_.tiles().progress()});
  const PixelRect r = history_.redraw(key, shadow_rect, w, h, options_.incremental);
  stats_.drawn_pixels = static_cast<std::int64_t>(r.width()) * r.height();
  stats_.incremental = !(r == PixelRect::whole(w, h));
  return r;
}

// What is drawn over the colour image after the pseudo-shadow: the probe, then the world view.
// Either is outside the frame key, so the frame after one redraws everything (the simple choice:
// the window's overlays move with the probe and would widen the redrawn box to about the same).
void Renderer::draw_overlays(PassTimer& timer) {
  const View& view = *view_;
  const glm::dmat4 view_proj =
      view_projection(view.camera, static_cast<double>(scene_.render.width) / scene_.render.height);
  if (probe_drawn()) {
    ProbeViewPass::Inputs in;
    in.view_proj = view_proj;
    in.light = &view.light;
    in.probe = probe_input();  // after this frame's displacement
    probe_view_.run(in);
    timer.lap("probe_view");
    history_.invalidate();
  }
  if (!world_view_.empty(scene_, view)) {
    world_view_.run(options_.glsl_root, surface_, {view_proj, &scene_, &view, probe_input(), probe_.position});
    timer.lap("world_view");
    history_.invalidate();
  }
}

}  // namespace ps
