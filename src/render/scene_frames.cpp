#include "render/scene_frames.h"

namespace ps {

Status render_scene_frames(Renderer& renderer, int frames, const std::function<void(int)>& after_frame) {
  for (int i = 0; i < frames; ++i) {
    if (Status s = renderer.render_frame(); !s) return s;
    if (after_frame) after_frame(i);
  }
  return ok_status();
}

}  // namespace ps
