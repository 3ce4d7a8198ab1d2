#include "maze/maze_frames.h"

#include <cstdio>

#include "image/image.h"
#include "maze/maze_screen.h"

namespace ps::maze {

Status FrameWriter::on_frame(const FrameView& v) {
  stale_ = stale_ || v.scene_changed;
  if (every_ <= 0 || v.index % every_ != 0) return ok_status();
  if (stale_ || !renderer_) {
    renderer_.reset();  // the old one's GL objects go before the new one's are made
    auto r = Renderer::create(v.scene.scene, RendererOptions{});
    if (!r) return r.error();
    renderer_ = std::move(r.value());
    stale_ = false;
  }
  renderer_->set_camera(follow_camera(desc_, v.state.proxy_mm));
  renderer_->set_probe_state(v.state.proxy_mm, v.state.velocity_mm_s);
  if (Status s = renderer_->render_frame(); !s) return s;
  Image im = renderer_->read_color();
  stamp_label(im, v.label);
  char name[48];
  std::snprintf(name, sizeof name, "/frame_%05d.png", v.index);
  if (Status s = write_image(dir_ + name, im); !s) return s;
  ++written_;
  return ok_status();
}

}  // namespace ps::maze
