#include "maze/maze_frames.h"

#include <cstdio>

#include "frame/haptic_frame.h"
#include "image/image.h"
#include "maze/maze_screen.h"
#include "prepare/prepare.h"

namespace ps::maze {

Status FrameWriter::on_frame(const FrameView& v) {
  stale_ = stale_ || v.scene_changed;
  if (every_ <= 0 || v.index % every_ != 0) return ok_status();
  if (stale_ || !renderer_) {
    renderer_.reset();  // the old one's GL objects go before the new one's are made
    auto r = open_renderer(v.scene.scene, RendererOptions{});
    if (!r) return r.error();
    renderer_ = std::move(r.value());
    stale_ = false;
  }
  const HapticFrameSources maze{.camera = follow_camera(desc_, v.state.proxy_mm)};
  if (auto f = renderer_->render(haptic_frame_input(*renderer_, v.state, maze)); !f) return f.error();
  Image im = renderer_->read_color();
  stamp_label(im, v.label);
  char name[48];
  std::snprintf(name, sizeof name, "/frame_%05d.png", v.index);
  if (Status s = write_image(dir_ + name, im); !s) return s;
  ++written_;
  return ok_status();
}

}  // namespace ps::maze
