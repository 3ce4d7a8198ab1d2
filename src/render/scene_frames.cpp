#include "render/scene_frames.h"

namespace ps {

Status render_scene_frames(Renderer& renderer, int frames, const std::function<void(int)>& after_frame) {
  const FrameInput start = start_frame_input(renderer.scene());
  for (int i = 0; i < frames; ++i) {
    if (auto s = renderer.render(i == 0 ? start : FrameInput{}); !s) return s.error();
    if (after_frame) after_frame(i);
  }
  return ok_status();
}

}  // namespace ps
