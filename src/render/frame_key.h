// Incremental frames (docs/architecture.md, "Incremental frames"): while nothing but the probe
// changes, a frame redraws only the bounding box of the last and the new pseudo-shadow
// rectangles and keeps every other pixel of the colour, normal and depth targets from the last
// frame. Whether anything else changed is decided from a frame key the renderer computes from
// the frame's actual inputs, never from a caller's promise:
//   - every byte of each draw's SurfaceBlock that the plain (PS_SHADOW=0) variant reads: the
//     camera (view_proj), light, reference normal (body shadows), material colours and
//     intensity curve, body spheres, 4D sheet, cutaway and eye, the probe's cast shadow
//     (render.cast_shadow: it moves with the probe, outside the rectangle) and the feedback
//     flags (surface.frag, surface.vert);
//   - each draw's mesh, its variant outside the rectangle, its textures and wireframe mode;
//   - the mesh version (bumped by every deformation upload), the background, the image size,
//     the Gabor tiles' bake progress.
// The fields the plain variant never reads (window, probe, speed gain, Gabor block, the plane's
// tangents and probe heights) change with the probe alone and only inside the rectangle.
// Anything not in the key forces a full redraw through FrameHistory::invalidate (overlays).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "passes/pixel_rect.h"
#include "passes/surface.h"

namespace ps {

// The frame's inputs outside the pseudo-shadow rectangle, as bytes compared exactly (no hash:
// two different frames can never share a key).
struct FrameKey {
  std::vector<std::byte> bytes;
  bool operator==(const FrameKey&) const = default;
};

struct FrameKeyInputs {
  const std::vector<SurfaceDraw>* draws = nullptr;
  glm::dvec3 background{0.0};
  int width = 0, height = 0;
  std::uint64_t mesh_version = 0;  // Renderer: bumped by each deformed mesh upload
  double bake_progress = 1.0;      // the Gabor tiles' (TileBaker::progress)
};

FrameKey make_frame_key(const FrameKeyInputs& in);

// The smallest rectangle holding both (one empty: the other).
PixelRect bounding_union(const PixelRect& a, const PixelRect& b);

// What the last frame left in the surface pass's targets, and the pixels the next one redraws.
class FrameHistory {
 public:
  // The pixels this frame must draw: the whole image unless `enabled`, the last frame was kept
  // (not invalidated) and its key equals `key`; then the bounding box of the last and this
  // frame's shadow rectangles (empty when neither frame had one). Remembers this frame.
  PixelRect redraw(FrameKey key, const PixelRect& shadow_rect, int width, int height, bool enabled);
  // Something not in the key was drawn into the targets (overlays, a priming pass): the next
  // frame redraws everything.
  void invalidate() { valid_ = false; }

 private:
  bool valid_ = false;
  FrameKey key_;
  PixelRect shadow_rect_;
};

}  // namespace ps
