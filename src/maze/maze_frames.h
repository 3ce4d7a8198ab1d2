// The frames of a headless maze session (`maze --every N`): each FrameView the session hands
// out (maze_session.h) drawn by a renderer of the pass's scene from the follow camera, the room
// label stamped in (cues off), every N-th written as DIR/frame_NNNNN.png. Needs a current GL
// context (the caller's); library ps_maze_render.
#pragma once

#include <memory>
#include <string>

#include "core/result.h"
#include "maze/maze_session.h"
#include "render/renderer.h"

namespace ps::maze {

class FrameWriter {
 public:
  FrameWriter(const MazeDesc& desc, std::string dir, int every) : desc_(desc), dir_(std::move(dir)), every_(every) {}
  Status on_frame(const FrameView& v);
  // The renderer that drew the last written frame (null before the first).
  const Renderer* renderer() const { return renderer_.get(); }
  int written() const { return written_; }

 private:
  MazeDesc desc_;
  std::string dir_;
  int every_;
  std::unique_ptr<Renderer> renderer_;
  // A pass began since the renderer was made. Kept across frames that are not written: the
  // session reports a pass switch once, maybe on a frame this writer skips.
  bool stale_ = true;
  int written_ = 0;
};

}  // namespace ps::maze
